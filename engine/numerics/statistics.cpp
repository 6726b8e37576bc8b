#include "engine/numerics/statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <unsupported/Eigen/FFT>

namespace spiral::engine {
namespace {

constexpr double kEulerGamma = 0.57721566490153286;

void require_samples(std::span<const double> x, std::size_t minimum, const char* what) {
  if (x.size() < minimum) {
    throw std::invalid_argument(fmt::format("{}: need at least {} samples, got {}", what, minimum, x.size()));
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw std::invalid_argument(fmt::format("{}: sample {} is not finite", what, i));
    }
  }
}

void require_dt(double dt_s, const char* what) {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) {
    throw std::invalid_argument(fmt::format("{}: dt must be > 0 s, got {} s", what, dt_s));
  }
}

double mean_of(std::span<const double> x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

}  // namespace

ChannelMoments channel_moments(std::span<const double> x) {
  require_samples(x, 2, "channel_moments");
  ChannelMoments m;
  m.samples = x.size();
  m.mean = mean_of(x);
  m.minimum = *std::min_element(x.begin(), x.end());
  m.maximum = *std::max_element(x.begin(), x.end());
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (double v : x) {
    const double d = v - m.mean;
    const double d2 = d * d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
  }
  const double n = static_cast<double>(x.size());
  m2 /= n;
  m3 /= n;
  m4 /= n;
  m.std_dev = std::sqrt(m2);
  if (m2 > 0.0) {
    m.skewness = m3 / std::pow(m2, 1.5);
    m.kurtosis = m4 / (m2 * m2);
  }
  return m;
}

Spectrum welch_spectrum(std::span<const double> x, double dt_s, std::size_t L) {
  require_dt(dt_s, "welch_spectrum");
  if (L < 16) {
    throw std::invalid_argument(fmt::format("welch_spectrum: segment_length must be >= 16 samples, got {}", L));
  }
  require_samples(x, L, "welch_spectrum (segment_length)");
  // Hann window (periodic form, exact 50 % overlap-add), Welch (1967).
  std::vector<double> w(L);
  double sum_w2 = 0.0;
  for (std::size_t i = 0; i < L; ++i) {
    w[i] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(L)));
    sum_w2 += w[i] * w[i];
  }
  const std::size_t hop = L / 2;
  const std::size_t n_seg = (x.size() - L) / hop + 1;
  const std::size_t n_bins = L / 2 + 1;
  Eigen::VectorXd power = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n_bins));
  Eigen::FFT<double> fft;
  std::vector<double> segment(L);
  std::vector<std::complex<double>> spectrum;
  for (std::size_t s = 0; s < n_seg; ++s) {
    const auto part = x.subspan(s * hop, L);
    const double mu = mean_of(part);
    for (std::size_t i = 0; i < L; ++i) segment[i] = (part[i] - mu) * w[i];
    fft.fwd(spectrum, segment);
    for (std::size_t k = 0; k < n_bins; ++k) power(static_cast<Eigen::Index>(k)) += std::norm(spectrum[k]);
  }
  // Two-sided P(f_k) = |X_k|² / (fs sum w²); one-sided doubles every bin but
  // DC and (even L) Nyquist; S(w) = P(f)/(2 pi).
  const double fs = 1.0 / dt_s;
  power /= static_cast<double>(n_seg) * fs * sum_w2 * 2.0 * std::numbers::pi;
  for (std::size_t k = 1; k < n_bins; ++k) {
    if (!(L % 2 == 0 && k == L / 2)) power(static_cast<Eigen::Index>(k)) *= 2.0;
  }
  Spectrum out;
  out.frequency_step_rad_s = 2.0 * std::numbers::pi / (static_cast<double>(L) * dt_s);
  out.frequency_rad_s = Eigen::VectorXd::LinSpaced(static_cast<Eigen::Index>(n_bins), 0.0,
                                                   out.frequency_step_rad_s * static_cast<double>(n_bins - 1));
  out.density = power;
  out.segments = n_seg;
  return out;
}

std::vector<double> low_pass_dft(std::span<const double> x, double dt_s, double cutoff_rad_s) {
  if (x.size() < 2 || !(dt_s > 0.0) || !(cutoff_rad_s > 0.0)) {
    throw std::invalid_argument(
        fmt::format("low_pass_dft: need >= 2 samples, dt > 0 s and a cut-off > 0 rad/s; got {}, {} s, {} "
                    "rad/s",
                    x.size(), dt_s, cutoff_rad_s));
  }
  const std::size_t n = x.size();
  const double slope = (x.back() - x.front()) / static_cast<double>(n - 1);
  std::vector<double> detrended(n);
  for (std::size_t i = 0; i < n; ++i) detrended[i] = x[i] - x.front() - slope * static_cast<double>(i);
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, detrended);
  const double dw = 2.0 * std::numbers::pi / (static_cast<double>(n) * dt_s);
  for (std::size_t k = 0; k < spectrum.size(); ++k) {
    if (static_cast<double>(k) * dw > cutoff_rad_s) spectrum[k] = 0.0;
  }
  std::vector<double> out;
  fft.inv(out, spectrum, n);
  for (std::size_t i = 0; i < n; ++i) out[i] += x.front() + slope * static_cast<double>(i);
  return out;
}

