// Validation of the random-phase wave realization, the dispersion relation,
// Wheeler-stretched Airy kinematics and the first-order hull excitation series:
//  - statistics of 3-hour records (Hs from the variance, spectral peak from a
//    Welch periodogram) against the target JONSWAP sea;
//  - reproducibility (same seed -> bit-identical) and seed sensitivity;
//  - no repetition at the lag 2 pi / dw_mean (a uniform grid repeats there);
//  - dispersion deep/shallow limits; Wheeler at the surface and above it;
//  - regular-wave excitation = |X| a cos(w t + phi + arg X) on the HAMS buoy.

#include "engine/environment/wave_realization.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "engine/hull/first_order_wave_response.hpp"
#include "engine/hull/wamit_3.hpp"
#include "support/expect_near.hpp"

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr double kG = 9.80665;
constexpr double kRho = 1025.0;
constexpr double kRecord_s = 10800.0;  // 3 hours
constexpr double kDt_s = 0.5;
constexpr int kSeeds = 10;
// Closed-form checks of the same expressions: round-off only.
constexpr double kRoundOffRelTol = 1e-12;
// Hs of the mean over kSeeds records: 2 % (the brief's target). Its adequacy
// is asserted in the test: 2 % >= 3 standard deviations of the mean (Gaussian
// sampling variability of a variance estimate over T: var(m0_hat) = 2 pi
// int S^2 dw / T, Hs relative std = half the m0 relative std).
constexpr double kHsMeanRelTol = 0.02;
constexpr double kSigmas = 3.0;  // per-record and mean bands are 3-sigma bands
// Autocorrelation at the nominal grid repeat lag: expected ~0 with std
// 1/sqrt(2N) = 0.05 for N = 200 equal-variance components (header of
// wave_realization.hpp), plus the estimator's own ~0.02; 0.25 is 5 sigma.
// A uniform grid gives ~1 there (checked alongside).
constexpr double kNoRepeatCorrelation = 0.25;
constexpr double kGridRepeatCorrelation = 0.95;
// Dispersion: Newton stops at 1e-14 relative step; residual at round-off.
constexpr double kDispersionResidual = 1e-13;
// Shallow-water series k = k0 (1 + (k0 h)^2 / 6) drops O((kh)^4) ~ 1e-8 at kh = 0.01.
constexpr double kShallowSeriesRelTol = 1e-7;
// The default band [0.5, 5] wp holds all but 1.25 (1/5)^4 = 0.2 % of m0.
constexpr double kBandTruncationRelTol = 0.003;
// Kinematics against the closed-form expressions evaluated differently
// (exponential forms vs cosh/sinh): round-off amplified by a few operations.
constexpr double kKinematicsRelTol = 1e-12;
constexpr double kKinematicsAbs_m = 1e-12;
// Buoy.3 prints the surge phase as 89.99997 deg, not 90: at the crest the
// surge force is 5e-7 of its amplitude, and the quarter-period-earlier value
// differs from the amplitude by ~1e-13; 1e-4 of the amplitude bounds both.
constexpr double kPhaseLeadRelTol = 1e-4;

WaveSpectrum test_spectrum() { return make_jonswap_spectrum({6.0, 12.0, 3.3}); }

WaveRealizationInput long_crested(std::uint64_t seed) {
  WaveRealizationInput in;
  in.spectrum = test_spectrum();
  in.seed = seed;
  in.duration_s = kRecord_s;
  in.components_per_direction = 200;
  in.water_depth_m = 200.0;
  in.water = {kRho, kG};
  return in;
}

Eigen::VectorXd record_times() {
  const int n = static_cast<int>(kRecord_s / kDt_s);
  return Eigen::VectorXd::LinSpaced(n, 0.0, (n - 1) * kDt_s);
}

double variance(const Eigen::VectorXd& x) { return (x.array() - x.mean()).square().mean(); }

// Gaussian-process relative std of an m0 estimate over T: sqrt(2 pi int S^2 dw / T) / m0.
double m0_relative_std(const WaveSpectrum& s, double T) {
  const double wp = s.peak_rad_per_s();
  const int n = 40000;
  const double dw = 10.0 * wp / n;
  double m0 = 0.0;
  double s2 = 0.0;
  for (int i = 1; i < n; ++i) {
    const double v = spectral_density_m2s_per_rad(s, i * dw);
    m0 += v * dw;
    s2 += v * v * dw;
  }
  return std::sqrt(2.0 * kPi * s2 / T) / m0;
}

