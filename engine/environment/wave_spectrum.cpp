#include "engine/environment/wave_spectrum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;

void require_positive(double value, const char* name, const char* unit) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("wave spectrum: {} must be > 0 {}, got {} {}", name, unit, value, unit));
  }
}

void validate(const WaveSpectrum& s) {
  require_positive(s.Hs_m, "Hs", "m");
  require_positive(s.Tp_s, "Tp", "s");
  if (!(s.gamma >= 1.0) || !std::isfinite(s.gamma)) {
    throw std::invalid_argument(
        fmt::format("wave spectrum: JONSWAP gamma must be >= 1 (dimensionless), got {}", s.gamma));
  }
  if (!(s.sigma_below > 0.0) || !(s.sigma_above > 0.0)) {
    throw std::invalid_argument(fmt::format("wave spectrum: JONSWAP sigma must be > 0 (dimensionless), got {} and {}",
                                            s.sigma_below, s.sigma_above));
  }
}

// Mean-direction deviation wrapped to (-pi, pi].
double wrap_deviation(double theta) {
  double t = std::remainder(theta, 2.0 * kPi);
  if (t <= -kPi) t += 2.0 * kPi;
  return t;
}

// Gamma(x + 1/2) / Gamma(x) for x >= 1/2 without lgamma (which writes the
// global `signgam` in glibc: not safe for parallel load cases). Direct for
// moderate x; above, the asymptotic series (Abramowitz & Stegun 6.1.47), whose
// truncation error at x = 100 is ~1e-13.
double gamma_half_ratio(double x) {
  if (x < 100.0) return std::tgamma(x + 0.5) / std::tgamma(x);
  const double r = 1.0 / x;
  return std::sqrt(x) * (1.0 - r / 8.0 + r * r / 128.0 + 5.0 * r * r * r / 1024.0 - 21.0 * r * r * r * r / 32768.0);
}

double spreading_half_width(SpreadingForm form) { return form == SpreadingForm::cos_2s ? kPi : 0.5 * kPi; }

}  // namespace

double WaveSpectrum::peak_rad_per_s() const { return 2.0 * kPi / Tp_s; }

double default_jonswap_gamma(double Hs_m, double Tp_s) {
  require_positive(Hs_m, "Hs", "m");
  require_positive(Tp_s, "Tp", "s");
  // DNV-RP-C205 §3.5.5.5 (= OpenFAST WavePkShpDefault): ratio in s/sqrt(m).
  const double ratio = Tp_s / std::sqrt(Hs_m);
  if (ratio <= 3.6) return 5.0;
  if (ratio >= 5.0) return 1.0;
  return std::exp(5.75 - 1.15 * ratio);
}

WaveSpectrum make_jonswap_spectrum(const JonswapInput& input) {
  WaveSpectrum s;
  s.Hs_m = input.Hs_m;
  s.Tp_s = input.Tp_s;
  require_positive(s.Hs_m, "Hs", "m");
  require_positive(s.Tp_s, "Tp", "s");
  s.gamma = input.gamma ? *input.gamma : default_jonswap_gamma(input.Hs_m, input.Tp_s);
  validate(s);
  return s;
}

WaveSpectrum make_pierson_moskowitz_spectrum(double Hs_m, double Tp_s) {
  return make_jonswap_spectrum({Hs_m, Tp_s, 1.0});
}

double spectral_density_m2s_per_rad(const WaveSpectrum& s, double omega) {
  if (!(omega > 0.0)) return 0.0;
  const double wp = s.peak_rad_per_s();
  const double x = wp / omega;
  // exp(-1.25 x^4) < 1e-300 for x > 21; return 0 before w^-5 can overflow.
  if (x > 20.0) return 0.0;
  // DNV-RP-C205 eq. 3.5.5.1 (PM) and §3.5.5.2 (JONSWAP).
  const double pm =
      5.0 / 16.0 * s.Hs_m * s.Hs_m * std::pow(wp, 4) * std::pow(omega, -5) * std::exp(-1.25 * std::pow(x, 4));
  if (s.gamma == 1.0) return pm;
  const double sigma = omega <= wp ? s.sigma_below : s.sigma_above;
  const double a_gamma = 1.0 - 0.287 * std::log(s.gamma);
  const double shape = std::exp(-0.5 * std::pow((omega - wp) / (sigma * wp), 2));
  return a_gamma * pm * std::pow(s.gamma, shape);
}

