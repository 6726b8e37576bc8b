#include "engine/environment/wave_realization.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "engine/common/solver_error.hpp"

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
// Newton on x tanh x = y converges quadratically from the Eckart-type start;
// 1e-14 relative is round-off level, 50 iterations is never reached in practice.
constexpr double kDispersionRelTol = 1e-14;
constexpr int kDispersionMaxIterations = 50;
// Default band as multiples of the peak frequency. Below 0.5 wp a JONSWAP/PM
// spectrum holds < 1e-8 of m0 (exp(-1.25 x 16)); above 5 wp the w^-5 tail holds
// 1.25 (1/5)^4 = 0.2 % of m0 (Hs low by 0.1 %), reported in the diagnostics.
constexpr double kDefaultBandStartOverPeak = 0.5;
constexpr double kDefaultBandEndOverPeak = 5.0;
// Intervals of the cumulative-variance table used to place equal-variance bin
// edges (trapezoid; the relative error of a bin integral is ~1e-8 for 20000).
constexpr int kCumulativeIntervals = 20000;
// e^{-2k(z'+h)} is dropped once k(z'+h) exceeds this (e^{-40} ~ 4e-18 << 1 ulp).
constexpr double kDeepProfileExponent = 20.0;

void require_positive(double value, const char* name, const char* unit) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("wave realization: {} must be > 0 {}, got {} {}", name, unit, value, unit));
  }
}

// Uniform double in [0, 1) from 53 random bits: portable, unlike
// std::uniform_real_distribution.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

// Depth attenuation written with exponentials of non-positive arguments only,
// e.g. cosh k(z+h) / sinh kh = e^{kz} (1 + e^{-2k(z+h)}) / (1 - e^{-2kh}),
// so that deep components (kh of hundreds) do not overflow.
WaveProfiles wave_profiles(const WaveComponent& c, double z_stretched, const std::optional<double>& h) {
  const double k = c.wavenumber_rad_per_m;
  const double e = std::exp(k * z_stretched);
  if (!h) return {e, e, e};
  const double kzh = k * (z_stretched + *h);
  const double g = kzh > kDeepProfileExponent ? 0.0 : std::exp(-2.0 * kzh);
  return {e * (1.0 + g) * c.inv_one_minus_e2kh, e * (1.0 - g) * c.inv_one_minus_e2kh,
          e * (1.0 + g) * c.inv_one_plus_e2kh};
}

DispersionSolution solve_dispersion(const DispersionInput& in) {
  require_positive(in.omega_rad_per_s, "wave frequency", "rad/s");
  require_positive(in.gravity_m_per_s2, "gravity", "m/s^2");
  const double w2 = in.omega_rad_per_s * in.omega_rad_per_s;
  DispersionSolution out;
  if (!in.water_depth_m) {
    out.wavenumber_rad_per_m = w2 / in.gravity_m_per_s2;
    return out;
  }
  const double h = *in.water_depth_m;
  require_positive(h, "water depth", "m");
  // Non-dimensional form x tanh x = y, x = kh, y = w^2 h / g.
  const double y = w2 * h / in.gravity_m_per_s2;
  double x = y / std::sqrt(std::tanh(y));  // exact in both limits, ~5 % in between
  double residual = 0.0;
  for (int it = 1; it <= kDispersionMaxIterations; ++it) {
    const double t = std::tanh(x);
    const double f = x * t - y;
    const double df = t + x * (1.0 - t * t);
    const double step = f / df;
    x -= step;
    out.iterations = it;
    residual = std::abs(x * std::tanh(x) - y) / y;
    if (std::abs(step) <= kDispersionRelTol * x) {
      out.wavenumber_rad_per_m = x / h;
      out.relative_residual = residual;
      return out;
    }
  }
  throw SolverError(fmt::format("dispersion relation: Newton did not converge for w = {} rad/s, "
                                "h = {} m after {} iterations (relative residual {:.3g}); check "
                                "the inputs",
                                in.omega_rad_per_s, h, kDispersionMaxIterations, residual),
                    {kDispersionMaxIterations, residual, "-"});
}

