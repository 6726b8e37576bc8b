#pragma once
// Low-frequency 6-DOF hull equations of motion in the time domain — step 3 of
// the semi-coupled (S-C) method and the hull part of the uncoupled level
// (DESIGN.md §1):
//
//   (M + A + A_lines) q'' + (B_lin + B_lines) q' + diag(b_quad) |q'| q'
//       + mu(t) + C_hydro q = F_hs0 + F_lines(q, q') + F_ext(t, q, q')
//
//   q      offset of the hull reference point from its position at rest
//          (surge, sway, heave in m; roll, pitch, yaw in rad; DESIGN.md §4)
//   mu(t)  radiation memory (Cummins 1962), int_0^t_max K(tau) q'(t - tau) dtau,
//          only with a RetardationKernel; A must then be A(inf)
//   F_hs0  net hydrostatic force at q = 0 (buoyancy − weight, e.g. the
//          vertical line pretension the hull carries at rest)
//
// Kinematic assumption. The equations are written in the earth-fixed frame
// with q' = dq/dt. Roll and pitch are small: their rates are taken as the
// angular-velocity components and the moments as their generalized forces
// (linearized rotational kinematics, the usual low-frequency model). Yaw may
// be large only through the force callbacks: the nonlinear line force and
// F_ext receive the full q and may evaluate the exact pose
// (pose_from_offset, R = Rz·Ry·Rx). The hull's own matrices M, A, B, b_quad,
// C are constant (not rotated with yaw), and the Coriolis–centripetal terms of
// a yawing hull (~ m·yaw'·u, second order in low-frequency velocity) are
// neglected: exact for a hull whose matrices are invariant under rotation
// about z (a symmetric semi-submersible or a spar), approximate for a
// weathervaning ship-shaped hull at large mean yaw, where the caller should
// rotate the matrices into the mean heading.
//
// State layout: y = [q (6); q' (6)] (a flat Eigen::VectorXd, STYLE rule 2).
// The derivative is a pure function of (model, loads, memory history, t, y).
//
// Errors: std::invalid_argument for invalid model data (non-finite entries,
// a total mass matrix that is not positive definite, negative quadratic
// damping, a DOF index out of range); IntegrationError (a SolverError) when
// the integrator fails; the line/external callbacks' exceptions pass through
// (SolverError from a callback is retried with a smaller step first).

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>
#include <functional>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "engine/numerics/sundials_cvode.hpp"
#include "engine/common/eigen_types.hpp"
#include "engine/hull/retardation_kernel.hpp"

