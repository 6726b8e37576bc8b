#include "report/terminal/static_case_tables.hpp"

#include <fmt/format.h>

#include "report/terminal/statics_table.hpp"
#include "engine/common/dof_names.hpp"

namespace spiral::report {

using namespace design;

namespace {

using engine::kDofNames;

std::string case_heading(const StaticCaseResult& r, const std::string& project_name) {
  return fmt::format("{} — case '{}' (environment {}, {}{})\n", project_name, r.case_name, r.environment,
                     to_string(r.integrity), r.damaged_line ? fmt::format(": line {} removed", *r.damaged_line) : "");
}

}  // namespace

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
  if (r.dynamic_stiffness_lines > 0) {
    out += fmt::format(
        "\nWith the dynamic EA of the polyester ({} lines) for the motions about this equilibrium (the S-C "
        "and coupled dynamics):\n",
        r.dynamic_stiffness_lines);
    for (const NaturalMode& m : r.dynamic_natural_modes)
      out += fmt::format("  {:>8.2f} s  {}\n", m.period_s, m.dominant_dof);
  }
  return out;
}

}  // namespace spiral::report
