// Configurations with zero horizontal tension (H = 0), which Newton on H > 0
// cannot reach: a slack line hanging vertically from the fairlead with the rest
// on the seabed (its slack taken up by the laid part), and a straight vertical
// line for a zero horizontal span. Vertical spans from Irvine (1981) eq. 1.44
// at H = 0: z = L + (V_top + V_bottom) L / (2 EA).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/lines/catenary_spans.hpp"

namespace spiral::engine::catenary_detail {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// ---------------------------------------------------------------------------
// Zero horizontal tension (H = 0): the line hangs vertically from the fairlead.

/// Vertical hanging line at H = 0: height reached by the suspended part and
/// its derivative; laid part from the touchdown walk. Valid while V >= 0 along
/// the suspended part (a vertical line cannot carry compression).
struct Hanging {
  double z_m = 0.0;
  double dz_dV = 0.0;
  double laid_length_m = 0.0;
  bool valid = true;
  Infeasibility infeasible = Infeasibility::none;
  int infeasible_index = -1;
};

Hanging hanging_line(const LineView& view, double V_F) {
  // Reuse the touchdown walk at a tiny H: only its contact fields are used.
  Hanging h;
  SpanEvaluation e;
  if (view.anchor_on_seabed && V_F < view.total_weight_N) {
    e = evaluate_spans(view, 1.0, V_F);
    if (e.infeasible != Infeasibility::none) {
      h.valid = false;
      h.infeasible = e.infeasible;
      h.infeasible_index = e.infeasible_index;
      return h;
    }
  }
  const auto& seg = view.line->segments;
  const int n = static_cast<int>(seg.size());
  const int k = e.contact ? e.touchdown_segment : 0;
  double above_N = 0.0;
  for (int i = n - 1; i >= k; --i) {
    const CatenarySegment& s = seg[i];
    const bool td_piece = e.contact && i == k && !e.touchdown_at_joint;
    const double L = td_piece ? s.length_m - e.touchdown_laid_m : s.length_m;
    const double Vt = V_F - above_N;
    const double Vb = td_piece ? 0.0 : Vt - s.weight_N_per_m * L;
    // Round-off allowance: the walk sums forces of the size of the line's weight.
    const double allowance_N = 1e-12 * (std::abs(V_F) + std::abs(view.total_weight_N));
    if (Vt < -allowance_N || Vb < -allowance_N) h.valid = false;
    // Irvine eq. 1.44 at H = 0: z = L + (Vt + Vb) L/(2 EA).
    h.z_m += L + 0.5 * (Vt + Vb) * L / s.EA_N;
    h.dz_dV += L / s.EA_N + (td_piece ? (1.0 + Vb / s.EA_N) / s.weight_N_per_m : 0.0);
    above_N += s.weight_N_per_m * s.length_m;
    if (i > 0) above_N += view.joint_load(i - 1);
  }
  h.laid_length_m = e.laid_length_m;
  return h;
}

/// V_F of the vertical hanging line with a laid part closing ZF (bracketed
/// Newton on the monotone z(V_F) over (0, W_total)). Returns false when no
/// such configuration exists.
bool solve_hanging(const LineView& view, double ZF, double tol, double& V_F, Hanging& h, int& iterations) {
  double lo = 0.0, hi = view.total_weight_N;
  if (hi <= 0.0) return false;
  const Hanging top = hanging_line(view, hi);
  if (!top.valid || top.z_m <= ZF) return false;
  double V = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    ++iterations;
    h = hanging_line(view, V);
    const double f = h.valid ? h.z_m - ZF : -1.0;  // invalid: V too low (buoyant laid)
    if (h.valid && std::abs(f) <= tol) {
      V_F = V;
      return true;
    }
    (f > 0.0 ? hi : lo) = V;
    double next = h.valid && h.dz_dV > 0.0 ? V - f / h.dz_dV : lo - 1.0;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 4.0 * kEps * view.total_weight_N) {
      V_F = V;
      return h.valid;
    }
    V = next;
  }
  return false;
}