namespace spiral::engine {

/// The hull: mass, hydrodynamics and hydrostatics about the reference point.
struct HullDynamicsModel {
  Matrix6d mass = Matrix6d::Zero();                       ///< rigid-body M (rigid_body_mass_matrix)
  Matrix6d added_mass = Matrix6d::Zero();                 ///< A(0) low-frequency, or A(inf) with memory
  Matrix6d linear_damping = Matrix6d::Zero();             ///< B_lin, N/(m/s), N·m/(rad/s) …
  Vector6d quadratic_damping = Vector6d::Zero();          ///< b_quad per DOF, N/(m/s)², N·m/(rad/s)², >= 0
  Matrix6d hydrostatic_stiffness = Matrix6d::Zero();      ///< C_hydro incl. gravity terms, N/m, N·m/rad
  Vector6d hydrostatic_force_at_rest = Vector6d::Zero();  ///< F_hs0, N, N·m
  std::optional<RetardationKernel> radiation_memory;      ///< Cummins memory; A must be A(inf)
};

/// A relaxation of the lines' stiffness (a Zener, or standard linear solid,
/// element): with x = q − q0 and an internal state z (6, m and rad),
///   F = −Δ (x − z),   τ ż = x − z,
/// i.e. −Δ iωτ/(1 + iωτ) X at frequency ω: nothing for a slow motion (z
/// follows x), the added stiffness Δ for a fast one, and most damping at
/// ωτ = 1. A line restrained by a strong current stiffens so at low
/// frequency: its current-loaded shape relaxes through the water
/// (engine/lines/fe_line_impedance.hpp).
struct LineRelaxation {
  Matrix6d stiffness = Matrix6d::Zero();  ///< Δ, symmetric positive semi-definite, N/m, N·m/rad …
  double time_constant_s = 0.0;           ///< τ, > 0
};

/// Semi-coupled line model (DESIGN.md §1, step 2): the line array linearized
/// at the static equilibrium q0,  F = F0 − K (q − q0) − B_lines q'.
/// The enhanced S-C adds B_lines (line damping) and A_lines (line added mass at
/// the fairleads, added to M), and with the lines' dynamic reduction their
/// relaxations.
struct LinearizedLines {
  Vector6d force_at_equilibrium = Vector6d::Zero();  ///< F0, N, N·m
  Matrix6d stiffness = Matrix6d::Zero();             ///< K = −dF/dq at q0
  Vector6d equilibrium_offset = Vector6d::Zero();    ///< q0, m, rad
  std::optional<Matrix6d> damping;                   ///< B_lines (enhanced S-C)
  std::optional<Matrix6d> added_mass;                ///< A_lines (enhanced S-C)
  /// The lines' frequency-dependent stiffness (enhanced S-C with the lines'
  /// dynamic reduction): each adds six states to the hull's equations, which
  /// start relaxed (z = x: no force).
  std::vector<LineRelaxation> relaxations;
};

/// Uncoupled level: the lines as nonlinear quasi-static restoring forces,
/// F_lines(q) (N, N·m about the displaced reference point, global axes), e.g.
/// evaluate_line_array at pose_from_offset(q). May throw SolverError
/// (treated as a recoverable integrator failure).
using NonlinearLineForce = std::function<Vector6d(const Vector6d& q)>;

using LineForceModel = std::variant<LinearizedLines, NonlinearLineForce>;

/// External low-frequency force F_ext(t, q, q') (N, N·m): wave slow drift,
/// wind and current with relative velocity — built by the caller.
using ExternalForce = std::function<Vector6d(double t_s, const Vector6d& q, const Vector6d& q_dot)>;

/// What acts on the hull besides its own hydrodynamics.
struct HullLoads {
  LineForceModel lines = LinearizedLines{};
  ExternalForce external;  ///< empty = no external force
};

/// Velocity history for the radiation memory, sampled at the kernel's time
/// step: velocities.col(k) = q'(t_start + k·dt) (k = 0 .. count−1). Before
/// t_start the hull is at rest. An input of the derivative, written only by
/// the driver between steps.
struct VelocityHistory {
  double start_time_s = 0.0;
  double time_step_s = 0.0;
  Eigen::Matrix<double, 6, Eigen::Dynamic> velocities;
  Eigen::Index count = 0;
};

/// The radiation memory force mu(t) = int_0^t_max K(tau) q'(t − tau) dtau by
/// the trapezoidal rule on the history grid, with q'(t) = the current
/// velocity and K between table points linearly interpolated. Between t and
/// the newest stored sample the velocity is joined linearly (one trapezoid
/// when that is at most a step, the kernel's grid inside a longer gap).
/// Cost per call: about n_kernel × 36 multiply-adds (a 60 s kernel at 0.1 s:
/// ~2e4).
Vector6d radiation_memory_force(const RetardationKernel& kernel, const VelocityHistory& history, double t_s,
                                const Vector6d& velocity);

/// Time-independent data derived once from a model and its line model.
struct HullEquations {
  HullDynamicsModel model;
  HullLoads loads;
  Matrix6d total_mass;  ///< M + A + A_lines
  Eigen::PartialPivLU<Matrix6d> total_mass_lu;
  Matrix6d total_linear_damping;  ///< B_lin + B_lines
};

/// Validates the model and factorizes the total mass matrix.
HullEquations make_hull_equations(const HullDynamicsModel& model, const HullLoads& loads);

/// The force on the hull at (t, q, q') other than inertia (everything on the
/// right-hand side minus the left-hand damping/stiffness terms), N, N·m.
Vector6d hull_generalized_force(const HullEquations& eq, double t_s, const Vector6d& q, const Vector6d& q_dot,
                                const VelocityHistory* history);

/// y' = f(model, loads, history, t, y) with y = [q; q'; z_1 … z_R] (z_j: the
/// states of the lines' relaxations, LinearizedLines::relaxations). Writes ydot only.
void hull_state_derivative(const HullEquations& eq, const VelocityHistory* history, double t_s,
                           const Eigen::VectorXd& y, Eigen::VectorXd& ydot);

/// Integrator settings for the hull. Default: Adams–Moulton (variable order
/// up to 12) with Newton and a dense difference-quotient Jacobian — the
/// low-frequency system is non-stiff (periods 17–120 s) and smooth, where high
/// order pays; rtol 1e-10, atol 1e-10 m and m/s, 1e-12 rad and rad/s. The
/// integration error is then far below any engineering resolution (measured
/// in tests/validation/engine/analysis/hull_free_decay_test.cpp: period error ~1e-6, energy
/// drift 7e-7 over 20 surge periods of OC4). With a NonlinearLineForce from
/// catenary solves, the force carries the line solvers' closure noise (~1e-9
/// relative): raise rtol to 1e-7..1e-8, above that noise, or the error test
/// fails repeatedly.
CvodeOptions default_hull_integrator_options();

struct HullSimulationOptions {
  double start_time_s = 0.0;
  std::vector<double> output_times_s;  ///< strictly increasing, >= start_time_s
  CvodeOptions integrator = default_hull_integrator_options();
};

/// Time series of a hull simulation.
struct HullTimeSeries {
  Eigen::VectorXd times_s;
  Eigen::Matrix<double, 6, Eigen::Dynamic> position;  ///< q at times_s, m, rad
  Eigen::Matrix<double, 6, Eigen::Dynamic> velocity;  ///< q' at times_s, m/s, rad/s
  CvodeStatistics statistics;
  double wall_clock_s = 0.0;  ///< cost of the run (DESIGN.md §1: every level reports it)
};

/// Integrates the hull equations from (q0, q'0). With radiation memory the
/// integration advances in history steps (CVODE stops exactly at each, no
/// restart) and appends q' to the history after each. Cost with memory: at
/// least one step per history step, each RHS ~n_kernel × 72 flops; the
/// memory force is only piecewise smooth in t, so use rtol ~1e-7: the 1e-10
/// default costs several times as much for no gain (timings in
/// docs/decisions/hull-dynamics-tolerances.md).
HullTimeSeries simulate_hull(const HullDynamicsModel& model, const HullLoads& loads, const Vector6d& initial_position,
                             const Vector6d& initial_velocity, const HullSimulationOptions& options);

/// Free decay in one DOF (0..5): starts at rest at the equilibrium (q0 of
/// LinearizedLines; q = 0 for a nonlinear line force) displaced by
/// `initial_displacement` (m or rad) in `dof`, no external force, outputs
/// every output_step_s over duration_s.
HullTimeSeries free_decay(const HullDynamicsModel& model, const LineForceModel& lines, int dof,
                          double initial_displacement, double duration_s, double output_step_s = 0.05,
                          const CvodeOptions& integrator = default_hull_integrator_options());

}  // namespace spiral::engine
