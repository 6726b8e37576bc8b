#include "engine/hull/slow_drift.hpp"

#include "engine/common/rigid_body.hpp"

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
  Vector6d z_re = Vector6d::Zero();
  Vector6d z_im = Vector6d::Zero();
  Vector6d zs_re = Vector6d::Zero();
  Vector6d zs_im = Vector6d::Zero();
  for (Eigen::Index k = 0; k < s.weight.cols(); ++k) {
    const double theta =
        s.omega_rad_per_s[static_cast<std::size_t>(k)] * t_s + s.phase_rad[static_cast<std::size_t>(k)];
    const double c = std::cos(theta);
    const double sn = std::sin(theta);
    z_re += c * s.weight.col(k);
    z_im += sn * s.weight.col(k);
    zs_re += c * s.signed_weight.col(k);
    zs_im += sn * s.signed_weight.col(k);
  }
  // Re{Z_s conj(Z)}.
  const Vector6d body = zs_re.cwiseProduct(z_re) + zs_im.cwiseProduct(z_im);
  // Body -> global by the mean yaw.
  return yaw_body_to_global(body, s.yaw_rad);
}

}  // namespace spiral::engine