/// Integral of ds/T over a segment of a vertical line (H = 0, V > 0 throughout):
/// ln(Vt/Vb)/w written as L log1p(wL/Vb)/(wL/Vb)/Vb (finite as w -> 0).
double vertical_compliance_integral(double Vt, double L, double w) {
  const double Vb = Vt - w * L;
  if (Vb <= 0.0) return std::numeric_limits<double>::infinity();
  return L * log1p_over(w * L / Vb) / Vb;
}

/// H = 0 solutions: slack line hanging vertically with the rest on the seabed,
/// or a straight vertical line for XF = 0. Returns false if neither applies.
}  // namespace

bool solve_vertical(const LineView& view, const CatenaryGeometry& g, double tol, CatenarySolution& s) {
  const double XF = g.horizontal_span_m, ZF = g.vertical_span_m;
  if (view.anchor_on_seabed) {
    double V = 0.0;
    Hanging h;
    int iterations = 0;
    if (solve_hanging(view, ZF, tol, V, h, iterations) && XF <= h.laid_length_m + tol) {
      s = {};
      s.fairlead_vertical_N = V;
      s.fairlead_tension_N = V;
      s.laid_length_m = h.laid_length_m;
      s.touchdown_x_m = XF;
      s.regime = CatenaryRegime::slack_vertical;
      s.tangent_stiffness(1, 1) = 1.0 / h.dz_dV;  // horizontal terms are zero: slack on the seabed
      s.iterations = iterations;
      s.residual_m = std::abs(h.z_m - ZF);
      return true;
    }
  }
  if (XF > tol) return false;
  // Straight vertical line, V >= 0 all along: z(V_F) is affine (Irvine eq. 1.44 at H = 0).
  const auto& seg = view.line->segments;
  const int n = static_cast<int>(seg.size());
  double z0 = 0.0, slope = 0.0, above = 0.0;
  for (int i = n - 1; i >= 0; --i) {
    const double L = seg[i].length_m, EA = seg[i].EA_N;
    z0 += L + 0.5 * (-2.0 * above - seg[i].weight_N_per_m * L) * L / EA;
    slope += L / EA;
    above += seg[i].weight_N_per_m * L;
    if (i > 0) above += view.joint_load(i - 1);
  }
  const double V_F = (ZF - z0) / slope;
  double compliance_x = 0.0;  // integral of (1/T + 1/EA) ds, m/N
  above = 0.0;
  for (int i = n - 1; i >= 0; --i) {
    const double Vt = V_F - above, Vb = Vt - seg[i].weight_N_per_m * seg[i].length_m;
    if (Vt < 0.0 || Vb < 0.0) {
      throw SolverError(
          fmt::format("catenary: zero horizontal span with a line that is not taut along its whole length "
                      "(vertical force {:.6g} N at the bottom of segments[{}]): the line would fold on "
                      "itself; give a horizontal span > 0",
                      std::min(Vt, Vb), i));
    }
    compliance_x +=
        vertical_compliance_integral(Vt, seg[i].length_m, seg[i].weight_N_per_m) + seg[i].length_m / seg[i].EA_N;
    above += seg[i].weight_N_per_m * seg[i].length_m;
    if (i > 0) above += view.joint_load(i - 1);
  }
  s = {};
  s.fairlead_vertical_N = V_F;
  s.fairlead_tension_N = std::abs(V_F);
  s.anchor_vertical_N = V_F - view.total_weight_N;
  s.anchor_tension_N = std::abs(s.anchor_vertical_N);
  s.regime = CatenaryRegime::suspended;
  // Pendulum (geometric) stiffness dH/dXF = 1 / integral (1/T + 1/EA) ds.
  s.tangent_stiffness(0, 0) = std::isfinite(compliance_x) ? 1.0 / compliance_x : 0.0;
  s.tangent_stiffness(1, 1) = 1.0 / slope;
  s.iterations = 1;
  s.residual_m = 0.0;
  return true;
}

}  // namespace spiral::engine::catenary_detail
