#pragma once
// Time-domain dynamics of one mooring line or riser: the ANCF cable/beam
// element of the FE statics (fe_line_statics.hpp: same mesh, DOFs, internal
// forces, weight, seabed penalty) in motion, started from a static solution.
//
// Equations of motion (d'Alembert, per free DOF of the element assembly):
//   M(q) q̈ = g_static(q) + g_dyn(t, q, q̇) ,
// with the consistent mass M of the Hermite shape functions (structural mass
// plus the normal/tangential added mass, which makes M depend on the line
// direction; Gerstmayr & Shabana 2006 note that the ANCF mass matrix is
// otherwise constant), and g_dyn the Morison drag on the velocity relative
// to current + waves, Froude–Krylov and added-mass fluid inertia, axial
// (Kelvin–Voigt) damping, seabed damping and regularised Coulomb friction —
// see ancf_dynamic_loads.hpp for each term and its source.
//
// Polyester (section EA_dynamic_N > 0): the dynamic stiffness acts on the
// strain change from the static state — N = EA_s ε_s + EA_d (ε − ε_s), the
// "static–dynamic" two-stiffness model of DNV-OS-E301 ch. 2 sec. 4 /
// DNV-RP-E305 — so the static solution stays an equilibrium.
//
// Integration: SUNDIALS IDA (variable-step BDF, order ≤ 2 by default: A-stable,
// so the axial modes of a stiff line — periods of milliseconds — do not limit
// the step; they are damped numerically instead of resolved) on the first-
// order DAE y = [q, v]:
//   q̇ − v = 0,   M a − g(t, q, v) = 0        (free DOFs)
//   q − q_p(t) = 0,   v − q̇_p(t) = 0         (prescribed DOFs: algebraic)
// The Newton matrix [[c I, −I], [−K, c M − C]] is reduced to the banded
// n × n matrix S = c² M − c C − K (K = ∂g/∂q, C = ∂g/∂q̇) by eliminating
// the velocity corrections (δv = c δq − b_q), so each factorisation costs
// that of the static tangent (half-bandwidth 11–14) instead of a 2n system
// with twice the band: ≈ 14× fewer operations.
//
// Per step (fe_line_dynamics.cpp): one pass over each element's Gauss points
// for the whole residual (ancf::dynamic_element_forces; shape functions
// cached, element lengths being fixed) and one for its Newton matrices
// (ancf::element_newton_matrices: M, C, K kept per element); S is symmetric
// and, for a line in tension, positive definite: banded Cholesky, band LU as
// the fallback. The Newton matrix is refreshed in full every 20 steps and
// after a convergence failure, and updated — new c_j, re-evaluated elements
// — when c_j changed by 25 % or an element's seabed contact by 10 % of its
// length (the contact stiffness k L ≈ 1e7 N/m of an OC4 element dwarfs
// c² M: a matrix factored before the change makes the Newton iteration
// diverge).
//
// What limits the step: a ≈ 2.5 s in-plane mode of the lower catenary, in
// the vertical slopes of the nodes from the touchdown point to ≈ 150 m above
// it; BDF2 resolves it with ≈ 50 steps per period at rtol 1e-6. The
// benchmark behind the defaults, and what was tried and not kept (BDF order
// > 2, tolerances along the line, other refresh rules, ARKODE's DIRK and
// ESDIRK methods), are in docs/decisions/fe-line-dynamics-integrator.md.
//
// Why implicit: an explicit step must resolve the highest axial frequency,
// ω ≈ 2 √(EA/(m h²)) — for the OC4 chain with 80 elements (h = 10.4 m)
// 494 rad/s, a step below 4–6 ms; for a steel riser with 1 m elements near
// the touchdown point below 0.1 ms. The implicit step follows the motion
// instead (tenths of a second for wave-frequency motions).
//
// Ends: end A (anchor, riser foot) fixed at its static position or free; end
// B (fairlead, hang-off) prescribed by a motion, fixed, or free. Slopes are
// free at every end (pinned). The end force is the force the line exerts on
// the support, inertia of the line included.
//
// Frames and units: global frame, z up, SI.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "engine/numerics/sundials_ida.hpp"
#include "engine/environment/wave_realization.hpp"
#include "engine/lines/fe_line_statics.hpp"

