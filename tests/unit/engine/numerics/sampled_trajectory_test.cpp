// The natural cubic spline trajectory and the quintic build-up ramp.
#include "engine/numerics/sampled_trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace spiral::engine {
namespace {

TEST(SampledTrajectory, SineSamplesGiveItsVelocityAndAcceleration) {
  // x = sin(ω t) sampled at 0.5 s (20 samples per period): the spline's
  // interior error is O(h⁴ ω⁴) in position, O(h³ ω³)·ω in velocity and
  // O(h² ω²)·ω² in acceleration (de Boor, A Practical Guide to Splines, ch. IV).
  const double w = 2.0 * std::numbers::pi / 10.0, dt = 0.5;
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k <= 200; ++k) x.emplace_back(std::sin(w * dt * k), 0.0, 2.0);
  const SampledTrajectory traj(0.0, dt, x);
  for (double t = 20.0; t < 80.0; t += 0.37) {
    const TrajectoryPoint p = traj.at(t);
    EXPECT_NEAR(p.position_m.x(), std::sin(w * t), 1e-4);
    EXPECT_NEAR(p.velocity_m_per_s.x(), w * std::cos(w * t), 1e-3 * w);
    EXPECT_NEAR(p.acceleration_m_per_s2.x(), -w * w * std::sin(w * t), 1e-2 * w * w);
    EXPECT_DOUBLE_EQ(p.position_m.z(), 2.0);
  }
}

TEST(SampledTrajectory, ContinuesStraightBeyondTheSamples) {
  const SampledTrajectory traj(10.0, 1.0, {{0, 0, 0}, {1, 0, 0}, {4, 0, 0}});
  const TrajectoryPoint end = traj.at(12.0), beyond = traj.at(13.0);
  EXPECT_NEAR(end.acceleration_m_per_s2.x(), 0.0, 1e-12);  // natural end
  EXPECT_NEAR(beyond.position_m.x(), end.position_m.x() + end.velocity_m_per_s.x(), 1e-12);
  EXPECT_NEAR(beyond.velocity_m_per_s.x(), end.velocity_m_per_s.x(), 1e-12);
  EXPECT_THROW(SampledTrajectory(0.0, 0.0, {{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
}

TEST(SampledTrajectory, UnevenTimesOfAUniformGridGiveTheUniformSpline) {
  // The uneven-knot system reduces to the uniform one when the knots are even:
  // same spline up to round-off.
  std::vector<Eigen::Vector3d> x;
  std::vector<double> t;
  for (int k = 0; k <= 40; ++k) {
    x.emplace_back(std::sin(0.3 * k), std::cos(0.7 * k), 0.1 * k);
    t.push_back(5.0 + 0.25 * k);
  }
  const SampledTrajectory uniform(5.0, 0.25, x), uneven(t, x);
  for (double s = 4.0; s < 16.5; s += 0.113) {
    const TrajectoryPoint a = uniform.at(s), b = uneven.at(s);
    EXPECT_LT((a.position_m - b.position_m).norm(), 1e-12) << s;
    EXPECT_LT((a.velocity_m_per_s - b.velocity_m_per_s).norm(), 1e-10) << s;
    EXPECT_LT((a.acceleration_m_per_s2 - b.acceleration_m_per_s2).norm(), 1e-8) << s;
  }
  EXPECT_DOUBLE_EQ(uneven.start_time_s(), 5.0);
  EXPECT_DOUBLE_EQ(uneven.end_time_s(), 15.0);
}

TEST(SampledTrajectory, UnevenSamplesInterpolateWithContinuousVelocity) {
  // sin(ω t) at steps alternating 0.3 s and 0.7 s: the samples are met, the
  // interior error is O(h_max⁴ ω⁴) (h_max = 0.7 s: ~2e-4), and velocity and
  // acceleration are continuous across every knot (C²).
  const double w = 2.0 * std::numbers::pi / 10.0;
  std::vector<double> t;
  std::vector<Eigen::Vector3d> x;
  for (double s = 0.0; s <= 100.0; s += (t.size() % 2 == 0 ? 0.3 : 0.7)) {
    t.push_back(s);
    x.emplace_back(std::sin(w * s), 0.0, 0.0);
  }
  const SampledTrajectory traj(t, x);
  for (std::size_t k = 20; k + 20 < t.size(); ++k) {
    EXPECT_NEAR(traj.at(t[k]).position_m.x(), x[k].x(), 1e-12);
    const TrajectoryPoint before = traj.at(t[k] - 1e-9), after = traj.at(t[k] + 1e-9);
    EXPECT_NEAR(before.velocity_m_per_s.x(), after.velocity_m_per_s.x(), 1e-7);
    EXPECT_NEAR(before.acceleration_m_per_s2.x(), after.acceleration_m_per_s2.x(), 1e-6);
    const double mid = 0.5 * (t[k] + t[k + 1]);
    EXPECT_NEAR(traj.at(mid).position_m.x(), std::sin(w * mid), 5e-4);
    EXPECT_NEAR(traj.at(mid).velocity_m_per_s.x(), w * std::cos(w * mid), 5e-3 * w);
  }
  EXPECT_THROW(SampledTrajectory(std::vector<double>{0.0, 0.0}, {{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(SampledTrajectory(std::vector<double>{0.0}, {{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
}

TEST(SmoothRamp, GoesFromZeroToOneWithZeroRatesAtBothEnds) {
  EXPECT_EQ(smooth_ramp(-1.0, 10.0).value, 0.0);
  EXPECT_NEAR(smooth_ramp(5.0, 10.0).value, 0.5, 1e-15);
  EXPECT_EQ(smooth_ramp(10.0, 10.0).value, 1.0);
  for (double t : {1e-9, 10.0 - 1e-9}) {
    EXPECT_NEAR(smooth_ramp(t, 10.0).rate_per_s, 0.0, 1e-12);
    EXPECT_NEAR(smooth_ramp(t, 10.0).rate2_per_s2, 0.0, 1e-9);
  }
  // Rates by central differences.
  const double t = 3.0, h = 1e-5;
  EXPECT_NEAR(smooth_ramp(t, 10.0).rate_per_s,
              (smooth_ramp(t + h, 10.0).value - smooth_ramp(t - h, 10.0).value) / (2 * h), 1e-8);
  EXPECT_NEAR(smooth_ramp(t, 10.0).rate2_per_s2,
              (smooth_ramp(t + h, 10.0).rate_per_s - smooth_ramp(t - h, 10.0).rate_per_s) / (2 * h), 1e-7);
}

}  // namespace
}  // namespace spiral::engine