double spectrum_variance(const Spectrum& s) { return s.density.sum() * s.frequency_step_rad_s; }

double spectral_peak_period_s(const Spectrum& s) {
  if (s.density.size() < 2) throw std::invalid_argument("spectral_peak_period_s: empty spectrum");
  Eigen::Index k = 0;
  s.density.tail(s.density.size() - 1).maxCoeff(&k);
  return 2.0 * std::numbers::pi / s.frequency_rad_s(k + 1);
}

std::vector<double> upcrossing_times_s(std::span<const double> x, double dt_s, double level) {
  require_dt(dt_s, "upcrossing_times_s");
  std::vector<double> t;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    if (x[i] < level && x[i + 1] >= level) {
      const double frac = (level - x[i]) / (x[i + 1] - x[i]);
      t.push_back((static_cast<double>(i) + frac) * dt_s);
    }
  }
  return t;
}

double zero_upcrossing_period_s(std::span<const double> x, double dt_s) {
  require_samples(x, 3, "zero_upcrossing_period_s");
  const auto t = upcrossing_times_s(x, dt_s, mean_of(x));
  if (t.size() < 2) {
    throw std::invalid_argument(fmt::format("zero_upcrossing_period_s: need >= 2 mean up-crossings, found {} in {} s",
                                            t.size(), static_cast<double>(x.size()) * dt_s));
  }
  return (t.back() - t.front()) / static_cast<double>(t.size() - 1);
}

std::vector<double> cycle_maxima(std::span<const double> x, double level) {
  std::vector<double> peaks;
  bool in_cycle = false;
  double current = 0.0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    if (x[i] < level && x[i + 1] >= level) {  // up-crossing between i and i+1
      if (in_cycle) peaks.push_back(current);
      in_cycle = true;
      current = x[i + 1];
    } else if (in_cycle) {
      current = std::max(current, x[i + 1]);
    }
  }
  return peaks;  // the cycle still open at the end is incomplete: not counted
}

GumbelFit fit_gumbel_moments(std::span<const double> maxima) {
  require_samples(maxima, 2, "fit_gumbel_moments");
  const double m = mean_of(maxima);
  double var = 0.0;
  for (double v : maxima) var += (v - m) * (v - m);
  var /= static_cast<double>(maxima.size() - 1);  // unbiased sample variance
  if (!(var > 0.0)) throw std::invalid_argument("fit_gumbel_moments: all maxima are equal");
  GumbelFit g;
  g.scale = std::sqrt(6.0 * var) / std::numbers::pi;
  g.location = m - kEulerGamma * g.scale;
  return g;
}

WeibullFit fit_weibull_least_squares(std::span<const double> excess, double upper_fraction) {
  if (!(upper_fraction > 0.0 && upper_fraction <= 1.0)) {
    throw std::invalid_argument(
        fmt::format("fit_weibull_least_squares: upper_fraction must be in (0, 1], got {}", upper_fraction));
  }
  std::vector<double> x;
  x.reserve(excess.size());
  for (double v : excess) {
    if (v > 0.0 && std::isfinite(v)) x.push_back(v);
  }
  if (x.size() < 3) {
    throw std::invalid_argument(
        fmt::format("fit_weibull_least_squares: need >= 3 positive excesses, got {}", x.size()));
  }
  std::sort(x.begin(), x.end());
  const double n_all = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double F = static_cast<double>(i + 1) / (n_all + 1.0);
    if (F < 1.0 - upper_fraction) continue;
    n += 1.0;
    const double X = std::log(x[i]);
    const double Y = std::log(-std::log(1.0 - F));
    sx += X;
    sy += Y;
    sxx += X * X;
    sxy += X * Y;
  }
  if (n < 3.0) {
    throw std::invalid_argument(fmt::format(
        "fit_weibull_least_squares: need >= 3 samples in the fitted upper fraction {}, got {}", upper_fraction, n));
  }
  const double denom = n * sxx - sx * sx;
  if (!(denom > 0.0)) throw std::invalid_argument("fit_weibull_least_squares: all excesses equal");
  const double c = (n * sxy - sx * sy) / denom;  // slope
  const double intercept = (sy - c * sx) / n;    // = −c ln a
  return WeibullFit{std::exp(-intercept / c), c};
}

