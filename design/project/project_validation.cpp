// Semantic validation of a project (format v1): the placing of issues and the
// order of the section checks (project_validation_checks.hpp lists the files
// of each section's checks).

#include "design/project/project_validation.hpp"

#include <utility>

#include "design/project/project_validation_checks.hpp"

namespace spiral::design {

InputIssue make_issue(const Project& project, const std::string& path, std::string problem, std::string message) {
  InputIssue issue;
  issue.file = project.source_file;
  // A value that was defaulted has no node: use its closest written parent.
  std::string at = path;
  while (true) {
    if (const auto it = project.source_map.find(at); it != project.source_map.end()) {
      issue.line = it->second.line;
      issue.column = it->second.column;
      if (!it->second.file.empty()) issue.file = it->second.file;
      break;
    }
    const auto cut = at.find_last_of(".[");
    if (cut == std::string::npos) break;
    at.resize(cut);
  }
  issue.path = path;
  issue.message = std::move(message);
  issue.problem = std::move(problem);
  return issue;
}

std::vector<InputIssue> check_project(const Project& project, const LineCheckTable& line_types) {
  using namespace validation_detail;
  std::vector<InputIssue> issues;
  Reporter r(project, issues);
  check_site(project, r);
  check_line_types(project, r);
  check_mooring(project, line_types, r);
  check_hull(project, r);
  check_risers(project, r);
  check_environments(project, r);
  check_load_cases(project, r);
  check_load_case_matrix(project, r);
  check_criteria(project, r);
  check_stages(project, r);
  check_optimization(project, line_types, r);
  check_global_analysis(project, r);
  sort_in_file_order(issues);
  return issues;
}

void validate_project(const Project& project, const LineCheckTable& line_types) {
  auto issues = check_project(project, line_types);
  if (!issues.empty()) throw InputError(std::move(issues));
}

}  // namespace spiral::design
