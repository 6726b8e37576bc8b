#pragma once
// The fully coupled level (DESIGN.md §1): the hull's 6-DOF low-frequency
// equations (hull_dynamics.hpp) and the dynamic FE model of every line
// (fe_line_dynamics.hpp) integrated together as one implicit system with
// SUNDIALS IDA. Every line's force acts on the hull at every step (inside
// every Newton iteration), and the hull moves every line's end.
//
// Unknowns: y = [q, q̇ (hull, 12); y_1 … y_L (lines: [q_i, v_i])]. Line i's
// end B is held at the attachment point p_i(q̃) = x_ref(q̃) + R(q̃) r_i of the
// hull at the total offset q̃ = q + q_w(t) — the low-frequency state plus a
// prescribed wave-frequency motion q_w (from RAOs, as the S-C level; zero
// for a hull whose model carries its wave-frequency loads) — with velocity
// P_i q̃̇ and acceleration P_i q̃̈ + Ṗ_i q̃̇, P_i = ∂p_i/∂q̃ (3 × 6). The
// line's force on the hull is the generalized force of its end force f_i
// (virtual work f_i · δp_i = (P_iᵀ f_i) · δq), so the hull and the lines
// exchange energy exactly:
//   M_h q̈ = F_hull(t, q, q̇) + Σ_i P_iᵀ f_i(y_i, q̃),
// with F_hull the hull's own forces (hydrostatics, damping, slow drift,
// wind, current: hull_generalized_force with no line model).
//
// Newton solve: each line's reduced banded system (fe_dynamic_line.hpp) is
// condensed onto its end B — the line's dynamic stiffness Σ_i (3 × 3) and a
// force correction φ_i — so the hull's 6 × 6 Newton matrix becomes
//   c² M_h + c B_h + K_h + K_geo + Σ_i P_iᵀ Σ_i P_i
// (B_h, K_h: finite differences of F_hull at the setup; K_geo: the change of
// P_iᵀ f_i with the hull's rotation at fixed f_i), solved once, and the
// lines' corrections follow by back-substitution. The cost per Newton
// iteration is that of the lines' own solves plus 6 × 6 work: the coupled
// system costs about what the lines cost with the motion prescribed, but
// every line shares the one step size.
//
// Error control: the hull and every line are separate error groups
// (IdaOptions::error_group_starts): each meets the tolerance by itself.
//
// Lines are evaluated on `threads` threads of a worker pool (residual,
// setup, both halves of the solve; each line writes its own slots, the hull sums in line order, so
// the result does not depend on the thread count).
//
// Choices that set the cost (docs/decisions/coupled-dynamics-performance.md
// has the measurements behind each, and what was tried and not kept):
//  * the error norm is per block (above): one WRMS norm over all states let
//    a line's or the hull's error through, diluted by √(N/n);
//  * the lines run on a persistent worker pool, not on threads started per
//    loop, and so do IDA's vector operations (IdaOptions::vector_pool;
//    bit-identical); the system works on IDA's vectors in place
//    (ImplicitSystem takes Eigen::Ref);
//  * a partial Newton-matrix update refactors only the lines whose seabed
//    contact changed by 10 % of an element or whose c_j moved by 25 %; a
//    line refactored for its contact keeps its end-B condensation from the
//    last full setup, one refactored for c_j is condensed again (its end
//    stiffness goes as c_j²); a coarser contact refresh leaves the
//    stale-matrix Newton iterates' error in the motion;
//  * at an output time the end force comes from the end element's own wave
//    kinematics (evaluate_point), not from every element's.
//
// Radiation memory (Cummins 1962), when the hull model has a kernel: the
// hull takes A(inf) and the convolution of hull_dynamics.hpp, on a velocity
// history the driver extends at each output time by cubic Hermite
// interpolation of IDA's velocities and accelerations (the run stops at its
// outputs only); inside an output step the newest velocities are joined
// linearly. Waves on the lines come from the lines' environments
// (FeDynamicEnvironment::sea / waves).

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/analysis/hull_dynamics.hpp"
#include "engine/numerics/sundials_ida.hpp"
#include "engine/lines/fe_line_dynamics.hpp"