ExtremeEstimate most_probable_maximum(std::span<const double> x, double dt_s, const ExtremeOptions& options) {
  require_dt(dt_s, "most_probable_maximum");
  if (options.gumbel_segments < 2) {
    throw std::invalid_argument(
        fmt::format("most_probable_maximum: gumbel_segments must be >= 2, got {}", options.gumbel_segments));
  }
  if (!(options.target_duration_s > 0.0)) {
    throw std::invalid_argument(
        fmt::format("most_probable_maximum: target_duration_s must be > 0 s, got {} s", options.target_duration_s));
  }
  require_samples(x, 8 * options.gumbel_segments, "most_probable_maximum");
  const ChannelMoments mom = channel_moments(x);
  ExtremeEstimate e;
  e.record_duration_s = static_cast<double>(x.size()) * dt_s;

  // (a) Gumbel on equal-segment maxima, extrapolated by max-stability.
  const std::size_t seg_len = x.size() / options.gumbel_segments;
  std::vector<double> seg_max(options.gumbel_segments);
  for (std::size_t s = 0; s < options.gumbel_segments; ++s) {
    const auto part = x.subspan(s * seg_len, seg_len);
    seg_max[s] = *std::max_element(part.begin(), part.end());
  }
  e.gumbel = fit_gumbel_moments(seg_max);
  const double seg_duration_s = static_cast<double>(seg_len) * dt_s;
  e.mpm_gumbel = e.gumbel.location + e.gumbel.scale * std::log(options.target_duration_s / seg_duration_s);

  // (b) Weibull on the global-peak excesses over the mean.
  const auto peaks = cycle_maxima(x, mom.mean);
  e.peaks = peaks.size();
  std::vector<double> excess(peaks.size());
  for (std::size_t i = 0; i < peaks.size(); ++i) excess[i] = peaks[i] - mom.mean;
  e.weibull = fit_weibull_least_squares(excess, options.weibull_upper_fraction);
  e.expected_peaks_in_target = static_cast<double>(peaks.size()) * options.target_duration_s / e.record_duration_s;
  if (!(e.expected_peaks_in_target > 1.0)) {
    throw std::invalid_argument("most_probable_maximum: fewer than 1 expected peak in the target");
  }
  e.mpm_weibull = mom.mean + e.weibull.scale * std::pow(std::log(e.expected_peaks_in_target), 1.0 / e.weibull.shape);

  // (c) Rayleigh check for a Gaussian process.
  const double Tz = zero_upcrossing_period_s(x, dt_s);
  e.expected_cycles_in_target = options.target_duration_s / Tz;
  e.mpm_rayleigh = mom.mean + mom.std_dev * std::sqrt(2.0 * std::log(std::max(e.expected_cycles_in_target, 1.0)));
  return e;
}

ChannelStatistics analyze_channel(std::span<const double> x, double dt_s, std::size_t welch_segment_length,
                                  const ExtremeOptions& options) {
  ChannelStatistics c;
  c.moments = channel_moments(x);
  c.spectrum = welch_spectrum(x, dt_s, welch_segment_length);
  c.spectral_peak_period_s = spectral_peak_period_s(c.spectrum);
  c.zero_upcrossing_period_s = zero_upcrossing_period_s(x, dt_s);
  c.maximum = most_probable_maximum(x, dt_s, options);
  std::vector<double> negated(x.size());
  std::transform(x.begin(), x.end(), negated.begin(), [](double v) { return -v; });
  c.minimum = most_probable_maximum(negated, dt_s, options);
  c.minimum.mpm_gumbel = -c.minimum.mpm_gumbel;
  c.minimum.mpm_weibull = -c.minimum.mpm_weibull;
  c.minimum.mpm_rayleigh = -c.minimum.mpm_rayleigh;
  return c;
}

Eigen::Index spectrum_last_significant_bin(const Spectrum& sp) {
  double total = 0.0;
  for (Eigen::Index k = 0; k < sp.density.size(); ++k) total += sp.density(k);
  Eigen::Index last = sp.density.size() - 1;
  for (double tail = 0.0; last > 1 && tail + sp.density(last) <= 1e-6 * total; --last) tail += sp.density(last);
  return last;
}

std::size_t welch_segment_length(std::size_t n) {
  std::size_t s = 16;
  while (s * 2 <= n / 8) s *= 2;
  return std::min(s, n);
}

}  // namespace spiral::engine
