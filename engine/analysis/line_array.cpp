#include "engine/analysis/line_array.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "engine/common/parallel_for.hpp"

namespace spiral::engine {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

/// The pose after a small displacement q = (δu, δθ) composed onto `pose`.
HullPose perturbed(const HullPose& pose, int dof, double step) {
  HullPose p = pose;
  if (dof < 3) {
    p.reference_point_g(dof) += step;
  } else {
    p.rotation = Eigen::AngleAxisd(step, Eigen::Vector3d::Unit(dof - 3)).toRotationMatrix() * pose.rotation;
  }
  return p;
}

/// Solves every line at `pose`. Lines are independent (each holds its own
/// warm start), so when the array has expensive (FE) lines they are shared
/// out over the free hardware threads (engine::worker_count: none while the
/// scenarios or run tasks around this solve hold every core), each taking the
/// next unsolved line (solve times differ tenfold between a cold riser and a
/// warm mooring line); the
/// order of the results is the order of the lines either way, so the sums
/// below are deterministic.
/// force_only: only LineEndResponse::force_g is filled (StaticLine::solve_force).
std::vector<LineEndResponse> solve_all(std::span<const std::unique_ptr<StaticLine>> lines, const HullPose& pose,
                                       LineArrayQuantities quantities = LineArrayQuantities::force_and_stiffness) {
  std::vector<LineEndResponse> ends(lines.size());
  const auto solve_one = [&](std::size_t i) {
    const Eigen::Vector3d attachment_g = pose.point_g(lines[i]->attachment_b());
    switch (quantities) {
      case LineArrayQuantities::force:
        ends[i].force_g = lines[i]->solve_force(attachment_g);
        ends[i].top_tension_N = ends[i].force_g.norm();
        break;
      case LineArrayQuantities::force_and_stiffness:
        ends[i] = lines[i]->solve(attachment_g);
        break;
    }
  };
  const bool any_expensive = std::any_of(lines.begin(), lines.end(), [](const auto& l) { return l->expensive(); });
  const int count = static_cast<int>(lines.size());
  parallel_for(count, any_expensive ? worker_count(count) : 1, [&](int i) { solve_one(static_cast<std::size_t>(i)); });
  return ends;
}

Vector6d array_force(std::span<const std::unique_ptr<StaticLine>> lines, const HullPose& pose) {
  Vector6d force = Vector6d::Zero();
  const std::vector<LineEndResponse> ends = solve_all(lines, pose, LineArrayQuantities::force);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Eigen::Vector3d arm = pose.rotation * lines[i]->attachment_b();
    force.head<3>() += ends[i].force_g;
    force.tail<3>() += arm.cross(ends[i].force_g);
  }
  return force;
}

}  // namespace

HullPose pose_from_offset(const Eigen::Vector3d& reference_point_at_rest_g, const Vector6d& offset) {
  return {reference_point_at_rest_g + offset.head<3>(), rotation_matrix(offset.tail<3>())};
}

Matrix6d attachment_stiffness_6x6(const Eigen::Matrix3d& K_f, const Eigen::Vector3d& force_g,
                                  const Eigen::Vector3d& arm_g) {
  // δx_attach = δu + δθ × a = δu − [a×] δθ;  δf = −K_f δx_attach;
  // δM = δθ × a × f + a × δf = [f×][a×] δθ + [a×] δf  (derivation in the header).
  const Eigen::Matrix3d A = skew(arm_g);
  Matrix6d k;
  k.topLeftCorner<3, 3>() = K_f;
  k.topRightCorner<3, 3>() = -K_f * A;
  k.bottomLeftCorner<3, 3>() = A * K_f;
  k.bottomRightCorner<3, 3>() = -A * K_f * A - skew(force_g) * A;
  return k;
}

LineArrayResponse evaluate_line_array(std::span<const std::unique_ptr<StaticLine>> lines, const HullPose& pose,
                                      LineArrayQuantities quantities) {
  LineArrayResponse response;
  response.has_stiffness = quantities != LineArrayQuantities::force;
  response.lines.reserve(lines.size());
  std::vector<LineEndResponse> ends = solve_all(lines, pose, quantities);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    LineContribution c;
    const Eigen::Vector3d arm = pose.rotation * lines[i]->attachment_b();
    c.attachment_g = pose.reference_point_g + arm;
    c.end = std::move(ends[i]);
    c.force.head<3>() = c.end.force_g;
    c.force.tail<3>() = arm.cross(c.end.force_g);
    if (response.has_stiffness) c.stiffness = attachment_stiffness_6x6(c.end.stiffness_g, c.end.force_g, arm);
    response.force += c.force;
    response.stiffness += c.stiffness;
    response.lines.push_back(std::move(c));
  }
  return response;
}

Matrix6d finite_difference_stiffness(std::span<const std::unique_ptr<StaticLine>> lines, const HullPose& pose,
                                     const FiniteDifferenceSteps& steps) {
  Matrix6d k;
  for (int dof = 0; dof < 6; ++dof) {
    const double h = dof < 3 ? steps.translation_m : steps.rotation_rad;
    const Vector6d plus = array_force(lines, perturbed(pose, dof, h));
    const Vector6d minus = array_force(lines, perturbed(pose, dof, -h));
    k.col(dof) = -(plus - minus) / (2.0 * h);
  }
  // Leave every line's warm start at the pose itself (with its stiffness).
  solve_all(lines, pose);
  return k;
}

}  // namespace spiral::engine