namespace spiral::engine {

/// One line of the coupled system.
struct CoupledLine {
  std::string name;
  FeLineModel model;
  FeDynamicEnvironment environment;
  /// Static solution of `model` with end B at the attachment point of the
  /// hull at its initial position (and the prescribed motion's value at the
  /// start time, which the build-up ramp makes zero).
  FeStaticsResult initial;
  Eigen::Vector3d attachment_b_m = Eigen::Vector3d::Zero();  ///< body frame, from the reference point
  FeEndCondition end_A = FeEndCondition::fixed;              ///< fixed or free
};

/// A prescribed wave-frequency hull motion (m, rad; and its derivatives).
struct PrescribedHullMotion {
  Vector6d position = Vector6d::Zero();
  Vector6d velocity = Vector6d::Zero();
  Vector6d acceleration = Vector6d::Zero();
};
using PrescribedHullMotionFn = std::function<PrescribedHullMotion(double t_s)>;

struct CoupledOptions {
  double start_time_s = 0.0;
  std::vector<double> output_times_s;  ///< strictly increasing, > start_time_s
  /// Integrator tolerances: the lines' (FeDynamicsOptions' defaults) and the
  /// hull's absolute ones.
  double relative_tolerance = 2e-6;
  double position_tolerance_m = 1e-4;
  double slope_tolerance = 2e-6;
  double velocity_tolerance_m_per_s = 0.1;
  /// The hull's absolute tolerances (positions; velocities 10× per second).
  /// BDF2's period error grows as (ω h)²: where only the hull limits the
  /// step (a free decay), 1e-4 m gives 0.39 % on OC4's 17.6 s heave and
  /// 1e-5 m 0.07 % (coupled_dynamics_test); in a storm the lines limit the
  /// step (h ≈ 0.2 s: ≤ 0.2 % on a 17 s period), where 1e-5 m would let the
  /// gust-driven hull accelerations set it instead
  /// (docs/decisions/coupled-dynamics-performance.md).
  double hull_position_tolerance_m = 1e-4;
  double hull_rotation_tolerance_rad = 1e-6;
  int max_order = 2;
  std::optional<double> max_step_s;
  long max_steps_between_outputs = 500000;
  int threads = 1;  ///< >= 1
  /// A full Newton-matrix setup (every line's element matrices evaluated
  /// again, every line refactored and condensed) at least every this many
  /// steps; between them a line is refactored only when c_j moved or its
  /// seabed contact changed, on its old element matrices. 8 rather than
  /// IDA's 20: without wave-frequency motion, lc1 600 s, 2,221 → 1,927 steps,
  /// statistics within 0.7 % (5: no fewer steps, more setups). Under
  /// wave-frequency motion, default FPS, 200 s, the 12 risers' top-tension
  /// std against 0.03 of the tolerances (std after 60 s): a setup at every
  /// step +1.9 to +2.5 % on lc5 and +0.9 to +1.0 % on lc1; every 8 steps
  /// +1.0 to +1.2 % and +0.5 to +0.6 %, in 0.59 of the time (lc5 27.1 →
  /// 16.0 s, lc1 43.8 → 26.1 s). A setup at every step had been needed
  /// there while the split solve counted the predictors' difference at end
  /// B as a motion of the end (fe_dynamic_line.hpp, "End B attached"): on a
  /// stale matrix the iteration then converged too slowly for IDA's test
  /// (docs/decisions/coupled-dynamics-performance.md, "The coupled Newton
  /// solve and end B").
  int steps_between_full_setups = 8;
  /// With these, a full setup re-evaluates only the elements that have
  /// moved since their matrices were evaluated: a slope component (r',
  /// dimensionless: its direction and strain) by more than
  /// element_refresh_slope, or a node's velocity or the sea's at the element
  /// by more than element_refresh_velocity_m_per_s; the others keep theirs
  /// (a change of seabed contact re-evaluates an element in any case). 0
  /// (the default): every element at every full setup. Measured on the
  /// default FPS, lc2, 100 s, WF motion, a setup at every step: 1e-4 and
  /// 0.05 m/s keep 61 % of the element matrices, the run takes the same 738
  /// steps, 1,732 residuals and 2 failed Newton solves, every output stays
  /// within 8.5e-5 of its range of the every-element run's, and the run is
  /// 14 % faster; 1e-3 and 0.3 m/s keep 93 %, fail 77 Newton solves and
  /// take 856 steps. With a setup every 8 steps under WF motion: lc5 200 s
  /// 18.8 → 16.0 s, lc1 26.6 → 26.1 s, the risers' std as close to the
  /// reference. Without WF motion the kept matrices are older than the
  /// partial updates' (OC4 free decay: 1e-4 and 0.05 m/s, 849 → 1,031
  /// steps), so the design layer sets these under WF motion only
  /// (docs/decisions/coupled-dynamics-performance.md, "Selective refresh").
  double element_refresh_slope = 0.0;
  double element_refresh_velocity_m_per_s = 0.0;
  /// At each output the line pool grows to the cores that other
  /// parallel_for work has freed (worker_count), up to a thread per line: a
  /// run started beside another (the advanced stage's verifications two at
  /// a time) gets both cores once the other ends. Results do not depend on
  /// the thread count (each line and vector range writes its own values).
  bool take_freed_cores = false;
  PrescribedHullMotionFn wave_frequency_motion;  ///< empty: none
};

struct CoupledTimeSeries {
  Eigen::VectorXd times_s;                                              ///< start time, then output_times_s
  Eigen::Matrix<double, 6, Eigen::Dynamic> position;                    ///< low-frequency hull offset q, m, rad
  Eigen::Matrix<double, 6, Eigen::Dynamic> velocity;                    ///< q̇
  std::vector<Eigen::Matrix<double, 3, Eigen::Dynamic>> end_B_force_N;  ///< per line, global
  IdaStatistics statistics;
  /// Per line (then the hull, last): at how many outputs its weighted local
  /// error was the largest — which part of the system sets the step.
  std::vector<long> step_limiting_outputs;
  long state_size = 0;
  /// Element-matrix evaluations (every line, setups and partial updates),
  /// and the element matrices full setups kept (element_refresh_slope).
  long element_matrix_evaluations = 0;
  long element_matrices_kept = 0;
  double wall_clock_s = 0.0;
};

/// Integrates hull + lines from the hull at `initial_offset` (at rest; the
/// lines from their static solutions). `loads.lines` must be a
/// LinearizedLines (usually all zero: the FE lines replace it; non-zero it
/// adds, e.g., lines left out of the FE set). Throws std::invalid_argument
/// for bad options, SolverError for a line
/// that cannot start (named), IntegrationError (time reached, cause) when
/// the integration fails.
CoupledTimeSeries simulate_coupled(const HullDynamicsModel& hull, const HullLoads& loads,
                                   const Eigen::Vector3d& reference_point_at_rest_g, const Vector6d& initial_offset,
                                   const std::vector<CoupledLine>& lines, const CoupledOptions& options);

}  // namespace spiral::engine
