// Fixed-point wave kinematics (engine/environment/fixed_point_wave_kinematics.hpp)
// against the direct sums:
//  * a wave so small that stretching vanishes: linear theory written out
//    (u = a ω cosh k(z+h)/sinh kh cos θ, …, DNV-RP-C205 §3.2.2) to 1e-9;
//  * a steep regular wave: engine::wave_kinematics (exact Wheeler stretching)
//    within the second-order expansion's (k a)³/6;
//  * a short-crested sea: wave_kinematics within the depth cutoff (1e-3 of
//    each component's surface profile) and the expansion's error;
//  * points above the still-water level and below every component's reach
//    are still;
//  * sampled in time: the direct sums within the cubic interpolant's
//    Lagrange remainder, the wet/dry state exact but within the
//    interpolated η's error of the surface, and a moved point resampled.
#include "engine/environment/fixed_point_wave_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/environment/wave_spectrum.hpp"

namespace spiral::engine {
namespace {

void direct_sum(const WaveRealization& sea, const Eigen::Vector3d& x, double t, Eigen::Vector3d& u,
                Eigen::Vector3d& a) {
  u.setZero();
  a.setZero();
  for (const WaveComponent& c : sea.components) {
    const double theta = c.omega_rad_per_s * t - c.kx_rad_per_m * x.x() - c.ky_rad_per_m * x.y() + c.phase_rad;
    const double k = c.wavenumber_rad_per_m, h = *sea.water_depth_m;
    // cosh k(z+h) / sinh kh written with e^{kz} (no overflow at kh of hundreds).
    const double e = std::exp(k * x.z()), g = std::exp(-2.0 * k * (x.z() + h));
    const double fh = e * (1.0 + g) / (1.0 - std::exp(-2.0 * k * h));
    const double fv = e * (1.0 - g) / (1.0 - std::exp(-2.0 * k * h));
    const double aw = c.amplitude_m * c.omega_rad_per_s, aw2 = aw * c.omega_rad_per_s;
    u += Eigen::Vector3d(aw * fh * std::cos(theta) * c.cos_heading, aw * fh * std::cos(theta) * c.sin_heading,
                         -aw * fv * std::sin(theta));
    a += Eigen::Vector3d(-aw2 * fh * std::sin(theta) * c.cos_heading, -aw2 * fh * std::sin(theta) * c.sin_heading,
                         -aw2 * fv * std::cos(theta));
  }
}

TEST(FixedPointWaveKinematics, SmallRegularWaveIsLinearTheory) {
  RegularWaveInput in;
  in.amplitude_m = 1e-4;
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
      // Stretching by η ≤ 1e-4 m changes the profile by k η ≈ 4e-6.
      EXPECT_LT((u[p] - u_ref).norm(), 1e-5 * scale) << "t " << t;
      EXPECT_LT((a[p] - a_ref).norm(), 1e-5 * scale * in.omega_rad_per_s) << "t " << t;
    }
  }
}

TEST(FixedPointWaveKinematics, SteepRegularWaveIsWheelerStretched) {
  RegularWaveInput in;
  in.amplitude_m = 4.0;
  in.omega_rad_per_s = 0.6;  // k = 0.037 rad/m in 200 m: k a = 0.15, (k a)^3 / 6 = 5.5e-4
  in.heading_rad = 0.7;
  in.water_depth_m = 200.0;
  auto sea = std::make_shared<const WaveRealization>(make_regular_wave(in));
  const std::vector<Eigen::Vector3d> points = {{10.0, -20.0, -6.0}, {300.0, 50.0, -40.0}};
  const FixedPointWaveKinematics kin(sea, points, 1e-9);
  std::vector<Eigen::Vector3d> u, a;
  const double scale = in.amplitude_m * in.omega_rad_per_s;
  double worst = 0.0;
  for (double t = 0.0; t < 12.0; t += 0.5) {
    kin.evaluate(t, u, a);
    for (std::size_t p = 0; p < points.size(); ++p) {
      const WaveKinematics ref = wave_kinematics(*sea, points[p], t);
      ASSERT_TRUE(ref.wet);
      worst = std::max(worst, (u[p] - ref.velocity_m_per_s).norm() / scale);
      EXPECT_LT((a[p] - ref.acceleration_m_per_s2).norm(), 1e-3 * scale * in.omega_rad_per_s);
    }
  }
  EXPECT_LT(worst, 1e-3);
  // Without the stretching the difference would be k η ≈ 0.15 of a ω near the surface.
}

