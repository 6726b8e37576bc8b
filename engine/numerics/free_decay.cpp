#include "engine/numerics/free_decay.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>

namespace spiral::engine {

std::vector<DecayHalfCycle> free_decay_half_cycles(std::span<const double> time_s, std::span<const double> x,
                                                   double final_position, double start_s, double smallest_amplitude) {
  if (time_s.size() != x.size()) throw std::invalid_argument("free decay: times and values differ in length");
  std::size_t first = 0;
  while (first < time_s.size() && time_s[first] < start_s) ++first;
  if (time_s.size() - first < 3) throw std::invalid_argument("free decay: fewer than 3 samples after the release");

  // The largest |x − final| between zero crossings, one per excursion; the
  // extreme sample refined by the parabola through it and its neighbours.
  struct Extreme {
    double t, value;
  };
  std::vector<Extreme> extremes;
  std::size_t best = first;
  auto close_excursion = [&](std::size_t k) {
    double t = time_s[k], v = x[k] - final_position;
    if (k > first && k + 1 < x.size()) {
      const double a = x[k - 1] - final_position, c = x[k + 1] - final_position;
      const double curvature = a - 2.0 * v + c;
      if (curvature != 0.0) {
        const double shift = 0.5 * (a - c) / curvature;  // in samples, |shift| <= 0.5 at an extreme
        if (std::abs(shift) <= 1.0) {
          const double h = 0.5 * (time_s[k + 1] - time_s[k - 1]);
          t += shift * h;
          v -= 0.25 * (a - c) * shift;
        }
      }
    }
    extremes.push_back({t, v});
  };
  for (std::size_t k = first + 1; k < x.size(); ++k) {
    const double prev = x[k - 1] - final_position, now = x[k] - final_position;
    if ((prev > 0.0) != (now > 0.0)) {
      close_excursion(best);
      best = k;
    } else if (std::abs(now) > std::abs(x[best] - final_position)) {
      best = k;
    }
  }

  std::vector<DecayHalfCycle> cycles;
  for (std::size_t k = 0; k + 1 < extremes.size(); ++k) {
    const Extreme& a = extremes[k];
    const Extreme& b = extremes[k + 1];
    if (std::abs(a.value) <= smallest_amplitude || std::abs(b.value) <= smallest_amplitude) break;
    const double L = std::log(std::abs(a.value) / std::abs(b.value));
    cycles.push_back({a.t, 0.5 * (std::abs(a.value) + std::abs(b.value)), 2.0 * (b.t - a.t),
                      L / std::sqrt(std::numbers::pi * std::numbers::pi + L * L)});
  }
  return cycles;
}

}  // namespace spiral::engine
