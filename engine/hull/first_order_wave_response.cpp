#include "engine/hull/first_order_wave_response.hpp"

#include <cmath>
#include <complex>

namespace spiral::engine {

FirstOrderWaveSeries prepare_first_order_series(const WaveRealization& sea, const WaveTransferTable& table,
                                                const HullWavePlacement& placement) {
  FirstOrderWaveSeries series;
  series.quantity = table.quantity;
  series.omega_rad_per_s.reserve(sea.components.size());
  series.coefficient.reserve(sea.components.size());
  const double c = std::cos(placement.yaw_rad);
  const double s = std::sin(placement.yaw_rad);
  const double w_first = table.omega_rad_per_s.empty() ? 0.0 : table.omega_rad_per_s.front();
  const double w_last = table.omega_rad_per_s.empty() ? 0.0 : table.omega_rad_per_s.back();
  double outside = 0.0;
  double total = 0.0;
  for (const auto& k : sea.components) {
    if (k.amplitude_m == 0.0) continue;
    const double variance = 0.5 * k.amplitude_m * k.amplitude_m;
    total += variance;
    if (k.omega_rad_per_s < w_first || k.omega_rad_per_s > w_last) outside += variance;
    // Body-frame transfer function at the body-relative heading (WAMIT convention).
    const Vector6cd x_b = transfer_at(table, k.omega_rad_per_s, k.heading_rad - placement.yaw_rad);
    // Complex wave amplitude at the hull reference point.
    const double phase = k.phase_rad - k.kx_rad_per_m * placement.x_m - k.ky_rad_per_m * placement.y_m;
    const std::complex<double> amplitude = std::polar(k.amplitude_m, phase);
    Vector6cd coeff;
    // Rotate force/translation and moment/rotation 3-vectors body -> global (Rz(psi)).
    for (int block = 0; block < 6; block += 3) {
      const std::complex<double> bx = x_b(block) * amplitude;
      const std::complex<double> by = x_b(block + 1) * amplitude;
      coeff(block) = c * bx - s * by;
      coeff(block + 1) = s * bx + c * by;
      coeff(block + 2) = x_b(block + 2) * amplitude;
    }
    series.omega_rad_per_s.push_back(k.omega_rad_per_s);
    series.coefficient.push_back(coeff);
  }
  series.variance_share_outside_table = total > 0.0 ? outside / total : 0.0;
  return series;
}

Vector6d evaluate_first_order(const FirstOrderWaveSeries& series, double t_s) {
  Vector6d out = Vector6d::Zero();
  for (std::size_t k = 0; k < series.coefficient.size(); ++k) {
    const double wt = series.omega_rad_per_s[k] * t_s;
    const double cw = std::cos(wt);
    const double sw = std::sin(wt);
    // Re{C e^{iwt}} = Re C cos wt - Im C sin wt.
    out += series.coefficient[k].real() * cw - series.coefficient[k].imag() * sw;
  }
  return out;
}

Eigen::Matrix<double, 6, Eigen::Dynamic> evaluate_first_order_many(const FirstOrderWaveSeries& series,
                                                                   const Eigen::VectorXd& times_s) {
  Eigen::Matrix<double, 6, Eigen::Dynamic> out(6, times_s.size());
  for (Eigen::Index i = 0; i < times_s.size(); ++i) out.col(i) = evaluate_first_order(series, times_s(i));
  return out;
}

}  // namespace spiral::engine
