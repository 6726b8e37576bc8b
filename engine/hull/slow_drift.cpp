#include "engine/hull/slow_drift.hpp"

#include <cmath>
#include <numbers>

namespace spiral::engine {

SlowDriftSeries prepare_slow_drift(const WaveRealization& sea, const MeanDriftTable& table,
                                   const SlowDriftPlacement& placement) {
  SlowDriftSeries s;
  const auto n = static_cast<Eigen::Index>(sea.components.size());
  s.weight.setZero(6, n);
  s.signed_weight.setZero(6, n);
  s.yaw_rad = placement.yaw_rad;
  for (Eigen::Index k = 0; k < n; ++k) {
    const WaveComponent& c = sea.components[static_cast<std::size_t>(k)];
    s.omega_rad_per_s.push_back(c.omega_rad_per_s);
    s.phase_rad.push_back(c.phase_rad - (c.kx_rad_per_m * placement.x_m + c.ky_rad_per_m * placement.y_m));
    double beta = c.heading_rad - placement.yaw_rad;
    beta = std::fmod(beta, 2.0 * std::numbers::pi);
    if (beta < 0.0) beta += 2.0 * std::numbers::pi;
    const Vector6d d = mean_drift_coefficients(table, c.omega_rad_per_s, beta);
    for (int i = 0; i < 6; ++i) {
      const double root = std::sqrt(std::abs(d(i)));
      s.weight(i, k) = c.amplitude_m * root;
      s.signed_weight(i, k) = c.amplitude_m * (d(i) < 0.0 ? -root : root);
      s.mean_force_b(i) += c.amplitude_m * c.amplitude_m * d(i);
    }
  }
  return s;
}

Vector6d slow_drift_force(const SlowDriftSeries& s, double t_s) {
  Vector6d plain = Vector6d::Zero();
  Vector6d signed_sum = Vector6d::Zero();
  for (Eigen::Index k = 0; k < s.weight.cols(); ++k) {
    const double c = std::cos(s.omega_rad_per_s[static_cast<std::size_t>(k)] * t_s +
                              s.phase_rad[static_cast<std::size_t>(k)]);
    plain += c * s.weight.col(k);
    signed_sum += c * s.signed_weight.col(k);
  }
  const Vector6d body = 2.0 * plain.cwiseProduct(signed_sum);
  // Body -> global by the mean yaw: (Fx, Fy) and (Mx, My) rotate, Fz and Mz do not.
  const double cy = std::cos(s.yaw_rad);
  const double sy = std::sin(s.yaw_rad);
  Vector6d global = body;
  global(0) = cy * body(0) - sy * body(1);
  global(1) = sy * body(0) + cy * body(1);
  global(3) = cy * body(3) - sy * body(4);
  global(4) = sy * body(3) + cy * body(4);
  return global;
}

}  // namespace spiral::engine
