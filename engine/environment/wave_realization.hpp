#pragma once
// Random-phase realization of a long- or short-crested linear (Airy) sea, its
// surface elevation and its kinematics with Wheeler stretching.
//
// Sea surface (linear superposition; DNV-RP-C205 §3.2 (Airy) and §3.5 (random
// seas); Faltinsen 1990 ch. 2):
//   eta(x, y, t) = sum_k a_k cos(theta_k),
//   theta_k      = w_k t - k_k (x cos b_k + y sin b_k) + phi_k,
// b_k the direction of propagation (global, CCW from +x; DESIGN.md §4), k_k
// from the dispersion relation w^2 = g k tanh(k h) (deep water: w^2 = g k).
// This is WAMIT's incident wave Re{A e^{i(wt - k.x)}} with complex amplitude
// A_k = a_k e^{i phi_k} at the origin (see engine/hull/wamit_3.hpp).
//
// Components: per direction d (weight W_d from discretise_spreading, or one
// direction of weight 1 when long-crested) the band [w_min, w_max] is split
// into N bins, either of equal variance (default) or of equal width; in each
// bin one frequency is drawn uniformly at random, and
//   a_k = sqrt(2 W_d int_bin S dw) = sqrt(2 W_d S_bar_k dw_k)
// (S_bar_k the bin-mean density: the exact-variance form of sqrt(2 S(w_k) dw_k),
// so sum a_k^2 / 2 equals the band variance exactly for every seed).
// Why random frequencies: with a uniform grid dw the record is periodic with
// period 2 pi / dw (all w_k t advance by whole turns), e.g. 200 components over
// [0.5, 5] wp at Tp = 12 s give dw = 0.0118 rad/s and a record that repeats
// after 533 s; keeping a grid free of repetition over a 3-hour record needs
// N >= T (w_max - w_min) / 2 pi = 4050 components. Frequencies drawn at random
// inside the bins make the record aperiodic: at the lag 2 pi / dw_mean the
// component phases w_k tau (mod 2 pi) are spread over the circle (by the draw
// inside equal-width bins, by the irregular bin edges of equal-variance bins),
// so the autocorrelation there is a near-zero-mean random quantity of standard
// deviation ~ sqrt(sum (a_k^2/2)^2 / 2) / m0 = 1 / sqrt(2N) = 0.05 for N = 200
// equal-variance components, instead of 1. Two draws may fall close across a bin
// edge; that only creates a slow beat, not a repetition.
// The grid (FrequencySelection::equal_spacing_grid: w_k = j dw, whole multiples
// as in an FFT synthesis, so exactly periodic with 2 pi / dw; bins of width dw
// around them clipped to the band) is kept for comparisons and requires
// 2 pi / dw >= duration_s (else std::invalid_argument).
//
// Reproducibility: one std::mt19937_64 seeded with `seed`; uniform numbers are
// (r >> 11) 2^-53 (not std::uniform_real_distribution, whose algorithm is
// implementation-defined), drawn in the order direction, bin, {frequency,
// phase} (grid: phase only). Same seed and input -> bit-identical components
// on any platform with IEEE doubles and the same libm.
//
// Kinematics (DNV-RP-C205 §3.2.2, linear wave theory, local acceleration only)
// at a point z <= eta, evaluated at the Wheeler-stretched coordinate
// (DNV-RP-C205 §3.2.3):
//   z' = (z - eta) h / (h + eta)      (deep water: z' = z - eta, the h -> inf limit)
//   u_h = a w cosh k(z'+h) / sinh kh cos(theta)   along (cos b, sin b)
//   u_z = -a w sinh k(z'+h) / sinh kh sin(theta)
//   du_h/dt = -a w^2 cosh/sinh sin(theta),   du_z/dt = -a w^2 sinh/sinh cos(theta)
//   p_dyn = rho g a cosh k(z'+h) / cosh kh cos(theta)   (hydrostatic -rho g z excluded)
// Above the instantaneous surface everything is zero.
//
// Errors: std::invalid_argument naming the quantity and unit; SolverError if
// the dispersion Newton iteration does not converge (it does for any w > 0, h > 0).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/common/seawater.hpp"
#include "engine/environment/wave_spectrum.hpp"

