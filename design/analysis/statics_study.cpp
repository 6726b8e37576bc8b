#include "design/analysis/statics_study.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/analysis/line_array.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

LineStaticsRow row_of(const MooringLineDesign& design, const engine::LineState& state) {
  LineStaticsRow row;
  row.name = design.name;
  const Eigen::Vector3d& top = state.top.force_g;
  const Eigen::Vector3d& bottom = state.bottom_force_g;
  row.fairlead_tension_N = top.norm();
  row.fairlead_horizontal_N = top.head<2>().norm();
  row.fairlead_vertical_N = -top.z();
  row.fairlead_angle_deg = std::atan2(row.fairlead_vertical_N, row.fairlead_horizontal_N) * kRadToDeg;
  row.anchor_tension_N = bottom.norm();
  row.anchor_horizontal_N = bottom.head<2>().norm();
  row.anchor_vertical_N = bottom.z();
  row.anchor_uplift_angle_deg =
      row.anchor_tension_N > 0.0 ? std::atan2(row.anchor_vertical_N, row.anchor_horizontal_N) * kRadToDeg : 0.0;
  row.laid_length_m = state.laid_length_m;
  row.touchdown_distance_m = state.touchdown_distance_m;
  row.regime = state.regime;
  row.iterations = state.top.iterations;

  row.max_tension_N = std::max(row.fairlead_tension_N, row.anchor_tension_N);
  std::vector<double> segment_max(design.segment_types.size(), 0.0);
  for (const engine::LineProfilePoint& point : state.profile) {
    const auto segment = static_cast<std::size_t>(point.segment);
    if (segment < segment_max.size()) segment_max[segment] = std::max(segment_max[segment], point.tension_N);
    row.max_tension_N = std::max(row.max_tension_N, point.tension_N);
  }
  // Within a catenary segment T² = H² + V(s)² with V linear in s, and on the
  // seabed T falls monotonically towards the anchor: the largest tension of a
  // segment is at one of its ends, which the profile always contains.
  for (std::size_t i = 0; i < segment_max.size(); ++i) {
    const double utilization = segment_max[i] / design.segment_types[i].breaking_load_N;
    if (utilization >= row.utilization) {
      row.utilization = utilization;
      row.governing_segment_type = design.segment_types[i].name;
    }
  }
  row.profile = state.profile;
  return row;
}

}  // namespace

std::vector<LineStaticsRow> line_statics_rows(const LineArrayModel& model,
                                              const std::vector<engine::LineState>& states) {
  std::vector<LineStaticsRow> rows;
  rows.reserve(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) rows.push_back(row_of(model.designs[i], states[i]));
  return rows;
}

StaticsResult run_statics(LineArrayModel& model, const engine::Vector6d& offset) {
  engine::Stopwatch start;
  const engine::HullPose pose = engine::pose_from_offset(model.reference_point_g, offset);
  StaticsResult result;
  result.offset = offset;
  std::vector<engine::LineState> states;
  states.reserve(model.lines.size());
  for (const auto& line : model.lines) {
    const Eigen::Vector3d arm = pose.rotation * line->attachment_b();
    states.push_back(line->state(pose.reference_point_g + arm, kResultProfilePointsPerSegment));
    result.hull_force.head<3>() += states.back().top.force_g;
    result.hull_force.tail<3>() += arm.cross(states.back().top.force_g);
  }
  result.lines = line_statics_rows(model, states);
  result.wall_time_s = start.seconds();
  return result;
}

const std::vector<engine::LineProfilePoint>* line_profile(const std::vector<LineStaticsRow>& lines,
                                                          const std::string& name) {
  for (const LineStaticsRow& row : lines)
    if (row.name == name) return &row.profile;
  return nullptr;
}

}  // namespace spiral::design
