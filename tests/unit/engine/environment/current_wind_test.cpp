// Unit tests of the current profile (interpolation, held ends, heading, the
// OpenFAST 1/7 power law) and of the wind model (NPD / ISO 19901-1 profile and
// gust factor, NPD and API spectra).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/environment/current_profile.hpp"
#include "engine/environment/wind.hpp"
#include "engine/environment/wind_realization.hpp"
#include "support/expect_near.hpp"

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
// Linear interpolation and trigonometry of exact inputs: round-off only.
constexpr double kRoundOffRelTol = 1e-12;
// Hand-computed reference values are written with 6-7 significant digits.
constexpr double kHandValueRelTol = 1e-6;
// Spectrum integrals: trapezoid in ln f over 1e-7..1e7 Hz with 400000 points;
// the density falls as f^-5/3 at the top, so the omitted part scales as
// F^-2/3: ~2e-3 of the variance at F = 1e3 Hz (seen), ~1e-5 at 1e7 Hz; flat
// at the bottom (omitted < 1e-5).
constexpr double kSpectrumIntegralRelTol = 5e-4;
// NPD spectrum vs NPD turbulence intensity (ISO 19901-1): the two NPD formulas
// are separate fits and are not exactly consistent; at U0 = 40 m/s, z = 10 m
// the spectrum's sigma is 5.9 % above I_u U0 (19 % at 20 m/s). The brief's
// acceptance band is 10 % on sigma at a design (storm) wind speed.
constexpr double kNpdConsistencyRelTol = 0.10;

CurrentProfile three_point_profile() { return {{-100.0, -50.0, 0.0}, {0.2, 0.8, 1.2}, 30.0 * kPi / 180.0}; }

TEST(CurrentProfile, InterpolatesLinearlyAndPointsAlongTheHeading) {
  const CurrentProfile p = three_point_profile();
  const double c = std::cos(30.0 * kPi / 180.0);
  const double s = std::sin(30.0 * kPi / 180.0);
  // z = -25: halfway between 0.8 (z = -50) and 1.2 (z = 0) -> 1.0 m/s.
  const Eigen::Vector3d v = current_velocity_g(p, -25.0);
  EXPECT_EIGEN_REL_NEAR(v, Eigen::Vector3d(1.0 * c, 1.0 * s, 0.0), kRoundOffRelTol);
  // z = -80: 0.2 + (20/50) (0.8 - 0.2) = 0.44 m/s.
  EXPECT_REL_NEAR(current_velocity_g(p, -80.0).norm(), 0.44, kRoundOffRelTol);
  // Table points are reproduced.
  EXPECT_REL_NEAR(current_velocity_g(p, -50.0).norm(), 0.8, kRoundOffRelTol);
}

TEST(CurrentProfile, HoldsTheEndValuesBeyondTheTable) {
  const CurrentProfile p = three_point_profile();
  EXPECT_REL_NEAR(current_velocity_g(p, -500.0).norm(), 0.2, kRoundOffRelTol);
  EXPECT_REL_NEAR(current_velocity_g(p, 3.0).norm(), 1.2, kRoundOffRelTol);
  // One point: uniform current.
  const CurrentProfile uniform{{-10.0}, {0.7}, 0.0};
  EXPECT_REL_NEAR(current_velocity_g(uniform, -900.0).x(), 0.7, kRoundOffRelTol);
  EXPECT_EQ(current_velocity_g(uniform, -900.0).y(), 0.0);
}

TEST(CurrentProfile, RejectsMalformedTables) {
  EXPECT_THROW(current_velocity_g({{}, {}, 0.0}, 0.0), std::invalid_argument);
  EXPECT_THROW(current_velocity_g({{-10.0, 0.0}, {1.0}, 0.0}, 0.0), std::invalid_argument);
  EXPECT_THROW(current_velocity_g({{0.0, -10.0}, {1.0, 0.5}, 0.0}, 0.0), std::invalid_argument);
  try {
    current_velocity_g({{-10.0, 0.0}, {1.0, -0.5}, 0.0}, 0.0);
    FAIL() << "negative speed accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("speed_m_per_s[1] must be >= 0 m/s"), std::string::npos) << e.what();
  }
}

