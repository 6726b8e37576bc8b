#include "design/results/statics_output.hpp"

#include <numbers>

#include <fmt/format.h>

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

nlohmann::json six(const engine::Vector6d& v) { return nlohmann::json::array({v(0), v(1), v(2), v(3), v(4), v(5)}); }

}  // namespace

nlohmann::json statics_to_json(const StaticsResult& result, const std::string& project_name) {
  nlohmann::json lines = nlohmann::json::array();
  for (const LineStaticsRow& row : result.lines) {
    lines.push_back({
        {"name", row.name},
        {"fairlead_tension_N", row.fairlead_tension_N},
        {"fairlead_horizontal_N", row.fairlead_horizontal_N},
        {"fairlead_vertical_N", row.fairlead_vertical_N},
        {"fairlead_angle_deg", row.fairlead_angle_deg},
        {"anchor_tension_N", row.anchor_tension_N},
        {"anchor_horizontal_N", row.anchor_horizontal_N},
        {"anchor_vertical_N", row.anchor_vertical_N},
        {"anchor_uplift_angle_deg", row.anchor_uplift_angle_deg},
        {"laid_length_m", row.laid_length_m},
        {"touchdown_distance_m", row.touchdown_distance_m},
        {"max_tension_N", row.max_tension_N},
        {"utilization", row.utilization},
        {"governing_segment_type", row.governing_segment_type},
        {"regime", row.regime},
        {"iterations", row.iterations},
    });
  }
  return {
      {"format", "spiral.statics"},        {"format_version", 1}, {"project", project_name},
      {"offset_6dof", six(result.offset)}, {"lines", lines},      {"hull_force_6dof", six(result.hull_force)},
      {"wall_time_s", result.wall_time_s},
  };
}

std::string statics_table(const StaticsResult& result, const std::string& project_name) {
  std::string out;
  const engine::Vector6d& o = result.offset;
  out += fmt::format("Mooring statics — {}\n", project_name);
  out += fmt::format(
      "Hull offset: surge {:.3f} m, sway {:.3f} m, heave {:.3f} m, roll {:.3f}°, pitch {:.3f}°, "
      "yaw {:.3f}°\n\n",
      o(0), o(1), o(2), o(3) * kRadToDeg, o(4) * kRadToDeg, o(5) * kRadToDeg);
  out += fmt::format("{:<10} {:>11} {:>11} {:>11} {:>7} {:>11} {:>8} {:>9} {:>7} {:<9}\n", "line", "T_fair kN",
                     "H_fair kN", "V_fair kN", "ang °", "T_anch kN", "uplift°", "laid m", "util", "regime");
  for (const LineStaticsRow& row : result.lines) {
    out += fmt::format("{:<10} {:>11.1f} {:>11.1f} {:>11.1f} {:>7.2f} {:>11.1f} {:>8.2f} {:>9.1f} {:>7.3f} {:<9}\n",
                       row.name, row.fairlead_tension_N / 1e3, row.fairlead_horizontal_N / 1e3,
                       row.fairlead_vertical_N / 1e3, row.fairlead_angle_deg, row.anchor_tension_N / 1e3,
                       row.anchor_uplift_angle_deg, row.laid_length_m, row.utilization, row.regime);
  }
  const engine::Vector6d& f = result.hull_force;
  out += fmt::format(
      "\nMooring force on the hull (global axes, about the displaced reference point):\n"
      "  Fx {:.1f} kN  Fy {:.1f} kN  Fz {:.1f} kN  Mx {:.1f} kN·m  My {:.1f} kN·m  Mz {:.1f} kN·m\n",
      f(0) / 1e3, f(1) / 1e3, f(2) / 1e3, f(3) / 1e3, f(4) / 1e3, f(5) / 1e3);
  out += "Utilization: largest tension in a segment / that segment's MBL (no safety factor).\n";
  return out;
}

}  // namespace spiral::design
