#pragma once
// The semantic validation pass over a parsed project (format v1): physical
// ranges, references between sections, unique names and the at-rest geometry
// of the mooring lines. Every check reports a named problem (the `problem` of
// each InputIssue; the list is in docs/project-format.md, "Validation"), and
// every issue found is reported, with the position of the offending node
// taken from Project::source_map.
//
// The pass reads the model only; it never clamps or defaults a value.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "design/project/input_error.hpp"
#include "design/project/project.hpp"

namespace spiral::design {

/// What the line-length checks need to know of a line type. Fill it from the
/// resolved properties (resolve_line_type in design/project/line_properties.hpp);
/// a type missing from the table falls back to the explicit values of its
/// LineTypeInput (axial_stiffness, breaking_load, submerged_weight).
struct LineCheckProperties {
  std::optional<double> axial_stiffness_N;         ///< EA (polyester: static EA)
  std::optional<double> breaking_load_N;           ///< MBL
  std::optional<double> submerged_weight_N_per_m;  ///< < 0 for a buoyant line
};

/// Line-type name -> properties for the checks.
using LineCheckTable = std::map<std::string, LineCheckProperties, std::less<>>;

/// Mean strain above which a line that is shorter than its anchor-fairlead
/// chord is reported when its EA or MBL is unknown (no polyester, wire or
/// chain survives 10 % strain).
inline constexpr double kMaxStrainWithoutProperties = 0.10;

/// Tolerance on the anchor depth: an anchor may sit on the seabed to round-off.
inline constexpr double kSeabedTolerance_m = 1e-6;

/// An issue at `path` of `project`, placed at the nearest recorded node of the
/// path (a defaulted value has no node of its own: its parent's is used).
InputIssue make_issue(const Project& project, const std::string& path, std::string problem, std::string message);

/// Every issue of `project`, in file order; empty when the project is valid.
std::vector<InputIssue> check_project(const Project& project, const LineCheckTable& line_types = {});

/// Throws InputError listing every issue of `project`.
void validate_project(const Project& project, const LineCheckTable& line_types = {});

}  // namespace spiral::design
