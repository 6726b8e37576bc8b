#pragma once
// Statistics and extremes of one time-series channel (offset, tension, …):
// moments, Welch spectrum, zero up-crossing period, cycle maxima and the most
// probable maximum (MPM) for a target duration (default 3 h) by three
// estimators that the results store reports side by side.
//
// Conventions.
//   * A channel is uniformly sampled at dt_s (s); its unit is "unit".
//   * Spectrum: one-sided, angular frequency w in rad/s, density in unit²·s/rad,
//     so that the variance is int_0^inf S(w) dw (the convention of
//     engine/environment/wave_spectrum.hpp and DNV-RP-C205).
//   * Extremes are of the *maximum*; for the minimum pass the negated channel.
//   * Up-crossings, peaks and the Weibull excess are relative to the sample mean.
//
// Extreme-value approach (DNV-OS-E301 Ch.2 Sec.2 and DNV-RP-C205 §3.7 on
// short-term extremes, as recalled, clause numbers not re-read): the
// design value is the MPM of the maximum in a 3-hour sea state, estimated
// from the simulated response by fitting an extreme-value distribution.
//   (a) Gumbel: the record is cut into n equal segments of length T_s; their
//       maxima are fitted with F(x) = exp(−exp(−(x − u)/b)) by the method of
//       moments: b = s·sqrt(6)/pi, u = mean − gamma_E·b (gamma_E = 0.5772…).
//       The Gumbel family is max-stable, so the maximum over T = k·T_s is
//       Gumbel with the same b and u_T = u + b ln(T/T_s); its mode — the MPM —
//       is u_T.
//   (b) Weibull: the global peaks (largest value between successive zero
//       up-crossings) minus the mean, x > 0, fitted with a 2-parameter
//       Weibull F(x) = 1 − exp(−(x/a)^c) by least squares on the Weibull plot
//       ln(−ln(1 − F_i)) = c ln x_(i) − c ln a, plotting positions
//       F_i = i/(n + 1), over the upper part of the sample only (F_i >= 1 −
//       upper_fraction, default the upper half): the extreme is a tail
//       property, and the smallest peaks (small cycles riding on larger ones
//       in a finite-bandwidth process) have a large leverage in ln–ln
//       coordinates — fitted over all peaks of a Gaussian process the shape
//       came out 1.7 instead of 2 and the MPM 20 % high (statistics_test).
//       For N = n_peaks·T/T_record expected peaks in the
//       target duration, MPM = mean + a (ln N)^(1/c), the value exceeded by
//       one peak on average (1 − F = 1/N), the asymptotic mode of the
//       maximum of N independent peaks.
//   (c) Rayleigh (Gaussian process check): MPM = mean + sigma sqrt(2 ln N),
//       N = T/T_z (Cartwright & Longuet-Higgins 1956: with N counted by zero
//       up-crossings this holds for any bandwidth, asymptotically in N).
//
// Errors: std::invalid_argument for too short a record (named minimum),
// non-finite samples or non-positive dt / durations.

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

