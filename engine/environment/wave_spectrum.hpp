#pragma once
// One-sided wave energy spectra and directional spreading.
//
// Spectra (DNV-RP-C205 (2010 and later editions), §3.5.5):
//   Pierson-Moskowitz (eq. 3.5.5.1):
//     S_PM(w) = 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (w/wp)^-4)
//   JONSWAP (§3.5.5.2):
//     S_J(w) = A_g S_PM(w) g^exp(-(w - wp)^2 / (2 s^2 wp^2)),
//     A_g = 1 - 0.287 ln(g) (normalising factor), s = 0.07 (w <= wp), 0.09 (w > wp).
//   gamma = 1 gives Pierson-Moskowitz exactly.
//   Default peak-shape parameter (DNV-RP-C205 §3.5.5.5; identical to OpenFAST
//   Waves.f90 WavePkShpDefault and RAFT helpers.py, shared/data/reference-platforms.md §2.6):
//     g = 5 for Tp/sqrt(Hs) <= 3.6; exp(5.75 - 1.15 Tp/sqrt(Hs)) for 3.6 < Tp/sqrt(Hs) < 5;
//     1 for Tp/sqrt(Hs) >= 5 (Tp in s, Hs in m: the ratio is dimensional).
//   With A_g the JONSWAP m0 equals Hs^2/16 only approximately (DNV: "approximately");
//   spectral_moments() reports the m0 actually obtained.
//
// Units: w (omega) in rad/s, S in m^2 s/rad (one-sided: variance = int_0^inf S dw).
//
// Directional spreading (DNV-RP-C205 §3.5.8), directions are directions of
// propagation (DESIGN.md §4), theta measured from the mean direction theta_p:
//   cos_2s (Longuet-Higgins cos-2s, full circle, §3.5.8.6):
//     D(t) = Gamma(s+1) / (2 sqrt(pi) Gamma(s+1/2)) cos^(2s)((t - tp)/2),  |t - tp| <= pi
//   cos_power (cos^n, half circle, §3.5.8.4; OpenFAST WaveDirSpread, OrcaFlex spreading exponent):
//     D(t) = Gamma(1+n/2) / (sqrt(pi) Gamma(1/2+n/2)) cos^n(t - tp),   |t - tp| <= pi/2
//   Both integrate to 1 over their support. (DNV paragraph numbers are recalled,
//   not re-read; the formulas are checked by the normalisation tests.)
//
// Errors: std::invalid_argument naming the quantity and its unit.

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace spiral::engine {

/// A validated one-sided JONSWAP spectrum (gamma = 1: Pierson-Moskowitz).
/// Build it with make_jonswap_spectrum / make_pierson_moskowitz_spectrum.
struct WaveSpectrum {
  double Hs_m = 0.0;              ///< significant wave height (spectral, 4 sqrt(m0) nominal), > 0
  double Tp_s = 0.0;              ///< peak period, > 0
  double gamma = 1.0;             ///< peak-shape (enhancement) factor, >= 1
  double sigma_below = 0.07;      ///< spectral width parameter for w <= wp
  double sigma_above = 0.09;      ///< spectral width parameter for w > wp
  double peak_rad_per_s() const;  ///< wp = 2 pi / Tp
};

/// DNV-RP-C205 §3.5.5.5 default gamma from Hs (m) and Tp (s); validates both > 0.
double default_jonswap_gamma(double Hs_m, double Tp_s);

struct JonswapInput {
  double Hs_m = 0.0;            ///< > 0
  double Tp_s = 0.0;            ///< > 0
  std::optional<double> gamma;  ///< >= 1; empty selects default_jonswap_gamma(Hs, Tp)
};

/// Validates Hs > 0 m, Tp > 0 s, gamma >= 1 (if given); throws std::invalid_argument.
WaveSpectrum make_jonswap_spectrum(const JonswapInput& input);
/// Pierson-Moskowitz = JONSWAP with gamma = 1. Validates Hs > 0 m, Tp > 0 s.
WaveSpectrum make_pierson_moskowitz_spectrum(double Hs_m, double Tp_s);

/// S(w) in m^2 s/rad; 0 for w <= 0 and where the exponential underflows.
double spectral_density_m2s_per_rad(const WaveSpectrum& spectrum, double omega_rad_per_s);

/// Quadrature of integrals int_0^inf f(w) S(w) dw:
///   ~ sum_i weight_m2[i] f(omega[i]) + f(tail_start) tail_m0_m2     (f slowly varying in the tail)
/// weight_m2[i] = S(omega[i]) x composite-Simpson weight on [0, tail_start];
/// beyond tail_start the spectrum is its w^-5 tail (exp and gamma factors -> 1 there:
/// relative error ~1.25 (wp/W)^4 = 1.25e-4 of the tail for W = 10 wp), so
/// int_W^inf w^n S dw = S(W) W^(n+1) / (4 - n) exactly for a pure w^-5 tail.
struct SpectrumQuadrature {
  Eigen::VectorXd omega_rad_per_s;
  Eigen::VectorXd weight_m2;  ///< variance carried by each node, m^2
  double tail_start_rad_per_s = 0.0;
  double tail_density_m2s_per_rad = 0.0;  ///< S(tail_start)
  double tail_m0_m2 = 0.0;                ///< int_W^inf S dw = S(W) W / 4
};

struct SpectrumQuadratureOptions {
  double upper_limit_over_peak = 10.0;     ///< W = this x wp (and at least `min_upper_limit`), > 1
  double min_upper_limit_rad_per_s = 0.0;  ///< raise W to cover e.g. a coefficient table
  int intervals = 4000;                    ///< Simpson intervals on [0, W], even, >= 2
};

SpectrumQuadrature spectrum_quadrature(const WaveSpectrum& spectrum, const SpectrumQuadratureOptions& options = {});

/// Spectral moments m_n = int_0^inf w^n S dw (n = 0, 1, 2) and derived periods.
struct SpectralMoments {
  double m0_m2 = 0.0;
  double m1_m2_per_s = 0.0;
  double m2_m2_per_s2 = 0.0;
  double Hm0_m = 0.0;                ///< 4 sqrt(m0)
  double Tz_s = 0.0;                 ///< mean zero-up-crossing period 2 pi sqrt(m0/m2) (DNV-RP-C205 §3.5.5.4)
  double Tm01_s = 0.0;               ///< mean period 2 pi m0/m1
  double tail_fraction_of_m0 = 0.0;  ///< share of m0 in the analytic tail beyond W
};

SpectralMoments spectral_moments(const WaveSpectrum& spectrum, const SpectrumQuadratureOptions& options = {});

enum class SpreadingForm {
  cos_2s,     ///< D ~ cos^(2s)(theta/2), support |theta| <= pi; exponent = s
  cos_power,  ///< D ~ cos^n(theta), support |theta| <= pi/2; exponent = n
};

struct DirectionalSpreading {
  SpreadingForm form = SpreadingForm::cos_2s;
  double exponent = 0.0;  ///< s (cos_2s) or n (cos_power), >= 0 (0: uniform over the support)
};

/// D(theta) in 1/rad for the deviation theta (rad) from the mean direction,
/// wrapped to (-pi, pi]; 0 outside the support. Throws for exponent < 0.
double spreading_density_per_rad(const DirectionalSpreading& spreading, double deviation_rad);

struct SpreadingDirection {
  double heading_rad = 0.0;  ///< direction of propagation, global, CCW from +x
  double weight = 0.0;       ///< share of the wave variance, sum over directions = 1
};

/// N equal-width bins over the support, centred on mean_heading_rad (odd N puts
/// a direction on the mean). weight = int of D over the bin (16-panel Simpson
/// per bin), so the weights sum to 1 to quadrature accuracy (not renormalised).
/// Throws std::invalid_argument for N < 1.
std::vector<SpreadingDirection> discretise_spreading(const DirectionalSpreading& spreading, double mean_heading_rad,
                                                     int count);

}  // namespace spiral::engine
