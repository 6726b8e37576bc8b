#pragma once
// The multi-segment elastic catenary posed the other way round: the top end
// and its departure angle are given, the bottom end (an anchor or riser foot
// on the seabed, in the line's vertical plane) is the unknown. This is how a
// riser's foot is placed: at rest the riser must leave its hang-off at the
// design top angle.
//
// With the top angle θ from vertical fixed, the top forces lie on the ray
// H = V_F tan θ, so one unknown remains, V_F; vertical equilibrium of the
// suspended part fixes the laid length (its weight is W_total − V_F, laid
// from the foot), and the vertical closure z(V_F tan θ, V_F) = Z_F is a 1-D
// root. The horizontal span then follows. Span formulas: the elastic
// catenary pieces of catenary_spans.hpp (Irvine 1981 eqs. 1.43–1.44;
// Jonkman, NREL/TP-500-41958, App. B), frictionless on the seabed.
//
// Why not a search on the foot distance with the usual catenary: for a
// lazy-wave riser (heavy – buoyant – heavy) a foot close to the hull puts the
// whole lower section on the seabed and the buoyant section after it, which
// the catenary cannot represent, so such a search has no usable bracket;
// posed on V_F the feasible set is simply V_F > W_total − W_laid,max
// (W_laid,max: the weight of the non-buoyant run from the foot).
//
// Frame: the line's vertical plane, origin at the bottom end on the seabed,
// x towards the top end, z up. SI.

#include "engine/lines/catenary.hpp"

namespace spiral::engine {

struct TopAngleCatenary {
  double horizontal_span_m = 0.0;      ///< XF, bottom end -> top end
  double fairlead_horizontal_N = 0.0;  ///< H at the top
  double fairlead_vertical_N = 0.0;    ///< V_F at the top (> 0 pulls the top down)
  double laid_length_m = 0.0;          ///< unstretched length on the seabed (0: the line meets it at an angle)
  int evaluations = 0;                 ///< span evaluations spent
};

/// The catenary through a top point `vertical_span_m` (> 0) above a seabed
/// end that leaves the top at `top_angle_rad` from vertical, in (0, π/2).
/// `line.seabed_friction` must be 0 (the placement is frictionless: an
/// as-laid line has no friction history). Where several solutions exist (z is
/// not monotone in V_F once buoyant sections lift) the one with the smallest
/// top tension — the longest laid length, the foot nearest the hull — is
/// returned. Throws SolverError (with the range of V_F searched) when no
/// solution exists: the line is too short for the angle, or would need a
/// buoyant segment on the seabed.
TopAngleCatenary solve_catenary_for_top_angle(const CatenaryLine& line, double vertical_span_m, double top_angle_rad);

}  // namespace spiral::engine
