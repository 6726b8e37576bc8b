// Catenary with a given top angle: scan of V_F on its feasible ray, then a
// safeguarded Newton / bisection on the vertical closure. See
// catenary_top_angle.hpp for the formulation.

#include "engine/lines/catenary_top_angle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/lines/catenary_spans.hpp"

namespace spiral::engine {

namespace detail = catenary_detail;

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Largest mean strain searched: solve_catenary's default limit (30 %, beyond
// every riser and mooring material's break strain).
constexpr double kMaxStrain = 0.3;
// Scan of V_F − V_min on a geometric grid from 1e-12 of the scale up to the
// strain limit: 24 points per decade resolve the roots of a lazy wave
// (z(V_F) turns at most twice) while costing a few hundred microseconds.
constexpr int kScanPointsPerDecade = 24;
constexpr double kScanStartFraction = 1e-12;
// Bisection/Newton steps on the bracket: enough to reach round-off of V_F.
constexpr int kMaxRootIterations = 200;

[[noreturn]] void fail(const std::string& message) { throw SolverError("catenary (top angle): " + message); }

}  // namespace

TopAngleCatenary solve_catenary_for_top_angle(const CatenaryLine& line, double vertical_span_m, double top_angle_rad) {
  if (line.segments.empty()) fail("segments: at least one segment is required");
  if (!(std::isfinite(vertical_span_m) && vertical_span_m > 0.0)) {
    fail(fmt::format("vertical_span_m: must be > 0, got {} m", vertical_span_m));
  }
  if (!(top_angle_rad > 0.0 && top_angle_rad < 0.5 * std::numbers::pi)) {
    fail(fmt::format("top angle: must be in (0, 90) deg from vertical, got {} deg", top_angle_rad * kRadToDeg));
  }
  if (line.seabed_friction != 0.0) {
    fail(fmt::format("seabed_friction: must be 0 for the placement, got {}", line.seabed_friction));
  }
  detail::LineView view;
  view.line = &line;
  view.anchor_on_seabed = true;
  double min_EA_N = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < line.segments.size(); ++i) {
    const CatenarySegment& s = line.segments[i];
    if (!(std::isfinite(s.length_m) && s.length_m > 0.0 && std::isfinite(s.weight_N_per_m) && std::isfinite(s.EA_N) &&
          s.EA_N > 0.0)) {
      fail(fmt::format("segments[{}]: needs length_m > 0, finite weight_N_per_m and EA_N > 0", i));
    }
    view.total_weight_N += s.weight_N_per_m * s.length_m;
    view.total_length_m += s.length_m;
    min_EA_N = std::min(min_EA_N, s.EA_N);
  }
  if (!(line.joint_load_N.empty() || line.joint_load_N.size() + 1 == line.segments.size())) {
    fail("joint_load_N: must be empty or have one entry per joint");
  }
  // The heaviest laid part the seabed can carry: the run of non-buoyant
  // segments and clumps from the foot (catenary_spans.cpp, locate_touchdown).
  double laid_max_N = 0.0;
  for (std::size_t i = 0; i < line.segments.size(); ++i) {
    if (line.segments[i].weight_N_per_m < 0.0) break;
    laid_max_N += line.segments[i].weight_N_per_m * line.segments[i].length_m;
    if (i + 1 < line.segments.size()) {
      if (view.joint_load(i) < 0.0) break;
      laid_max_N += view.joint_load(i);
    }
  }
  const double tan_theta = std::tan(top_angle_rad);
  const double V_min = std::max(0.0, view.total_weight_N - laid_max_N);
  const double V_max = kMaxStrain * min_EA_N * std::cos(top_angle_rad);
  const double scale = std::max({std::abs(view.total_weight_N), laid_max_N, 1.0});
  if (!(V_max > V_min + kScanStartFraction * scale)) {
    fail(fmt::format("the line cannot hang from its top: V_F would exceed {:.4g} N", V_max));
  }

  TopAngleCatenary result;
  // g(V) = z(V tan θ, V) − Z_F and dg/dV along the ray.
  const auto closure = [&](double V, double& slope) {
    ++result.evaluations;
    const detail::SpanEvaluation e = detail::evaluate_spans(view, V * tan_theta, V);
    if (e.infeasible != detail::Infeasibility::none) return std::numeric_limits<double>::quiet_NaN();
    slope = e.jacobian(1, 0) * tan_theta + e.jacobian(1, 1);
    return e.z_m - vertical_span_m;
  };

  // Scan upwards from the feasibility edge for the first sign change.
  const double d_first = kScanStartFraction * scale;
  const int points = 1 + static_cast<int>(std::ceil(kScanPointsPerDecade * std::log10((V_max - V_min) / d_first)));
  const double ratio = std::pow((V_max - V_min) / d_first, 1.0 / (points - 1));
  double slope = 0.0;
  double lo = V_min + d_first;
  double g_lo = closure(lo, slope);
  const double g_edge = g_lo;
  double hi = lo;
  double g_hi = g_lo;
  bool bracketed = !std::isnan(g_lo) && g_lo == 0.0;
  double d = d_first;
  for (int k = 1; k < points && !bracketed; ++k) {
    d *= ratio;
    const double V = std::min(V_min + d, V_max);
    const double g = closure(V, slope);
    if (std::isnan(g)) continue;
    if (!std::isnan(g_lo) && (g >= 0.0) != (g_lo >= 0.0)) {
      hi = V;
      g_hi = g;
      bracketed = true;
    } else {
      lo = V;
      g_lo = g;
    }
  }
  if (!bracketed && g_edge > 0.0) {
    fail(
        fmt::format("for every V_F in [{:.4g}, {:.4g}] N the line rises higher than its top {:.2f} m above the "
                    "foot (at the lowest V_F, with the whole non-buoyant run from the foot laid: {:.2f} m): it "
                    "is too long or too buoyant for this span, a buoyant segment would have to lie on the "
                    "seabed; increase the top angle ({:.2f} deg) or shorten the segments above the bottom run",
                    V_min, V_max, vertical_span_m, g_edge + vertical_span_m, top_angle_rad * kRadToDeg));
  }
  if (!bracketed) {
    fail(
        fmt::format("no bottom-end position gives the top angle {:.2f} deg: over V_F in [{:.4g}, {:.4g}] N the "
                    "line never reaches the top {:.2f} m above the seabed (too short for this angle)",
                    top_angle_rad * kRadToDeg, V_min, V_max, vertical_span_m));
  }
  // Newton inside the bracket [lo, hi] (g changes sign across it), bisection
  // where a Newton step would leave it.
  const double tolerance_m = 64.0 * std::numeric_limits<double>::epsilon() * (view.total_length_m + vertical_span_m);
  const bool rising = g_hi > g_lo;
  double V = g_lo == 0.0 ? lo : lo - g_lo * (hi - lo) / (g_hi - g_lo);
  for (int k = 0; k < kMaxRootIterations; ++k) {
    const double g = closure(V, slope);
    if (std::abs(g) <= tolerance_m) break;
    ((g > 0.0) == rising ? hi : lo) = V;
    double next = slope != 0.0 ? V - g / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) break;
    V = next;
  }
  const detail::SpanEvaluation e = detail::evaluate_spans(view, V * tan_theta, V);
  result.horizontal_span_m = e.x_m;
  result.fairlead_horizontal_N = V * tan_theta;
  result.fairlead_vertical_N = V;
  result.laid_length_m = e.laid_length_m;
  return result;
}

}  // namespace spiral::engine
