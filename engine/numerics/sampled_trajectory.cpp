#include "engine/numerics/sampled_trajectory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spiral::engine {

SampledTrajectory::SampledTrajectory(double t0_s, double dt_s, std::vector<Eigen::Vector3d> positions_m)
    : t0_(t0_s), dt_(dt_s), x_(std::move(positions_m)) {
  if (x_.size() < 2 || !(dt_ > 0.0) || !std::isfinite(t0_)) {
    throw std::invalid_argument(
        fmt::format("SampledTrajectory: needs >= 2 samples and dt > 0 s, got {} and {} s", x_.size(), dt_));
  }
  // Uniform knots: x''_{k-1} + 4 x''_k + x''_{k+1} = 6 (x_{k-1} − 2 x_k + x_{k+1}) / dt², x''_0 =
  // x''_N = 0.
  const std::size_t n = x_.size();
  second_.assign(n, Eigen::Vector3d::Zero());
  if (n < 3) return;
  std::vector<double> c(n, 0.0);
  std::vector<Eigen::Vector3d> d(n, Eigen::Vector3d::Zero());
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const Eigen::Vector3d rhs = 6.0 * (x_[k - 1] - 2.0 * x_[k] + x_[k + 1]) / (dt_ * dt_);
    const double denominator = 4.0 - (k > 1 ? c[k - 1] : 0.0);
    c[k] = 1.0 / denominator;
    d[k] = (rhs - (k > 1 ? d[k - 1] : Eigen::Vector3d::Zero())) / denominator;
  }
  for (std::size_t k = n - 2; k >= 1; --k) {
    second_[k] = d[k] - c[k] * second_[k + 1];
    if (k == 1) break;
  }
}

TrajectoryPoint SampledTrajectory::at(double t_s) const {
  TrajectoryPoint p;
  const double last = static_cast<double>(x_.size() - 1);
  const double u = std::clamp((t_s - t0_) / dt_, 0.0, last);
  const auto k = std::min(static_cast<std::size_t>(std::floor(u)), x_.size() - 2);
  const double b = u - static_cast<double>(k), a = 1.0 - b, h = dt_;
  const Eigen::Vector3d &x0 = x_[k], &x1 = x_[k + 1], &m0 = second_[k], &m1 = second_[k + 1];
  p.position_m = a * x0 + b * x1 + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0;
  p.velocity_m_per_s = (x1 - x0) / h - (3.0 * a * a - 1.0) / 6.0 * h * m0 + (3.0 * b * b - 1.0) / 6.0 * h * m1;
  p.acceleration_m_per_s2 = a * m0 + b * m1;
  // Outside the samples: straight on with the end velocity. The natural
  // spline has zero acceleration at its ends, so this stays C² (an integrator
  // may step past the last output time and interpolate back).
  const double beyond_s = t_s < t0_ ? t_s - t0_ : (t_s > end_time_s() ? t_s - end_time_s() : 0.0);
  p.position_m += beyond_s * p.velocity_m_per_s;
  return p;
}

RampValue smooth_ramp(double t_s, double ramp_s) {
  if (!(ramp_s > 0.0) || t_s >= ramp_s) return {};
  if (t_s <= 0.0) return {0.0, 0.0, 0.0};
  const double tau = t_s / ramp_s, rest = 1.0 - tau;
  return {tau * tau * tau * (10.0 - 15.0 * tau + 6.0 * tau * tau), 30.0 * tau * tau * rest * rest / ramp_s,
          60.0 * tau * rest * (1.0 - 2.0 * tau) / (ramp_s * ramp_s)};
}

}  // namespace spiral::engine
