#pragma once
// Finite-element static equilibrium of one mooring line or riser in 3D, with
// weight/buoyancy, Morison drag from a depth-varying current, penalty seabed
// contact, point loads at section joints and (for risers) bending stiffness.
//
// Element: geometrically exact ANCF cable element — nodal position r and
// slope r' = dr/ds (s: unstretched arc length), cubic Hermite interpolation
// (J. Gerstmayr and A. A. Shabana, "Analysis of thin beams and cables using
// the absolute nodal co-ordinate formulation", Nonlinear Dyn. 45 (2006);
// the same element as Project Chrono's ChElementCableANCF). Internal virtual
// work per unstretched length: N δ|r'| + EI/2 δ(κ²) with the engineering
// axial strain ε = |r'| − 1, N = EA ε (Hooke's law of the elastic catenary,
// Irvine 1981 eq. 1.4) and κ = |r' × r''| / |r'|³; 5-point Gauss quadrature;
// distributed loads applied consistently (work-equivalent) through the
// Hermite shape functions. Ends are pinned: positions fixed, slopes free
// (the natural boundary condition is zero end moment).
//
// Section joints are hinges with a slope per side where EA or EI changes
// (unless both sides bend): the stretch |r'| = 1 + T/EA jumps there, and a
// clump or buoy kinks a cable. Joints between two bending sections share the
// slope (moment continuity).
//
// Why this element: against the exact elastic catenary it converges fast
// with the element count (order ≈ 5.5 on the fully suspended OC4 line;
// tests/validation/engine/lines/fe_statics_catenary_test), and one element
// carries drag, seabed contact and (for risers) bending. Exact
// elastic-catenary elements (Peyrot & Goulois 1979) are exact only under a
// uniform load per element and would need a separate beam element for
// risers. The accuracy figures are in docs/decisions/fe-line-statics.md.
//
// Touchdown: a cubic element cannot follow "flat, then curved" inside itself,
// so the node nearest the touchdown point is moved onto it (r-adaptivity) and
// the line re-solved until it stays (secant iteration, ≈ 3–8 re-solves). The
// result's node_arc_length_m then differs from the model's mesh there.
//
// Loads (per unit unstretched length unless stated):
//  - weight: (0, 0, −w), w the submerged weight (effective weight for risers:
//    steel + contents − displaced water), so the computed axial force is the
//    effective tension (Sparks, "Fundamentals of Marine Riser Mechanics").
//  - drag (OrcaFlex / MoorDyn v2 convention), on the stretched length |r'| ds:
//    normal ½ ρ Cdn D |u_n| u_n, tangential ½ ρ Cdt π D |u_t| u_t, with u the
//    current at the point (line at rest), u_t = (u·t) t, u_n = u − u_t.
//  - seabed: z = z_seabed, penalty force k · max(0, z_seabed − z) upward, z of
//    the centreline (as the catenary and MoorDyn measure it), integrated
//    exactly over the penetrating part of each element. An end pinned on the
//    seabed also carries the weight that the unresolved penalty layer
//    √(T/k) leaves to it (a downward pull ≤ half an element's weight, never a
//    false uplift). Axial seabed friction is NOT applied in statics: friction
//    is path dependent, and a static solve has no path (it would need an
//    as-laid reference to measure sliding from); the result is the
//    frictionless equilibrium, which is what the catenary solver returns
//    with zero friction. The coefficient is kept for the dynamic model.
//
// Solver: Newton–Raphson on all free DOFs with an exact Jacobian (the analytic
// element tangent; forward-mode AD for the drag's derivatives only, checked
// against full AD in tests/unit/ancf_tangent_test), a banded LU with partial
// pivoting; in warm-started solves modified Newton (the factorised Jacobian
// of the previous solution is kept while chord steps at least halve the
// residual — typically one or two fresh Jacobians per warm solve, incl. the
// one the end-B stiffness needs at the converged state); Armijo
// backtracking on the force residual with a watchdog (a full step may raise
// the residual for up to two steps), and continuations when a direct solve
// crawls or fails: seabed stiffness (×10 per stage from a soft bed), current
// velocity (adaptive steps, with EA capped at 10 × the tension during the
// swing, then restored ×10 per stage). Start: the multi-segment elastic
// catenary (solve_catenary) when it has a solution, else a stretched
// one-weight catenary or a straight line; or a given shape or warm state.
// Under current a cold start is first swung rigidly about its chord until
// the loads have no moment about it (no strain, so none of the spurious
// stretch of a linear rotation step): most cold solves under current then
// converge without continuation (docs/decisions/fe-line-statics.md).
// A warm start is predicted to first order with the previous solution's
// tangent and solved by Newton at the full current; if that fails, the
// solve starts cold (a continuation from a warm state would restart from
// zero current).
// Cost: tests/bench/fe_statics_bench (timings in docs/decisions/fe-line-statics.md).
// Frames and units: global frame, z up, SI. End A is the anchor / riser
// bottom, end B the fairlead / hang-off.

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "engine/common/solver_error.hpp"

