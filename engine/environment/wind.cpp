#include "engine/environment/wind.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace spiral::engine {
namespace {

void require_positive(double value, const char* what, const char* unit) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("wind: {} must be > 0 {}, got {} {}", what, unit, value, unit));
  }
}

void require_non_negative(double value, const char* what, const char* unit) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("wind: {} must be >= 0 {}, got {} {}", what, unit, value, unit));
  }
}

constexpr double kReferenceHeight_m = 10.0;    // NPD / ISO 19901-1 reference height
constexpr double kReferencePeriod_s = 3600.0;  // 1-hour mean
constexpr double kNpdExponent = 0.468;         // n of the NPD spectrum

}  // namespace

double wind_profile_coefficient(double U0_m_per_s, WindProfileStandard standard) {
  require_non_negative(U0_m_per_s, "U0 (1-hour mean at 10 m)", "m/s");
  // ISO 19901-1 / DNV-RP-C205: 0.148 s/m. API RP 2A: 0.0457 s/ft x 3.280839895 ft/m.
  const double c1 = standard == WindProfileStandard::iso_19901_1 ? 0.148 : 0.0457 * 3.280839895;
  return 5.73e-2 * std::sqrt(1.0 + c1 * U0_m_per_s);
}

double npd_turbulence_intensity(double U0_m_per_s, double height_m) {
  require_non_negative(U0_m_per_s, "U0 (1-hour mean at 10 m)", "m/s");
  require_positive(height_m, "height above mean water level", "m");
  // ISO 19901-1 / NPD: I_u = 0.06 (1 + 0.043 U0) (z/10)^-0.22.
  return 0.06 * (1.0 + 0.043 * U0_m_per_s) * std::pow(height_m / kReferenceHeight_m, -0.22);
}

double mean_wind_speed_m_per_s(const WindProfileInput& in) {
  require_positive(in.height_m, "height above mean water level", "m");
  if (!(in.averaging_time_s > 0.0) || !(in.averaging_time_s <= kReferencePeriod_s)) {
    throw std::invalid_argument(
        fmt::format("wind: averaging time must be in (0, 3600] s, got {} s", in.averaging_time_s));
  }
  const double U0 = in.U0_m_per_s;
  const double C = wind_profile_coefficient(U0, in.standard);
  // ISO 19901-1 / NPD: U(z) = U0 [1 + C ln(z/10)], times the gust factor
  // [1 - 0.41 I_u(z) ln(t/t0)] for averaging time t < t0 = 1 h.
  const double profile = U0 * (1.0 + C * std::log(in.height_m / kReferenceHeight_m));
  const double gust =
      1.0 - 0.41 * npd_turbulence_intensity(U0, in.height_m) * std::log(in.averaging_time_s / kReferencePeriod_s);
  return profile * gust;
}

double npd_wind_spectrum(const NpdSpectrumInput& in, double f_Hz) {
  require_positive(in.U0_m_per_s, "U0 (1-hour mean at 10 m)", "m/s");
  require_positive(in.height_m, "height above mean water level", "m");
  if (!(f_Hz > 0.0)) return 0.0;
  const double u = in.U0_m_per_s / 10.0;
  const double zr = in.height_m / kReferenceHeight_m;
  // NPD (Froya): S = 320 u^2 zr^0.45 / (1 + ft^n)^(5/(3n)), ft = 172 f zr^(2/3) u^-0.75.
  const double ft = 172.0 * f_Hz * std::pow(zr, 2.0 / 3.0) * std::pow(u, -0.75);
  return 320.0 * u * u * std::pow(zr, 0.45) / std::pow(1.0 + std::pow(ft, kNpdExponent), 5.0 / (3.0 * kNpdExponent));
}

double npd_wind_variance_m2_per_s2(const NpdSpectrumInput& in) {
  require_positive(in.U0_m_per_s, "U0 (1-hour mean at 10 m)", "m/s");
  require_positive(in.height_m, "height above mean water level", "m");
  const double u = in.U0_m_per_s / 10.0;
  const double zr = in.height_m / kReferenceHeight_m;
  const double n = kNpdExponent;
  // int_0^inf (1 + x^n)^(-5/(3n)) dx = (1/n) B(1/n, 2/(3n)) (substitute y = x^n).
  const double a = 1.0 / n;
  const double b = 2.0 / (3.0 * n);
  const double beta = std::tgamma(a) * std::tgamma(b) / std::tgamma(a + b);
  const double scale = 172.0 * std::pow(zr, 2.0 / 3.0) * std::pow(u, -0.75);  // ft per Hz
  return 320.0 * u * u * std::pow(zr, 0.45) / scale * beta / n;
}

double api_turbulence_intensity(double height_m) {
  require_positive(height_m, "height above mean water level", "m");
  constexpr double kSurfaceLayer_m = 20.0;  // zs of API RP 2A
  const double exponent = height_m <= kSurfaceLayer_m ? -0.125 : -0.275;
  return 0.15 * std::pow(height_m / kSurfaceLayer_m, exponent);
}

double api_wind_spectrum(const ApiSpectrumInput& in, double f_Hz) {
  require_positive(in.mean_speed_m_per_s, "mean wind speed U(z)", "m/s");
  require_positive(in.height_m, "height above mean water level", "m");
  require_non_negative(in.sigma_m_per_s, "gust standard deviation", "m/s");
  if (!(in.a >= 0.01 && in.a <= 0.1)) {
    throw std::invalid_argument(fmt::format("wind: API spectrum parameter a must be in [0.01, 0.1], got {}", in.a));
  }
  if (!(f_Hz > 0.0)) return 0.0;
  // API RP 2A: S = sigma^2 / fp / (1 + 1.5 f/fp)^(5/3), fp = a U(z)/z.
  const double fp = in.a * in.mean_speed_m_per_s / in.height_m;
  return in.sigma_m_per_s * in.sigma_m_per_s / fp / std::pow(1.0 + 1.5 * f_Hz / fp, 5.0 / 3.0);
}

}  // namespace spiral::engine