void complete_wave_component(WaveComponent& c, std::optional<double> water_depth_m, double gravity_m_per_s2) {
  c.wavenumber_rad_per_m = solve_dispersion({c.omega_rad_per_s, water_depth_m, gravity_m_per_s2}).wavenumber_rad_per_m;
  c.cos_heading = std::cos(c.heading_rad);
  c.sin_heading = std::sin(c.heading_rad);
  c.kx_rad_per_m = c.wavenumber_rad_per_m * c.cos_heading;
  c.ky_rad_per_m = c.wavenumber_rad_per_m * c.sin_heading;
  if (water_depth_m) {
    const double e2kh = std::exp(-2.0 * c.wavenumber_rad_per_m * *water_depth_m);
    c.inv_one_minus_e2kh = 1.0 / (1.0 - e2kh);
    c.inv_one_plus_e2kh = 1.0 / (1.0 + e2kh);
  } else {
    c.inv_one_minus_e2kh = 1.0;
    c.inv_one_plus_e2kh = 1.0;
  }
}

WaveRealization make_wave_realization(const WaveRealizationInput& in) {
  const SpectralMoments moments = spectral_moments(in.spectrum);  // validates the spectrum
  require_positive(in.duration_s, "duration", "s");
  require_positive(in.water.gravity_m_per_s2, "gravity", "m/s^2");
  require_positive(in.water.density_kg_per_m3, "water density", "kg/m^3");
  if (in.water_depth_m) require_positive(*in.water_depth_m, "water depth", "m");
  if (in.components_per_direction < 1) {
    throw std::invalid_argument(
        fmt::format("wave realization: components_per_direction must be >= 1, got {}", in.components_per_direction));
  }
  if (in.direction_count < 1) {
    throw std::invalid_argument(
        fmt::format("wave realization: direction_count must be >= 1, got {}", in.direction_count));
  }
  if (!in.spreading && in.direction_count != 1) {
    throw std::invalid_argument(
        fmt::format("wave realization: direction_count must be 1 for a long-crested sea (no spreading), got {}",
                    in.direction_count));
  }
  const double wp = in.spectrum.peak_rad_per_s();
  const double w_lo = in.omega_min_rad_per_s.value_or(kDefaultBandStartOverPeak * wp);
  const double w_hi = in.omega_max_rad_per_s.value_or(kDefaultBandEndOverPeak * wp);
  require_positive(w_lo, "omega_min", "rad/s");
  if (!(w_hi > w_lo) || !std::isfinite(w_hi)) {
    throw std::invalid_argument(
        fmt::format("wave realization: omega_max must be > omega_min = {} rad/s, got {} rad/s", w_lo, w_hi));
  }
  const int n = in.components_per_direction;
  const double mean_dw = (w_hi - w_lo) / n;
  const double grid_period = 2.0 * kPi / mean_dw;
  if (in.frequency_selection == FrequencySelection::equal_spacing_grid && grid_period < in.duration_s) {
    throw std::invalid_argument(
        fmt::format("wave realization: a uniform frequency grid of {} components over [{:.4g}, {:.4g}] rad/s "
                    "repeats after 2 pi / dw = {:.1f} s < duration {} s; use >= {} components or a random "
                    "frequency selection",
                    n, w_lo, w_hi, grid_period, in.duration_s,
                    static_cast<long long>(std::ceil(in.duration_s * (w_hi - w_lo) / (2.0 * kPi)))));
  }

  // Cumulative variance F(w) on a fine trapezoid table over the band.
  std::vector<double> grid_w(kCumulativeIntervals + 1);
  std::vector<double> cumulative(kCumulativeIntervals + 1, 0.0);
  {
    const double dw = (w_hi - w_lo) / kCumulativeIntervals;
    double previous = spectral_density_m2s_per_rad(in.spectrum, w_lo);
    grid_w[0] = w_lo;
    for (int i = 1; i <= kCumulativeIntervals; ++i) {
      grid_w[i] = w_lo + dw * i;
      const double s = spectral_density_m2s_per_rad(in.spectrum, grid_w[i]);
      cumulative[i] = cumulative[i - 1] + 0.5 * dw * (previous + s);
      previous = s;
    }
  }
  const double band_m0 = cumulative.back();
  if (!(band_m0 > 0.0)) {
    throw std::invalid_argument(
        fmt::format("wave realization: the spectrum carries no variance in [{:.4g}, {:.4g}] rad/s", w_lo, w_hi));
  }
  // F at any w (piecewise linear in the table) and its inverse.
  const auto cumulative_at = [&](double w_any) {
    const double w = std::clamp(w_any, w_lo, w_hi);
    const double s = (w - w_lo) / (w_hi - w_lo) * kCumulativeIntervals;
    const int i = std::clamp(static_cast<int>(s), 0, kCumulativeIntervals - 1);
    const double f = s - i;
    return (1.0 - f) * cumulative[i] + f * cumulative[i + 1];
  };
  const auto frequency_at = [&](double variance) {
    const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), variance);
    if (it == cumulative.begin()) return w_lo;
    if (it == cumulative.end()) return w_hi;
    const std::size_t i = static_cast<std::size_t>(it - cumulative.begin());
    const double span = cumulative[i] - cumulative[i - 1];
    const double f = span > 0.0 ? (variance - cumulative[i - 1]) / span : 0.0;
    return grid_w[i - 1] + f * (grid_w[i] - grid_w[i - 1]);
  };

  // Bin edges (the same for every direction).
  std::vector<double> edges(n + 1);
  edges[0] = w_lo;
  edges[n] = w_hi;
  for (int k = 1; k < n; ++k) {
    edges[k] = in.frequency_selection == FrequencySelection::equal_energy_random ? frequency_at(band_m0 * k / n)
                                                                                 : w_lo + mean_dw * k;
  }
  // Grid: frequencies at whole multiples j dw (as in an FFT synthesis), so
  // that the record is exactly periodic with 2 pi / dw; bins [w_k -+ dw/2]
  // clipped to the band.
  std::vector<double> grid_centres;
  if (in.frequency_selection == FrequencySelection::equal_spacing_grid) {
    const double j0 = std::max(1.0, std::round(w_lo / mean_dw + 0.5));
    for (int k = 0; k < n; ++k) grid_centres.push_back((j0 + k) * mean_dw);
    for (int k = 0; k <= n; ++k) edges[k] = (j0 + k - 0.5) * mean_dw;
  }
  std::vector<double> bin_variance(n);
  for (int k = 0; k < n; ++k) {
    bin_variance[k] = std::max(cumulative_at(edges[k + 1]) - cumulative_at(edges[k]), 0.0);
  }

  std::vector<SpreadingDirection> directions =
      in.spreading ? discretise_spreading(*in.spreading, in.mean_heading_rad, in.direction_count)
                   : std::vector<SpreadingDirection>{{in.mean_heading_rad, 1.0}};

  WaveRealization sea;
  sea.water_depth_m = in.water_depth_m;
  sea.water = in.water;
  sea.omega_min_rad_per_s = w_lo;
  sea.omega_max_rad_per_s = w_hi;
  sea.spectrum_variance_m2 = moments.m0_m2;
  sea.mean_delta_omega_rad_per_s = mean_dw;
  sea.grid_repeat_period_s = grid_period;
  sea.duration_s = in.duration_s;
  sea.components.reserve(directions.size() * n);

  std::mt19937_64 rng(in.seed);
  double variance = 0.0;
  for (const auto& direction : directions) {
    for (int k = 0; k < n; ++k) {
      WaveComponent c;
      if (in.frequency_selection == FrequencySelection::equal_spacing_grid) {
        c.omega_rad_per_s = grid_centres[k];
      } else {
        c.omega_rad_per_s = edges[k] + uniform01(rng) * (edges[k + 1] - edges[k]);
      }
      c.phase_rad = 2.0 * kPi * uniform01(rng);
      // a_k = sqrt(2 W_d int_bin S dw): DNV-RP-C205 §3.5 random-phase model with
      // the bin-mean density (exact variance per bin).
      c.amplitude_m = std::sqrt(2.0 * direction.weight * bin_variance[k]);
      c.heading_rad = direction.heading_rad;
      complete_wave_component(c, in.water_depth_m, in.water.gravity_m_per_s2);
      variance += 0.5 * c.amplitude_m * c.amplitude_m;
      sea.components.push_back(c);
    }
  }
  sea.band_variance_m2 = variance;
  return sea;
}