namespace spiral::engine {

struct FeLineTangent;  // opaque: the factorised Jacobian of a converged state

/// One homogeneous section of the line.
struct FeLineSection {
  double length_m = 0.0;          ///< unstretched length, > 0
  double EA_N = 0.0;              ///< axial stiffness, > 0
  double EI_Nm2 = 0.0;            ///< bending stiffness, >= 0 (0: chain, rope)
  double mass_kg_per_m = 0.0;     ///< mass per unstretched length (incl. contents), >= 0; unused by statics
  double weight_N_per_m = 0.0;    ///< submerged (effective) weight per length; < 0 is buoyant
  double hydro_diameter_m = 0.0;  ///< outer hydrodynamic diameter for drag, >= 0
  double drag_normal = 0.0;       ///< Cdn on hydro_diameter_m, >= 0
  double drag_tangential = 0.0;   ///< Cdt on π·hydro_diameter_m, >= 0
  double element_length_m = 0.0;  ///< target element length, > 0 (elements are equal within a section)
  // Dynamics only (fe_line_dynamics.hpp); statics ignores them.
  double displaced_area_m2 = 0.0;      ///< volume per length (Froude–Krylov, added mass), >= 0
  double added_mass_normal = 0.0;      ///< C_an on displaced_area_m2, >= 0
  double added_mass_tangential = 0.0;  ///< C_at on displaced_area_m2, >= 0
  double axial_damping_Ns = 0.0;       ///< c in N_d = c dε/dt (strain-rate damping), >= 0
  double EA_dynamic_N = 0.0;           ///< axial stiffness for the fluctuations about the mean (polyester); 0: EA_N
  bool operator==(const FeLineSection&) const = default;
};

/// A stretch of finer mesh, e.g. around the expected touchdown point.
struct FeRefinementZone {
  double start_arc_length_m = 0.0;  ///< unstretched arc length from end A where the zone starts
  double length_m = 0.0;            ///< > 0
  double element_length_m = 0.0;    ///< > 0; used where smaller than the section's own target
  bool operator==(const FeRefinementZone&) const = default;
};

/// The line (immutable): sections ordered from end A to end B.
struct FeLineModel {
  std::vector<FeLineSection> sections;
  /// Net downward point load at the joint between sections i and i+1 (size
  /// sections.size() − 1, or empty): clump weight (> 0) or buoy (< 0), N.
  std::vector<double> joint_load_N;
  std::optional<FeRefinementZone> refinement;
  bool operator==(const FeLineModel&) const = default;
};

/// Where the two ends are held (pinned), global frame.
struct FeLineEnds {
  Eigen::Vector3d end_A_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d end_B_m = Eigen::Vector3d::Zero();
};

/// Current velocity at one depth.
struct CurrentProfilePoint {
  double z_m = 0.0;                                            ///< global z (negative below MWL)
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();  ///< global frame
};

/// The environment the line statics needs (engine-only).
struct FeEnvironment {
  double water_density_kg_per_m3 = 1025.0;
  /// Current, sorted by increasing z; linear in z between points, constant
  /// beyond the ends; empty means no current.
  std::vector<CurrentProfilePoint> current;
  double seabed_z_m = -1.0e30;             ///< seabed level (global z)
  double seabed_stiffness_N_per_m2 = 0.0;  ///< per m of line per m penetration, >= 0
  double seabed_axial_friction = 0.0;      ///< kept for dynamics; not applied in statics (see top)
};

struct FeStaticsOptions {
  /// Converged when every nodal force residual (slope residuals divided by
  /// the element length) is below this fraction of the force scale (largest
  /// of: total |weight| + |point loads| + drag estimate, and the largest axial
  /// force), or below the round-off floor 10 ε max(EA/h) × coordinate size.
  double relative_force_tolerance = 1e-10;
  int max_iterations = 100;         ///< Newton iterations per continuation stage
  int max_load_step_halvings = 10;  ///< current continuation: step halvings allowed
  /// Initial shape as a function of unstretched arc length from end A
  /// (e.g. a catenary profile). Default: inextensible catenary in the
  /// vertical plane through A and B, lying on the seabed from A if A is on it;
  /// a straight line if the line is shorter than the chord.
  std::function<Eigen::Vector3d(double arc_length_m)> initial_shape;
  /// initial_shape is an equilibrium of this same problem already (e.g. the
  /// node profile a static case stored): Newton starts from it as from a
  /// warm state — its slopes from the shape alone, no swing into the current
  /// and no continuation — at the node arc lengths
  /// warm_start_node_arc_length_m if given (a node moved onto the touchdown
  /// point); if that fails, from the default shape as a cold solve.
  bool initial_shape_is_equilibrium = false;
  /// Converged state of a previous solve on the same model (same mesh) to warm
  /// start from (FeStaticsResult::state); takes precedence over initial_shape.
  std::optional<Eigen::VectorXd> warm_start_state;
  /// Node arc lengths of that solution (FeStaticsResult::node_arc_length_m),
  /// which differ from the model's mesh where a node was moved onto the
  /// touchdown point; optional, used with warm_start_state or an
  /// initial_shape_is_equilibrium.
  std::vector<double> warm_start_node_arc_length_m;
  /// Factorised Jacobian of that solution (FeStaticsResult::tangent); the
  /// warm solve predicts the first-order response to the end displacements
  /// with it, then steps with it while it contracts the residual (modified
  /// Newton) instead of re-assembling. Optional, used with warm_start_state;
  /// ignored if it belongs to another mesh size.
  std::shared_ptr<const FeLineTangent> warm_start_tangent;
  /// The condensed 3×3 dF_B/dx_B (a factorisation at the solution and three
  /// back-substitutions).
  bool compute_end_B_stiffness = true;
  /// After converging by chord steps, go on with chord steps while they
  /// contract, to 1e-3 of the tolerance (the state a Newton step would have
  /// left). Off for screening solves that only need the tolerance (the SOZ
  /// march, the pretension optimizer).
  bool polish_chord_steps = true;
  /// Move the nearest node onto the touchdown point and re-solve (r-adaptivity;
  /// keeps the element's convergence order on lines that lie on the seabed).
  bool snap_node_to_touchdown = true;
};

struct FeTouchdown {
  double arc_length_m = 0.0;  ///< unstretched, from end A
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
};

struct FeStaticsResult {
  // Per node (node 0 at end A).
  std::vector<double> node_arc_length_m;  ///< unstretched arc length from A
  std::vector<Eigen::Vector3d> node_position_m;
  std::vector<double> node_tension_N;          ///< effective tension EA(|r'| − 1) at the node
  std::vector<double> node_curvature_per_m;    ///< κ, mean of the two adjacent elements
  std::vector<double> node_bending_moment_Nm;  ///< EI κ
  /// Net force on each node's position DOFs (internal + external), N: zero up
  /// to the tolerance at free nodes; at the ends it is the end force below.
  std::vector<Eigen::Vector3d> node_force_residual_N;
  // Per element.
  std::vector<double> element_tension_N;  ///< effective tension at the element midpoint
  // Ends: the force the line exerts on each end, N (global frame).
  Eigen::Vector3d end_A_force_N = Eigen::Vector3d::Zero();
  Eigen::Vector3d end_B_force_N = Eigen::Vector3d::Zero();
  /// d(end_B_force_N)/d(end_B_m), N/m, with all free DOFs re-equilibrated
  /// (static condensation of the Jacobian). The hull stiffness contribution
  /// is its negative.
  Eigen::Matrix3d end_B_stiffness_N_per_m = Eigen::Matrix3d::Zero();
  bool has_end_B_stiffness = false;  ///< end_B_stiffness_N_per_m computed (FeStaticsOptions::compute_end_B_stiffness)
  /// Last contact point along the line from A (lift-off point, z = z_seabed);
  /// empty when nothing touches. With a penalty seabed it lies ≈ √(H/k)
  /// beyond the rigid-seabed touchdown point (H: horizontal tension).
  std::optional<FeTouchdown> touchdown;
  int iterations = 0;            ///< total Newton iterations
  int load_steps = 0;            ///< Newton solves (continuation stages)
  int touchdown_remeshes = 0;    ///< node moves onto the touchdown point
  int jacobian_evaluations = 0;  ///< Jacobian assemblies + factorisations (incl. the end-B stiffness)
  double residual_N = 0.0;       ///< final max nodal force residual
  double force_scale_N = 0.0;    ///< scale the tolerance refers to
  /// [r, r'] per node (a second r' at hinge joints), for warm starts.
  Eigen::VectorXd state;
  /// Factorised Jacobian (at the converged state when compute_end_B_stiffness),
  /// for warm starts (FeStaticsOptions::warm_start_tangent).
  std::shared_ptr<const FeLineTangent> tangent;
};

/// Node arc lengths (unstretched, from A) of the mesh the model produces.
/// Throws SolverError on invalid model data.
std::vector<double> fe_line_mesh(const FeLineModel& model);

/// Seeds `options` with everything a previous solution of the same model
/// offers a warm start: its state, node arc lengths and factorised tangent.
inline void warm_start_from(FeStaticsOptions& options, const FeStaticsResult& previous) {
  options.warm_start_state = previous.state;
  options.warm_start_node_arc_length_m = previous.node_arc_length_m;
  options.warm_start_tangent = previous.tangent;
}

/// Static equilibrium. Throws SolverError on invalid input (message names the
/// field and value) and on non-convergence (iterations, residual in N, hint).
FeStaticsResult solve_fe_line_statics(const FeLineModel& model, const FeEnvironment& environment,
                                      const FeLineEnds& ends, const FeStaticsOptions& options = {});

/// `solution` (converged by solve_fe_line_statics on `model` in `environment`
/// without compute_end_B_stiffness) completed with its end-B stiffness and
/// the factorised tangent at its own state, bit for bit what the same solve
/// with compute_end_B_stiffness returns: no Newton step, the state is kept
/// (a caller that first needed only the force, then the stiffness at the
/// same ends, gets the results of one solve with both). Throws SolverError
/// when the tangent is singular.
FeStaticsResult with_end_B_stiffness(const FeLineModel& model, const FeEnvironment& environment,
                                     FeStaticsResult solution);

/// d(end_B_force_N)/d(end_B_m) at `solution` (a static solution of `model` in
/// `environment`) when the strain changes from that state are carried by
/// `incremental_EA_N` (one per section, end A first) instead of each
/// section's EA: the static–dynamic two-stiffness convention for fibre ropes
/// (DNV-OS-E301 ch. 2 sec. 2 [2.4], DNV-RP-E305 §2.4; see
/// catenary_incremental_tangent). The state and its forces are the static
/// ones; sign as FeStaticsResult::end_B_stiffness_N_per_m (equal to it when
/// every incremental EA is the section's EA). Throws SolverError on invalid
/// input.
Eigen::Matrix3d fe_line_incremental_end_B_stiffness(const FeLineModel& model, const FeEnvironment& environment,
                                                    const FeStaticsResult& solution,
                                                    const std::vector<double>& incremental_EA_N);

}  // namespace spiral::engine
