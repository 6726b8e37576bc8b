#pragma once
// Results of the lines under a motion history (design/analysis/motion_lines.hpp)
// as files (docs/lines.md):
//   * time series CSV: time_s, the hull motion as given (interpolated to the
//     output times: surge_m … yaw_deg), then per mooring line
//     fairlead_tension_<L>_N, anchor_tension_<L>_N, anchor_uplift_<L>_deg,
//     laid_length_<L>_m, and per riser top_tension_<R>_N, top_angle_<R>_deg,
//     flex_joint_rotation_<R>_deg, touchdown_distance_<R>_m,
//     min_effective_tension_<R>_N, min_bending_radius_<R>_m,
//     [von_mises_utilization_<R>], utilization_<R> — every value of the FE
//     line dynamics;
//   * JSON summary (`spiral.motion_lines` v1): the statistics of every channel
//     over the window after the build-up ramp, each mooring line's dynamic
//     tension check and each riser's criteria at their worst time.
//
// The dynamic tension check (mooring_checks.hpp) takes the record's mean and,
// as its extreme, the Gumbel MPM of the 3-h maximum when the window is at
// least kMpmMinimumRecord_s long (a sample of a storm), else the record's own
// maximum (a short, deterministic motion: its maximum is the extreme).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "design/analysis/motion_lines.hpp"
#include "design/results/time_series_output.hpp"

namespace spiral::design {

/// Shortest statistics window whose 3-h MPM the tension check uses (1 h:
/// about 10 Gumbel segments of 6 min, each holding tens of wave cycles).
inline constexpr double kMpmMinimumRecord_s = 3600.0;

/// The columns of the time series CSV, in its order, at full precision.
std::vector<TimeSeriesColumn> motion_lines_columns(const MotionLinesResult& result);

/// The time series CSV.
std::string motion_lines_csv(const MotionLinesResult& result);

/// The summary; `motion_file` names the history as the user gave it.
nlohmann::json motion_lines_to_json(const MotionLinesResult& result, const ValidatedProject& project,
                                    const std::string& motion_file);

}  // namespace spiral::design