WaveRealization make_regular_wave(const RegularWaveInput& in) {
  if (!(in.amplitude_m >= 0.0) || !std::isfinite(in.amplitude_m)) {
    throw std::invalid_argument(fmt::format("regular wave: amplitude must be >= 0 m, got {} m", in.amplitude_m));
  }
  if (in.water_depth_m) require_positive(*in.water_depth_m, "water depth", "m");
  WaveComponent c;
  c.amplitude_m = in.amplitude_m;
  c.omega_rad_per_s = in.omega_rad_per_s;
  c.heading_rad = in.heading_rad;
  c.phase_rad = in.phase_rad;
  complete_wave_component(c, in.water_depth_m, in.water.gravity_m_per_s2);
  WaveRealization sea;
  sea.components = {c};
  sea.water_depth_m = in.water_depth_m;
  sea.water = in.water;
  sea.omega_min_rad_per_s = sea.omega_max_rad_per_s = in.omega_rad_per_s;
  sea.band_variance_m2 = sea.spectrum_variance_m2 = 0.5 * in.amplitude_m * in.amplitude_m;
  return sea;
}

double surface_elevation_m(const WaveRealization& sea, double x_m, double y_m, double t_s) {
  double eta = 0.0;
  for (const auto& c : sea.components) {
    eta +=
        c.amplitude_m * std::cos(c.omega_rad_per_s * t_s - c.kx_rad_per_m * x_m - c.ky_rad_per_m * y_m + c.phase_rad);
  }
  return eta;
}

