#include "engine/analysis/static_equilibrium.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <fmt/format.h>

namespace spiral::engine {

namespace {

constexpr const char* kDofNames[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
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
                    const Eigen::Matrix3d& rotation) {
  Evaluation e;
  e.pose = {position_g, rotation};
  e.offset.head<3>() = position_g - hull.reference_point_at_rest_g;
  e.offset.tail<3>() = roll_pitch_yaw(rotation);
  // Linear hydrostatics about the rest position (large heave/roll/pitch need
  // a panel or member model; yaw and surge/sway do not change them).
  e.hydrostatic = hull.rest_force - hull.hydrostatic_stiffness * e.offset;
  e.external = external_load ? external_load(e.offset) : Vector6d::Zero();
  e.lines = evaluate_line_array(lines, e.pose);
  e.residual = e.hydrostatic + e.external + e.lines.force;
  return e;
}

double merit(const Vector6d& residual, double force_ref, double moment_ref) {
  return std::hypot(residual.head<3>().norm() / force_ref, residual.tail<3>().norm() / moment_ref);
}

}  // namespace

Eigen::Vector3d roll_pitch_yaw(const Eigen::Matrix3d& r) {
  return {std::atan2(r(2, 1), r(2, 2)), -std::asin(std::clamp(r(2, 0), -1.0, 1.0)), std::atan2(r(1, 0), r(0, 0))};
}

EquilibriumResult solve_static_equilibrium(const HullStaticModel& hull,
                                           std::span<const std::unique_ptr<StaticLine>> lines,
                                           const ExternalLoad& external_load, const Vector6d& initial_offset,
                                           const EquilibriumOptions& options) {
  const HullPose start = pose_from_offset(hull.reference_point_at_rest_g, initial_offset);
  Evaluation current = evaluate(hull, lines, external_load, start.reference_point_g, start.rotation);

  double arm_ref_m = 1.0;
  for (const auto& line : lines) arm_ref_m = std::max(arm_ref_m, line->attachment_b().norm());
  double force_ref_N = std::max(hull.rest_force.head<3>().norm(), current.external.head<3>().norm());
  for (const auto& c : current.lines.lines) force_ref_N += c.end.force_g.norm();
  force_ref_N = std::max(force_ref_N, 1.0);
  const double moment_ref_Nm = force_ref_N * arm_ref_m;

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
      throw SolverError(fmt::format("static equilibrium did not converge in {} iterations: largest residual in "
                                    "{} ({:.4g} {}); the hull may have no equilibrium under this load (lines "
                                    "too slack or too few to hold it) — check the environment and pretensions",
                                    iteration, kDofNames[worst], current.residual(worst), worst < 3 ? "N" : "N·m"),
                        {iteration, current_merit, "relative"});
    }
    ++iteration;

    const Matrix6d tangent = hull.hydrostatic_stiffness + current.lines.stiffness;
    const Eigen::FullPivLU<Matrix6d> lu(tangent);
    if (!lu.isInvertible()) {
      throw SolverError(
          "static equilibrium: the hull has no stiffness in at least one DOF (no hydrostatic or "
          "line restoring, e.g. yaw without mooring lines); add lines or hydrostatics",
          {iteration, current_merit, "relative"});
    }
    Vector6d step = lu.solve(current.residual);
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
        Evaluation trial = evaluate(hull, lines, external_load, position, rotation_step * current.pose.rotation);
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