/// Hs 8 m (or hs_m), Tp 12 s, cos-2s spreading over 5 directions, 1800 m deep, 1 h.
std::shared_ptr<const WaveRealization> short_crested_sea(std::uint64_t seed, double hs_m = 8.0) {
  WaveRealizationInput in;
  in.spectrum = make_jonswap_spectrum({hs_m, 12.0, 3.3});
  in.seed = seed;
  in.duration_s = 3600.0;
  in.components_per_direction = 100;
  in.spreading = DirectionalSpreading{SpreadingForm::cos_2s, 2.0};
  in.direction_count = 5;
  in.water_depth_m = 1800.0;
  return std::make_shared<const WaveRealization>(make_wave_realization(in));
}

TEST(FixedPointWaveKinematics, ShortCrestedSeaWithinTheCutoff) {
  const auto sea = short_crested_sea(7);
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
      const WaveKinematics ref = wave_kinematics(*sea, points[p], t);
      // cutoff (1e-3 of each component) + expansion ((k a)³/6 per component)
      EXPECT_LT((u[p] - ref.velocity_m_per_s).norm(), 5e-3 * surface_scale) << p;
      EXPECT_GT(ref.velocity_m_per_s.norm(), 0.0);
    }
  }
}

// The gradients are the fields': central differences of points built 1 mm
// either side agree (in a 0.2 m sea, where the stretching they leave out,
// ∂η/∂x in z', is k η ≈ 1e-3 of them), and a point carried 0.9 m by them
// meets the point built there within the second-order term Σ a ω (k d)²/2,
// ten times closer than without them.
TEST(FixedPointWaveKinematics, GradientsCarryAPointToItsNeighbourhood) {
  const auto sea = short_crested_sea(9, 0.2);
  const Eigen::Vector3d p(5.0, -3.0, -12.0);
  const FixedPointWaveKinematics at_p(sea, {p});
  std::vector<Eigen::Vector3d> u, a, u_plus, a_plus, u_minus, a_minus;
  std::vector<FixedPointWaveKinematics::Gradients> g;
  const Eigen::Vector3d d(0.6, -0.5, 0.4);
  double second_order = 0.0;
  for (const WaveComponent& c : sea->components) {
    const double kd = c.wavenumber_rad_per_m * d.norm();
    second_order +=
        c.amplitude_m * c.omega_rad_per_s * std::exp(c.wavenumber_rad_per_m * (p.z() + d.norm())) * kd * kd / 2.0;
  }
  const FixedPointWaveKinematics at_d(sea, {p + d});
  for (double t : {300.0, 1700.0}) {
    at_p.evaluate(t, u, a, &g);
    for (int j = 0; j < 3; ++j) {
      const double h = 1e-3;
      const FixedPointWaveKinematics plus(sea, {p + h * Eigen::Vector3d::Unit(j)});
      const FixedPointWaveKinematics minus(sea, {p - h * Eigen::Vector3d::Unit(j)});
      plus.evaluate(t, u_plus, a_plus);
      minus.evaluate(t, u_minus, a_minus);
      EXPECT_LT((g[0].velocity_per_s.col(j) - (u_plus[0] - u_minus[0]) / (2.0 * h)).norm(),
                1e-2 * g[0].velocity_per_s.norm())
          << t << " " << j;
      EXPECT_LT((g[0].acceleration_per_s2.col(j) - (a_plus[0] - a_minus[0]) / (2.0 * h)).norm(),
                1e-2 * g[0].acceleration_per_s2.norm())
          << t << " " << j;
    }
    EXPECT_NEAR(g[0].velocity_per_s.trace(), 0.0, 1e-12);  // incompressible
    std::vector<Eigen::Vector3d> u_d, a_d;
    at_d.evaluate(t, u_d, a_d);
    const double carried = (u[0] + g[0].velocity_per_s * d - u_d[0]).norm();
    EXPECT_LT(carried, second_order) << t;
    EXPECT_GT((u[0] - u_d[0]).norm(), 10.0 * carried) << t;
  }
}

