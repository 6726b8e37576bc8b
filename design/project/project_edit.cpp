#include "design/project/project_edit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace spiral::design {

namespace {

struct Edit {
  std::size_t offset = 0;  ///< into the text
  std::size_t length = 0;
  std::string value;
};

/// Byte offset of 1-based (line, column) in `text`.
std::size_t offset_of(const std::string& text, int line, int column) {
  std::size_t at = 0;
  for (int l = 1; l < line; ++l) {
    at = text.find('\n', at);
    if (at == std::string::npos) throw std::invalid_argument("source position past the end of the project text");
    ++at;
  }
  return at + static_cast<std::size_t>(column - 1);
}

/// Length of the plain scalar that starts at `at` (ends at a flow or
/// comment delimiter, or the line's end).
std::size_t scalar_length(const std::string& text, std::size_t at) {
  std::size_t end = at;
  while (end < text.size() && std::string_view(",}]#\n\r").find(text[end]) == std::string_view::npos) ++end;
  while (end > at && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  return end - at;
}

}  // namespace

std::string with_line_payouts(const std::string& text, const Project& project,
                              const std::map<std::string, double>& payouts_m, const std::string& header) {
  std::vector<Edit> edits;
  for (const auto& [name, payout] : payouts_m) {
    const auto it = std::find_if(project.mooring.lines.begin(), project.mooring.lines.end(),
                                 [&](const MooringLine& l) { return l.name == name; });
    if (it == project.mooring.lines.end() || it->segments.empty())
      throw std::invalid_argument(fmt::format("no mooring line named '{}'", name));
    const auto line_index = static_cast<std::size_t>(it - project.mooring.lines.begin());
    const std::size_t top = it->segments.size() - 1;
    const std::string path = fmt::format("mooring.lines[{}].segments[{}].length", line_index, top);
    const auto position = project.source_map.find(path);
    if (position == project.source_map.end())
      throw std::invalid_argument(fmt::format("no source position for {} (a project built in code?)", path));
    const std::size_t at = offset_of(text, position->second.line, position->second.column);
    edits.push_back({at, scalar_length(text, at), fmt::format("{:.4f}", it->segments[top].length_m + payout)});
  }
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.offset > b.offset; });
  std::string out = text;
  for (const Edit& e : edits) out.replace(e.offset, e.length, e.value);
  std::ostringstream commented;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) commented << (line.empty() ? "#" : "# " + line) << '\n';
  return commented.str() + out;
}

}  // namespace spiral::design
