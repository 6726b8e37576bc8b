#pragma once
// A hull motion history from another program (or from `spiral analyze`'s
// time_series.csv): a delimited text file with a header row naming the
// columns, one row per time.
//
//   time_s, surge_m, sway_m, heave_m, roll_deg, pitch_deg, yaw_deg
//   0.0,    0.0,     0.0,    0.0,     0.0,      0.0,       0.0
//
// Columns are found by name, in any order, case-insensitive: `time` (or `t`),
// `surge`, `sway`, `heave`, `roll`, `pitch`, `yaw`, each with an optional
// unit as `name_unit`, `name [unit]` or `name (unit)`: s for time, m for the
// translations, deg (default) or rad for the rotations. Other columns are
// ignored and listed in `notes` (analyze's `surge_lf_m`, tensions, ...).
// Delimiter: the header's first of `,` `;` tab, else runs of blanks. Blank
// lines and lines starting with `#` are skipped. The motion is the offset of
// the hull reference point from its nominal position, global frame, DOF order
// and rotation convention of DESIGN.md §4 (what analyze writes as the total
// motion).
//
// Errors: design::InputError, one issue per problem, `file:line:col: column:
// problem` (a missing or repeated column, a unit not understood, a value that
// is not a finite number, times that do not increase, fewer than two rows),
// all at once up to kMaxMotionIssues.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace spiral::design {

struct MotionHistory {
  std::vector<double> time_s;                       ///< strictly increasing
  Eigen::Matrix<double, 6, Eigen::Dynamic> offset;  ///< m, rad, one column per time
  std::vector<std::string> notes;                   ///< columns read as ignored, unit choices made
};

/// More issues than this in one file: the rest are summed up in one last issue.
inline constexpr std::size_t kMaxMotionIssues = 50;

/// `source_name` names the file in the messages.
MotionHistory parse_motion_history(std::string_view text, const std::string& source_name);
/// Reads and parses `file` (InputError without a position when it cannot be read).
MotionHistory read_motion_history(const std::filesystem::path& file);

}  // namespace spiral::design