TEST(WaveRealization, SignificantWaveHeightOverThreeHours) {
  const WaveSpectrum spectrum = test_spectrum();
  const double hs_rel_std = 0.5 * m0_relative_std(spectrum, kRecord_s);
  ASSERT_GE(kHsMeanRelTol, kSigmas * hs_rel_std / std::sqrt(double(kSeeds)))
      << "the 2 % band is not a 3-sigma band for " << kSeeds << " seeds";
  const Eigen::VectorXd t = record_times();
  double hs_sum = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const auto sea = make_wave_realization(long_crested(seed));
    // The components carry the band variance exactly (bin integrals).
    EXPECT_REL_NEAR(sea.band_variance_m2, sea.spectrum_variance_m2, kBandTruncationRelTol);
    const Eigen::VectorXd eta = surface_elevation_many(sea, 0.0, 0.0, t);
    const double hs = 4.0 * std::sqrt(variance(eta));
    EXPECT_REL_NEAR(hs, spectrum.Hs_m, kSigmas * hs_rel_std) << "seed " << seed;
    hs_sum += hs;
  }
  EXPECT_REL_NEAR(hs_sum / kSeeds, spectrum.Hs_m, kHsMeanRelTol);
}

TEST(WaveRealization, WelchPeriodogramPeaksAtTp) {
  // Hann-windowed, 50 % overlapping segments of 512 samples (256 s): bin
  // width 2 pi / 256 s = 0.0245 rad/s = 4.7 % of wp. The gamma = 3.3 peak drops
  // by > 20 % one bin away, the averaged estimate (4 seeds x 83 segments)
  // scatters by ~5 %: the peak is in the bin of wp or its neighbour.
  constexpr int kSegment = 512;
  const double bin_rad_per_s = 2.0 * kPi / (kSegment * kDt_s);
  const Eigen::VectorXd t = record_times();
  Eigen::FFT<double> fft;
  std::vector<double> psd(kSegment / 2 + 1, 0.0);
  Eigen::VectorXd window(kSegment);
  for (int i = 0; i < kSegment; ++i) window(i) = 0.5 - 0.5 * std::cos(2.0 * kPi * i / kSegment);
  for (int seed = 1; seed <= 4; ++seed) {
    const Eigen::VectorXd eta = surface_elevation_many(make_wave_realization(long_crested(seed)), 0.0, 0.0, t);
    for (Eigen::Index start = 0; start + kSegment <= eta.size(); start += kSegment / 2) {
      std::vector<double> segment(kSegment);
      for (int i = 0; i < kSegment; ++i) segment[i] = window(i) * eta(start + i);
      std::vector<std::complex<double>> spectrum;
      fft.fwd(spectrum, segment);
      for (int j = 0; j <= kSegment / 2; ++j) psd[j] += std::norm(spectrum[j]);
    }
  }
  int peak = 1;
  for (int j = 1; j <= kSegment / 2; ++j) {
    if (psd[j] > psd[peak]) peak = j;
  }
  const double wp = test_spectrum().peak_rad_per_s();
  EXPECT_NEAR(peak * bin_rad_per_s, wp, bin_rad_per_s)
      << "periodogram peak period " << 2.0 * kPi / (peak * bin_rad_per_s) << " s, Tp 12 s";
}