TEST(CurrentProfile, PowerLawFollowsTheOpenFastSubSurfaceForm) {
  // V(z) = V0 ((z + h)/h)^(1/7), h = 1000 m, V0 = 1.5 m/s (GoM 100-yr surface current).
  const CurrentProfile p = power_law_current_profile({1.5, 1000.0, 0.0, 1.0 / 7.0, 11});
  ASSERT_EQ(p.z_m.size(), 11u);
  EXPECT_EQ(p.z_m.front(), -1000.0);
  EXPECT_EQ(p.z_m.back(), 0.0);
  EXPECT_EQ(p.speed_m_per_s.front(), 0.0);
  EXPECT_REL_NEAR(p.speed_m_per_s.back(), 1.5, kRoundOffRelTol);
  // z = -500 m (table point 5): 1.5 x 0.5^(1/7) = 1.5 x 0.9057236 = 1.3585854 m/s.
  EXPECT_REL_NEAR(current_velocity_g(p, -500.0).norm(), 1.3585854, kHandValueRelTol);
  EXPECT_THROW(power_law_current_profile({1.0, 0.0, 0.0, 1.0 / 7.0, 11}), std::invalid_argument);
  EXPECT_THROW(power_law_current_profile({1.0, 100.0, 0.0, 1.0 / 7.0, 1}), std::invalid_argument);
}

TEST(WindProfile, TenMetreSpeedIsTheReferenceSpeed) {
  for (const double U0 : {0.0, 15.0, 40.0}) {
    EXPECT_REL_NEAR(mean_wind_speed_m_per_s({U0, 10.0}), U0, kRoundOffRelTol);
  }
}

TEST(WindProfile, HandComputedSpeedAt50Metres) {
  // U0 = 40 m/s (GoM 100-yr), z = 50 m, ISO 19901-1:
  //   C = 0.0573 sqrt(1 + 0.148 x 40) = 0.0573 x 2.630589 = 0.1507328
  //   U = 40 (1 + 0.1507328 ln 5) = 40 (1 + 0.1507328 x 1.6094379) = 49.70380 m/s
  EXPECT_REL_NEAR(mean_wind_speed_m_per_s({40.0, 50.0}), 49.70380, kHandValueRelTol);
  // API RP 2A: C = 0.0573 sqrt(1 + 0.1499344 x 40) = 0.0573 x 2.645255 = 0.1515731
  //   U = 40 (1 + 0.1515731 x 1.6094379) = 49.75790 m/s
  EXPECT_REL_NEAR(mean_wind_speed_m_per_s({40.0, 50.0, 3600.0, WindProfileStandard::api_rp_2a}), 49.75790,
                  kHandValueRelTol);
}

TEST(WindProfile, GustFactorForShorterAveragingTimes) {
  // 1-minute mean at 10 m, U0 = 40 m/s: I_u = 0.06 (1 + 0.043 x 40) = 0.1632,
  //   factor = 1 - 0.41 x 0.1632 x ln(60/3600) = 1 + 0.066912 x 4.0943446 = 1.273961
  EXPECT_REL_NEAR(mean_wind_speed_m_per_s({40.0, 10.0, 60.0}), 40.0 * 1.273961, kHandValueRelTol);
  EXPECT_THROW(mean_wind_speed_m_per_s({40.0, 10.0, 7200.0}), std::invalid_argument);
  EXPECT_THROW(mean_wind_speed_m_per_s({40.0, 0.0}), std::invalid_argument);
}

double integrate_log(const std::function<double(double)>& S) {
  // Trapezoid in ln f: int S df = int S f d(ln f).
  const double a = std::log(1e-7);
  const double b = std::log(1e7);
  const int n = 400000;
  const double h = (b - a) / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double f = std::exp(a + i * h);
    sum += (i == 0 || i == n ? 0.5 : 1.0) * S(f) * f;
  }
  return sum * h;
}

TEST(WindSpectrum, NpdVarianceMatchesItsClosedForm) {
  for (const double z : {10.0, 50.0}) {
    const NpdSpectrumInput in{40.0, z};
    const double variance = integrate_log([&](double f) { return npd_wind_spectrum(in, f); });
    EXPECT_REL_NEAR(variance, npd_wind_variance_m2_per_s2(in), kSpectrumIntegralRelTol);
  }
  // Closed form at U0 = 40, z = 10: 1.0552970 x 4^2.75 = 47.75729 m^2/s^2.
  EXPECT_REL_NEAR(npd_wind_variance_m2_per_s2({40.0, 10.0}), 47.75729, kHandValueRelTol);
}

