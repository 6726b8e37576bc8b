#pragma once
// Paying out or hauling in a catenary mooring line at its fairlead: how the
// fairlead forces change with the unstretched length of the top segment (the
// length a winch or chain jack changes), and the payout that gives a line a
// target pretension.
//
// Sensitivity. The fairlead position is a function of the fairlead forces
// and the segment lengths, (X, Z) = G(H, V, L). Lengthening the top segment
// by δ at fixed (H, V) adds an element at the top whose weight w δ the rest
// of the line no longer carries, so
//   G(H, V, L + δ) = G(H, V − w δ, L) + δ (1 + T/EA) τ,   τ = (H, V)/T,
// the stretched element lying along the line's tangent at the fairlead.
// With the fairlead held, 0 = J d(H, V) + ∂G/∂L dL and J⁻¹ the tangent
// stiffness S = d(H, V)/d(X, Z) the solver returns:
//   d(H, V)/dL = w e_V − S τ (1 + T/EA).
// (Irvine, "Cable Structures", 1981, §1.4, for the elastic element's
// stretch; the implicit-function step is the one the solver's tangent uses.)
// Exact for every regime the solver has a tangent for (suspended, touchdown
// with or without seabed friction), since G's dependence on the lower line
// is entirely through J.

#include <Eigen/Core>

#include "engine/lines/catenary.hpp"

namespace spiral::engine {

/// d(H_F, V_F)/dL_top, N/m: the change of the fairlead forces (as
/// CatenarySolution reports them) per metre of unstretched length added to
/// the top segment, the fairlead held where `solution` was solved.
Eigen::Vector2d catenary_payout_sensitivity(const CatenaryLine& line, const CatenarySolution& solution);

/// d(T_F)/dL_top, N/m, from the sensitivity above.
double fairlead_tension_per_payout(const CatenaryLine& line, const CatenarySolution& solution);

/// `line` with `payout_m` added to the unstretched length of its top segment
/// (negative: hauled in). Throws std::invalid_argument when the top segment
/// would vanish.
CatenaryLine with_payout(const CatenaryLine& line, double payout_m);

struct PayoutBounds {
  double min_m = 0.0;  ///< most hauled in (< 0), > −top segment length
  double max_m = 0.0;  ///< most paid out
};

struct PayoutForTension {
  double payout_m = 0.0;            ///< top-segment length change that gives the target
  double fairlead_tension_N = 0.0;  ///< reached
  int iterations = 0;
};

/// The payout at which the line's fairlead tension equals `target_N` with the
/// fairlead at `geometry` (hull fixed, the industry's definition of
/// pretension). T_F usually falls as the line is paid out but need not (a
/// steep line without a laid part gains weight faster than it loses
/// stretch), so the bounds are sampled at 17 points and the sign change of
/// T_F − target nearest zero payout brackets the root; Newton with the
/// analytic slope above then converges inside that bracket (bisection when a
/// step leaves it) to |T_F − target| ≤ relative_tolerance × target. A
/// hauled-in length that makes the line too short for its span counts as
/// infinitely taut. Throws SolverError when no payout within the bounds
/// reaches the target (the message gives the tensions at the bounds and the
/// extremes over them) — never a silent miss.
PayoutForTension payout_for_fairlead_tension(const CatenaryLine& line, const CatenaryGeometry& geometry,
                                             double target_N, const PayoutBounds& bounds,
                                             double relative_tolerance = 1e-8);

}  // namespace spiral::engine
