#pragma once
// A point's trajectory through sampled positions, as a natural
// cubic spline per coordinate (C²: continuous acceleration, which an implicit
// integrator driven by it needs — a piecewise-linear or Catmull-Rom
// interpolant has acceleration jumps at every sample that cut its steps).
// Natural end conditions (zero second derivative at both ends); the
// tridiagonal system is solved by the Thomas algorithm (W. H. Press et al.,
// Numerical Recipes, 3rd ed., §3.3).

#include <Eigen/Core>
#include <vector>

namespace spiral::engine {

struct TrajectoryPoint {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration_m_per_s2 = Eigen::Vector3d::Zero();
};

class SampledTrajectory {
 public:
  /// positions[k] at t0 + k·dt; at least 2 samples, dt > 0 (std::invalid_argument otherwise).
  SampledTrajectory(double t0_s, double dt_s, std::vector<Eigen::Vector3d> positions_m);
  /// positions[k] at times[k] (a motion history at its own, possibly uneven,
  /// times); at least 2 samples, finite, strictly increasing times, one per
  /// position (std::invalid_argument otherwise).
  SampledTrajectory(std::vector<double> times_s, std::vector<Eigen::Vector3d> positions_m);
  /// Outside [t0, t_end]: continued along a straight line with the end velocity (C²).
  TrajectoryPoint at(double t_s) const;
  double start_time_s() const { return times_.empty() ? t0_ : times_.front(); }
  double end_time_s() const { return times_.empty() ? t0_ + dt_ * static_cast<double>(x_.size() - 1) : times_.back(); }

 private:
  double t0_ = 0.0, dt_ = 0.0;  // uniform samples (times_ empty)
  std::vector<double> times_;   // uneven samples
  std::vector<Eigen::Vector3d> x_;
  std::vector<Eigen::Vector3d> second_;  // x'' at the samples
};

/// The quintic smooth step r(t) = 10τ³ − 15τ⁴ + 6τ⁵, τ = t/T (0 before 0, 1
/// after T) and its first two derivatives, both zero at τ = 0 and 1: blends a
/// motion in from rest with continuous velocity and acceleration (the
/// "build-up" period of OrcaFlex).
struct RampValue {
  double value = 1.0, rate_per_s = 0.0, rate2_per_s2 = 0.0;
};
RampValue smooth_ramp(double t_s, double ramp_s);

}  // namespace spiral::engine
