#include "design/project/input_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace spiral::design {

std::string format_issue(const InputIssue& issue) {
  std::string out = issue.file;
  if (issue.line) {
    out += fmt::format(":{}:{}", *issue.line, issue.column.value_or(1));
  }
  out += ": ";
  if (!issue.path.empty()) out += issue.path + ": ";
  out += issue.message;
  return out;
}

void sort_in_file_order(std::vector<InputIssue>& issues) {
  std::stable_sort(issues.begin(), issues.end(), [](const InputIssue& a, const InputIssue& b) {
    return std::pair(a.line.value_or(0), a.column.value_or(0)) < std::pair(b.line.value_or(0), b.column.value_or(0));
  });
}

namespace {
std::string join_issues(const std::vector<InputIssue>& issues) {
  std::string text;
  for (const auto& issue : issues) {
    if (!text.empty()) text += '\n';
    text += format_issue(issue);
  }
  return text;
}
}  // namespace

InputError::InputError(std::vector<InputIssue> issues)
    : std::runtime_error(join_issues(issues)), issues_(std::move(issues)) {}

}  // namespace spiral::design
