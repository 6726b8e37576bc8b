#include "design/project/request_error.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace spiral::design {

InputError request_error(const Project& project, const std::string& argument, const std::string& message,
                         const std::string& problem) {
  InputIssue issue;
  issue.file = project.source_file;
  issue.path = argument;
  issue.origin = InputOrigin::request;
  issue.message = message;
  issue.problem = problem;
  return InputError({issue});
}

const LoadCase& find_load_case(const Project& project, const std::string& name) {
  const auto it = std::find_if(project.load_cases.begin(), project.load_cases.end(),
                               [&](const LoadCase& c) { return c.name == name; });
  if (it == project.load_cases.end()) {
    std::string names;
    for (const LoadCase& c : project.load_cases) names += (names.empty() ? "" : ", ") + c.name;
    throw request_error(project, "load_case", fmt::format("no load case named \"{}\" (defined: {})", name, names));
  }
  return *it;
}

}  // namespace spiral::design
