#include "engine/analysis/forcing_table.hpp"

#include <cmath>

#include "engine/environment/wind.hpp"

namespace spiral::engine {
namespace {

/// Exact phasors are recomputed every this many grid steps (the rotation
/// recurrence loses ~1e-16 per step).
constexpr int kPhasorResync = 4096;
/// Margin beyond the duration: CVODE may step past the last output time.
constexpr double kForcingMargin_s = 120.0;

}  // namespace

ForcingTable::ForcingTable(const SlowDriftSeries* drift, const WindRealization* gust, double duration_s)
    : drift_(drift), gust_(gust) {
  const auto n = static_cast<Eigen::Index>(std::ceil((duration_s + kForcingMargin_s) / kStep_s)) + 4;
  values_.setZero(7, n);
  if (drift) tabulate_drift(*drift);
  if (gust) tabulate_gust(*gust);
}

Eigen::Matrix<double, 7, 1> ForcingTable::exact(double t) const {
  Eigen::Matrix<double, 7, 1> v = Eigen::Matrix<double, 7, 1>::Zero();
  if (drift_) v.head<6>() = slow_drift_force(*drift_, t);
  if (gust_) v(6) = wind_gust_m_per_s(*gust_, t);
  return v;
}
void ForcingTable::tabulate_drift(const SlowDriftSeries& d) {
  const Eigen::Index k = d.weight.cols();
  Eigen::ArrayXd c(k), sn(k), rc(k), rs(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    rc(i) = std::cos(d.omega_rad_per_s[static_cast<std::size_t>(i)] * kStep_s);
    rs(i) = std::sin(d.omega_rad_per_s[static_cast<std::size_t>(i)] * kStep_s);
  }
  const double cy = std::cos(d.yaw_rad), sy = std::sin(d.yaw_rad);
  for (Eigen::Index j = 0; j < values_.cols(); ++j) {
    if (j % kPhasorResync == 0) {
      const double t = static_cast<double>(j - 1) * kStep_s;
      for (Eigen::Index i = 0; i < k; ++i) {
        const double theta =
            d.omega_rad_per_s[static_cast<std::size_t>(i)] * t + d.phase_rad[static_cast<std::size_t>(i)];
        c(i) = std::cos(theta);
        sn(i) = std::sin(theta);
      }
    }
    const Vector6d z_re = d.weight * c.matrix(), z_im = d.weight * sn.matrix();
    const Vector6d zs_re = d.signed_weight * c.matrix(), zs_im = d.signed_weight * sn.matrix();
    const Vector6d b = zs_re.cwiseProduct(z_re) + zs_im.cwiseProduct(z_im);
    values_.col(j).head<6>() << cy * b(0) - sy * b(1), sy * b(0) + cy * b(1), b(2), cy * b(3) - sy * b(4),
        sy * b(3) + cy * b(4), b(5);
    const Eigen::ArrayXd next_c = c * rc - sn * rs;
    sn = sn * rc + c * rs;
    c = next_c;
  }
}
void ForcingTable::tabulate_gust(const WindRealization& w) {
  const auto k = static_cast<Eigen::Index>(w.omega_rad_per_s.size());
  Eigen::ArrayXd c(k), sn(k), rc(k), rs(k), a(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    rc(i) = std::cos(w.omega_rad_per_s[static_cast<std::size_t>(i)] * kStep_s);
    rs(i) = std::sin(w.omega_rad_per_s[static_cast<std::size_t>(i)] * kStep_s);
    a(i) = w.amplitude_m_per_s[static_cast<std::size_t>(i)];
  }
  for (Eigen::Index j = 0; j < values_.cols(); ++j) {
    if (j % kPhasorResync == 0) {
      const double t = static_cast<double>(j - 1) * kStep_s;
      for (Eigen::Index i = 0; i < k; ++i) {
        const double theta =
            w.omega_rad_per_s[static_cast<std::size_t>(i)] * t + w.phase_rad[static_cast<std::size_t>(i)];
        c(i) = std::cos(theta);
        sn(i) = std::sin(theta);
      }
    }
    values_(6, j) = (a * c).sum();
    const Eigen::ArrayXd next_c = c * rc - sn * rs;
    sn = sn * rc + c * rs;
    c = next_c;
  }
}

}  // namespace spiral::engine
