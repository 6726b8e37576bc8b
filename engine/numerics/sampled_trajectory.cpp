#include "engine/numerics/sampled_trajectory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spiral::engine {
namespace {

/// x'' at the knots t of the natural cubic spline through x, h_k = t_{k+1} − t_k
/// (Press et al., Numerical Recipes, 3rd ed., eq. 3.3.7):
/// h_{k-1} x''_{k-1} + 2 (h_{k-1} + h_k) x''_k + h_k x''_{k+1}
///   = 6 ((x_{k+1} − x_k)/h_k − (x_k − x_{k-1})/h_{k-1}),  x''_0 = x''_N = 0,
/// by the Thomas algorithm.
std::vector<Eigen::Vector3d> natural_second_derivatives(const std::vector<double>& t,
                                                        const std::vector<Eigen::Vector3d>& x) {
  auto h = [&t](std::size_t k) { return t[k + 1] - t[k]; };
  const std::size_t n = x.size();
  std::vector<Eigen::Vector3d> second(n, Eigen::Vector3d::Zero());
  if (n < 3) return second;
  std::vector<double> c(n, 0.0);
  std::vector<Eigen::Vector3d> d(n, Eigen::Vector3d::Zero());
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double h_before = h(k - 1), h_after = h(k);
    const Eigen::Vector3d rhs = 6.0 * ((x[k + 1] - x[k]) / h_after - (x[k] - x[k - 1]) / h_before);
    const double lower = k > 1 ? h_before : 0.0;
    const double denominator = 2.0 * (h_before + h_after) - lower * c[k - 1];
    c[k] = h_after / denominator;
    d[k] = (rhs - lower * d[k - 1]) / denominator;
  }
  for (std::size_t k = n - 2; k >= 1; --k) {
    second[k] = d[k] - c[k] * second[k + 1];
    if (k == 1) break;
  }
  return second;
}

}  // namespace

SampledTrajectory::SampledTrajectory(double t0_s, double dt_s, std::vector<Eigen::Vector3d> positions_m)
    : t0_(t0_s), dt_(dt_s), x_(std::move(positions_m)) {
  if (x_.size() < 2 || !(dt_ > 0.0) || !std::isfinite(t0_)) {
    throw std::invalid_argument(
        fmt::format("SampledTrajectory: needs >= 2 samples and dt > 0 s, got {} and {} s", x_.size(), dt_));
  }
  // Uniform knots, the uneven system divided by dt: x''_{k-1} + 4 x''_k +
  // x''_{k+1} = 6 (x_{k-1} − 2 x_k + x_{k+1}) / dt², x''_0 = x''_N = 0. Kept
  // apart from the uneven solve: its round-off is what the coupled runs of the
  // golden baselines were made with (through it they move by up to 0.08 %).
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

SampledTrajectory::SampledTrajectory(std::vector<double> times_s, std::vector<Eigen::Vector3d> positions_m)
    : times_(std::move(times_s)), x_(std::move(positions_m)) {
  if (x_.size() < 2 || times_.size() != x_.size()) {
    throw std::invalid_argument(fmt::format("SampledTrajectory: needs >= 2 samples and one time each, got {} and {}",
                                            x_.size(), times_.size()));
  }
  for (std::size_t k = 0; k < times_.size(); ++k) {
    if (!std::isfinite(times_[k]) || (k > 0 && !(times_[k] > times_[k - 1]))) {
      throw std::invalid_argument(
          fmt::format("SampledTrajectory: times must be finite and increasing, got {} s at sample {}", times_[k], k));
    }
  }
  second_ = natural_second_derivatives(times_, x_);
}

TrajectoryPoint SampledTrajectory::at(double t_s) const {
  // The interval [t_k, t_k+1] holding t (clamped to the samples), its length h
  // and t's fraction b of it.
  std::size_t k = 0;
  double b = 0.0, h = dt_;
  if (times_.empty()) {
    const double last = static_cast<double>(x_.size() - 1);
    const double u = std::clamp((t_s - t0_) / dt_, 0.0, last);
    k = std::min(static_cast<std::size_t>(std::floor(u)), x_.size() - 2);
    b = u - static_cast<double>(k);
  } else {
    const double t = std::clamp(t_s, times_.front(), times_.back());
    const auto after = std::upper_bound(times_.begin(), times_.end(), t);
    k = std::min(static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - times_.begin() - 1, 0)), x_.size() - 2);
    h = times_[k + 1] - times_[k];
    b = std::clamp((t - times_[k]) / h, 0.0, 1.0);
  }
  TrajectoryPoint p;
  const double a = 1.0 - b;
  const Eigen::Vector3d &x0 = x_[k], &x1 = x_[k + 1], &m0 = second_[k], &m1 = second_[k + 1];
  p.position_m = a * x0 + b * x1 + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0;
  p.velocity_m_per_s = (x1 - x0) / h - (3.0 * a * a - 1.0) / 6.0 * h * m0 + (3.0 * b * b - 1.0) / 6.0 * h * m1;
  p.acceleration_m_per_s2 = a * m0 + b * m1;
  // Outside the samples: straight on with the end velocity. The natural
  // spline has zero acceleration at its ends, so this stays C² (an integrator
  // may step past the last output time and interpolate back).
  const double beyond_s = t_s < start_time_s() ? t_s - start_time_s() : (t_s > end_time_s() ? t_s - end_time_s() : 0.0);
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
