// Fixed-point wave kinematics (engine/environment/fixed_point_wave_kinematics.hpp)
// against linear wave theory written out directly (DNV-RP-C205 §3.2.2):
//  * a regular wave in 200 m: u = a ω cosh k(z+h)/sinh kh cos θ, w = −a ω
//    sinh k(z+h)/sinh kh sin θ and their time derivatives, θ = ω t − k·x + φ,
//    to round-off (1e-12 of a ω);
//  * a short-crested sea: the same sum over every component, with the depth
//    cutoff (1e-3 of each component's surface profile) bounding the error;
//  * points above the still-water level and below every component's reach
//    are still.
#include "engine/environment/fixed_point_wave_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/environment/wave_spectrum.hpp"

namespace spiral::engine {
namespace {

void direct_sum(const WaveRealization& sea, const Eigen::Vector3d& x, double t,
                Eigen::Vector3d& u, Eigen::Vector3d& a) {
  u.setZero();
  a.setZero();
  for (const WaveComponent& c : sea.components) {
    const double theta =
        c.omega_rad_per_s * t - c.kx_rad_per_m * x.x() - c.ky_rad_per_m * x.y() + c.phase_rad;
    const double k = c.wavenumber_rad_per_m, h = *sea.water_depth_m;
    // cosh k(z+h) / sinh kh written with e^{kz} (no overflow at kh of hundreds).
    const double e = std::exp(k * x.z()), g = std::exp(-2.0 * k * (x.z() + h));
    const double fh = e * (1.0 + g) / (1.0 - std::exp(-2.0 * k * h));
    const double fv = e * (1.0 - g) / (1.0 - std::exp(-2.0 * k * h));
    const double aw = c.amplitude_m * c.omega_rad_per_s, aw2 = aw * c.omega_rad_per_s;
    u += Eigen::Vector3d(aw * fh * std::cos(theta) * c.cos_heading,
                         aw * fh * std::cos(theta) * c.sin_heading, -aw * fv * std::sin(theta));
    a += Eigen::Vector3d(-aw2 * fh * std::sin(theta) * c.cos_heading,
                         -aw2 * fh * std::sin(theta) * c.sin_heading, -aw2 * fv * std::cos(theta));
  }
}

TEST(FixedPointWaveKinematics, RegularWaveIsLinearTheory) {
  RegularWaveInput in;
  in.amplitude_m = 3.0;
  in.omega_rad_per_s = 0.6;
  in.heading_rad = 0.7;
  in.phase_rad = 0.3;
  in.water_depth_m = 200.0;
  auto sea = std::make_shared<const WaveRealization>(make_regular_wave(in));
  const std::vector<Eigen::Vector3d> points = {{10.0, -20.0, -5.0}, {300.0, 50.0, -80.0}};
  const FixedPointWaveKinematics kin(sea, points, 1e-9);
  std::vector<Eigen::Vector3d> u, a;
  const double scale = in.amplitude_m * in.omega_rad_per_s;
  for (double t : {0.0, 3.7, 1234.5}) {
    kin.evaluate(t, u, a);
    for (std::size_t p = 0; p < points.size(); ++p) {
      Eigen::Vector3d u_ref, a_ref;
      direct_sum(*sea, points[p], t, u_ref, a_ref);
      EXPECT_LT((u[p] - u_ref).norm(), 1e-12 * scale) << "t " << t;
      EXPECT_LT((a[p] - a_ref).norm(), 1e-12 * scale * in.omega_rad_per_s) << "t " << t;
    }
  }
}

TEST(FixedPointWaveKinematics, ShortCrestedSeaWithinTheCutoff) {
  WaveRealizationInput in;
  in.spectrum = make_jonswap_spectrum({8.0, 12.0, 3.3});
  in.seed = 7;
  in.duration_s = 3600.0;
  in.components_per_direction = 100;
  in.spreading = DirectionalSpreading{SpreadingForm::cos_2s, 2.0};
  in.direction_count = 5;
  in.water_depth_m = 1800.0;
  auto sea = std::make_shared<const WaveRealization>(make_wave_realization(in));
  const std::vector<Eigen::Vector3d> points = {{0.0, 0.0, -10.0}, {-40.0, 25.0, -150.0}};
  const FixedPointWaveKinematics kin(sea, points, 1e-3);
  // Left out: components with e^{kz} < 1e-3, each at most 1e-3 of its
  // surface amplitude a ω; all of them together bound the error.
  double surface_scale = 0.0;
  for (const WaveComponent& c : sea->components) surface_scale += c.amplitude_m * c.omega_rad_per_s;
  std::vector<Eigen::Vector3d> u, a;
  for (double t : {100.0, 2000.0}) {
    kin.evaluate(t, u, a);
    for (std::size_t p = 0; p < points.size(); ++p) {
      Eigen::Vector3d u_ref, a_ref;
      direct_sum(*sea, points[p], t, u_ref, a_ref);
      EXPECT_LT((u[p] - u_ref).norm(), 1e-3 * surface_scale) << p;
      EXPECT_GT(u_ref.norm(), 0.0);
    }
  }
}

TEST(FixedPointWaveKinematics, DryAndDeepPointsAreStill) {
  RegularWaveInput in;
  in.amplitude_m = 2.0;
  in.omega_rad_per_s = 0.8;  // k = 0.065 rad/m: e^{kz} = 1e-3 at z = -106 m
  in.water_depth_m = 1800.0;
  auto sea = std::make_shared<const WaveRealization>(make_regular_wave(in));
  const FixedPointWaveKinematics kin(sea, {{0.0, 0.0, 1.0}, {0.0, 0.0, -500.0}, {0, 0, -50.0}});
  EXPECT_TRUE(kin.still(0));
  EXPECT_TRUE(kin.still(1));
  EXPECT_FALSE(kin.still(2));
}

}  // namespace
}  // namespace spiral::engine
