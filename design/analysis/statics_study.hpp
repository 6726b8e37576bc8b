#pragma once
// The statics study behind `spiral statics`: every mooring line solved at a
// prescribed hull offset, with the quantities a mooring engineer checks first
// (fairlead and anchor tensions, uplift, laid length, utilization against MBL)
// and the total mooring force on the hull.

#include <string>
#include <vector>

#include "design/model/mooring_model.hpp"
#include "engine/common/rigid_body.hpp"
#include "engine/analysis/static_line.hpp"

namespace spiral::design {

struct LineStaticsRow {
  std::string name;
  double fairlead_tension_N = 0.0;
  double fairlead_horizontal_N = 0.0;
  double fairlead_vertical_N = 0.0;
  double fairlead_angle_deg = 0.0;  ///< line angle at the fairlead, from horizontal
  double anchor_tension_N = 0.0;
  double anchor_horizontal_N = 0.0;
  double anchor_vertical_N = 0.0;
  double anchor_uplift_angle_deg = 0.0;  ///< from the seabed; > 0 pulls the anchor up
  double laid_length_m = 0.0;
  double touchdown_distance_m = 0.0;   ///< horizontal, from the anchor
  double max_tension_N = 0.0;          ///< largest along the line
  double utilization = 0.0;            ///< max over segments of (max tension in segment / segment MBL)
  std::string governing_segment_type;  ///< line type of the segment that sets the utilization
  engine::LineRegime regime = engine::LineRegime::suspended;
  int iterations = 0;
  /// Points along the line, anchor to fairlead: positions and effective
  /// tension (for profile plots, 3D views and tension-along-line plots).
  std::vector<engine::LineProfilePoint> profile;
};

/// Profile points per segment in the results (the largest tension of a
/// catenary segment is at one of its ends, so any count finds it; 20 draws
/// a smooth curve in plots and 3D views).
inline constexpr int kResultProfilePointsPerSegment = 20;

struct StaticsResult {
  engine::Vector6d offset = engine::Vector6d::Zero();  ///< m, rad
  std::vector<LineStaticsRow> lines;
  engine::Vector6d hull_force = engine::Vector6d::Zero();  ///< N, N·m about the displaced reference point
  double wall_time_s = 0.0;
};

/// The table rows of every line in `states` (same order as model.designs).
std::vector<LineStaticsRow> line_statics_rows(const LineArrayModel& model,
                                              const std::vector<engine::LineState>& states);

/// Solves the mooring of `model` at `offset`. Throws engine::SolverError naming the line.
StaticsResult run_statics(LineArrayModel& model, const engine::Vector6d& offset);

/// The profile of the line named `name` among `lines`; null when it is not
/// there (a second start for that line's FE statics, dynamic_mooring_line).
const std::vector<engine::LineProfilePoint>* line_profile(const std::vector<LineStaticsRow>& lines,
                                                          const std::string& name);

}  // namespace spiral::design
