#include "engine/environment/wind_realization.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace spiral::engine {

WindRealization make_wind_realization(const WindRealizationInput& input) {
  if (!input.spectrum) throw std::invalid_argument("wind realization: no spectrum given");
  if (!(input.frequency_min_Hz > 0.0) || !(input.frequency_max_Hz > input.frequency_min_Hz)) {
    throw std::invalid_argument(fmt::format("wind realization: band must satisfy 0 < f_min < f_max, got [{}, {}] Hz",
                                            input.frequency_min_Hz, input.frequency_max_Hz));
  }
  if (input.components < 1) {
    throw std::invalid_argument(fmt::format("wind realization: components must be >= 1, got {}", input.components));
  }
  std::mt19937_64 rng(input.seed);
  const auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  WindRealization w;
  const double log_min = std::log(input.frequency_min_Hz);
  const double log_step = (std::log(input.frequency_max_Hz) - log_min) / input.components;
  for (int k = 0; k < input.components; ++k) {
    const double f_lo = std::exp(log_min + k * log_step);
    const double f_hi = std::exp(log_min + (k + 1) * log_step);
    const double f = f_lo + uniform() * (f_hi - f_lo);
    const double phase = 2.0 * std::numbers::pi * uniform();
    const double s = input.spectrum(f);
    if (!(s >= 0.0) || !std::isfinite(s)) {
      throw std::invalid_argument(
          fmt::format("wind realization: spectrum must be finite and >= 0, got {} at {} Hz", s, f));
    }
    const double a = std::sqrt(2.0 * s * (f_hi - f_lo));
    w.omega_rad_per_s.push_back(2.0 * std::numbers::pi * f);
    w.amplitude_m_per_s.push_back(a);
    w.phase_rad.push_back(phase);
    w.variance_m2_per_s2 += 0.5 * a * a;
  }
  return w;
}

double wind_gust_m_per_s(const WindRealization& w, double t_s) {
  double u = 0.0;
  for (std::size_t k = 0; k < w.omega_rad_per_s.size(); ++k) {
    u += w.amplitude_m_per_s[k] * std::cos(w.omega_rad_per_s[k] * t_s + w.phase_rad[k]);
  }
  return u;
}

}  // namespace spiral::engine
