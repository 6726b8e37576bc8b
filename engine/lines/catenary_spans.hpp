#pragma once
// Internal kernels of the multi-segment elastic catenary (see catenary.hpp):
// span closure of one suspended or laid piece with analytic derivatives, and
// the line-level evaluation x(H, V_F), z(H, V_F) with its 2x2 Jacobian.
//
// Equation sources:
//   suspended elastic catenary: Irvine, "Cable Structures" (1981), eqs. 1.43-1.44;
//     Jonkman, NREL/TP-500-41958 (2007), eqs. B-1, B-2 (single segment, V_B = V_F - wL);
//   seabed piece with Coulomb friction: Jonkman (2007), eqs. B-7 .. B-9, generalised
//     per piece (tension falls at mu*w per unit length, floored at 0).
// The closed forms are rewritten so that no term divides by w or by H
// (cancellation-free for w -> 0, H -> 0, |V| >> H); the rewrite is noted at each step.

#include <Eigen/Core>
#include <cmath>

#include "engine/lines/catenary.hpp"

namespace spiral::engine::catenary_detail {

/// log1p(r)/r, continuous at r = 0.
inline double log1p_over(double r) { return std::abs(r) < 1e-8 ? 1.0 - 0.5 * r : std::log1p(r) / r; }
/// sinh(u)/u, continuous at u = 0.
inline double sinh_over(double u) { return std::abs(u) < 1e-5 ? 1.0 + u * u / 6.0 : std::sinh(u) / u; }

/// Spans of one piece and their partial derivatives with respect to the
/// horizontal force H, the vertical force at the piece's top V_top, and the
/// piece's unstretched length L (V_top held fixed).
struct PieceSpans {
  double x_m = 0.0;
  double z_m = 0.0;
  double dx_dH = 0.0, dx_dVtop = 0.0, dx_dL = 0.0;  // m/N, m/N, -
  double dz_dH = 0.0, dz_dVtop = 0.0, dz_dL = 0.0;
};

/// Suspended elastic catenary piece (Irvine 1981 eqs. 1.43-1.44):
///   x = H/w [asinh(Vt/H) - asinh(Vb/H)] + H L/EA
///   z = 1/w [sqrt(H^2+Vt^2) - sqrt(H^2+Vb^2)] + (Vt + Vb) L/(2 EA),   Vb = Vt - w L.
/// Requires H > 0, or H = 0 with V > 0 all along the piece.
inline PieceSpans suspended_piece(double H, double Vt, double L, double w, double EA) {
  const double Vb = Vt - w * L;
  const double Tt = std::sqrt(H * H + Vt * Vt);
  const double Tb = std::sqrt(H * H + Vb * Vb);
  // du = asinh(Vt/H) - asinh(Vb/H) = log1p(r) with
  //   r = w L (1 + (Vt+Vb)/(Tt+Tb)) / (Vb + Tb)
  // (from asinh(a) = log(a + sqrt(1+a^2)) and sqrt(1+a^2) - sqrt(1+b^2) = (a^2-b^2)/(...)).
  // asinh is odd, so for Vt + Vb < 0 use the mirrored pair (-Vb, -Vt), which keeps the
  // bracket in [1, 2]; 1/(Vb + Tb) = (Tb - Vb)/H^2 avoids cancellation for Vb < 0.
  double vt = Vt, vb = Vb, tt = Tt, tb = Tb;
  if (vt + vb < 0.0) {
    vt = -Vb;
    vb = -Vt;
    tt = Tb;
    tb = Tt;
  }
  const double m = 1.0 + (vt + vb) / (tt + tb);
  const double q = vb >= 0.0 ? 1.0 / (vb + tb) : (tb - vb) / (H * H);
  const double r = w * L * m * q;
  const double du = std::log1p(r);
  const double x_over_H = L * m * q * log1p_over(r);  // = du / w, finite as w -> 0
  const double x_c = H * x_over_H;
  // (Tt - Tb)/w = (Vt^2 - Vb^2)/(w (Tt + Tb)) = L (Vt + Vb)/(Tt + Tb).
  const double z_c = L * (Vt + Vb) / (Tt + Tb);
  // (Vt/Tt - Vb/Tb)/w = H^2 sinh(du)/(w Tt Tb) = H^2 (x_c/H) sinhc(du)/(Tt Tb)
  // (tanh identity with cosh(asinh(V/H)) = T/H).
  const double k = H * H * x_over_H * sinh_over(du) / (Tt * Tb);
  // H (1/Tt - 1/Tb)/w = -H L (Vt + Vb)/(Tt Tb (Tt + Tb)).
  const double cross = -H * L * (Vt + Vb) / (Tt * Tb * (Tt + Tb));
  const double L_EA = L / EA;
  PieceSpans s;
  s.x_m = x_c + H * L_EA;
  s.z_m = z_c + 0.5 * (Vt + Vb) * L_EA;
  s.dx_dH = x_over_H - k + L_EA;
  s.dx_dVtop = cross;
  s.dz_dH = cross;
  s.dz_dVtop = k + L_EA;
  // Extra length added at the bottom, where the unit tangent is (H, Vb)/Tb.
  s.dx_dL = H / Tb + H / EA;
  s.dz_dL = Vb / Tb + Vb / EA;
  return s;
}

/// A piece lying on the seabed, entered at its upper end with tension T_top,
/// tension falling at mu_w = mu*w per unit length towards the anchor, floored at 0
/// (Jonkman 2007 eqs. B-7..B-9, one piece).
struct LaidPiece {
  double x_m = 0.0;                    // stretched horizontal length
  double dx_dTtop = 0.0;               // m/N
  double dx_dL = 0.0;                  // -
  double T_bottom_N = 0.0;             // tension at the anchor-side end
  bool tension_reaches_bottom = true;  // false: tension fell to 0 inside the piece
};

inline LaidPiece laid_piece(double T_top, double L, double mu_w, double EA) {
  LaidPiece p;
  double integral_T = 0.0;  // integral of the tension over the piece, N m
  if (T_top >= mu_w * L) {
    integral_T = L * (T_top - 0.5 * mu_w * L);
    p.dx_dTtop = L / EA;
    p.T_bottom_N = T_top - mu_w * L;
  } else {
    integral_T = T_top * T_top / (2.0 * mu_w);
    p.dx_dTtop = T_top / (mu_w * EA);
    p.T_bottom_N = 0.0;
    p.tension_reaches_bottom = false;
  }
  p.x_m = L + integral_T / EA;
  p.dx_dL = 1.0 + p.T_bottom_N / EA;  // d(integral)/dL = tension at the bottom end
  return p;
}

/// Why an evaluation point cannot be represented by the model.
enum class Infeasibility {
  none,
  buoyant_segment_on_seabed,  // index = segment
  buoy_on_seabed,             // index = joint
  no_suspended_part,          // V_F <= 0 with the anchor on the seabed
};

/// The line at one (H, V_F): spans, Jacobian d(x, z)/d(H, V_F) and contact state.
struct SpanEvaluation {
  double x_m = 0.0;
  double z_m = 0.0;
  Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();  // rows x, z; columns H, V_F
  Infeasibility infeasible = Infeasibility::none;
  int infeasible_index = -1;
  bool contact = false;
  int touchdown_segment = -1;       // segment holding the touchdown point (or below the joint)
  bool touchdown_at_joint = false;  // touchdown at the joint above touchdown_segment
  double touchdown_laid_m = 0.0;    // laid unstretched length inside touchdown_segment
  double clump_rest_N = 0.0;        // part of a touchdown clump carried by the seabed
  double laid_length_m = 0.0;
  double touchdown_x_m = 0.0;
  double anchor_horizontal_N = 0.0;
  double anchor_vertical_N = 0.0;
};

/// Line data the evaluator needs, checked and summed once per solve.
struct LineView {
  const CatenaryLine* line = nullptr;
  bool anchor_on_seabed = true;
  double total_weight_N = 0.0;  // sum of w L and joint loads
  double total_length_m = 0.0;
  double joint_load(std::size_t i) const { return line->joint_load_N.empty() ? 0.0 : line->joint_load_N[i]; }
};

/// x, z and their Jacobian at (H, V_F); H > 0. No allocation.
SpanEvaluation evaluate_spans(const LineView& view, double H, double V_F);

/// H = 0 solutions (catenary_vertical.cpp): a slack line hanging vertically with
/// the rest on the seabed (anchor on the seabed, XF <= laid length), or, for
/// XF <= tol, a straight vertical line taut along its whole length. Returns false
/// if neither applies; throws SolverError for XF = 0 with a line that would fold.
bool solve_vertical(const LineView& view, const CatenaryGeometry& g, double tol, CatenarySolution& solution);

}  // namespace spiral::engine::catenary_detail

namespace spiral::engine {
/// Fills solution.profile for a solved line (catenary_profile.cpp).
void fill_catenary_profile(const CatenaryLine& line, const CatenaryGeometry& geometry, int points_per_segment,
                           CatenarySolution& solution);
}  // namespace spiral::engine
