#pragma once
// Random-phase realization of the longitudinal wind gust u(t) (m/s) from a
// one-sided spectrum S(f) (m²/s²/Hz, wind.hpp: NPD or API), for the dynamic
// wind load on the hull: U(t) = U_mean + u(t).
//
//   u(t) = sum_k sqrt(2 S(f_k) df_k) cos(2 pi f_k t + phi_k)
//
// The band [f_min, f_max] is cut into N bins of equal width in log f (the
// wind spectra span decades, most variance below 0.05 Hz), one frequency drawn
// uniformly inside each bin (aperiodic record, as wave_realization.hpp
// explains) and the phases uniform in [0, 2 pi). Random numbers: one
// std::mt19937_64 seeded with `seed`, uniform = (r >> 11) 2^-53, drawn in the
// order {frequency, phase} per bin: bit-reproducible for a seed.
// Errors: std::invalid_argument for a bad band, count or spectrum.
#include <cstdint>
#include <functional>
#include <vector>

namespace spiral::engine {

struct WindRealizationInput {
  std::function<double(double frequency_Hz)> spectrum;  ///< S(f), m²/s²/Hz, >= 0
  double frequency_min_Hz = 1.0e-4;                     ///< > 0
  double frequency_max_Hz = 1.0;                        ///< > frequency_min_Hz
  int components = 400;                                 ///< >= 1
  std::uint64_t seed = 1;
};

struct WindRealization {
  std::vector<double> omega_rad_per_s;
  std::vector<double> amplitude_m_per_s;
  std::vector<double> phase_rad;
  double variance_m2_per_s2 = 0.0;  ///< sum a_k²/2
};

WindRealization make_wind_realization(const WindRealizationInput& input);

/// u(t), m/s. Allocation-free.
double wind_gust_m_per_s(const WindRealization& wind, double t_s);

}  // namespace spiral::engine
