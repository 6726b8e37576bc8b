#pragma once
// Quasi-static multi-segment elastic catenary of one mooring line in its
// vertical plane (anchor -> fairlead), with seabed contact and axial seabed
// friction, clump weights and buoys at joints.
//
// Formulation: J. Jonkman, "Dynamics Modeling and Loads Analysis of an
// Offshore Floating Wind Turbine", NREL/TP-500-41958 (2007), App. B (the
// form used by MAP++ and MoorPy), generalised to several segments by walking
// the vertical force from the fairlead down; H. M. Irvine, "Cable
// Structures" (1981), ch. 1, for the elastic catenary.
//
// Plane coordinates: origin at the anchor, x horizontal towards the fairlead,
// z up. All quantities SI.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "engine/common/solver_error.hpp"

namespace spiral::engine {

/// One homogeneous segment as the catenary sees it.
struct CatenarySegment {
  double length_m = 0.0;        ///< unstretched length, > 0
  double weight_N_per_m = 0.0;  ///< submerged weight per unit unstretched length; < 0 is buoyant
  double EA_N = 0.0;            ///< axial stiffness, > 0
};

/// A line: segments ordered from the anchor (end A) to the fairlead (end B).
struct CatenaryLine {
  std::vector<CatenarySegment> segments;
  /// Net downward point load at the joint between segments[i] and segments[i+1]
  /// (size segments.size() - 1, or empty for none): the submerged weight of a
  /// clump (> 0) or the net buoyancy of a buoy (< 0), N.
  std::vector<double> joint_load_N;
  double seabed_friction = 0.0;  ///< axial Coulomb friction coefficient on the seabed, >= 0
};

/// Where the fairlead is relative to the anchor, in the line's vertical plane.
struct CatenaryGeometry {
  double horizontal_span_m = 0.0;  ///< XF >= 0, anchor to fairlead
  double vertical_span_m = 0.0;    ///< ZF, fairlead height above the anchor (may be < 0)
  /// Height of the anchor above the seabed, >= 0. Seabed contact (laid length,
  /// friction) is modelled only for an anchor on the seabed (0).
  double anchor_height_above_seabed_m = 0.0;
};

/// Fairlead force components used to warm-start the Newton iteration.
struct CatenaryGuess {
  double horizontal_N = 0.0;
  double vertical_N = 0.0;
};

enum class CatenaryRegime {
  suspended,       ///< no seabed contact
  touchdown,       ///< part of the line lies on the seabed
  slack_vertical,  ///< zero horizontal tension: vertical hanging part, rest on the seabed
};

struct CatenaryOptions {
  double tolerance_m = 1e-9;  ///< closure tolerance on both spans (absolute, m); also scaled by span
  int max_iterations = 100;
  /// Largest mean strain the solver accepts before declaring the line too short
  /// for its span (an elastic line can always be stretched; beyond this it would
  /// break long before). Default 30 % exceeds every mooring material's break strain.
  double max_strain = 0.3;
  /// Profile points per segment (0: no profile). Touchdown points are added.
  /// Each segment gives profile_points_per_segment + 1 evenly spaced points
  /// including both its ends (a joint appears once per adjacent segment, as the
  /// tension jumps across a clump or buoy).
  int profile_points_per_segment = 0;
};

/// A point of the line profile.
struct CatenaryProfilePoint {
  double arc_length_m = 0.0;  ///< unstretched arc length from the anchor
  double x_m = 0.0;           ///< horizontal, from the anchor towards the fairlead
  double z_m = 0.0;           ///< vertical, above the anchor
  double tension_N = 0.0;     ///< effective tension
  // Added by the solver's implementation (catenary.cpp):
  /// Components of the effective tension, N: the force the part of the line
  /// towards the fairlead exerts on the part towards the anchor, along +x and +z
  /// (horizontal_N = H on the suspended part; vertical_N = 0 on the seabed).
  double horizontal_N = 0.0;
  double vertical_N = 0.0;
  int segment = 0;         ///< index of the segment the point belongs to
  bool on_seabed = false;  ///< the point rests on the seabed
};

struct CatenarySolution {
  // Forces the line exerts on its ends (magnitudes; directions in comments).
  double fairlead_horizontal_N = 0.0;  ///< H_F, pulls the fairlead towards the anchor
  double fairlead_vertical_N = 0.0;    ///< V_F, pulls the fairlead down (< 0: up)
  double fairlead_tension_N = 0.0;
  double anchor_horizontal_N = 0.0;  ///< H_A, pulls the anchor towards the fairlead
  double anchor_vertical_N = 0.0;    ///< V_A, pulls the anchor up (< 0: down)
  double anchor_tension_N = 0.0;
  double laid_length_m = 0.0;  ///< unstretched length resting on the seabed
  double touchdown_x_m = 0.0;  ///< horizontal distance anchor -> touchdown point (0 if none)
  CatenaryRegime regime = CatenaryRegime::suspended;
  /// d(H_F, V_F)/d(XF, ZF): the line's tangent stiffness in its plane, N/m.
  Eigen::Matrix2d tangent_stiffness = Eigen::Matrix2d::Zero();
  int iterations = 0;
  double residual_m = 0.0;  ///< final closure error (norm of the span errors), m
  std::vector<CatenaryProfilePoint> profile;
};

/// Solves the line for the given geometry. Throws SolverError with a message
/// stating the cause (line too short for its span, no convergence with the
/// iteration count and residual, invalid data) — never returns NaN.
///
/// Model notes (catenary.cpp):
/// - Anchor on the seabed: the laid part is the stretch from the anchor whose
///   weight the suspended part does not carry (W_total - V_F); it must consist of
///   non-buoyant segments and clumps, else SolverError ("... is buoyant ... seabed").
///   The fairlead must then be above the seabed (ZF > 0).
/// - H = 0 configurations: a slack line hanging vertically with the rest on the
///   seabed (regime slack_vertical; laid points of the profile spread evenly over
///   XF), or XF = 0 with a line taut along its whole length.
/// - The closure tolerance is max(options.tolerance_m, 64 eps (L + XF + |ZF|)).
/// - A warm start with horizontal_N <= 0 or non-finite values is ignored.
CatenarySolution solve_catenary(const CatenaryLine& line, const CatenaryGeometry& geometry,
                                const CatenaryOptions& options = {},
                                const std::optional<CatenaryGuess>& warm_start = std::nullopt);

/// The line's in-plane tangent d(H_F, V_F)/d(XF, ZF) at `solution` when the
/// strain *changes* from that state are carried by `incremental_EA_N` (one per
/// segment, anchor first) instead of each segment's EA: the static–dynamic
/// two-stiffness convention for fibre ropes (DNV-OS-E301 ch. 2 sec. 2 [2.4]
/// and DNV-RP-E305 §2.4: the mean state with the static, post-installation
/// EA; the motions about it with the dynamic EA). The spans are geometric
/// terms independent of EA plus elastic stretches linear in 1/EA (Irvine
/// 1981 eqs. 1.43–1.44; the laid pieces likewise): the Jacobian at the same
/// (H, V) with the incremental EA in the elastic terms is the tangent of
/// N = N_s + EA_inc (ε − ε_s) but for one term, the turning of the fixed
/// part of the stretch, ε_s (1 − EA_s/EA_inc), with the line's direction;
/// it is left out, an error of that relative size on the geometric part
/// (≈ 3e-3 of it for 1 % static strain and EA_inc = 1.65 EA_s; 1e-4 of K
/// on a taut polyester leg against the FE line's exact tangent,
/// tests/validation/engine/lines/two_stiffness_tangent_test.cpp).
/// A slack-vertical state (H = 0) returns the solution's own tangent.
/// Throws std::invalid_argument for a size mismatch or an EA that is not > 0.
Eigen::Matrix2d catenary_incremental_tangent(const CatenaryLine& line, const CatenaryGeometry& geometry,
                                             const CatenarySolution& solution,
                                             const std::vector<double>& incremental_EA_N);

}  // namespace spiral::engine
