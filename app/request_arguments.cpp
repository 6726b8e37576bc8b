#include "app/request_arguments.hpp"

#include <string_view>
#include <utility>

namespace spiral::app {

std::string flag_of(const std::string& argument) {
  // The request fields of design/ (StaticCaseRequest, DynamicAnalysisRequest,
  // SozOptions, ...) and the flags of app/commands that set them.
  static constexpr std::pair<std::string_view, std::string_view> kFlags[] = {
      {"load_case", "--case"},
      {"damaged_line", "--damaged"},
      {"level", "--level"},
      {"duration_s", "--duration"},
      {"stage", "--stage"},
      {"step_deg", "--step-deg"},
      {"tolerance_m", "--tolerance"},
      {"search_limit_pct_depth", "--search-limit"},
      {"exclude_risers", "--exclude"},
      {"extreme", "--extreme"},
      {"cases", "--cases"},
      {"groups", "--groups"},
      {"points", "--points"},
      {"objective", "--objective"},
      {"max_evaluations", "--max-evaluations"},
      {"until", "--until"},
      {"jobs", "--jobs"},
      {"lines", "--lines"},
      {"motion", "--motion"},
      {"output_step_s", "--step"},
      {"ramp_s", "--ramp"},
      {"tolerance_scale", "--tolerance-scale"},
      {"decay.displacement", "--decay"},
      {"decay.release_s", "--release"},
  };
  for (const auto& [name, flag] : kFlags)
    if (name == argument) return std::string(flag);
  return argument;
}

std::string describe(const design::InputError& error) {
  std::string text;
  for (design::InputIssue issue : error.issues()) {
    if (issue.origin == design::InputOrigin::request) issue.path = flag_of(issue.path);
    if (!text.empty()) text += '\n';
    text += design::format_issue(issue);
  }
  return text;
}

}  // namespace spiral::app
