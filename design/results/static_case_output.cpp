#include "design/results/static_case_output.hpp"

#include <fmt/format.h>

#include "design/results/statics_output.hpp"
#include "design/criteria/riser_checks.hpp"

namespace spiral::design {

namespace {

constexpr const char* kDofNames[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

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

std::string case_heading(const StaticCaseResult& r, const std::string& project_name) {
  return fmt::format("{} — case '{}' (environment {}, {}{})\n", project_name, r.case_name, r.environment,
                     to_string(r.integrity), r.damaged_line ? fmt::format(": line {} removed", *r.damaged_line) : "");
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
                      {"kind", row.kind},
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
  nlohmann::json modes = nlohmann::json::array();
  for (const NaturalMode& m : r.natural_modes)
    modes.push_back({{"period_s", m.period_s}, {"dominant_dof", m.dominant_dof}});
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
      {"natural_modes", modes},
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

std::string equilibrium_table(const StaticCaseResult& r, const std::string& project_name) {
  std::string out = "Coupled static equilibrium — " + case_heading(r, project_name);
  const OffsetSummary& o = r.offset_summary;
  out += fmt::format(
      "Offset: {:.3f} m horizontal ({:.3f} % of depth) towards {:.1f}°, heave {:.4f} m, "
      "roll {:.4f}°, pitch {:.4f}°, yaw {:.4f}°\n",
      o.horizontal_m, o.horizontal_pct_depth, o.direction_deg, o.heave_m, o.roll_deg, o.pitch_deg, o.yaw_deg);
  out += fmt::format("Converged in {} Newton iterations ({:.3f} ms); residual |F| {:.3g} N, |M| {:.3g} N·m\n\n",
                     r.equilibrium_iterations, 1e3 * r.equilibrium_wall_s, r.residual.head<3>().norm(),
                     r.residual.tail<3>().norm());
  const std::string statics = statics_table({r.offset, r.lines, r.line_force, 0.0}, project_name);
  // Reuse the per-line table of `spiral statics` (from its column header on).
  out += statics.substr(statics.find("line "));
  out += fmt::format("Hydrostatic + gravity force: Fz {:.1f} kN, Mx {:.1f} kN·m, My {:.1f} kN·m\n",
                     r.hydrostatic_force(2) / 1e3, r.hydrostatic_force(3) / 1e3, r.hydrostatic_force(4) / 1e3);
  if (!r.risers.empty()) {
    out += fmt::format("\nRisers (design factor of the '{}' condition):\n", to_string(r.design_condition));
    out += fmt::format("{:<8} {:>10} {:>8} {:>9} {:>11} {:>9} {:>8} {:>7}  {}\n", "riser", "T_top kN", "angle°",
                       "TDP m", "Te_min kN", "R_min m", "vM util", "util", "governing");
    for (const RiserStaticsRow& row : r.risers) {
      const std::string von_mises =
          row.max_von_mises_utilization ? fmt::format("{:.3f}", *row.max_von_mises_utilization) : "–";
      out += fmt::format("{:<8} {:>10.1f} {:>8.2f} {:>9.1f} {:>11.1f} {:>9.1f} {:>8} {:>7.3f}  {}{}\n", row.name,
                         row.top_tension_N / 1e3, row.top_angle_deg, row.touchdown_distance_m,
                         row.min_effective_tension_N / 1e3, row.min_bending_radius_m, von_mises, row.utilization,
                         row.governing_criterion, row.passes ? "" : "  FAIL");
    }
  }
  const engine::Vector6d& e = r.environment_force;
  out += fmt::format("Mean environmental load on the hull: Fx {:.1f} kN, Fy {:.1f} kN, Mz {:.1f} kN·m\n", e(0) / 1e3,
                     e(1) / 1e3, e(5) / 1e3);
  for (const std::string& note : r.notes) out += "Note: " + note + "\n";
  return out;
}

std::string stiffness_table(const StaticCaseResult& r, const std::string& project_name) {
  std::string out = "Line-array stiffness at the static equilibrium — " + case_heading(r, project_name);
  out += "K (N/m, N/rad, N·m/m, N·m/rad; rows = force DOF, columns = displacement DOF):\n";
  out += fmt::format("{:>8}", "");
  for (const char* name : kDofNames) out += fmt::format(" {:>12}", name);
  out += "\n";
  for (int i = 0; i < 6; ++i) {
    out += fmt::format("{:>8}", kDofNames[i]);
    for (int j = 0; j < 6; ++j) out += fmt::format(" {:>12.4e}", r.stiffness(i, j));
    out += "\n";
  }
  out += "\nF (N, N·m):";
  for (int i = 0; i < 6; ++i) out += fmt::format(" {}={:.4e}", kDofNames[i], r.line_force(i));
  out += "\n";
  if (r.stiffness_check_relative_difference) {
    out += fmt::format("Analytic vs central finite differences (±1 cm, ±1e-4 rad): ‖K − K_fd‖/‖K_fd‖ = {:.2e}\n",
                       *r.stiffness_check_relative_difference);
  }
  out += fmt::format("Computed in {:.3f} ms after the equilibrium.\n", 1e3 * r.stiffness_wall_s);
  if (!r.natural_modes.empty()) {
    out += fmt::format("\nNatural periods of the moored hull (stiffness: hydrostatics + lines; mass: {}):\n",
                       r.added_mass_included ? "rigid body + added mass"
                                             : "rigid body only — no added mass given, so the periods are too short");
    for (const NaturalMode& m : r.natural_modes) out += fmt::format("  {:>8.2f} s  {}\n", m.period_s, m.dominant_dof);
  }
  return out;
}

}  // namespace spiral::design
