#pragma once
// Internal to the validation pass (not a public design API): the reporter,
// the value checks every section uses, and the checks of each section of the
// project (format v1). One file per group of sections:
//   project_validation_checks.cpp    the value checks and the FE mesh / file checks
//   project_validation_mooring.cpp   site, line_types, mooring (incl. the
//                                    at-rest line-length checks)
//   project_validation_hull.cpp      hull (tables, hydrodynamics, geometry)
//   project_validation_risers.cpp    risers and the riser criteria
//   project_validation_cases.cpp     environments, load_cases, criteria, stages
//   project_validation_optimization.cpp  optimization
// and project_validation.cpp runs them in that order. Each check reports each
// problem under its name; the problem names and messages are
// listed in docs/project-format.md. (Layout after Drake's
// geometry/scene_graph_config.cc ValidateOrThrow.)

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "design/project/project.hpp"
#include "design/project/project_validation.hpp"

namespace spiral::design::validation_detail {

inline constexpr double kRadToDeg = 180.0 / std::numbers::pi;

/// Collects issues, placing each at the nearest recorded node of its path.
class Reporter {
 public:
  Reporter(const Project& project, std::vector<InputIssue>& out) : project_(project), out_(out) {}

  void fail(const std::string& path, std::string problem, std::string message) {
    out_.push_back(make_issue(project_, path, std::move(problem), std::move(message)));
  }

 private:
  const Project& project_;
  std::vector<InputIssue>& out_;
};

// ---------------------------------------------------------------- values ----
// Each reports `problem` at `path` when the value breaks the rule; an
// absent optional value is not checked.

void positive(Reporter& r, const std::string& path, double value, std::string_view unit, const char* problem);
void positive(Reporter& r, const std::string& path, const std::optional<double>& value, std::string_view unit,
              const char* problem);
void at_least(Reporter& r, const std::string& path, double value, double minimum, std::string_view unit,
              const char* problem);
void at_least(Reporter& r, const std::string& path, const std::optional<double>& value, double minimum,
              std::string_view unit, const char* problem);

/// Reports the second and later uses of a name in a list.
template <typename T>
void unique_names(Reporter& r, const std::vector<T>& items, const std::string& list_path, const char* what,
                  const char* problem) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (items[i].name == items[j].name) {
        r.fail(fmt::format("{}[{}].name", list_path, i), problem,
               fmt::format("duplicate {} name \"{}\", first used by {}[{}]", what, items[i].name, list_path, j));
        break;
      }
    }
  }
}

template <typename T>
bool defined(const std::vector<T>& items, const std::string& name) {
  return std::any_of(items.begin(), items.end(), [&](const T& item) { return item.name == name; });
}

/// " (defined: a, b, c)" for reference errors.
template <typename T>
std::string defined_list(const std::vector<T>& items) {
  std::vector<std::string> names;
  for (const auto& item : items) names.push_back(item.name);
  return names.empty() ? std::string(" (none defined)") : fmt::format(" (defined: {})", fmt::join(names, ", "));
}

// -------------------------------------------------------------- sections ----

/// The EA/MBL/weight of a line type: the resolved table first, explicit input second.
LineCheckProperties check_properties(const Project& p, const LineCheckTable& table, const std::string& type);

/// A global-analysis mesh coarser than this many elements per line is not a
/// mesh of the line's shape: 2,740 m at the default FPS's 40 m gives 68.5
/// (70 elements, each segment meshed whole).
inline constexpr double kMinGlobalElementsPerLine = 10.0;

/// FE discretization of a line or riser at `at` (its `fe` map).
void check_fe_mesh(Reporter& r, const std::string& at, const FeMesh& mesh);
/// A file the project refers to exists (file_exists).
void check_file(Reporter& r, const std::string& at, const std::filesystem::path& file);
/// Riser criteria values given at `at` (criteria.risers or risers[i].criteria).
void check_riser_criteria(Reporter& r, const std::string& at, const RiserCriteriaOverrides& c);

void check_site(const Project& p, Reporter& r);
void check_line_types(const Project& p, Reporter& r);
/// Segments, attachments, anchor and fairlead depths, meshes and the at-rest
/// line length of every mooring line (`table`: EA, MBL and weight of the line
/// types), and the line groups.
void check_mooring(const Project& p, const LineCheckTable& table, Reporter& r);
void check_hull(const Project& p, Reporter& r);
void check_risers(const Project& p, Reporter& r);
void check_environments(const Project& p, Reporter& r);
void check_load_cases(const Project& p, Reporter& r);
/// Environments, headings, damaged lines and generated names of `load_case_matrix`.
void check_load_case_matrix(const Project& p, Reporter& r);
void check_criteria(const Project& p, Reporter& r);
void check_stages(const Project& p, Reporter& r);
/// Groups, bounds (ordered, no line left too short), cases and limits of `optimization`.
void check_optimization(const Project& p, const LineCheckTable& table, Reporter& r);
/// `global_analysis.element_length`: > 0, and at least kMinGlobalElementsPerLine
/// elements on the shortest mooring line or riser.
void check_global_analysis(const Project& p, Reporter& r);

}  // namespace spiral::design::validation_detail