Eigen::VectorXd surface_elevation_many(const WaveRealization& sea, double x_m, double y_m,
                                       const Eigen::VectorXd& times_s) {
  Eigen::VectorXd eta(times_s.size());
  for (Eigen::Index i = 0; i < times_s.size(); ++i) {
    eta(i) = surface_elevation_m(sea, x_m, y_m, times_s(i));
  }
  return eta;
}

WaveKinematics wave_kinematics(const WaveRealization& sea, const Eigen::Vector3d& p, double t_s) {
  WaveKinematics out;
  const auto& h = sea.water_depth_m;
  if (h && p.z() < -*h) {
    throw std::invalid_argument(
        fmt::format("wave kinematics: point z = {} m is below the seabed (z = -{} m)", p.z(), *h));
  }
  out.elevation_m = surface_elevation_m(sea, p.x(), p.y(), t_s);
  const double eta = out.elevation_m;
  if (p.z() > eta) return out;  // above the instantaneous surface: dry
  out.wet = true;
  // Wheeler stretching, DNV-RP-C205 §3.2.3: z' = (z - eta) h / (h + eta).
  if (h) {
    if (!(*h + eta > 0.0)) {
      throw std::invalid_argument(
          fmt::format("wave kinematics: trough eta = {} m reaches the seabed (depth {} m) at t = {} s", eta, *h, t_s));
    }
    out.stretched_z_m = (p.z() - eta) * *h / (*h + eta);
  } else {
    out.stretched_z_m = p.z() - eta;
  }
  const double rho_g = sea.water.density_kg_per_m3 * sea.water.gravity_m_per_s2;
  double u_h_x = 0.0, u_h_y = 0.0, u_z = 0.0, a_x = 0.0, a_y = 0.0, a_z = 0.0, pressure = 0.0;
  for (const auto& c : sea.components) {
    const double theta = c.omega_rad_per_s * t_s - c.kx_rad_per_m * p.x() - c.ky_rad_per_m * p.y() + c.phase_rad;
    const double cos_t = std::cos(theta);
    const double sin_t = std::sin(theta);
    const WaveProfiles f = wave_profiles(c, out.stretched_z_m, h);
    const double aw = c.amplitude_m * c.omega_rad_per_s;
    const double aw2 = aw * c.omega_rad_per_s;
    // DNV-RP-C205 §3.2.2 (linear wave theory), eta = a cos(theta).
    const double u_h = aw * f.ch_over_sh * cos_t;
    const double du_h = -aw2 * f.ch_over_sh * sin_t;
    u_h_x += u_h * c.cos_heading;
    u_h_y += u_h * c.sin_heading;
    a_x += du_h * c.cos_heading;
    a_y += du_h * c.sin_heading;
    u_z += -aw * f.sh_over_sh * sin_t;
    a_z += -aw2 * f.sh_over_sh * cos_t;
    pressure += rho_g * c.amplitude_m * f.ch_over_ch * cos_t;
  }
  out.velocity_m_per_s = {u_h_x, u_h_y, u_z};
  out.acceleration_m_per_s2 = {a_x, a_y, a_z};
  out.dynamic_pressure_Pa = pressure;
  return out;
}

}  // namespace spiral::engine
