#include "engine/analysis/static_equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <fmt/format.h>

#include "engine/common/rigid_body.hpp"
#include "engine/common/table_range_error.hpp"
#include "engine/common/dof_names.hpp"

namespace spiral::engine {

namespace {

constexpr int kMaxLineSearchHalvings = 10;

struct Evaluation {
  HullPose pose;
  Vector6d offset;
  Vector6d residual;
  Vector6d hydrostatic;
  Vector6d external;
  LineArrayResponse lines;
};

Evaluation evaluate(const HullStaticModel& hull, std::span<const std::unique_ptr<StaticLine>> lines,
                    const ExternalLoad& external_load, const Eigen::Vector3d& position_g,
                    const Eigen::Matrix3d& rotation, LineArrayQuantities quantities) {
  Evaluation e;
  e.pose = {position_g, rotation};
  e.offset.head<3>() = position_g - hull.reference_point_at_rest_g;
  e.offset.tail<3>() = roll_pitch_yaw(rotation);
  // Linear hydrostatics about the rest position (large heave/roll/pitch need
  // a panel or member model; yaw and surge/sway do not change them).
  e.hydrostatic = hull.rest_force - hull.hydrostatic_stiffness * e.offset;
  e.external = external_load ? external_load(e.offset) : Vector6d::Zero();
  e.lines = evaluate_line_array(lines, e.pose, quantities);
  e.residual = e.hydrostatic + e.external + e.lines.force;
  return e;
}

double merit(const Vector6d& residual, double force_ref, double moment_ref) {
  return std::hypot(residual.head<3>().norm() / force_ref, residual.tail<3>().norm() / moment_ref);
}

/// A bound on how far any attachment within `arm_m` of the reference point
/// moves between two poses: the translation plus the rotation angle times
/// the arm.
double attachment_move_m(const HullPose& a, const HullPose& b, double arm_m) {
  const double angle = Eigen::AngleAxisd(b.rotation * a.rotation.transpose()).angle();
  return (b.reference_point_g - a.reference_point_g).norm() + std::abs(angle) * arm_m;
}

}  // namespace

Matrix6d external_load_stiffness(const ExternalLoad& external_load, const Vector6d& offset) {
  Matrix6d k = Matrix6d::Zero();
  if (!external_load) return k;
  // The load at `offset` itself is defined; a step may leave its table (a
  // relative heading at the edge of a coefficient table): then a one-sided
  // difference on the side that stays in it (first order, h/2 of curvature).
  const auto load_at = [&](const Vector6d& at) -> std::optional<Vector6d> {
    try {
      return external_load(at);
    } catch (const TableRangeError&) {
      return std::nullopt;
    }
  };
  std::optional<Vector6d> centre;
  for (int j = 0; j < 6; ++j) {
    const double h = j < 3 ? 1e-2 : 1e-4;
    Vector6d plus = offset, minus = offset;
    plus(j) += h;
    minus(j) -= h;
    const std::optional<Vector6d> up = load_at(plus), down = load_at(minus);
    if (up && down) {
      k.col(j) = -(*up - *down) / (2.0 * h);
      continue;
    }
    if (!centre) centre = external_load(offset);
    if (up) k.col(j) = -(*up - *centre) / h;
    if (down) k.col(j) = -(*centre - *down) / h;
  }
  return k;
}

Matrix6d offset_increment_to_global(const Vector6d& offset) {
  Matrix6d t = Matrix6d::Identity();
  t.bottomRightCorner<3, 3>() = euler_rate_to_global(offset.tail<3>());
  return t;
}

Matrix6d equilibrium_tangent(const HullStaticModel& hull, const Matrix6d& line_stiffness,
                             const ExternalLoad& external_load, const Vector6d& offset) {
  return hull.hydrostatic_stiffness + line_stiffness * offset_increment_to_global(offset) +
         external_load_stiffness(external_load, offset);
}

Eigen::Vector3d roll_pitch_yaw(const Eigen::Matrix3d& r) {
  return {std::atan2(r(2, 1), r(2, 2)), -std::asin(std::clamp(r(2, 0), -1.0, 1.0)), std::atan2(r(1, 0), r(0, 0))};
}

EquilibriumResult solve_static_equilibrium(const HullStaticModel& hull,
                                           std::span<const std::unique_ptr<StaticLine>> lines,
                                           const ExternalLoad& external_load, const Vector6d& initial_offset,
                                           const EquilibriumOptions& options) {
  const HullPose start = pose_from_offset(hull.reference_point_at_rest_g, initial_offset);
  Evaluation current =
      evaluate(hull, lines, external_load, start.reference_point_g, start.rotation, LineArrayQuantities::force);

  double arm_ref_m = 1.0;
  for (const auto& line : lines) arm_ref_m = std::max(arm_ref_m, line->attachment_b().norm());
  double force_ref_N = std::max(hull.rest_force.head<3>().norm(), current.external.head<3>().norm());
  for (const auto& c : current.lines.lines) force_ref_N += c.end.force_g.norm();
  force_ref_N = std::max(force_ref_N, 1.0);
  const double moment_ref_Nm = force_ref_N * arm_ref_m;

  // The line-array stiffness the Newton tangent uses, and where it was computed.
  struct LineTangent {
    HullPose pose;
    Matrix6d stiffness;
  };
  std::optional<LineTangent> tangent_lines;

  int iteration = 0;
  while (true) {
    const double current_merit = merit(current.residual, force_ref_N, moment_ref_Nm);
    if (current_merit <= options.relative_tolerance) break;
    if (iteration >= options.max_iterations) {
      Eigen::Index worst = 0;
      Vector6d scaled = current.residual;
      scaled.head<3>() /= force_ref_N;
      scaled.tail<3>() /= moment_ref_Nm;
      scaled.cwiseAbs().maxCoeff(&worst);
      // Where the search ended and which line carried the most there: a load
      // beyond the mooring's capacity shows as a far offset and a line far
      // above its pretension.
      std::string most_loaded;
      std::size_t most = 0;
      for (std::size_t i = 1; i < current.lines.lines.size(); ++i) {
        if (current.lines.lines[i].end.top_tension_N > current.lines.lines[most].end.top_tension_N) most = i;
      }
      if (!current.lines.lines.empty()) {
        most_loaded = fmt::format("; most loaded line '{}' at {:.4g} kN", lines[most]->name(),
                                  current.lines.lines[most].end.top_tension_N / 1e3);
      }
      throw SolverError(fmt::format("static equilibrium did not converge in {} iterations: largest residual in "
                                    "{} ({:.4g} {}) at a horizontal offset of {:.1f} m{}; the hull may have no "
                                    "equilibrium under this load (lines too slack or too few to hold it) — check "
                                    "the environment and pretensions",
                                    iteration, kDofNames[worst], current.residual(worst), worst < 3 ? "N" : "N·m",
                                    current.offset.head<2>().norm(), most_loaded),
                        {iteration, current_merit, "relative"});
    }
    ++iteration;

    // At the accepted pose: the lines' solutions are kept, an FE line only
    // factorises its Jacobian for the exact stiffness — or the stiffness of
    // an earlier iteration within options.stiffness_reuse_distance_m serves.
    if (!current.lines.has_stiffness &&
        !(tangent_lines && options.stiffness_reuse_distance_m > 0.0 &&
          attachment_move_m(tangent_lines->pose, current.pose, arm_ref_m) <= options.stiffness_reuse_distance_m)) {
      current.lines = evaluate_line_array(lines, current.pose);
    }
    if (current.lines.has_stiffness) tangent_lines = {current.pose, current.lines.stiffness};
    const Eigen::FullPivLU<Matrix6d> lu(
        equilibrium_tangent(hull, tangent_lines->stiffness, external_load, current.offset));
    if (!lu.isInvertible()) {
      throw SolverError(
          "static equilibrium: the hull has no stiffness in at least one DOF (no hydrostatic or "
          "line restoring, e.g. yaw without mooring lines); add lines or hydrostatics",
          {iteration, current_merit, "relative"});
    }
    Vector6d step = offset_increment_to_global(current.offset) * lu.solve(current.residual);
    const double translation = step.head<3>().norm();
    const double rotation = step.tail<3>().norm();
    double scale = 1.0;
    if (translation > options.max_translation_step_m) scale = options.max_translation_step_m / translation;
    if (rotation > options.max_rotation_step_rad) scale = std::min(scale, options.max_rotation_step_rad / rotation);
    step *= scale;

    // Backtracking: accept the first step that lowers the scaled residual. A
    // line that cannot be solved at the trial pose (over-stretched) also
    // shortens the step.
    bool accepted = false;
    for (int halving = 0; halving <= kMaxLineSearchHalvings && !accepted; ++halving) {
      const Eigen::Vector3d position = current.pose.reference_point_g + step.head<3>();
      const double angle = step.tail<3>().norm();
      Eigen::Matrix3d rotation_step = Eigen::Matrix3d::Identity();
      if (angle > 0.0) rotation_step = Eigen::AngleAxisd(angle, step.tail<3>() / angle).toRotationMatrix();
      try {
        Evaluation trial = evaluate(hull, lines, external_load, position, rotation_step * current.pose.rotation,
                                    LineArrayQuantities::force);
        if (merit(trial.residual, force_ref_N, moment_ref_Nm) < current_merit || halving == kMaxLineSearchHalvings) {
          current = std::move(trial);
          accepted = true;
        }
      } catch (const SolverError& error) {
        if (halving == kMaxLineSearchHalvings) {
          throw SolverError(
              fmt::format("static equilibrium: no acceptable step at Newton iteration {} (scaled residual "
                          "{:.3g}); {} — the load may exceed what the lines can hold: check the load case "
                          "and the pretensions",
                          iteration, current_merit, error.what()),
              {iteration, current_merit, "relative"});
        }
      }
      step *= 0.5;
    }
  }

  if (options.stiffness_at_solution && !current.lines.has_stiffness)
    current.lines = evaluate_line_array(lines, current.pose);

  EquilibriumResult result;
  result.offset = current.offset;
  result.pose = current.pose;
  result.residual = current.residual;
  result.hydrostatic_force = current.hydrostatic;
  result.external_force = current.external;
  result.lines = std::move(current.lines);
  result.iterations = iteration;
  result.force_reference_N = force_ref_N;
  return result;
}

}  // namespace spiral::engine