TEST(WindSpectrum, NpdStandardDeviationIsConsistentWithNpdTurbulenceIntensity) {
  // Reference: ISO 19901-1 / NPD, I_u = 0.06 (1 + 0.043 U0) (z/10)^-0.22, so
  // sigma = I_u U0 (the intensity is defined on the 1-hour mean at z; at 10 m,
  // U(10) = U0). At U0 = 40 m/s: 6.528 m/s; the spectrum gives 6.911 m/s.
  const double U0 = 40.0;
  const double sigma_spectrum = std::sqrt(integrate_log([&](double f) { return npd_wind_spectrum({U0, 10.0}, f); }));
  const double sigma_intensity = npd_turbulence_intensity(U0, 10.0) * U0;
  EXPECT_REL_NEAR(sigma_spectrum, sigma_intensity, kNpdConsistencyRelTol);
}

TEST(WindSpectrum, ApiSpectrumIntegratesToItsVariance) {
  // int_0^inf sigma^2/fp (1 + 1.5 f/fp)^(-5/3) df = sigma^2 exactly.
  const double z = 10.0;
  const double U = 40.0;
  const double sigma = api_turbulence_intensity(z) * U;
  // I(10) = 0.15 (10/20)^-0.125 = 0.15 x 1.0905077 = 0.1635762
  EXPECT_REL_NEAR(api_turbulence_intensity(z), 0.1635762, kHandValueRelTol);
  const ApiSpectrumInput in{U, z, sigma, 0.025};
  const double variance = integrate_log([&](double f) { return api_wind_spectrum(in, f); });
  EXPECT_REL_NEAR(variance, sigma * sigma, kSpectrumIntegralRelTol);
  EXPECT_THROW(api_wind_spectrum({U, z, sigma, 0.5}, 0.1), std::invalid_argument);
}

// The gust realization of an NPD spectrum (40 m/s at 10 m): its variance is
// the spectrum's over the band (the closed form less the tails outside
// [1e-4, 1] Hz), a long record's sample variance agrees, and a seed
// reproduces the record bit for bit.
TEST(WindRealization, NpdGustCarriesTheSpectrumVarianceAndIsSeeded) {
  const NpdSpectrumInput npd{40.0, 10.0};
  WindRealizationInput input;
  input.spectrum = [npd](double f) { return npd_wind_spectrum(npd, f); };
  input.seed = 7;
  const WindRealization gust = make_wind_realization(input);
  // Band integral of S(f) by the midpoint rule on a fine log grid.
  double band = 0.0;
  const int n = 200000;
  const double l0 = std::log(input.frequency_min_Hz), l1 = std::log(input.frequency_max_Hz);
  for (int i = 0; i < n; ++i) {
    const double f = std::exp(l0 + (l1 - l0) * (i + 0.5) / n);
    band += npd_wind_spectrum(npd, f) * f * (l1 - l0) / n;
  }
  // 400 log-spaced bins with the exact-variance amplitudes of each bin's
  // random frequency: within 2 % of the band integral.
  EXPECT_NEAR(gust.variance_m2_per_s2 / band, 1.0, 0.02);
  // The default band holds 86 % of the NPD variance (measured: 41.2 of
  // 47.8 m²/s²); the rest lies above 1 Hz, where no hull responds.
  EXPECT_LT(band, npd_wind_variance_m2_per_s2(npd));
  EXPECT_GT(band, 0.8 * npd_wind_variance_m2_per_s2(npd));
  // Sample variance of 20 hours at 0.5 s: the record's slowest components
  // (1e-4 Hz) make it scatter by ~10 %; 20 % is the bound.
  double sum = 0.0, sum2 = 0.0;
  const int samples = 144000;
  for (int k = 0; k < samples; ++k) {
    const double u = wind_gust_m_per_s(gust, 0.5 * k);
    sum += u;
    sum2 += u * u;
  }
  const double mean = sum / samples, variance = sum2 / samples - mean * mean;
  EXPECT_NEAR(variance / gust.variance_m2_per_s2, 1.0, 0.2);
  const WindRealization again = make_wind_realization(input);
  EXPECT_EQ(wind_gust_m_per_s(again, 1234.5), wind_gust_m_per_s(gust, 1234.5));
  input.seed = 8;
  EXPECT_NE(wind_gust_m_per_s(make_wind_realization(input), 1234.5), wind_gust_m_per_s(gust, 1234.5));
}

}  // namespace
}  // namespace spiral::engine
