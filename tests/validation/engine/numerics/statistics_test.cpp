// Validation of the statistics and extremes module: moments and periods of
// deterministic signals, Welch spectrum against known variance (Parseval),
// Gumbel/Weibull fits against samples of known distributions, and the three
// 3-hour MPM estimators against each other and against the Rayleigh result
// on Gaussian processes synthesized from a known spectrum (many seeds).

#include "engine/numerics/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "support/expect_near.hpp"

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;

// Brief: the Welch spectrum integrates to the variance within 1 %.
constexpr double kWelchVarianceRelTol = 1e-2;

std::vector<double> sum_of_sines(const std::vector<double>& a, const std::vector<double>& w,
                                 const std::vector<double>& phase, double dt, std::size_t n) {
  std::vector<double> x(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    for (std::size_t k = 0; k < a.size(); ++k) x[i] += a[k] * std::sin(w[k] * t + phase[k]);
  }
  return x;
}

TEST(Statistics, MomentsOfASineAreClosedForm) {
  // 50 full periods of 2 + 3 sin(0.5 t): mean 2, std 3/sqrt 2, skew 0, kurtosis 1.5.
  const double dt = 0.01;
  const auto n = static_cast<std::size_t>(std::lround(50.0 * 4.0 * kPi / dt));
  auto x = sum_of_sines({3.0}, {0.5}, {0.0}, dt, n);
  for (double& v : x) v += 2.0;
  const auto m = channel_moments(x);
  // Discretization of a whole number of periods: error ~ 1/n.
  EXPECT_NEAR(m.mean, 2.0, 1e-3);
  EXPECT_REL_NEAR(m.std_dev, 3.0 / std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(m.skewness, 0.0, 1e-3);
  EXPECT_REL_NEAR(m.kurtosis, 1.5, 1e-4);
  EXPECT_NEAR(m.maximum, 5.0, 1e-6);
  EXPECT_NEAR(m.minimum, -1.0, 1e-6);
  EXPECT_REL_NEAR(zero_upcrossing_period_s(x, dt), 4.0 * kPi, 1e-6);
  // x(0) sits on the level (not below it): up-crossings at 1..49 periods
  // (the one at 50 T is the last sample), hence 48 complete cycles.
  EXPECT_EQ(cycle_maxima(x, 2.0).size(), 48u);
}

TEST(Statistics, WelchSpectrumOfSumOfSinesIntegratesToTheVariance) {
  const std::vector<double> a{1.0, 0.6, 0.3, 0.8};
  const std::vector<double> w{0.05, 0.31, 0.62, 1.7};  // rad/s, slow drift to wave frequency
  const std::vector<double> phase{0.3, 1.1, 2.0, 4.0};
  const double dt = 0.25;
  const std::size_t n = 3 * 3600 * 4;  // 3 h
  const auto x = sum_of_sines(a, w, phase, dt, n);
  double variance = 0.0;
  for (double ak : a) variance += 0.5 * ak * ak;
  EXPECT_REL_NEAR(channel_moments(x).std_dev * channel_moments(x).std_dev, variance, 1e-2);
  const auto s = welch_spectrum(x, dt, 8192);  // dw = 3.07e-3 rad/s, 9 segments (50 % overlap)
  EXPECT_GE(s.segments, 9u);
  EXPECT_REL_NEAR(spectrum_variance(s), variance, kWelchVarianceRelTol);
  EXPECT_REL_NEAR(spectral_peak_period_s(s), 2.0 * kPi / 0.05, s.frequency_step_rad_s / 0.05);
  EXPECT_NEAR(s.frequency_rad_s(s.frequency_rad_s.size() - 1), kPi / dt, 1e-12);
}

// One-sided Gaussian-shaped band spectrum around w0 (rad/s), variance sigma².
double band_spectrum(double w, double sigma, double w0, double width) {
  return sigma * sigma / (std::sqrt(2.0 * kPi) * width) * std::exp(-0.5 * (w - w0) * (w - w0) / (width * width));
}

// Gaussian process by FFT with independent normal coefficients (exactly
// Gaussian, period = record length): x(t) = sum sqrt(S dw)(xi cos + eta sin).
std::vector<double> gaussian_process(std::size_t n, double dt, unsigned seed, double sigma, double w0, double width) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  const double dw = 2.0 * kPi / (static_cast<double>(n) * dt);
  std::vector<std::complex<double>> X(n, {0.0, 0.0});
  for (std::size_t k = 1; k < n / 2; ++k) {
    const double amp = std::sqrt(band_spectrum(static_cast<double>(k) * dw, sigma, w0, width) * dw);
    const double xi = normal(rng), eta = normal(rng);
    X[k] = 0.5 * static_cast<double>(n) * amp * std::complex<double>(xi, -eta);
    X[n - k] = std::conj(X[k]);
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> xc;
  fft.inv(xc, X);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = xc[i].real();
  return x;
}

TEST(Statistics, WelchSpectrumOfAGaussianProcessRecoversTheInputSpectrum) {
  const double dt = 0.25, sigma = 2.0, w0 = 0.6, width = 0.1;
  const auto x = gaussian_process(43200, dt, 7, sigma, w0, width);
  const auto s = welch_spectrum(x, dt, 4096);
  // A random record's variance differs from sigma² by ~sqrt(2/(T bandwidth))
  // ~ 3 %; the Welch integral must match the record's own variance to 1 %.
  const double record_var = std::pow(channel_moments(x).std_dev, 2);
  EXPECT_REL_NEAR(spectrum_variance(s), record_var, kWelchVarianceRelTol);
  EXPECT_REL_NEAR(record_var, sigma * sigma, 0.1);
  // Peak period: the input is flat to 5 % within +-0.03 rad/s of w0 and each
  // Welch bin scatters by ~1/sqrt(1.9 x 20 segments) = 16 %, so the argmax
  // wanders by ~+-0.04 rad/s, i.e. ~7 % in period.
  EXPECT_REL_NEAR(spectral_peak_period_s(s), 2.0 * kPi / w0, 0.08);
  // The band variance is a sturdier check: int_{w0-2s}^{w0+2s} S = 95.45 % of sigma².
  double band = 0.0;
  for (Eigen::Index k = 0; k < s.density.size(); ++k) {
    if (std::abs(s.frequency_rad_s(k) - w0) <= 2.0 * width) band += s.density(k);
  }
  EXPECT_REL_NEAR(band * s.frequency_step_rad_s, 0.9545 * record_var, 0.02);
}

TEST(Statistics, GumbelMomentFitRecoversKnownParameters) {
  constexpr double u = 10.0, b = 2.0;
  constexpr std::size_t n = 20000;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> x(n);
  for (double& v : x) v = u - b * std::log(-std::log(uniform(rng)));
  const auto fit = fit_gumbel_moments(x);
  // Standard errors of the moment estimators for n = 20000 (Gumbel kurtosis
  // 5.4): sd(b)/b ~ sqrt(1.1/n) = 0.74 %, sd(u) ~ 1.1 b/sqrt(n) = 0.016;
  // tolerances are ~4 standard errors.
  EXPECT_REL_NEAR(fit.scale, b, 0.03);
  EXPECT_NEAR(fit.location, u, 0.07);
}

TEST(Statistics, WeibullLeastSquaresFitRecoversKnownParameters) {
  constexpr double a = 2.0, c = 1.5;
  constexpr std::size_t n = 5000;
  std::mt19937_64 rng(3);
  std::weibull_distribution<double> weibull(c, a);
  std::vector<double> x(n);
  for (double& v : x) v = weibull(rng);
  const auto fit = fit_weibull_least_squares(x);
  // Least squares on the Weibull plot with n = 5000: scatter ~1–2 % (the
  // lowest order statistics carry large leverage in ln-ln space).
  EXPECT_REL_NEAR(fit.shape, c, 0.04);
  EXPECT_REL_NEAR(fit.scale, a, 0.02);
}

// Many 3-hour Gaussian records: the three MPM estimators agree with the
// Rayleigh MPM, and the mode of the simulated 3-h maxima (Gumbel fit over the
// seeds) agrees with it too.
TEST(Statistics, ThreeHourMpmEstimatorsAgreeOnGaussianProcesses) {
  constexpr int kSeeds = 40;
  const double dt = 0.25, sigma = 2.0, w0 = 0.6, width = 0.1;
  const std::size_t n = 43200;  // 3 h
  double sum_r = 0, sum_g = 0, sum_w = 0, sum_shape = 0;
  std::vector<double> maxima;
  for (int seed = 0; seed < kSeeds; ++seed) {
    const auto x = gaussian_process(n, dt, 1000u + static_cast<unsigned>(seed), sigma, w0, width);
    const auto e = most_probable_maximum(x, dt);
    sum_r += e.mpm_rayleigh;
    sum_g += e.mpm_gumbel;
    sum_w += e.mpm_weibull;
    sum_shape += e.weibull.shape;
    maxima.push_back(channel_moments(x).maximum);
    EXPECT_NEAR(e.expected_cycles_in_target, 10800.0 / (2.0 * kPi / w0), 60.0);
  }
  const double rayleigh = sum_r / kSeeds, gumbel = sum_g / kSeeds, weibull = sum_w / kSeeds;
  // Statistical tolerances (40 seeds):
  //  * Weibull on the upper half of ~1000 peaks per record: per-seed scatter
  //    3.5 %, mean 0.6 % (measured); peaks of a narrow-band process are
  //    Rayleigh (shape 2); 3 % covers scatter + plotting-position bias.
  //  * Gumbel on 10 segment maxima per record, extrapolated by ln 10: per-seed
  //    scatter ~10 %, mean ~2 %; 5 %.
  //  * Mode of 40 simulated 3-h maxima: sd(u) ~ 1.1 b/sqrt(40), b ~ sigma/3.7,
  //    i.e. ~1.3 % of the MPM; 5 % (~4 sd).
  EXPECT_REL_NEAR(weibull, rayleigh, 0.03);
  EXPECT_REL_NEAR(gumbel, rayleigh, 0.05);
  EXPECT_REL_NEAR(sum_shape / kSeeds, 2.0, 0.1);
  const auto fit = fit_gumbel_moments(maxima);
  EXPECT_REL_NEAR(fit.location, rayleigh, 0.05);
  // And the Rayleigh MPM itself against the input spectrum: sigma sqrt(2 ln N).
  EXPECT_REL_NEAR(rayleigh, sigma * std::sqrt(2.0 * std::log(10800.0 * w0 / (2.0 * kPi))), 0.02);
  RecordProperty("mpm_rayleigh", std::to_string(rayleigh));
  RecordProperty("mpm_gumbel", std::to_string(gumbel));
  RecordProperty("mpm_weibull", std::to_string(weibull));
  RecordProperty("mode_of_3h_maxima", std::to_string(fit.location));
}

TEST(Statistics, AnalyzeChannelReportsMinimaWithTheirSign) {
  const auto x = gaussian_process(43200, 0.25, 11, 2.0, 0.6, 0.1);
  const auto c = analyze_channel(x, 0.25, 4096);
  EXPECT_GT(c.maximum.mpm_rayleigh, c.moments.mean);
  EXPECT_LT(c.minimum.mpm_rayleigh, c.moments.mean);
  EXPECT_NEAR(c.maximum.mpm_rayleigh - c.moments.mean, c.moments.mean - c.minimum.mpm_rayleigh, 1e-2);
}

TEST(Statistics, ShortOrInvalidRecordsThrow) {
  const std::vector<double> tiny{1.0};
  EXPECT_THROW(channel_moments(tiny), std::invalid_argument);
  const std::vector<double> some(100, 1.0);
  EXPECT_THROW(welch_spectrum(some, 0.1, 200), std::invalid_argument);
  EXPECT_THROW(welch_spectrum(some, 0.0, 32), std::invalid_argument);
  EXPECT_THROW(zero_upcrossing_period_s(some, 0.1), std::invalid_argument);
  std::vector<double> nan_record(100, 0.0);
  nan_record[5] = std::nan("");
  EXPECT_THROW(channel_moments(nan_record), std::invalid_argument);
}

// Low-pass by the DFT: a slow cosine + a trend pass unchanged, a fast cosine
// is removed. Both cosines sit on DFT bins (whole cycles over n dt) and are
// centred on the record, so they take equal values at both ends: the line
// through the end samples is then the trend plus a constant (DC, kept), and
// the split is exact to round-off.
TEST(LowPassDft, KeepsTheSlowPartAndTheTrendAndRemovesTheFastPart) {
  constexpr std::size_t n = 4000;
  constexpr double dt = 0.5;
  const double duration = n * dt;
  const double t_mid = 0.5 * (n - 1) * dt;
  const double w_slow = 2.0 * std::numbers::pi * 3.0 / duration;    // 3 cycles
  const double w_fast = 2.0 * std::numbers::pi * 150.0 / duration;  // 150 cycles
  std::vector<double> x(n), slow(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    slow[i] = 2.0 + 0.001 * static_cast<double>(i) + 1.5 * std::cos(w_slow * (t - t_mid));
    x[i] = slow[i] + 0.7 * std::cos(w_fast * (t - t_mid));
  }
  const auto low = low_pass_dft(x, dt, 0.5 * (w_slow + w_fast));
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(low[i] - slow[i]));
  EXPECT_LT(worst, 1e-10);
  // A cut below the slow cosine removes it too: the trend alone is left
  // (whole cycles have no DC).
  const auto trend = low_pass_dft(x, dt, 0.5 * w_slow);
  worst = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    worst = std::max(worst, std::abs(trend[i] - (2.0 + 0.001 * static_cast<double>(i))));
  EXPECT_LT(worst, 1e-10);
  EXPECT_THROW(low_pass_dft(std::vector<double>{1.0}, dt, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
