// Line-level span evaluation of the multi-segment elastic catenary: walk the
// vertical force from the fairlead down (V at a segment's bottom = V_top - w L,
// minus the joint load at each joint), sum the closed-form spans of each piece
// and chain their derivatives (every segment's V_top moves one-for-one with V_F).
// Seabed contact follows Jonkman (NREL/TP-500-41958, 2007, App. B) per piece.

#include "engine/lines/catenary_spans.hpp"

namespace spiral::engine::catenary_detail {

namespace {

/// Locates the touchdown point for an anchor on the seabed: the laid part is
/// the stretch from the anchor whose weight equals what the suspended part does
/// not carry, W_laid = W_total - V_F (vertical equilibrium of the suspended part,
/// V = 0 at touchdown). Walking from the anchor keeps the laid part made of
/// non-buoyant pieces, which is what the seabed can support.
void locate_touchdown(const LineView& view, double V_F, SpanEvaluation& e) {
  const auto& seg = view.line->segments;
  const std::size_t n = seg.size();
  const double target_N = view.total_weight_N - V_F;
  double laid_weight_N = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = seg[i].weight_N_per_m;
    if (w < 0.0) {
      e.infeasible = Infeasibility::buoyant_segment_on_seabed;
      e.infeasible_index = static_cast<int>(i);
      return;
    }
    const double segment_weight_N = w * seg[i].length_m;
    if (w > 0.0 && laid_weight_N + segment_weight_N >= target_N) {
      e.touchdown_segment = static_cast<int>(i);
      e.touchdown_laid_m = std::min((target_N - laid_weight_N) / w, seg[i].length_m);
      return;
    }
    laid_weight_N += segment_weight_N;
    if (i + 1 < n) {
      const double P = view.joint_load(i);
      if (P < 0.0) {
        e.infeasible = Infeasibility::buoy_on_seabed;
        e.infeasible_index = static_cast<int>(i);
        return;
      }
      if (P > 0.0 && laid_weight_N + P >= target_N) {
        e.touchdown_segment = static_cast<int>(i + 1);
        e.touchdown_at_joint = true;
        e.clump_rest_N = target_N - laid_weight_N;
        return;
      }
      laid_weight_N += P;
    }
  }
  e.infeasible = Infeasibility::no_suspended_part;
}

}  // namespace

SpanEvaluation evaluate_spans(const LineView& view, double H, double V_F) {
  SpanEvaluation e;
  const auto& seg = view.line->segments;
  const int n = static_cast<int>(seg.size());
  const double mu = view.line->seabed_friction;

  if (view.anchor_on_seabed && V_F - view.total_weight_N < 0.0) {
    if (V_F <= 0.0) {
      e.infeasible = Infeasibility::no_suspended_part;
      return e;
    }
    locate_touchdown(view, V_F, e);
    if (e.infeasible != Infeasibility::none) return e;
    e.contact = true;
  }
  // Lowest segment index with a suspended part.
  const int k = e.contact ? e.touchdown_segment : 0;

  // Suspended part, fairlead -> touchdown (or anchor).
  double weight_above_N = 0.0;
  for (int i = n - 1; i >= k; --i) {
    const CatenarySegment& s = seg[i];
    const double Vt = V_F - weight_above_N;
    const bool td_piece = e.contact && i == k && !e.touchdown_at_joint;
    const double L = td_piece ? s.length_m - e.touchdown_laid_m : s.length_m;
    const PieceSpans p = suspended_piece(H, Vt, L, s.weight_N_per_m, s.EA_N);
    e.x_m += p.x_m;
    e.z_m += p.z_m;
    e.jacobian(0, 0) += p.dx_dH;
    e.jacobian(1, 0) += p.dz_dH;
    // Touchdown piece: its suspended length is V_top/w, so dL/dV_F = 1/w.
    const double dL_dV = td_piece ? 1.0 / s.weight_N_per_m : 0.0;
    e.jacobian(0, 1) += p.dx_dVtop + p.dx_dL * dL_dV;
    e.jacobian(1, 1) += p.dz_dVtop + p.dz_dL * dL_dV;
    weight_above_N += s.weight_N_per_m * s.length_m;
    if (i > 0) weight_above_N += view.joint_load(i - 1);
  }

  if (!e.contact) {
    e.anchor_horizontal_N = H;
    e.anchor_vertical_N = V_F - view.total_weight_N;
    return e;
  }

  // Laid part, touchdown -> anchor: tension T(H, V_F) carried with its derivatives.
  double T = H, dT_dH = 1.0, dT_dV = 0.0;
  int top = k;  // highest segment with a laid piece
  if (e.touchdown_at_joint) {
    // The clump's resting part W_total - V_F - (laid weight) adds mu*rest of friction.
    const double after = T - mu * e.clump_rest_N;
    if (after > 0.0) {
      T = after;
      dT_dV += mu;
    } else {
      T = dT_dH = dT_dV = 0.0;
    }
    top = k - 1;
  }
  double x_laid = 0.0, dx_dH = 0.0, dx_dV = 0.0;
  for (int i = top; i >= 0; --i) {
    const CatenarySegment& s = seg[i];
    const bool td_piece = i == k && !e.touchdown_at_joint;
    const double L = td_piece ? e.touchdown_laid_m : s.length_m;
    const double dL_dV = td_piece ? -1.0 / s.weight_N_per_m : 0.0;
    const double mu_w = mu * s.weight_N_per_m;
    const LaidPiece p = laid_piece(T, L, mu_w, s.EA_N);
    x_laid += p.x_m;
    dx_dH += p.dx_dTtop * dT_dH;
    dx_dV += p.dx_dTtop * dT_dV + p.dx_dL * dL_dV;
    e.laid_length_m += L;
    if (p.tension_reaches_bottom) {
      T = p.T_bottom_N;
      dT_dV -= mu_w * dL_dV;
    } else {
      T = dT_dH = dT_dV = 0.0;
    }
    if (i > 0) {  // clump fully on the seabed: friction mu * W_clump
      const double after = T - mu * view.joint_load(i - 1);
      if (after > 0.0) {
        T = after;
      } else {
        T = dT_dH = dT_dV = 0.0;
      }
    }
  }
  e.x_m += x_laid;
  e.jacobian(0, 0) += dx_dH;
  e.jacobian(0, 1) += dx_dV;
  e.touchdown_x_m = x_laid;
  e.anchor_horizontal_N = T;
  e.anchor_vertical_N = 0.0;
  return e;
}

}  // namespace spiral::engine::catenary_detail
