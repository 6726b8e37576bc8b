#include "design/project/command_line_reference.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace spiral::design {

InputError command_line_error(const Project& project, const std::string& option, const std::string& message,
                              const std::string& condition) {
  InputIssue issue;
  issue.file = project.source_file;
  issue.path = option;
  issue.message = message;
  issue.condition = condition;
  return InputError({issue});
}

const LoadCase& find_load_case(const Project& project, const std::string& name) {
  const auto it = std::find_if(project.load_cases.begin(), project.load_cases.end(),
                               [&](const LoadCase& c) { return c.name == name; });
  if (it == project.load_cases.end()) {
    std::string names;
    for (const LoadCase& c : project.load_cases) names += (names.empty() ? "" : ", ") + c.name;
    throw command_line_error(project, "--case", fmt::format("no load case named \"{}\" (defined: {})", name, names));
  }
  return *it;
}

}  // namespace spiral::design