TEST(WaveRealization, SameSeedIsBitIdenticalOtherSeedDiffers) {
  auto in = long_crested(42);
  in.spreading = DirectionalSpreading{SpreadingForm::cos_2s, 8.0};
  in.direction_count = 9;
  in.mean_heading_rad = 30.0 * kDeg;
  const auto a = make_wave_realization(in);
  const auto b = make_wave_realization(in);
  ASSERT_EQ(a.components.size(), 9u * 200u);
  ASSERT_EQ(a.components.size(), b.components.size());
  for (std::size_t k = 0; k < a.components.size(); ++k) {
    EXPECT_EQ(a.components[k].omega_rad_per_s, b.components[k].omega_rad_per_s);
    EXPECT_EQ(a.components[k].phase_rad, b.components[k].phase_rad);
    EXPECT_EQ(a.components[k].amplitude_m, b.components[k].amplitude_m);
    EXPECT_EQ(a.components[k].heading_rad, b.components[k].heading_rad);
  }
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(2000, 0.0, 999.5);
  const Eigen::VectorXd ea = surface_elevation_many(a, 10.0, -5.0, t);
  const Eigen::VectorXd eb = surface_elevation_many(b, 10.0, -5.0, t);
  EXPECT_EQ((ea - eb).cwiseAbs().maxCoeff(), 0.0);
  in.seed = 43;
  const Eigen::VectorXd ec = surface_elevation_many(make_wave_realization(in), 10.0, -5.0, t);
  EXPECT_GT((ea - ec).cwiseAbs().maxCoeff(), 1.0);  // Hs 6 m: records differ by metres
}

// Normalised correlation of eta(t) and eta(t + lag) over [0, T - lag], sampled at dt.
double correlation_at_lag(const WaveRealization& sea, double lag_s) {
  const int n = static_cast<int>((kRecord_s - lag_s) / kDt_s);
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n, 0.0, (n - 1) * kDt_s);
  const Eigen::VectorXd e0 = surface_elevation_many(sea, 0.0, 0.0, t);
  const Eigen::VectorXd e1 = surface_elevation_many(sea, 0.0, 0.0, (t.array() + lag_s).matrix());
  return e0.dot(e1) / std::sqrt(e0.squaredNorm() * e1.squaredNorm());
}

TEST(WaveRealization, DoesNotRepeatAtTheMeanFrequencySpacingLag) {
  for (const auto selection : {FrequencySelection::equal_energy_random, FrequencySelection::equal_spacing_random}) {
    auto in = long_crested(7);
    in.frequency_selection = selection;
    const auto sea = make_wave_realization(in);
    EXPECT_NEAR(sea.grid_repeat_period_s, 2.0 * kPi / (4.5 * 2.0 * kPi / 12.0 / 200.0),
                kRoundOffRelTol * sea.grid_repeat_period_s);
    EXPECT_LT(std::abs(correlation_at_lag(sea, sea.grid_repeat_period_s)), kNoRepeatCorrelation);
  }
  // The uniform grid is periodic: it repeats at 2 pi / dw (533 s here), and is
  // refused for a duration longer than that.
  auto grid = long_crested(7);
  grid.frequency_selection = FrequencySelection::equal_spacing_grid;
  EXPECT_THROW(make_wave_realization(grid), std::invalid_argument);
  grid.duration_s = 500.0;
  const auto sea = make_wave_realization(grid);
  EXPECT_GT(correlation_at_lag(sea, sea.grid_repeat_period_s), kGridRepeatCorrelation);
}

TEST(Dispersion, DeepAndShallowLimits) {
  // Deep water: k = w^2 / g exactly, and a deep finite depth agrees.
  const double w = 1.2;
  EXPECT_EQ(solve_dispersion({w, std::nullopt, kG}).wavenumber_rad_per_m, w * w / kG);
  EXPECT_REL_NEAR(solve_dispersion({w, 1000.0, kG}).wavenumber_rad_per_m, w * w / kG, kRoundOffRelTol);
  // Shallow water: k -> w / sqrt(g h) (1 + (kh)^2 / 6).
  const double ws = 0.01;
  const double h = 10.0;
  const double k0 = ws / std::sqrt(kG * h);
  EXPECT_REL_NEAR(solve_dispersion({ws, h, kG}).wavenumber_rad_per_m, k0 * (1.0 + (k0 * h) * (k0 * h) / 6.0),
                  kShallowSeriesRelTol);
  // Intermediate depths: residual at round-off.
  for (const double wi : {0.05, 0.3, 0.7, 1.5, 4.0}) {
    for (const double hi : {5.0, 50.0, 200.0, 2000.0}) {
      const auto s = solve_dispersion({wi, hi, kG});
      const double k = s.wavenumber_rad_per_m;
      EXPECT_LT(std::abs(kG * k * std::tanh(k * hi) - wi * wi) / (wi * wi), kDispersionResidual)
          << wi << " rad/s, " << hi << " m";
      EXPECT_LE(s.iterations, 8);
    }
  }
  EXPECT_THROW(solve_dispersion({0.0, 10.0, kG}), std::invalid_argument);
  EXPECT_THROW(solve_dispersion({1.0, -10.0, kG}), std::invalid_argument);
}