namespace spiral::engine {

struct ChannelMoments {
  double mean = 0.0;
  double std_dev = 0.0;  ///< population (1/n) standard deviation
  double minimum = 0.0;
  double maximum = 0.0;
  double skewness = 0.0;  ///< m3 / m2^1.5 (0 for a Gaussian process)
  double kurtosis = 0.0;  ///< m4 / m2² (3 for a Gaussian process; not the excess)
  std::size_t samples = 0;
};

/// Moments of a channel (>= 2 samples, not constant for skewness/kurtosis:
/// a constant channel gives skewness 0 and kurtosis 0).
ChannelMoments channel_moments(std::span<const double> x);

struct Spectrum {
  Eigen::VectorXd frequency_rad_s;  ///< 0, dw, 2dw, … up to the Nyquist frequency
  Eigen::VectorXd density;          ///< one-sided S(w), unit²·s/rad
  double frequency_step_rad_s = 0.0;
  std::size_t segments = 0;  ///< Welch segments averaged
};

/// Welch estimate: Hann-windowed segments of segment_length samples with 50 %
/// overlap, each with its mean removed, |FFT|² averaged and scaled by
/// 1/(fs·sum w²) so that the sum S·dw over the bins equals the mean windowed
/// variance (Welch 1967). segment_length >= 16 and <= x.size(). The frequency
/// resolution is dw = 2 pi/(segment_length dt); the estimate's relative
/// standard error is about 1/sqrt(segments·~1.9) (Hann, 50 % overlap).
Spectrum welch_spectrum(std::span<const double> x, double dt_s, std::size_t segment_length);

/// Zero-phase low-pass of a uniformly sampled record by the DFT: the straight
/// line through the first and last samples is removed (the periodic extension
/// then has no jump), every bin above cutoff_rad_s is zeroed, the line is
/// added back. A brick wall rings near the cut (Gibbs): put the cut well away
/// from the band to remove. x.size() >= 2, dt_s > 0, cutoff_rad_s > 0 (else
/// std::invalid_argument).
std::vector<double> low_pass_dft(std::span<const double> x, double dt_s, double cutoff_rad_s);

/// Variance from a spectrum: sum S(w_k) dw (rectangle rule over the bins).
double spectrum_variance(const Spectrum& s);

/// 2 pi / w at the largest density (excluding w = 0), s.
double spectral_peak_period_s(const Spectrum& s);

/// Zero up-crossings about `level`: crossing times (s from the first sample,
/// linearly interpolated) in order.
std::vector<double> upcrossing_times_s(std::span<const double> x, double dt_s, double level);

/// Mean zero up-crossing period about the mean: (t_last − t_first)/(n − 1)
/// over the up-crossings; throws if fewer than 2 up-crossings.
double zero_upcrossing_period_s(std::span<const double> x, double dt_s);

/// Global peaks: the largest sample between each pair of successive
/// up-crossings of `level` (one per cycle).
std::vector<double> cycle_maxima(std::span<const double> x, double level);

struct GumbelFit {
  double location = 0.0;  ///< u (mode), unit
  double scale = 0.0;     ///< b > 0, unit
};

/// Method of moments (>= 2 samples, not all equal).
GumbelFit fit_gumbel_moments(std::span<const double> maxima);

struct WeibullFit {
  double scale = 0.0;  ///< a, unit
  double shape = 0.0;  ///< c (2 = Rayleigh)
};

/// 2-parameter Weibull on positive excesses by least squares on the Weibull
/// plot; the non-positive values are dropped; only the ranked samples with
/// plotting position F_i >= 1 − upper_fraction (0 < upper_fraction <= 1)
/// enter the fit (>= 3 of them).
WeibullFit fit_weibull_least_squares(std::span<const double> excess, double upper_fraction = 1.0);

struct ExtremeOptions {
  double target_duration_s = 10800.0;   ///< 3 h sea state
  std::size_t gumbel_segments = 10;     ///< equal segments for the Gumbel fit (>= 2)
  double weibull_upper_fraction = 0.5;  ///< part of the ranked peaks in the Weibull fit
};

struct ExtremeEstimate {
  double record_duration_s = 0.0;
  std::size_t peaks = 0;                   ///< global peaks in the record
  double expected_peaks_in_target = 0.0;   ///< N for Weibull
  double expected_cycles_in_target = 0.0;  ///< T/T_z for Rayleigh
  GumbelFit gumbel;                        ///< fit to the segment maxima
  WeibullFit weibull;                      ///< fit to the peak excesses over the mean
  double mpm_gumbel = 0.0;                 ///< unit
  double mpm_weibull = 0.0;                ///< unit
  double mpm_rayleigh = 0.0;               ///< unit
};

/// The three MPM estimates of the channel maximum over the target duration.
ExtremeEstimate most_probable_maximum(std::span<const double> x, double dt_s, const ExtremeOptions& options = {});

/// Everything the results store keeps per channel.
struct ChannelStatistics {
  ChannelMoments moments;
  Spectrum spectrum;
  double spectral_peak_period_s = 0.0;
  double zero_upcrossing_period_s = 0.0;
  ExtremeEstimate maximum;
  ExtremeEstimate minimum;  ///< of −x, reported with the sign restored (MPM minima)
};

/// Moments, Welch spectrum (segment_length samples), periods and extremes.
ChannelStatistics analyze_channel(std::span<const double> x, double dt_s, std::size_t welch_segment_length,
                                  const ExtremeOptions& options = {});

/// Welch segment length for a record of `samples` samples: the largest power
/// of two <= samples/8 (>= 8 segments averaged with 50 % overlap, ~15 for a
/// full record), at least 16 samples (and at most `samples`).
std::size_t welch_segment_length(std::size_t samples);

/// Last bin of a Welch spectrum that matters: the bins above it hold at most
/// 1e-6 of the variance (the Nyquist tail of a 0.5 s record is noise).
Eigen::Index spectrum_last_significant_bin(const Spectrum& spectrum);

}  // namespace spiral::engine
