#pragma once
// The line array (every mooring line and riser attached to the hull) reduced
// to a 6-DOF force and a 6×6 tangent stiffness at a hull pose — step 2 of the
// semi-coupled method (DESIGN.md §1): K and F that the hull equations of
// motion use in place of the lines.
//
// Force: sum of the line forces on the hull, global axes, and their moments
// about the hull reference point at its displaced position. Stiffness:
// K = −dF/dq for a displacement q = (δu, δθ) of the reference point, with δθ a
// small rotation about the global axes composed onto the current attitude
// (R → Rot(δθ)·R); at zero rotation this equals the derivative with respect
// to roll, pitch and yaw.

#include <memory>
#include <span>
#include <vector>

#include "engine/common/rigid_body.hpp"
#include "engine/analysis/static_line.hpp"

namespace spiral::engine {

/// Position and attitude of the hull.
struct HullPose {
  Eigen::Vector3d reference_point_g = Eigen::Vector3d::Zero();  ///< m
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();       ///< body -> global
  /// Where a point of the hull (body frame, relative to the reference point) is, global.
  Eigen::Vector3d point_g(const Eigen::Vector3d& point_b) const { return reference_point_g + rotation * point_b; }
};

/// The pose of a hull whose reference point is at `reference_point_at_rest_g`
/// at rest, displaced by `offset` (m, rad; DOF order of DESIGN.md §4).
HullPose pose_from_offset(const Eigen::Vector3d& reference_point_at_rest_g, const Vector6d& offset);

/// One line's part of the array response.
struct LineContribution {
  Eigen::Vector3d attachment_g = Eigen::Vector3d::Zero();
  LineEndResponse end;                    ///< force and 3×3 stiffness at the attachment
  Vector6d force = Vector6d::Zero();      ///< its 6-DOF force on the hull
  Matrix6d stiffness = Matrix6d::Zero();  ///< its 6×6 tangent stiffness
};

struct LineArrayResponse {
  Vector6d force = Vector6d::Zero();      ///< N, N·m
  Matrix6d stiffness = Matrix6d::Zero();  ///< analytic tangent, N/m, N/rad, N·m/m, N·m/rad
  bool has_stiffness = true;              ///< false: forces only (LineArrayQuantities::force), stiffness zero
  std::vector<LineContribution> lines;    ///< in the order given
};

/// The 6×6 stiffness of a force f (N) acting at arm a = x_attach − x_ref (m)
/// with 3×3 stiffness K_f = −df/dx_attach:
///   [ K_f        −K_f [a×]               ]
///   [ [a×] K_f   −[a×] K_f [a×] − [f×][a×] ]
/// The last term is the geometric stiffness of a force whose arm turns with
/// the hull; it makes the rotational block non-symmetric unless the total
/// moment vanishes.
Matrix6d attachment_stiffness_6x6(const Eigen::Matrix3d& K_f, const Eigen::Vector3d& force_g,
                                  const Eigen::Vector3d& arm_g);

/// What evaluate_line_array computes: the stiffness of an FE line costs a
/// factorisation of its Jacobian at the solution, often most of a warm solve.
enum class LineArrayQuantities { force_and_stiffness, force };

/// Solves every line at `pose` and sums force and (unless asked for the force
/// only) analytic stiffness.
LineArrayResponse evaluate_line_array(std::span<const std::unique_ptr<StaticLine>> lines, const HullPose& pose,
                                      LineArrayQuantities quantities = LineArrayQuantities::force_and_stiffness);

/// Perturbation sizes of the finite-difference stiffness. Large against the
/// line solvers' closure tolerance (1e-9 m) so that round-off stays below
/// 1e-7 of K, small against the length over which the stiffness of a
/// mooring changes (metres): the O(h²) truncation error is below 1e-8 of K.
struct FiniteDifferenceSteps {
  double translation_m = 1e-2;
  double rotation_rad = 1e-4;
};

/// Central finite differences of the line-array force (12 array solves),
/// the cross-check of the analytic tangent.
Matrix6d finite_difference_stiffness(std::span<const std::unique_ptr<StaticLine>> lines, const HullPose& pose,
                                     const FiniteDifferenceSteps& steps = {});

}  // namespace spiral::engine