namespace spiral::engine {

// ---------------------------------------------------------------- dispersion

struct DispersionInput {
  double omega_rad_per_s = 0.0;         ///< > 0
  std::optional<double> water_depth_m;  ///< > 0; empty: deep water
  double gravity_m_per_s2 = 9.80665;    ///< > 0
};

struct DispersionSolution {
  double wavenumber_rad_per_m = 0.0;
  int iterations = 0;              ///< Newton iterations (0 for deep water)
  double relative_residual = 0.0;  ///< |k g tanh(kh) - w^2| / w^2
};

/// Solves w^2 = g k tanh(k h) for k by Newton's method on x = kh from an
/// explicit starting value x0 = y / sqrt(tanh y), y = w^2 h / g (within ~5 %).
/// Deep water (no depth): k = w^2 / g.
DispersionSolution solve_dispersion(const DispersionInput& input);

// --------------------------------------------------------------- realization

enum class FrequencySelection {
  equal_energy_random,   ///< equal-variance bins, random frequency inside each (default)
  equal_spacing_random,  ///< equal-width bins, random frequency inside each
  equal_spacing_grid,    ///< w_k = j dw (periodic with 2 pi / dw; must be >= duration)
};

struct WaveRealizationInput {
  WaveSpectrum spectrum;                          ///< make_jonswap_spectrum / make_pierson_moskowitz_spectrum
  double mean_heading_rad = 0.0;                  ///< direction of propagation, global, CCW from +x
  std::optional<DirectionalSpreading> spreading;  ///< empty: long-crested
  int direction_count = 1;                        ///< >= 1; must be 1 when long-crested
  int components_per_direction = 200;             ///< >= 1
  FrequencySelection frequency_selection = FrequencySelection::equal_energy_random;
  std::optional<double> omega_min_rad_per_s;  ///< band start, > 0; default 0.5 wp
  std::optional<double> omega_max_rad_per_s;  ///< band end, > start; default 5 wp
  double duration_s = 10800.0;                ///< simulation length the record is meant for, > 0
  std::uint64_t seed = 1;
  std::optional<double> water_depth_m;  ///< > 0; empty: deep water
  Seawater water;                       ///< rho (pressure) and g (dispersion)
};

/// One regular component; derived members are filled by the factories.
struct WaveComponent {
  double amplitude_m = 0.0;
  double omega_rad_per_s = 0.0;
  double wavenumber_rad_per_m = 0.0;
  double heading_rad = 0.0;  ///< direction of propagation, global
  double phase_rad = 0.0;    ///< phi_k, phase of eta at the origin at t = 0
  // derived
  double cos_heading = 1.0;
  double sin_heading = 0.0;
  double kx_rad_per_m = 0.0;        ///< k cos b
  double ky_rad_per_m = 0.0;        ///< k sin b
  double inv_one_minus_e2kh = 1.0;  ///< 1 / (1 - e^{-2kh}); 1 in deep water
  double inv_one_plus_e2kh = 1.0;   ///< 1 / (1 + e^{-2kh}); 1 in deep water
};

struct WaveRealization {
  std::vector<WaveComponent> components;
  std::optional<double> water_depth_m;  ///< empty: deep water
  Seawater water;
  // diagnostics
  double omega_min_rad_per_s = 0.0;
  double omega_max_rad_per_s = 0.0;
  double band_variance_m2 = 0.0;            ///< sum a_k^2 / 2 (variance the realization carries)
  double spectrum_variance_m2 = 0.0;        ///< m0 of the whole spectrum (spectral_moments)
  double mean_delta_omega_rad_per_s = 0.0;  ///< (w_max - w_min) / N
  double grid_repeat_period_s = 0.0;        ///< 2 pi / mean dw: period of a uniform grid of that spacing
  double duration_s = 0.0;
};

/// Depth profiles of a component at (stretched) z, DNV-RP-C205 §3.2.2.
struct WaveProfiles {
  double ch_over_sh = 0.0;  ///< cosh k(z'+h) / sinh kh (horizontal velocity); e^{kz'} in deep water
  double sh_over_sh = 0.0;  ///< sinh k(z'+h) / sinh kh (vertical velocity)
  double ch_over_ch = 0.0;  ///< cosh k(z'+h) / cosh kh (pressure)
};
WaveProfiles wave_profiles(const WaveComponent& component, double z_stretched_m,
                           const std::optional<double>& water_depth_m);

/// Builds the components (validates every input; see the header comment).
WaveRealization make_wave_realization(const WaveRealizationInput& input);

struct RegularWaveInput {
  double amplitude_m = 0.0;      ///< >= 0
  double omega_rad_per_s = 0.0;  ///< > 0
  double heading_rad = 0.0;
  double phase_rad = 0.0;
  std::optional<double> water_depth_m;
  Seawater water;
};

/// A one-component "realization": eta = a cos(w t - k.x + phi).
WaveRealization make_regular_wave(const RegularWaveInput& input);

/// Fills the derived members of `component` from depth and the first five
/// members (wavenumber solved here). Throws like solve_dispersion.
void complete_wave_component(WaveComponent& component, std::optional<double> water_depth_m, double gravity_m_per_s2);

// ---------------------------------------------------------------- evaluation

/// eta(x, y, t) in m. Allocation-free.
double surface_elevation_m(const WaveRealization& sea, double x_m, double y_m, double t_s);

/// eta at one (x, y) for many times.
Eigen::VectorXd surface_elevation_many(const WaveRealization& sea, double x_m, double y_m,
                                       const Eigen::VectorXd& times_s);

struct WaveKinematics {
  double elevation_m = 0.0;    ///< eta at (x, y, t)
  bool wet = false;            ///< z <= eta (else velocity, acceleration, pressure are 0)
  double stretched_z_m = 0.0;  ///< Wheeler z' used for the profiles (0 when dry)
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();       ///< global frame
  Eigen::Vector3d acceleration_m_per_s2 = Eigen::Vector3d::Zero();  ///< local du/dt, global
  double dynamic_pressure_Pa = 0.0;                                 ///< excludes the hydrostatic -rho g z
};

/// Kinematics at a global point (z up from the mean water level) with Wheeler
/// stretching. Throws std::invalid_argument for z below the seabed (z < -h) or
/// a trough reaching the seabed (h + eta <= 0). Allocation-free.
WaveKinematics wave_kinematics(const WaveRealization& sea, const Eigen::Vector3d& point_g_m, double t_s);

}  // namespace spiral::engine