// An element's midpoint stands for its mean over a length ℓ within
// (k ℓ)²/24 per component: for one deep-water component the bound is
// e^{k z_top} (k ℓ)²/24 of the surface amplitude, and the mean of e^{k z}
// over a vertical element indeed differs from its midpoint value by that
// to leading order.
TEST(FixedPointWaveKinematics, TheMidpointErrorIsTheDepthProfilesMeanAgainstItsMiddle) {
  RegularWaveInput in;
  in.amplitude_m = 1.0;
  in.omega_rad_per_s = 2.0 * std::numbers::pi / 10.0;
  in.water_depth_m = 3000.0;
  const WaveRealization sea = make_regular_wave(in);
  const double k = sea.components[0].wavenumber_rad_per_m, top = -30.0, length = 40.0;
  const double bound = FixedPointWaveKinematics::midpoint_error(sea, top, length);
  EXPECT_NEAR(bound, std::exp(k * top) * k * k * length * length / 24.0, 1e-9);
  const double mid = std::exp(k * (top - 0.5 * length));
  const double mean = (std::exp(k * top) - std::exp(k * (top - length))) / (k * length);
  EXPECT_NEAR((mean - mid) / mid, k * k * length * length / 24.0, 0.1 * k * k * length * length / 24.0);
  EXPECT_LT(mean - mid, bound);
  EXPECT_EQ(FixedPointWaveKinematics::midpoint_error(sea, -2000.0, length) < 1e-20, true);
}

