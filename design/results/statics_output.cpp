#include "design/results/statics_output.hpp"

namespace spiral::design {

namespace {

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
        {"regime", engine::to_string(row.regime)},
        {"iterations", row.iterations},
    });
  }
  return {
      {"format", "spiral.statics"},        {"format_version", 1}, {"project", project_name},
      {"offset_6dof", six(result.offset)}, {"lines", lines},      {"hull_force_6dof", six(result.hull_force)},
      {"wall_time_s", result.wall_time_s},
  };
}

}  // namespace spiral::design