namespace spiral::engine {

/// Fluid velocity and acceleration of the waves at a global point and time
/// (Airy kinematics with Wheeler stretching, engine/environment); zero above
/// the surface.
using WaveKinematicsFn = std::function<void(const Eigen::Vector3d& point_m, double t_s,
                                            Eigen::Vector3d& velocity_m_per_s, Eigen::Vector3d& acceleration_m_per_s2)>;

struct FeDynamicEnvironment {
  FeEnvironment statics;                    ///< density, current, seabed level, penalty stiffness and axial friction
                                            ///< coefficient
  double seabed_lateral_friction = 0.0;     ///< μ across the line, >= 0
  double seabed_damping_N_s_per_m2 = 0.0;   ///< per m of line per m/s vertical, in contact, >= 0
  double friction_velocity_m_per_s = 0.01;  ///< full friction above this sliding speed, > 0
  WaveKinematicsFn waves;                   ///< empty: no waves (a point-wise field)
  /// A wave realization acting on the line: linear kinematics at a point per
  /// element, moved to its midpoint at an output time when the element has
  /// drifted 0.5 m from it (engine/environment/fixed_point_wave_kinematics.hpp),
  /// added to `waves` if both are given. Null: none.
  std::shared_ptr<const WaveRealization> sea;
  /// The sea's kinematics built up from 0 by a quintic ramp over this time
  /// from the start time (engine::smooth_ramp), as the hull motion is: a
  /// line at rest cannot meet the full wave flow at once. >= 0.
  double sea_ramp_s = 0.0;
  /// The sea's sums taken on a time grid of this interval and interpolated
  /// between (FixedPointWaveKinematics, "Sampled in time"): unset, the
  /// interval at which the interpolated acceleration's rms error is 1e-3
  /// of the rms acceleration (FixedPointWaveKinematics::
  /// default_sample_interval_s); 0: summed at every residual time. >= 0.
  std::optional<double> sea_sample_interval_s;
};

/// Position, velocity and acceleration of a prescribed end at time t (global).
struct EndKinematics {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration_m_per_s2 = Eigen::Vector3d::Zero();
};
using EndMotionFn = std::function<EndKinematics(double t_s)>;

/// attached: end B follows a body whose equations are integrated with the
/// line (the coupled hull + lines system, engine/analysis/coupled_dynamics.hpp).
enum class FeEndCondition { fixed, prescribed, free, attached };

struct FeDynamicsOptions {
  FeEndCondition end_A = FeEndCondition::fixed;
  FeEndCondition end_B = FeEndCondition::prescribed;
  EndMotionFn end_B_motion;  ///< required when end_B is prescribed; at t0 it must equal the static position
  double start_time_s = 0.0;
  /// Optional initial velocity field of the line (global, m/s) as a function
  /// of unstretched arc length from end A (default: at rest); slope rates
  /// follow by central differences.
  std::function<Eigen::Vector3d(double arc_length_m)> initial_velocity;
  // Integrator (IDA). Local error per step: rtol |y| + atol per component.
  // Defaults chosen on the OC4 line benchmark (tests/bench/fe_dynamics_bench,
  // 80 elements, 600 s; docs/decisions/fe-line-dynamics-integrator.md):
  // fairlead tension within 0.3 % of a 160-element rtol-1e-8 reference. The
  // slopes carry the strain (|r'| − 1 = T/EA ≈ 1e-3), so their error sets the
  // tension error. Velocities follow from the positions: their tolerance is
  // loose.
  double relative_tolerance = 2e-6;
  double position_tolerance_m = 1e-4;  ///< node positions
  double slope_tolerance = 2e-6;       ///< slopes r'
  double velocity_tolerance_m_per_s = 0.1;
  int max_order = 2;  ///< 1..5 (> 2 is not A-stable for undamped oscillations)
  std::optional<double> max_step_s;
  std::optional<double> initial_step_s;
  long max_steps_between_outputs = 500000;  ///< IDA gives up (IntegrationError) beyond this
};

/// The state the caller reads at an output time.
struct FeLineDynamicSnapshot {
  double time_s = 0.0;
  std::vector<double> node_arc_length_m;  ///< unstretched, from end A (the mesh of the initial statics)
  std::vector<Eigen::Vector3d> node_position_m;
  std::vector<Eigen::Vector3d> node_velocity_m_per_s;
  std::vector<double> node_tension_N;          ///< effective tension at the nodes (mean of the adjacent element ends)
  std::vector<double> node_curvature_per_m;    ///< κ, mean of the two adjacent element ends (as the statics)
  std::vector<double> node_bending_moment_Nm;  ///< EI κ
  Eigen::Vector3d end_A_force_N = Eigen::Vector3d::Zero();  ///< force of the line on its end A support
  Eigen::Vector3d end_B_force_N = Eigen::Vector3d::Zero();  ///< force of the line on its end B support
  /// Last point below the seabed from end A (as FeStaticsResult::touchdown); empty when nothing touches.
  std::optional<FeTouchdown> touchdown;
};

/// Mechanical energy of the line (no fluid: kinetic energy of the structural
/// mass only), J.
struct FeLineEnergy {
  double kinetic_J = 0.0;
  double strain_J = 0.0;   ///< EA/2 ε² + EI/2 κ² (− N_0 ε for a dynamic EA)
  double gravity_J = 0.0;  ///< ∫ w z ds (w: submerged weight per length)
  double seabed_J = 0.0;   ///< penalty spring ½ k p²
  double total() const { return kinetic_J + strain_J + gravity_J + seabed_J; }
};

class FeLineDynamics {
 public:
  /// `initial`: a converged static solution of `model` (its state and node
  /// arc lengths) in `environment.statics` (with its current: at rest the
  /// drag on the relative velocity equals the static current drag, so the
  /// static solution is the dynamic equilibrium). Throws SolverError on
  /// invalid input (field and value named).
  FeLineDynamics(const FeLineModel& model, const FeDynamicEnvironment& environment, const FeStaticsResult& initial,
                 const FeDynamicsOptions& options);
  ~FeLineDynamics();
  FeLineDynamics(FeLineDynamics&&) noexcept;
  FeLineDynamics& operator=(FeLineDynamics&&) noexcept;

  /// Integrates to t_s (> time_s()). Throws IntegrationError with the time
  /// reached and the cause.
  void advance_to(double t_s);
  double time_s() const;
  FeLineDynamicSnapshot snapshot() const;
  /// Force of the line on the end B support at the last output time (cheaper than a snapshot).
  Eigen::Vector3d end_B_force_N() const;
  FeLineEnergy energy() const;
  IdaStatistics statistics() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace spiral::engine