TEST(WheelerStretching, SurfaceValuesEqualAiryAtMeanLevelAndZeroAbove) {
  const double a = 2.0;
  const double w = 0.6;
  const double h = 50.0;
  const double beta = 40.0 * kDeg;
  const auto sea = make_regular_wave({a, w, beta, 0.4, h, {kRho, kG}});
  const double k = sea.components[0].wavenumber_rad_per_m;
  for (const double t : {0.0, 1.3, 4.0, 7.7}) {
    const Eigen::Vector3d xy(3.0, -2.0, 0.0);
    const double theta = w * t - k * (xy.x() * std::cos(beta) + xy.y() * std::sin(beta)) + 0.4;
    // The surface as the library computes it (a 1-ulp difference would put z = eta above it).
    const double eta = surface_elevation_m(sea, xy.x(), xy.y(), t);
    EXPECT_REL_NEAR_SCALE(eta, a * std::cos(theta), kRoundOffRelTol, a);
    // At z = eta: the Airy values at z = 0 (DNV-RP-C205 §3.2.3).
    const auto at = wave_kinematics(sea, {xy.x(), xy.y(), eta}, t);
    ASSERT_TRUE(at.wet);
    EXPECT_NEAR(at.stretched_z_m, 0.0, kKinematicsAbs_m);
    const double uh = a * w / std::tanh(k * h) * std::cos(theta);
    const double duh = -a * w * w / std::tanh(k * h) * std::sin(theta);
    const Eigen::Vector3d u(uh * std::cos(beta), uh * std::sin(beta), -a * w * std::sin(theta));
    const Eigen::Vector3d du(duh * std::cos(beta), duh * std::sin(beta), -a * w * w * std::cos(theta));
    EXPECT_EIGEN_REL_NEAR(at.velocity_m_per_s, u, kKinematicsRelTol);
    EXPECT_EIGEN_REL_NEAR(at.acceleration_m_per_s2, du, kKinematicsRelTol);
    EXPECT_REL_NEAR_SCALE(at.dynamic_pressure_Pa, kRho * kG * eta, kKinematicsRelTol, kRho * kG * a);
    // Just above the surface: nothing.
    const auto dry = wave_kinematics(sea, {xy.x(), xy.y(), eta + 1e-6}, t);
    EXPECT_FALSE(dry.wet);
    EXPECT_EQ(dry.velocity_m_per_s.norm(), 0.0);
    EXPECT_EQ(dry.acceleration_m_per_s2.norm(), 0.0);
    EXPECT_EQ(dry.dynamic_pressure_Pa, 0.0);
    // At the seabed z' = -h: no vertical velocity, u = a w / sinh(kh) cos(theta).
    const auto bed = wave_kinematics(sea, {xy.x(), xy.y(), -h}, t);
    EXPECT_NEAR(bed.velocity_m_per_s.z(), 0.0, kKinematicsAbs_m);
    EXPECT_REL_NEAR_SCALE(std::hypot(bed.velocity_m_per_s.x(), bed.velocity_m_per_s.y()),
                          std::abs(a * w / std::sinh(k * h) * std::cos(theta)), kKinematicsRelTol, a * w);
    // Mid-depth: the profile at the stretched z' = (z - eta) h / (h + eta).
    const double z = -20.0;
    const double zs = (z - eta) * h / (h + eta);
    const auto mid = wave_kinematics(sea, {xy.x(), xy.y(), z}, t);
    EXPECT_NEAR(mid.stretched_z_m, zs, kKinematicsAbs_m);
    EXPECT_REL_NEAR_SCALE(mid.dynamic_pressure_Pa,
                          kRho * kG * a * std::cosh(k * (zs + h)) / std::cosh(k * h) * std::cos(theta),
                          kKinematicsRelTol, kRho * kG * a);
  }
  EXPECT_THROW(wave_kinematics(sea, {0.0, 0.0, -h - 1.0}, 0.0), std::invalid_argument);
  // Deep water: z' = z - eta and the e^{kz'} profile.
  const auto deep = make_regular_wave({a, w, 0.0, 0.0, std::nullopt, {kRho, kG}});
  const auto d = wave_kinematics(deep, {0.0, 0.0, -10.0}, 0.0);  // crest: eta = a
  EXPECT_NEAR(d.stretched_z_m, -10.0 - a, kKinematicsAbs_m);
  EXPECT_REL_NEAR(d.velocity_m_per_s.x(), a * w * std::exp(w * w / kG * (-10.0 - a)), kKinematicsRelTol);
}

