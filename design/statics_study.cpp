#include "design/statics_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Profile points per segment for the tension along the line. Within a
// catenary segment T^2 = H^2 + V(s)^2 with V linear in s, and on the seabed T
// falls monotonically towards the anchor, so the largest tension of a segment
// is at one of its ends: a few points per segment find it exactly.
constexpr int kProfilePointsPerSegment = 3;
// Arc-length slack (m) when assigning profile points at a joint to both segments.
constexpr double kJointSlack_m = 1e-9;

const char* regime_name(engine::CatenaryRegime regime) {
  switch (regime) {
    case engine::CatenaryRegime::suspended: return "suspended";
    case engine::CatenaryRegime::touchdown: return "touchdown";
    case engine::CatenaryRegime::slack_vertical: return "slack";
  }
  return "unknown";
}

void fill_utilization(const engine::CatenaryLine& line, const MooringLineDesign& design,
                      const engine::CatenarySolution& solution, LineStaticsRow& row) {
  row.max_tension_N = std::max(solution.fairlead_tension_N, solution.anchor_tension_N);
  double segment_start_m = 0.0;
  for (std::size_t i = 0; i < line.segments.size(); ++i) {
    const double segment_end_m = segment_start_m + line.segments[i].length_m;
    double segment_max_N = 0.0;
    for (const auto& point : solution.profile) {
      if (point.arc_length_m >= segment_start_m - kJointSlack_m &&
          point.arc_length_m <= segment_end_m + kJointSlack_m) {
        segment_max_N = std::max(segment_max_N, point.tension_N);
      }
    }
    row.max_tension_N = std::max(row.max_tension_N, segment_max_N);
    const double utilization = segment_max_N / design.segment_types[i].breaking_load_N;
    if (utilization >= row.utilization) {
      row.utilization = utilization;
      row.governing_segment_type = design.segment_types[i].name;
    }
    segment_start_m = segment_end_m;
  }
}

}  // namespace

StaticsResult run_statics(const MooringDesignModel& model, const engine::Vector6d& offset) {
  const auto start = std::chrono::steady_clock::now();
  engine::CatenaryOptions options;
  options.profile_points_per_segment = kProfilePointsPerSegment;
  const engine::MooringStaticResult mooring =
      engine::solve_mooring_statics(model.system, offset, options);

  StaticsResult result;
  result.offset = offset;
  result.hull_force = mooring.hull_force;
  for (std::size_t i = 0; i < mooring.lines.size(); ++i) {
    const engine::CatenarySolution& s = mooring.lines[i].solution;
    LineStaticsRow row;
    row.name = model.system.lines[i].name;
    row.fairlead_tension_N = s.fairlead_tension_N;
    row.fairlead_horizontal_N = s.fairlead_horizontal_N;
    row.fairlead_vertical_N = s.fairlead_vertical_N;
    row.fairlead_angle_deg = std::atan2(s.fairlead_vertical_N, s.fairlead_horizontal_N) * kRadToDeg;
    row.anchor_tension_N = s.anchor_tension_N;
    row.anchor_horizontal_N = s.anchor_horizontal_N;
    row.anchor_vertical_N = s.anchor_vertical_N;
    row.anchor_uplift_angle_deg =
        s.anchor_tension_N > 0.0 ? std::atan2(s.anchor_vertical_N, s.anchor_horizontal_N) * kRadToDeg
                                 : 0.0;
    row.laid_length_m = s.laid_length_m;
    row.touchdown_distance_m = s.touchdown_x_m;
    row.regime = regime_name(s.regime);
    row.iterations = s.iterations;
    fill_utilization(model.system.lines[i].line, model.lines[i], s, row);
    result.lines.push_back(std::move(row));
  }
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace spiral::design
