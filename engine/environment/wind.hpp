#pragma once
// Offshore wind: mean profile, gust (averaging-time) factor and turbulence
// spectra for dynamic wind. Heights z in m above mean water level, f in Hz.
//
// Mean profile and gust factor (NPD / Froya model; ISO 19901-1 §6.3 and
// Annex A.6; DNV-RP-C205 §2.3.2.11-12):
//   U(z, t) = U0 [1 + C ln(z/10)] [1 - 0.41 I_u(z) ln(t/t0)],  t <= t0 = 3600 s
//   C       = 5.73e-2 (1 + c1 U0)^(1/2)
//   I_u(z)  = 0.06 (1 + 0.043 U0) (z/10)^-0.22
// with U0 the 1-hour mean at 10 m (m/s). c1 = 0.148 s/m in ISO 19901-1 /
// DNV-RP-C205 / NPD; API RP 2A-WSD (21st ed., §2.3.2) writes the same law in
// feet, C = 5.73e-2 (1 + 0.0457 U0[ft/s])^(1/2), i.e. c1 = 0.0457 x 3.28084
// = 0.14994 s/m: selectable below (the two differ by < 0.1 % in U).
//
// NPD (Froya) spectrum of the longitudinal gust (ISO 19901-1 Annex A;
// DNV-RP-C205 §2.3.4.10), one-sided, in m^2/s^2/Hz:
//   S(f) = 320 (U0/10)^2 (z/10)^0.45 / (1 + ft^n)^(5/(3n)),
//   ft   = 172 f (z/10)^(2/3) (U0/10)^-0.75,  n = 0.468.
// Units: 320 carries m^2/s (the formula is for U0 in m/s, z in m, f in Hz),
// so S is (m/s)^2 per Hz. Its variance has the closed form
//   sigma^2 = 320/172 (U0/10)^2.75 (z/10)^(0.45-2/3) (1/n) B(1/n, 2/(3n))
// (substitute y = ft^n; B is the Beta function) = 1.0553 (U0/10)^2.75 (z/10)^-0.2167.
// It is not exactly I_u^2 U^2 of the profile formula above: the ratio of
// standard deviations is 1.06 at U0 = 40 m/s and 1.19 at 20 m/s (z = 10 m).
//
// API spectrum (API RP 2A-WSD 21st ed. §2.3.2; recalled, not re-read):
//   S(f) = sigma^2 / fp / (1 + 1.5 f/fp)^(5/3),  fp = a U(z)/z, a = 0.025 (0.01..0.1)
// It integrates to sigma^2 exactly; sigma = I(z) U(z) with
//   I(z) = 0.15 (z/zs)^-0.125 for z <= zs, 0.15 (z/zs)^-0.275 for z > zs, zs = 20 m.
//
// (Clause numbers of ISO 19901-1, DNV-RP-C205 and API RP 2A are recalled, not
// re-read.) Errors: std::invalid_argument naming the quantity and its unit.

namespace spiral::engine {

enum class WindProfileStandard {
  iso_19901_1,  ///< C = 5.73e-2 (1 + 0.148 U0)^0.5 (ISO 19901-1, DNV-RP-C205, NPD)
  api_rp_2a,    ///< C = 5.73e-2 (1 + 0.14994 U0)^0.5 (API RP 2A, converted from feet)
};

struct WindProfileInput {
  double U0_m_per_s = 0.0;           ///< 1-hour mean wind speed at 10 m, >= 0
  double height_m = 10.0;            ///< z > 0 above mean water level
  double averaging_time_s = 3600.0;  ///< t, 0 < t <= 3600 s (gust factor for t < 3600 s)
  WindProfileStandard standard = WindProfileStandard::iso_19901_1;
};

/// Profile coefficient C (dimensionless) for U0 (m/s).
double wind_profile_coefficient(double U0_m_per_s, WindProfileStandard standard);

/// NPD turbulence intensity I_u(z) = 0.06 (1 + 0.043 U0) (z/10)^-0.22.
double npd_turbulence_intensity(double U0_m_per_s, double height_m);

/// U(z, t): t-averaged mean wind speed at height z, m/s.
double mean_wind_speed_m_per_s(const WindProfileInput& input);

struct NpdSpectrumInput {
  double U0_m_per_s = 0.0;  ///< 1-hour mean at 10 m, > 0
  double height_m = 10.0;   ///< z > 0
};

/// NPD spectral density at f (Hz) in m^2/s^2/Hz; 0 for f <= 0.
double npd_wind_spectrum(const NpdSpectrumInput& input, double frequency_Hz);

/// Closed-form variance of the NPD spectrum, m^2/s^2 (see header comment).
double npd_wind_variance_m2_per_s2(const NpdSpectrumInput& input);

struct ApiSpectrumInput {
  double mean_speed_m_per_s = 0.0;  ///< U(z), > 0
  double height_m = 10.0;           ///< z > 0
  double sigma_m_per_s = 0.0;       ///< standard deviation of the gust, >= 0
  double a = 0.025;                 ///< peak parameter, 0.01..0.1 (API)
};

/// API turbulence intensity I(z) (0.15 at zs = 20 m, see header).
double api_turbulence_intensity(double height_m);

/// API spectral density at f (Hz) in m^2/s^2/Hz; 0 for f <= 0.
double api_wind_spectrum(const ApiSpectrumInput& input, double frequency_Hz);

}  // namespace spiral::engine