TEST(FirstOrderExcitation, RegularWaveIsModulusTimesCosineWithPhaseLead) {
  WamitReadOptions options;
  options.frequency_column = FrequencyColumn::angular_frequency;
  options.water = {kRho, kG};
  const auto table = read_wamit_3(SPIRAL_TEST_DATA_DIR "/hydro/cylinder-buoy/Buoy.3", options);
  const double a = 1.5;
  const double w = 0.4;  // a tabulated frequency: no interpolation
  const double phi = 0.3;
  const auto sea = make_regular_wave({a, w, 0.0, phi, 50.0, {kRho, kG}});
  const auto series = prepare_first_order_series(sea, table, {});
  EXPECT_EQ(series.variance_share_outside_table, 0.0);
  const Vector6cd X = transfer_at(table, w, 0.0);
  for (const double t : {0.0, 2.0, 5.5, 13.0}) {
    const Vector6d f = evaluate_first_order(series, t);
    for (int i = 0; i < 6; ++i) {
      EXPECT_REL_NEAR_SCALE(f(i), std::abs(X(i)) * a * std::cos(w * t + phi + std::arg(X(i))), kRoundOffRelTol,
                            std::abs(X(0)) * a + std::abs(X(2)) * a);
    }
  }
  // Surge leads the crest at the origin by ~90 deg: at the crest it is ~0 and
  // a quarter period earlier it is at its maximum.
  const double t_crest = (2.0 * kPi - phi) / w;
  EXPECT_LT(std::abs(evaluate_first_order(series, t_crest)(0)), kPhaseLeadRelTol * std::abs(X(0)) * a);
  EXPECT_REL_NEAR(evaluate_first_order(series, t_crest - 0.5 * kPi / w)(0), std::abs(X(0)) * a, kPhaseLeadRelTol);
  // Hull offset (x0, 0): the wave reaches it with phase -k x0. Hull yawed by
  // 30 deg in waves towards 30 deg: body-relative heading 0, force rotated.
  const double k = sea.components[0].wavenumber_rad_per_m;
  const auto sea30 = make_regular_wave({a, w, 30.0 * kDeg, phi, 50.0, {kRho, kG}});
  const auto moved = prepare_first_order_series(sea30, table, {20.0, 0.0, 30.0 * kDeg});
  const double t = 3.0;
  const double shift = -k * 20.0 * std::cos(30.0 * kDeg);
  const double fx_b = std::abs(X(0)) * a * std::cos(w * t + phi + shift + std::arg(X(0)));
  const double my_b = std::abs(X(4)) * a * std::cos(w * t + phi + shift + std::arg(X(4)));
  const Vector6d f = evaluate_first_order(moved, t);
  const double scale = std::abs(X(0)) * a;
  EXPECT_REL_NEAR_SCALE(f(0), std::cos(30.0 * kDeg) * fx_b, kRoundOffRelTol, scale);
  EXPECT_REL_NEAR_SCALE(f(1), std::sin(30.0 * kDeg) * fx_b, kRoundOffRelTol, scale);
  EXPECT_REL_NEAR_SCALE(f(3), -std::sin(30.0 * kDeg) * my_b, kRoundOffRelTol, std::abs(X(4)) * a);
  EXPECT_REL_NEAR_SCALE(f(4), std::cos(30.0 * kDeg) * my_b, kRoundOffRelTol, std::abs(X(4)) * a);
  // Waves from a heading the table lacks: refused at preparation.
  EXPECT_THROW(prepare_first_order_series(sea30, table, {}), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