SpectrumQuadrature spectrum_quadrature(const WaveSpectrum& spectrum, const SpectrumQuadratureOptions& options) {
  validate(spectrum);
  if (!(options.upper_limit_over_peak > 1.0)) {
    throw std::invalid_argument(
        fmt::format("spectrum quadrature: upper_limit_over_peak must be > 1, got {}", options.upper_limit_over_peak));
  }
  if (options.intervals < 2 || options.intervals % 2 != 0) {
    throw std::invalid_argument(
        fmt::format("spectrum quadrature: intervals must be even and >= 2, got {}", options.intervals));
  }
  const double W =
      std::max(options.upper_limit_over_peak * spectrum.peak_rad_per_s(), options.min_upper_limit_rad_per_s);
  const int n = options.intervals;
  const double h = W / n;
  SpectrumQuadrature q;
  q.omega_rad_per_s.resize(n + 1);
  q.weight_m2.resize(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double w = h * i;
    // Composite Simpson weights h/3 (1, 4, 2, ..., 4, 1).
    const double simpson = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    q.omega_rad_per_s(i) = w;
    q.weight_m2(i) = simpson * h / 3.0 * spectral_density_m2s_per_rad(spectrum, w);
  }
  q.tail_start_rad_per_s = W;
  q.tail_density_m2s_per_rad = spectral_density_m2s_per_rad(spectrum, W);
  // Pure w^-5 tail: int_W^inf C w^-5 dw = C W^-4 / 4 = S(W) W / 4.
  q.tail_m0_m2 = q.tail_density_m2s_per_rad * W / 4.0;
  return q;
}

SpectralMoments spectral_moments(const WaveSpectrum& spectrum, const SpectrumQuadratureOptions& options) {
  const SpectrumQuadrature q = spectrum_quadrature(spectrum, options);
  const double W = q.tail_start_rad_per_s;
  const double SW = q.tail_density_m2s_per_rad;
  SpectralMoments m;
  // Body by quadrature; tail int_W^inf w^n C w^-5 dw = S(W) W^(n+1) / (4 - n).
  m.m0_m2 = q.weight_m2.sum() + SW * W / 4.0;
  m.m1_m2_per_s = q.weight_m2.dot(q.omega_rad_per_s) + SW * W * W / 3.0;
  m.m2_m2_per_s2 = q.weight_m2.dot(q.omega_rad_per_s.cwiseProduct(q.omega_rad_per_s)) + SW * W * W * W / 2.0;
  m.Hm0_m = 4.0 * std::sqrt(m.m0_m2);
  m.Tz_s = 2.0 * kPi * std::sqrt(m.m0_m2 / m.m2_m2_per_s2);
  m.Tm01_s = 2.0 * kPi * m.m0_m2 / m.m1_m2_per_s;
  m.tail_fraction_of_m0 = q.tail_m0_m2 / m.m0_m2;
  return m;
}

double spreading_density_per_rad(const DirectionalSpreading& spreading, double deviation_rad) {
  const double e = spreading.exponent;
  if (!(e >= 0.0) || !std::isfinite(e)) {
    throw std::invalid_argument(fmt::format("directional spreading: exponent must be >= 0 (dimensionless), got {}", e));
  }
  const double t = wrap_deviation(deviation_rad);
  if (std::abs(t) > spreading_half_width(spreading.form)) return 0.0;
  if (spreading.form == SpreadingForm::cos_2s) {
    // DNV-RP-C205 §3.5.8: Gamma(s+1) / (2 sqrt(pi) Gamma(s+1/2)) cos^(2s)(t/2).
    const double norm = gamma_half_ratio(e + 0.5) / (2.0 * std::sqrt(kPi));
    return norm * std::pow(std::cos(0.5 * t), 2.0 * e);
  }
  // DNV-RP-C205 §3.5.8: Gamma(1+n/2) / (sqrt(pi) Gamma(1/2+n/2)) cos^n(t), |t| <= pi/2.
  const double norm = gamma_half_ratio(0.5 + 0.5 * e) / std::sqrt(kPi);
  return norm * std::pow(std::max(std::cos(t), 0.0), e);
}

std::vector<SpreadingDirection> discretise_spreading(const DirectionalSpreading& spreading, double mean_heading_rad,
                                                     int count) {
  if (count < 1) {
    throw std::invalid_argument(fmt::format("directional spreading: number of directions must be >= 1, got {}", count));
  }
  spreading_density_per_rad(spreading, 0.0);  // validates the exponent
  const double half = spreading_half_width(spreading.form);
  const double width = 2.0 * half / count;
  constexpr int kPanels = 16;  // Simpson panels per bin (even)
  std::vector<SpreadingDirection> directions;
  directions.reserve(count);
  for (int k = 0; k < count; ++k) {
    const double lo = -half + k * width;
    const double h = width / kPanels;
    double integral = 0.0;
    for (int j = 0; j <= kPanels; ++j) {
      const double c = (j == 0 || j == kPanels) ? 1.0 : (j % 2 == 1 ? 4.0 : 2.0);
      integral += c * spreading_density_per_rad(spreading, lo + j * h);
    }
    directions.push_back({mean_heading_rad + lo + 0.5 * width, integral * h / 3.0});
  }
  return directions;
}

}  // namespace spiral::engine