// A moved point is the point built there: the same amplitudes, so the same
// kinematics bit for bit, whether it moves deeper (fewer components reach
// it), shallower (more: the time phases cover them) or out of the water.
TEST(FixedPointWaveKinematics, AMovedPointIsThePointBuiltThere) {
  const auto sea = short_crested_sea(3);
  FixedPointWaveKinematics moving(sea, {{0.0, 0.0, -120.0}, {10.0, 0.0, -30.0}});
  const std::vector<Eigen::Vector3d> targets = {{3.0, -2.0, -8.0}, {12.5, 1.0, -300.0}};
  moving.move_point(0, targets[0]);
  moving.move_point(1, targets[1]);
  const FixedPointWaveKinematics built(sea, targets);
  EXPECT_EQ(moving.position(0), targets[0]);
  std::vector<Eigen::Vector3d> u1, a1, u2, a2;
  for (double t : {50.0, 1234.5}) {
    moving.evaluate(t, u1, a1);
    built.evaluate(t, u2, a2);
    for (std::size_t p = 0; p < targets.size(); ++p) {
      EXPECT_EQ(u1[p], u2[p]) << p;
      EXPECT_EQ(a1[p], a2[p]) << p;
    }
  }
  moving.move_point(1, {0.0, 0.0, 2.0});
  EXPECT_TRUE(moving.still(1));
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

// Sampled in time against summed at every time, the same object otherwise.
// Bound per component (Lagrange remainder of the cubic on its middle
// interval): (9/16) (ω Δ)⁴ / 24 of its amplitude — for the velocity a ω,
// for the acceleration a ω². The stretched profiles multiply components by
// η (k η terms, frequencies up to 2 ω_max): the bound is taken at 2 ω, 16×,
// which holds them. Near the surface a point the interpolated η puts on the
// other side of the surface than the direct one is allowed where the two η
// differ by the same bound — and only there.
TEST(FixedPointWaveKinematics, SampledInTimeIsTheDirectSumWithinTheInterpolationBound) {
  const auto sea = short_crested_sea(11);
  const double interval_s = FixedPointWaveKinematics::default_sample_interval_s(*sea);
  // ω_max = 5 ω_p = 2.62 rad/s; a JONSWAP sea reaches the rms error of 1e-2
  // at ω_max Δ ≈ 1.07 (1e-3: 0.6).
  const double omega_max = 5.0 * 2.0 * std::numbers::pi / 12.0;
  EXPECT_GT(omega_max * interval_s, 0.95);
  EXPECT_LT(omega_max * interval_s, 1.2);
  const std::vector<Eigen::Vector3d> points = {
      {0.0, 0.0, -0.5}, {5.0, 3.0, -3.0}, {-40.0, 25.0, -20.0}, {100.0, -10.0, -150.0}, {0.0, 0.0, -600.0}};
  const FixedPointWaveKinematics direct(sea, points);
  const FixedPointWaveKinematics sampled(sea, points, 1e-3, interval_s);
  double u_bound = 0.0, a_bound = 0.0, eta_bound = 0.0;
  for (const WaveComponent& c : sea->components) {
    const double wd = 2.0 * c.omega_rad_per_s * interval_s;
    const double r = 9.0 / 16.0 * std::pow(wd, 4) / 24.0;
    eta_bound += r * c.amplitude_m;
    u_bound += r * c.amplitude_m * c.omega_rad_per_s;
    a_bound += r * c.amplitude_m * c.omega_rad_per_s * c.omega_rad_per_s;
  }
  ASSERT_LT(eta_bound, 0.3);
  std::vector<Eigen::Vector3d> u1, a1, u2, a2;
  int compared = 0, dry = 0, near_surface = 0;
  double worst_u = 0.0;
  std::vector<double> error_sq(points.size(), 0.0), signal_sq(points.size(), 0.0);
  // Forward with IDA-like steps, some of them retried from an earlier time.
  double t = 300.0;
  for (int i = 0; i < 3000; ++i) {
    t += (i % 7 == 3) ? -0.05 : 0.0371;
    direct.evaluate(t, u1, a1);
    sampled.evaluate(t, u2, a2);
    for (std::size_t p = 0; p < points.size(); ++p) {
      const double eta = surface_elevation_m(*sea, points[p].x(), points[p].y(), t);
      if (std::abs(eta - points[p].z()) < eta_bound) {
        ++near_surface;
        continue;
      }
      if (u1[p].isZero()) ++dry;
      EXPECT_LT((u2[p] - u1[p]).norm(), u_bound) << "point " << p << " t " << t;
      EXPECT_LT((a2[p] - a1[p]).norm(), a_bound) << "point " << p << " t " << t;
      worst_u = std::max(worst_u, (u2[p] - u1[p]).norm());
      error_sq[p] += (a2[p] - a1[p]).squaredNorm();
      signal_sq[p] += a1[p].squaredNorm();
      ++compared;
    }
  }
  EXPECT_GT(dry, 100);  // the shallow points were dry at times, and agreed
  // The rms error the interval was chosen for (kSampledAccelerationError of
  // the rms acceleration of the linear sums), the stretching's products included.
  for (std::size_t p = 0; p + 1 < points.size(); ++p) {
    EXPECT_LT(std::sqrt(error_sq[p] / signal_sq[p]), 1.5 * FixedPointWaveKinematics::kSampledAccelerationError)
        << "point " << p;
    RecordProperty("rms_acceleration_error_" + std::to_string(p),
                   std::to_string(std::sqrt(error_sq[p] / signal_sq[p])));
  }
  EXPECT_LT(near_surface, 500);  // of 15,000: the two shallowest points within η's bound (0.23 m) of the surface
  EXPECT_GT(compared, 14500);
  // About one summed sample per interval, not one per time asked.
  EXPECT_LT(sampled.full_sums(), static_cast<long>(3000 * 0.0371 / interval_s) + 20);
  EXPECT_EQ(direct.full_sums(), 3000);
  // A single point from the held grid samples: the whole evaluation's value.
  Eigen::Vector3d u_point, a_point;
  sampled.evaluate_point(t, 2, u_point, a_point);
  EXPECT_EQ(u_point, u2[2]);
  EXPECT_EQ(a_point, a2[2]);
  RecordProperty("worst_velocity_error_m_per_s", std::to_string(worst_u));
  RecordProperty("velocity_bound_m_per_s", std::to_string(u_bound));
}

// A point moved while samples are held is resampled: afterwards it is the
// point built there, sampled on the same grid.
TEST(FixedPointWaveKinematics, AMovedSampledPointIsResampled) {
  const auto sea = short_crested_sea(5);
  const double interval_s = 0.2;
  FixedPointWaveKinematics moving(sea, {{0.0, 0.0, -120.0}, {10.0, 0.0, -30.0}}, 1e-3, interval_s);
  std::vector<Eigen::Vector3d> u1, a1, u2, a2;
  moving.evaluate(400.05, u1, a1);
  const std::vector<Eigen::Vector3d> targets = {{3.0, -2.0, -8.0}, {12.5, 1.0, -300.0}};
  moving.move_point(0, targets[0]);
  moving.move_point(1, targets[1]);
  const FixedPointWaveKinematics built(sea, targets, 1e-3, interval_s);
  for (double t : {400.07, 400.31, 400.12}) {
    moving.evaluate(t, u1, a1);
    built.evaluate(t, u2, a2);
    for (std::size_t p = 0; p < targets.size(); ++p) {
      EXPECT_EQ(u1[p], u2[p]) << p;
      EXPECT_EQ(a1[p], a2[p]) << p;
    }
  }
  // Moved again while its samples are held: one point's value at a held
  // time (an output's end force) is the point built there as well.
  moving.move_point(1, targets[0]);
  const FixedPointWaveKinematics built_there(sea, {targets[1], targets[0]}, 1e-3, interval_s);
  built_there.evaluate(400.12, u2, a2);
  Eigen::Vector3d u, a;
  moving.evaluate_point(400.12, 1, u, a);
  EXPECT_EQ(u, u2[1]);
  EXPECT_EQ(a, a2[1]);
}

}  // namespace
}  // namespace spiral::engine
