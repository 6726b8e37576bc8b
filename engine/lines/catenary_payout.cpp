#include "engine/lines/catenary_payout.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#include <optional>
#include <stdexcept>

namespace spiral::engine {

Eigen::Vector2d catenary_payout_sensitivity(const CatenaryLine& line, const CatenarySolution& solution) {
  const CatenarySegment& top = line.segments.back();
  const double h = solution.fairlead_horizontal_N;
  const double v = solution.fairlead_vertical_N;
  const double t = solution.fairlead_tension_N;
  if (!(t > 0.0)) return Eigen::Vector2d(0.0, top.weight_N_per_m);  // slack at the top: only the weight is added
  const Eigen::Vector2d tangent(h / t, v / t);
  return Eigen::Vector2d(0.0, top.weight_N_per_m) - solution.tangent_stiffness * tangent * (1.0 + t / top.EA_N);
}

double fairlead_tension_per_payout(const CatenaryLine& line, const CatenarySolution& solution) {
  const double t = solution.fairlead_tension_N;
  if (!(t > 0.0)) return 0.0;
  const Eigen::Vector2d d = catenary_payout_sensitivity(line, solution);
  return (solution.fairlead_horizontal_N * d.x() + solution.fairlead_vertical_N * d.y()) / t;
}

CatenaryLine with_payout(const CatenaryLine& line, double payout_m) {
  CatenaryLine out = line;
  CatenarySegment& top = out.segments.back();
  if (!(top.length_m + payout_m > 0.0)) {
    throw std::invalid_argument(
        fmt::format("a payout of {:.3f} m leaves no top segment (its length is {:.3f} m)", payout_m, top.length_m));
  }
  top.length_m += payout_m;
  return out;
}

PayoutForTension payout_for_fairlead_tension(const CatenaryLine& line, const CatenaryGeometry& geometry,
                                             double target_N, const PayoutBounds& bounds, double relative_tolerance) {
  if (!(target_N > 0.0)) throw SolverError(fmt::format("target pretension must be > 0, got {:.6g} N", target_N));
  if (!(bounds.min_m < bounds.max_m))
    throw SolverError(
        fmt::format("payout bounds: min {:.3f} m must be below max {:.3f} m", bounds.min_m, bounds.max_m));
  // Tension at a payout, or none when the line is too short for its span
  // there (the taut side of any target).
  std::optional<CatenaryGuess> warm;
  const auto solve_at = [&](double payout_m) -> std::optional<CatenarySolution> {
    try {
      CatenarySolution s = solve_catenary(with_payout(line, payout_m), geometry, {}, warm);
      warm = CatenaryGuess{s.fairlead_horizontal_N, s.fairlead_vertical_N};
      return s;
    } catch (const SolverError&) {
      return std::nullopt;
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  };
  // T_F − target; a line too short to reach counts as infinitely taut.
  const auto residual_of = [&](const std::optional<CatenarySolution>& s) {
    return s ? s->fairlead_tension_N - target_N : std::numeric_limits<double>::infinity();
  };

  // T_F usually falls as the line is paid out, but not always: a line hanging
  // steeply without a laid part gains weight faster than it loses stretch.
  // So the bounds are sampled (slack end first, for the warm start) and the
  // sign change nearest zero payout brackets the root.
  constexpr int kSamples = 16;
  std::vector<double> payout(kSamples + 1), residual(kSamples + 1);
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  double lowest_at = 0.0, highest_at = 0.0;
  for (int k = kSamples; k >= 0; --k) {
    payout[k] = bounds.min_m + (bounds.max_m - bounds.min_m) * k / kSamples;
    const std::optional<CatenarySolution> s = solve_at(payout[k]);
    residual[k] = residual_of(s);
    if (s && s->fairlead_tension_N < lowest) lowest = s->fairlead_tension_N, lowest_at = payout[k];
    if (s && s->fairlead_tension_N > highest) highest = s->fairlead_tension_N, highest_at = payout[k];
  }
  int bracket = -1;
  for (int k = 0; k < kSamples; ++k) {
    if ((residual[k] > 0.0) == (residual[k + 1] > 0.0)) continue;
    if (bracket < 0 || std::min(std::abs(payout[k]), std::abs(payout[k + 1])) <
                           std::min(std::abs(payout[bracket]), std::abs(payout[bracket + 1])))
      bracket = k;
  }
  if (bracket < 0 && std::isfinite(lowest)) {
    // No sign change among the samples, but the target may sit in a dip (or
    // on a hump) between two of them: refine the extreme sample by
    // golden-section search and bracket against it.
    const bool dip = residual[kSamples] > 0.0;  // every sample above the target
    const double centre = dip ? lowest_at : highest_at;
    const double step = (bounds.max_m - bounds.min_m) / kSamples;
    double lo = std::max(bounds.min_m, centre - step), hi = std::min(bounds.max_m, centre + step);
    const double sign = dip ? 1.0 : -1.0;  // minimize sign · residual
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int i = 0; i < 80 && hi - lo > 1e-12 * (1.0 + std::abs(hi)); ++i) {
      const double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
      if (sign * residual_of(solve_at(x1)) < sign * residual_of(solve_at(x2))) {
        hi = x2;
      } else {
        lo = x1;
      }
    }
    const double extreme_at = 0.5 * (lo + hi);
    const std::optional<CatenarySolution> s = solve_at(extreme_at);
    const double r = residual_of(s);
    if (std::abs(r) <= relative_tolerance * target_N) return {extreme_at, s->fairlead_tension_N, 0};
    if ((r > 0.0) != dip) {
      // The extreme crosses the target: bracket between it and the sample beside it nearest zero payout.
      const auto k = static_cast<std::size_t>(std::lround((centre - bounds.min_m) / step));
      const bool left = k > 0 && (k == kSamples || std::abs(payout[k - 1]) < std::abs(payout[k + 1]));
      const std::size_t side = left ? k - 1 : k + 1;
      payout = {std::min(payout[side], extreme_at), std::max(payout[side], extreme_at)};
      residual = left ? std::vector<double>{residual[side], r} : std::vector<double>{r, residual[side]};
      bracket = 0;
    }
  }
  if (bracket < 0) {
    if (!std::isfinite(lowest))
      throw SolverError(
          fmt::format("no static solution at any payout in [{:.3f}, {:.3f}] m", bounds.min_m, bounds.max_m));
    if (residual[kSamples] > 0.0) {
      throw SolverError(fmt::format(
          "target {:.1f} kN is below the tension {:.1f} kN at the largest payout {:.3f} m (the least over the "
          "bounds: {:.1f} kN at {:.3f} m): pay out more than the bound allows, or raise the target",
          target_N / 1e3, residual_of(solve_at(bounds.max_m)) / 1e3 + target_N / 1e3, bounds.max_m, lowest / 1e3,
          lowest_at));
    }
    throw SolverError(fmt::format(
        "target {:.1f} kN is above the tension {:.1f} kN at the largest haul-in {:.3f} m (the most over the "
        "bounds: {:.1f} kN at {:.3f} m): haul in more than the bound allows, or lower the target",
        target_N / 1e3, residual[0] / 1e3 + target_N / 1e3, bounds.min_m, highest / 1e3, highest_at));
  }

  // Newton on the residual with the analytic slope, safeguarded by the
  // bracket [a, b] whose ends have residuals of opposite signs.
  double a = payout[bracket], b = payout[bracket + 1];
  double residual_a = residual[bracket];
  double x = std::abs(a) < std::abs(b) ? a : b;
  const double tolerance_N = relative_tolerance * target_N;
  constexpr int kMaxIterations = 200;
  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    const std::optional<CatenarySolution> s = solve_at(x);
    const double r = residual_of(s);
    if (std::abs(r) <= tolerance_N) return {x, s->fairlead_tension_N, iteration};
    if ((r > 0.0) == (residual_a > 0.0)) {
      a = x;
      residual_a = r;
    } else {
      b = x;
    }
    double next = 0.5 * (a + b);
    if (s) {
      const double slope = fairlead_tension_per_payout(with_payout(line, x), *s);
      if (slope != 0.0) {
        const double newton = x - r / slope;
        if (newton > std::min(a, b) && newton < std::max(a, b)) next = newton;
      }
    }
    if (std::abs(b - a) <= 1e-12 * (1.0 + std::abs(b))) break;
    x = next;
  }
  throw SolverError(fmt::format("payout for a fairlead tension of {:.1f} kN did not converge in [{:.6f}, {:.6f}] m",
                                target_N / 1e3, std::min(a, b), std::max(a, b)));
}

}  // namespace spiral::engine
