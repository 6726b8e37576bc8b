#include "design/criteria/riser_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "engine/lines/riser_section.hpp"

namespace spiral::design {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

}  // namespace

Eigen::Vector3d flex_joint_axis_b(const RiserDesign& design) {
  // The joint is installed along the riser's at-rest top tangent: the design
  // top angle from the downward vertical, in the vertical plane of the azimuth.
  const double s = std::sin(design.design_top_angle_rad);
  return {s * std::cos(design.azimuth_rad), s * std::sin(design.azimuth_rad), -std::cos(design.design_top_angle_rad)};
}

const std::vector<RiserProfilePoint>* riser_profile(const std::vector<RiserStaticsRow>& risers,
                                                    const std::string& name) {
  for (const RiserStaticsRow& row : risers)
    if (row.name == name) return &row.profile;
  return nullptr;
}

RiserStaticsRow riser_statics_row(const Project& project, const RiserDesign& design,
                                  const engine::FeStaticsResult& solution, DesignCondition condition,
                                  const Eigen::Matrix3d& hull_rotation) {
  const engine::Seawater water{project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2};
  RiserStaticsRow row;
  row.name = design.name;
  row.kind = design.kind;
  const Eigen::Vector3d& top = solution.end_B_force_N;  // on the hull: outwards and down
  row.top_tension_N = top.norm();
  row.top_angle_deg = std::atan2(top.head<2>().norm(), -top.z()) * kRadToDeg;
  // Flex-joint rotation: the angle between the riser's top tangent (the top
  // force, which points down the riser: a flex joint carries little moment,
  // so the end shear is small) and the joint's axis as the hull has turned
  // it. Unlike the change of top angle, it sees the riser plane swinging
  // about the vertical (cross offsets, hull yaw) and the hull's roll/pitch.
  // atan2 of |a × t| and a · t keeps small angles accurate.
  const Eigen::Vector3d axis_g = hull_rotation * flex_joint_axis_b(design);
  const Eigen::Vector3d tangent_g = top.normalized();
  row.flex_joint_rotation_deg = std::atan2(axis_g.cross(tangent_g).norm(), axis_g.dot(tangent_g)) * kRadToDeg;
  const Eigen::Vector3d hang_off_g = solution.node_position_m.back();
  if (solution.touchdown) row.touchdown_distance_m = (solution.touchdown->position_m - hang_off_g).head<2>().norm();

  const engine::InternalPressureProfile internal{design.internal_pressure_top_Pa, hang_off_g.z(),
                                                 design.contents_density_top_kg_per_m3};
  const double factor = design_factor(design.criteria.design_factor, condition);
  row.min_effective_tension_N = std::numeric_limits<double>::infinity();
  const std::vector<int> sections = engine::node_sections(design.fe_model, solution);
  for (std::size_t i = 0; i < solution.node_position_m.size(); ++i) {
    RiserProfilePoint q;
    q.position_g = solution.node_position_m[i];
    q.arc_length_m = solution.node_arc_length_m[i];
    const auto fe_section = static_cast<std::size_t>(sections[i]);
    q.section = static_cast<int>(design.sections.size() - 1 - fe_section);
    q.on_seabed = solution.touchdown && q.arc_length_m <= solution.touchdown->arc_length_m;
    q.effective_tension_N = solution.node_tension_N[i];
    q.curvature_per_m = std::abs(solution.node_curvature_per_m[i]);
    q.bending_moment_N_m = std::abs(solution.node_bending_moment_Nm[i]);
    const RiserSectionDesign& sd = design.sections[fe_section];
    // Pressures at the node: the contents column from the hang-off down and
    // the sea's hydrostatic head; T_w = T_e + p_i A_i − p_e A_o (Sparks 1984),
    // for a steel wall and a flexible's layered wall alike.
    const double z = q.position_g.z();
    const engine::PipePressures pressures{engine::internal_pressure_Pa(internal, z, water.gravity_m_per_s2),
                                          engine::external_pressure_Pa(z, water)};
    q.wall_tension_N = engine::wall_tension_N(q.effective_tension_N, pressures, sd.properties);
    if (sd.steel) {
      engine::StressCheckInput input;
      input.loads = {q.wall_tension_N, q.bending_moment_N_m, pressures};
      input.design_factor = factor;
      const engine::StressCheckResult stress = engine::check_pipe_stress(sd.properties, input);
      q.von_mises_Pa = stress.max_von_mises_Pa;
      q.von_mises_utilization = stress.utilization;
    }

    if (q.effective_tension_N < row.min_effective_tension_N) {
      row.min_effective_tension_N = q.effective_tension_N;
      row.min_effective_tension_arc_m = q.arc_length_m;
    }
    row.max_curvature_per_m = std::max(row.max_curvature_per_m, q.curvature_per_m);
    if (q.von_mises_utilization &&
        (!row.max_von_mises_utilization || *q.von_mises_utilization > *row.max_von_mises_utilization)) {
      row.max_von_mises_utilization = q.von_mises_utilization;
      row.max_von_mises_arc_m = q.arc_length_m;
    }
    row.profile.push_back(q);
  }
  row.min_bending_radius_m =
      row.max_curvature_per_m > 0.0 ? 1.0 / row.max_curvature_per_m : std::numeric_limits<double>::infinity();

  const RiserCriteria& c = design.criteria;
  const auto add = [&](std::string name, double value, double limit, std::string unit, double utilization) {
    row.checks.push_back({std::move(name), value, limit, std::move(unit), utilization, utilization <= 1.0});
  };
  if (row.max_von_mises_utilization) {
    add("von_mises", *row.max_von_mises_utilization, 1.0, "-", *row.max_von_mises_utilization);
  }
  // A floor, not a capacity: no ratio of T_min to its limit measures closeness
  // (the limit is usually 0), so the check is pass/fail — 0 while it holds,
  // 1 + deficit/T_top once T_min drops below the limit.
  const double deficit_N = c.min_effective_tension_N - row.min_effective_tension_N;
  add("min_effective_tension", row.min_effective_tension_N, c.min_effective_tension_N, "N",
      deficit_N >= 0.0 ? 1.0 + deficit_N / row.top_tension_N : 0.0);
  if (c.max_top_tension_N)
    add("max_top_tension", row.top_tension_N, *c.max_top_tension_N, "N", row.top_tension_N / *c.max_top_tension_N);
  if (c.max_top_angle_rad) {
    add("max_top_angle", row.top_angle_deg, *c.max_top_angle_rad * kRadToDeg, "deg",
        row.top_angle_deg / (*c.max_top_angle_rad * kRadToDeg));
  }
  if (c.max_flex_joint_rotation_rad) {
    add("flex_joint_rotation", row.flex_joint_rotation_deg, *c.max_flex_joint_rotation_rad * kRadToDeg, "deg",
        row.flex_joint_rotation_deg / (*c.max_flex_joint_rotation_rad * kRadToDeg));
  }
  if (c.min_bending_radius_m) {
    add("min_bending_radius", row.min_bending_radius_m, *c.min_bending_radius_m, "m",
        row.max_curvature_per_m * *c.min_bending_radius_m);
  }
  for (const RiserCriterionCheck& check : row.checks) {
    if (check.utilization >= row.utilization || row.governing_criterion.empty()) {
      row.utilization = check.utilization;
      row.governing_criterion = check.criterion;
    }
    row.passes = row.passes && check.passes;
  }
  return row;
}

}  // namespace spiral::design
