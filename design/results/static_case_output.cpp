#include "design/results/static_case_output.hpp"

#include "design/results/statics_output.hpp"
#include "design/criteria/riser_checks.hpp"

namespace spiral::design {

namespace {

nlohmann::json six(const engine::Vector6d& v) { return nlohmann::json::array({v(0), v(1), v(2), v(3), v(4), v(5)}); }

nlohmann::json optional_number(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json six_by_six(const engine::Matrix6d& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) rows.push_back(six(m.row(i).transpose()));
  return rows;
}

/// The riser's results along its length as parallel arrays, foot first.
nlohmann::json riser_profile_json(const std::vector<RiserProfilePoint>& profile) {
  nlohmann::json arc = nlohmann::json::array(), position = nlohmann::json::array(), section = nlohmann::json::array(),
                 on_seabed = nlohmann::json::array(), effective = nlohmann::json::array(),
                 wall = nlohmann::json::array(), moment = nlohmann::json::array(), curvature = nlohmann::json::array(),
                 von_mises = nlohmann::json::array(), utilization = nlohmann::json::array();
  for (const RiserProfilePoint& q : profile) {
    arc.push_back(q.arc_length_m);
    position.push_back({q.position_g.x(), q.position_g.y(), q.position_g.z()});
    section.push_back(q.section);
    on_seabed.push_back(q.on_seabed);
    effective.push_back(q.effective_tension_N);
    wall.push_back(q.wall_tension_N);
    moment.push_back(q.bending_moment_N_m);
    curvature.push_back(q.curvature_per_m);
    von_mises.push_back(optional_number(q.von_mises_Pa));
    utilization.push_back(optional_number(q.von_mises_utilization));
  }
  return {{"arc_length_m", arc},
          {"position_m", position},
          {"section", section},
          {"on_seabed", on_seabed},
          {"effective_tension_N", effective},
          {"wall_tension_N", wall},
          {"bending_moment_N_m", moment},
          {"curvature_per_m", curvature},
          {"von_mises_Pa", von_mises},
          {"von_mises_utilization", utilization}};
}

}  // namespace

nlohmann::json static_case_to_json(const StaticCaseResult& r, const std::string& project_name) {
  const nlohmann::json statics_lines = statics_to_json({r.offset, r.lines, r.line_force, 0.0}, project_name)["lines"];
  nlohmann::json lines = nlohmann::json::array();
  for (std::size_t i = 0; i < statics_lines.size(); ++i) {
    nlohmann::json line = statics_lines[i];
    line["stiffness_6x6"] = six_by_six(r.line_stiffness[i]);
    line["force_6dof"] = six(r.line_force_6dof[i]);
    lines.push_back(std::move(line));
  }
  nlohmann::json risers = nlohmann::json::array();
  for (std::size_t k = 0; k < r.risers.size(); ++k) {
    const RiserStaticsRow& row = r.risers[k];
    // Contributions are listed mooring lines first, then the risers.
    const std::size_t contribution = r.lines.size() + k;
    nlohmann::json checks = nlohmann::json::array();
    for (const RiserCriterionCheck& c : row.checks) {
      checks.push_back({{"criterion", c.criterion},
                        {"value", c.value},
                        {"limit", c.limit},
                        {"unit", c.unit},
                        {"utilization", c.utilization},
                        {"passes", c.passes}});
    }
    risers.push_back({{"name", row.name},
                      {"kind", to_string(row.kind)},
                      {"top_tension_N", row.top_tension_N},
                      {"top_angle_deg", row.top_angle_deg},
                      {"flex_joint_rotation_deg", row.flex_joint_rotation_deg},
                      {"touchdown_distance_m", row.touchdown_distance_m},
                      {"min_effective_tension_N", row.min_effective_tension_N},
                      {"min_effective_tension_arc_m", row.min_effective_tension_arc_m},
                      {"max_curvature_per_m", row.max_curvature_per_m},
                      {"min_bending_radius_m", row.min_bending_radius_m},
                      {"max_von_mises_utilization", optional_number(row.max_von_mises_utilization)},
                      {"max_von_mises_arc_m", optional_number(row.max_von_mises_arc_m)},
                      {"checks", checks},
                      {"governing_criterion", row.governing_criterion},
                      {"utilization", row.utilization},
                      {"passes", row.passes},
                      {"stiffness_6x6", six_by_six(r.line_stiffness.at(contribution))},
                      {"force_6dof", six(r.line_force_6dof.at(contribution))},
                      {"profile", riser_profile_json(row.profile)}});
  }
  auto modes_json = [](const std::vector<NaturalMode>& list) {
    nlohmann::json modes = nlohmann::json::array();
    for (const NaturalMode& m : list) modes.push_back({{"period_s", m.period_s}, {"dominant_dof", m.dominant_dof}});
    return modes;
  };
  const OffsetSummary& o = r.offset_summary;
  nlohmann::json doc = {
      {"format", "spiral.static_case"},
      {"format_version", 1},
      {"project", project_name},
      {"case", r.case_name},
      {"environment", r.environment},
      {"condition", to_string(r.integrity)},
      {"damaged_line", r.damaged_line ? nlohmann::json(*r.damaged_line) : nlohmann::json(nullptr)},
      {"offset_6dof", six(r.offset)},
      {"offset",
       {{"horizontal_m", o.horizontal_m},
        {"horizontal_pct_depth", o.horizontal_pct_depth},
        {"direction_deg", o.direction_deg},
        {"heave_m", o.heave_m},
        {"roll_deg", o.roll_deg},
        {"pitch_deg", o.pitch_deg},
        {"yaw_deg", o.yaw_deg}}},
      {"force_6dof", six(r.line_force)},
      {"stiffness_6x6", six_by_six(r.stiffness)},
      {"hydrostatic_force_6dof", six(r.hydrostatic_force)},
      {"environment_force_6dof", six(r.environment_force)},
      {"residual_6dof", six(r.residual)},
      {"hydrostatic_stiffness_6x6", six_by_six(r.hydrostatic_stiffness)},
      {"natural_modes", modes_json(r.natural_modes)},
      {"dynamic_stiffness_6x6", six_by_six(r.dynamic_stiffness)},
      {"dynamic_stiffness_lines", r.dynamic_stiffness_lines},
      {"dynamic_natural_modes", modes_json(r.dynamic_natural_modes)},
      {"notes", r.notes},
      {"added_mass_included", r.added_mass_included},
      {"lines", lines},
      {"risers", risers},
      {"design_condition", to_string(r.design_condition)},
      {"equilibrium_iterations", r.equilibrium_iterations},
      {"equilibrium_wall_s", r.equilibrium_wall_s},
      {"stiffness_wall_s", r.stiffness_wall_s},
  };
  if (r.stiffness_finite_difference) {
    doc["stiffness_finite_difference_6x6"] = six_by_six(*r.stiffness_finite_difference);
    doc["stiffness_check_relative_difference"] = *r.stiffness_check_relative_difference;
  }
  return doc;
}

}  // namespace spiral::design
