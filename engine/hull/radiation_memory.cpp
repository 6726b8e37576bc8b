#include "engine/hull/radiation_memory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/common/dof_names.hpp"

namespace spiral::engine {
namespace {

constexpr std::size_t kMinimumFrequencies = 8;

/// int_a^b (K_a + s (t − a)) f(w t) dt for f = cos or sin, exact (integration
/// by parts), summed over the kernel's intervals.
Matrix6d kernel_transform(const RetardationKernel& kernel, double w, bool cosine) {
  const double dt = kernel.time_step_s;
  const Eigen::Index n = kernel.size();
  Eigen::Matrix<double, 36, 1> sum = Eigen::Matrix<double, 36, 1>::Zero();
  for (Eigen::Index j = 0; j + 1 < n; ++j) {
    const double a = static_cast<double>(j) * dt;
    const double b = a + dt;
    const auto Ka = kernel.values.col(j);
    const auto Kb = kernel.values.col(j + 1);
    if (w == 0.0) {
      if (cosine) sum += 0.5 * dt * (Ka + Kb);
      continue;
    }
    const Eigen::Matrix<double, 36, 1> slope = (Kb - Ka) / dt;
    const double ca = std::cos(w * a), cb = std::cos(w * b);
    const double sa = std::sin(w * a), sb = std::sin(w * b);
    if (cosine) {
      // int K cos = [K sin/w + K' cos/w^2]
      sum += (Kb * sb - Ka * sa) / w + slope * ((cb - ca) / (w * w));
    } else {
      // int K sin = [−K cos/w + K' sin/w^2]
      sum += (Ka * ca - Kb * cb) / w + slope * ((sb - sa) / (w * w));
    }
  }
  return Eigen::Map<const Matrix6d>(sum.data());
}

}  // namespace

Matrix6d kernel_cosine_transform(const RetardationKernel& kernel, double omega_rad_per_s) {
  return kernel_transform(kernel, omega_rad_per_s, true);
}

Matrix6d kernel_sine_transform(const RetardationKernel& kernel, double omega_rad_per_s) {
  if (!(omega_rad_per_s > 0.0)) {
    throw std::invalid_argument(fmt::format("kernel_sine_transform: need w > 0 rad/s, got {}", omega_rad_per_s));
  }
  return kernel_transform(kernel, omega_rad_per_s, false);
}

RadiationMemory make_radiation_memory(const HydroCoefficients& r, const RadiationMemoryInput& input) {
  if (!(input.time_step_s > 0.0) || !(input.duration_s > input.time_step_s) || !(input.tail_ratio_limit > 0.0)) {
    throw std::invalid_argument(
        fmt::format("radiation memory: need time step > 0 s, duration > time step and a tail ratio > 0; got "
                    "{} s, {} s, {}",
                    input.time_step_s, input.duration_s, input.tail_ratio_limit));
  }
  const std::vector<double>& w = r.omega_rad_per_s;
  if (w.size() < kMinimumFrequencies || r.damping.size() != w.size() || r.added_mass.size() != w.size()) {
    throw RadiationDataError(
        fmt::format("{}: a radiation memory needs A(w) and B(w) at >= {} frequencies, the file has {}", r.file,
                    kMinimumFrequencies, w.size()));
  }

  RadiationMemory out;
  // Both ends of B(w) must have decayed (header comment).
  for (int d = 0; d < 6; ++d) {
    double peak = 0.0;
    for (const Matrix6d& B : r.damping) peak = std::max(peak, std::abs(B(d, d)));
    if (peak == 0.0) continue;
    const double first = std::abs(r.damping.front()(d, d)) / peak;
    const double last = std::abs(r.damping.back()(d, d)) / peak;
    out.tail_ratio(d) = std::max(first, last);
    for (const bool high : {true, false}) {
      const double ratio = high ? last : first;
      if (ratio <= input.tail_ratio_limit) continue;
      throw RadiationDataError(fmt::format(
          "{}: {} radiation damping B at the {} frequency {:.4g} rad/s is {:.1f} % of its peak "
          "(limit {:.1f} %): the table {}, so the retardation kernel K(t) = "
          "(2/pi) int B cos(wt) dw cannot be built; give a .1 file reaching {} frequencies, or "
          "use radiation: low_frequency",
          r.file, kDofNames[d], high ? "highest" : "lowest", high ? w.back() : w.front(), 100.0 * ratio,
          100.0 * input.tail_ratio_limit, high ? "stops before B(w) has decayed" : "starts after B(w) has risen",
          high ? "higher" : "lower"));
    }
  }
  // Grid spacing against the kernel duration.
  double max_dw = w.front();  // the interval [0, w_0] is part of the grid
  for (std::size_t i = 1; i < w.size(); ++i) max_dw = std::max(max_dw, w[i] - w[i - 1]);
  if (input.duration_s > std::numbers::pi / max_dw) {
    throw RadiationDataError(
        fmt::format("{}: the frequency spacing (largest step {:.4g} rad/s, including 0 to the first "
                    "frequency) resolves a retardation kernel of at most pi/dw = {:.3g} s, shorter than the "
                    "kernel duration {:.3g} s: give a finer .1 table or a shorter memory_duration",
                    r.file, max_dw, std::numbers::pi / max_dw, input.duration_s));
  }

  // K(t) with B(0) = 0 prepended (a floating body radiates nothing at w = 0).
  std::vector<double> frequencies;
  std::vector<Matrix6d> damping;
  frequencies.reserve(w.size() + 1);
  damping.reserve(w.size() + 1);
  if (w.front() > 0.0) {
    frequencies.push_back(0.0);
    damping.push_back(Matrix6d::Zero());
  }
  frequencies.insert(frequencies.end(), w.begin(), w.end());
  damping.insert(damping.end(), r.damping.begin(), r.damping.end());
  out.kernel = make_retardation_kernel(frequencies, damping, input.time_step_s, input.duration_s);

  // A(inf): the file's row, else Ogilvie's relation averaged over the band.
  const double t_max = out.kernel.duration_s();
  out.ogilvie_omega_min_rad_per_s = 2.0 * std::numbers::pi / t_max;
  std::vector<std::size_t> band;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (w[i] >= out.ogilvie_omega_min_rad_per_s) band.push_back(i);
  }
  out.ogilvie_frequencies = band.size();
  std::vector<Matrix6d> estimates;
  estimates.reserve(band.size());
  for (const std::size_t i : band) {
    estimates.push_back(r.added_mass[i] + kernel_sine_transform(out.kernel, w[i]) / w[i]);
  }
  if (r.added_mass_infinite) {
    out.added_mass_infinite = *r.added_mass_infinite;
    out.added_mass_infinite_from_file = true;
  } else {
    if (band.size() < 2) {
      throw RadiationDataError(
          fmt::format("{}: no infinite-frequency (PER = 0) row, and fewer than 2 frequencies above 2 pi / "
                      "t_max = {:.3g} rad/s to estimate A(inf) from Ogilvie's relation",
                      r.file, out.ogilvie_omega_min_rad_per_s));
    }
    Matrix6d sum = Matrix6d::Zero();
    for (const Matrix6d& e : estimates) sum += e;
    out.added_mass_infinite = sum / static_cast<double>(estimates.size());
  }
  for (int d = 0; d < 6; ++d) {
    const double scale = std::abs(out.added_mass_infinite(d, d));
    if (scale == 0.0) continue;
    for (const Matrix6d& e : estimates) {
      out.ogilvie_max_deviation(d) =
          std::max(out.ogilvie_max_deviation(d), std::abs(e(d, d) - out.added_mass_infinite(d, d)) / scale);
    }
  }
  return out;
}

}  // namespace spiral::engine
