#pragma once
// Coupled nonlinear static equilibrium of the hull and every line attached to
// it (step 1 of the semi-coupled method, DESIGN.md §1): the 6-DOF hull
// position where hydrostatics, gravity, the mean environmental loads and the
// line forces balance.
//
// Newton's method on the 6 DOF (offset with roll, pitch, yaw) with the
// tangent K_hydro + K_external + K_lines·diag(I, T) (equilibrium_tangent):
// K_lines analytic per small global rotation (line_array.hpp), mapped to the
// Euler angles by T; K_external by central differences of the mean
// environmental load, which turns with the hull's yaw (without it Newton
// converges only linearly, ≈ 1e-2 per iteration on the default FPS in its
// current). A backtracking line search on a scaled residual, and step
// limits; the attitude is updated by composing small global rotations, so
// large yaw is exact. Trial poses solve the lines' forces only; their
// stiffness is computed where a Newton step needs it.

#include <functional>
#include <memory>
#include <span>

#include "engine/analysis/line_array.hpp"

namespace spiral::engine {

/// The hull as statics sees it: linear hydrostatic + gravity restoring about
/// the reference point and the force at rest (buoyancy − weight, and the
/// moments of a CoB/CoG that are not on one vertical).
struct HullStaticModel {
  Eigen::Vector3d reference_point_at_rest_g = Eigen::Vector3d::Zero();  ///< m
  Matrix6d hydrostatic_stiffness = Matrix6d::Zero();  ///< buoyancy + gravity, about the reference point
  Vector6d rest_force = Vector6d::Zero();             ///< N, N·m at zero offset
};

/// Mean environmental load on the hull (N, N·m about the displaced reference
/// point, global axes) as a function of the hull offset (it may depend on yaw).
using ExternalLoad = std::function<Vector6d(const Vector6d& offset)>;

struct EquilibriumOptions {
  int max_iterations = 60;
  /// Converged when |force residual| ≤ tol·F_ref and |moment residual| ≤
  /// tol·F_ref·L_ref, with F_ref the largest of the rest force and the summed
  /// line-force magnitudes and L_ref the largest attachment arm (≥ 1 m).
  double relative_tolerance = 1e-9;
  double max_translation_step_m = 25.0;  ///< per Newton step
  double max_rotation_step_rad = 0.05;   ///< per Newton step (≈ 2.9°)
  /// EquilibriumResult::lines with the stiffness at the solution (false: the
  /// forces only there, when the caller needs no K: the FE lines then skip a
  /// factorisation each). Always the exact one.
  bool stiffness_at_solution = true;
  /// The Newton tangent keeps the line array's stiffness of an earlier
  /// iteration of this solve while no attachment has moved more than this
  /// (m, translation plus rotation times the largest arm) since it was
  /// computed: the closing steps of a solve started near its solution then
  /// cost the FE lines no Jacobian factorisation. A quasi-Newton step: its
  /// error is the stiffness change over that distance (an FE riser's end
  /// stiffness changes over metres of offset), so the convergence stays fast;
  /// the converged state is the same to the tolerance. 0: a fresh stiffness
  /// at every Newton pose.
  double stiffness_reuse_distance_m = 0.0;
};

struct EquilibriumResult {
  Vector6d offset = Vector6d::Zero();  ///< m, rad (roll, pitch, yaw; R = Rz·Ry·Rx)
  HullPose pose;
  Vector6d residual = Vector6d::Zero();
  Vector6d hydrostatic_force = Vector6d::Zero();
  Vector6d external_force = Vector6d::Zero();
  LineArrayResponse lines;  ///< forces and analytic 6×6 stiffness at the solution
  int iterations = 0;
  double force_reference_N = 0.0;
};

/// Throws SolverError (which DOF, residual, iterations, what to try) when the
/// equilibrium cannot be found, or when a line fails (the line is named).
EquilibriumResult solve_static_equilibrium(const HullStaticModel& hull,
                                           std::span<const std::unique_ptr<StaticLine>> lines,
                                           const ExternalLoad& external_load,
                                           const Vector6d& initial_offset = Vector6d::Zero(),
                                           const EquilibriumOptions& options = {});

/// −d(external load)/d(offset) by central differences (steps 1 cm and 1e-4
/// rad, as FiniteDifferenceSteps of the line array: truncation below 1e-8 of
/// a load that varies over metres and degrees). Zero for an empty function.
/// Where a step leaves the load's table (TableRangeError, e.g. a relative
/// heading at the edge of a coefficient table), a one-sided difference; a
/// column whose both steps leave it is zero.
Matrix6d external_load_stiffness(const ExternalLoad& external_load, const Vector6d& offset);

/// The equilibrium's Jacobian −dR/dq in its unknowns q = offset (x, y, z,
/// roll, pitch, yaw) at `offset`: hydrostatics and the mean environmental
/// load are functions of the angles, the line array's analytic K
/// (`line_stiffness`) is per small global rotation ω = T(angles) d(angles)
/// (euler_rate_to_global), so K_h + K_env + K_lines·diag(I, T). Without T the
/// Newton converges linearly once the hull has turned (roll/pitch mixed by the
/// yaw: a ratio of ≈ 0.2 per iteration at 12° of yaw).
Matrix6d equilibrium_tangent(const HullStaticModel& hull, const Matrix6d& line_stiffness,
                             const ExternalLoad& external_load, const Vector6d& offset);

/// diag(I, T(angles)): an increment of the offset (translations, Euler
/// angles) as translations and a small global rotation.
Matrix6d offset_increment_to_global(const Vector6d& offset);

/// Roll, pitch, yaw (rad) of a rotation matrix, R = Rz(yaw)·Ry(pitch)·Rx(roll).
Eigen::Vector3d roll_pitch_yaw(const Eigen::Matrix3d& rotation);

}  // namespace spiral::engine
