#include "design/import/motion_history.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>

#include "design/project/input_error.hpp"

namespace spiral::design {
namespace {

/// Column kinds: time, then the six DOFs in DESIGN.md §4 order.
constexpr std::array<std::string_view, 7> kColumnNames = {"time", "surge", "sway", "heave", "roll", "pitch", "yaw"};
constexpr std::array<std::string_view, 7> kColumnUnits = {"s", "m", "m", "m", "deg", "deg", "deg"};

struct Field {
  std::string_view text;
  int column = 1;  ///< 1-based character column of the field in its line
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s, int& column) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '"' || s.front() == '\'')) {
    s.remove_prefix(1);
    ++column;
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '"' || s.back() == '\'')) s.remove_suffix(1);
  return s;
}

/// The fields of one line, split at `delimiter` (0: runs of blanks).
std::vector<Field> split(std::string_view line, char delimiter) {
  std::vector<Field> fields;
  std::size_t i = 0;
  if (delimiter == 0) {
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      if (i >= line.size()) break;
      const std::size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
      fields.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return fields;
  }
  while (true) {
    const std::size_t end = line.find(delimiter, i);
    int column = static_cast<int>(i) + 1;
    const std::string_view raw = line.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i);
    const std::string_view text = trim(raw, column);
    fields.push_back({text, column});
    if (end == std::string_view::npos) break;
    i = end + 1;
  }
  return fields;
}

/// A header cell as (name, unit): `surge_m`, `surge [m]`, `surge (m)`, `surge`.
std::pair<std::string, std::string> name_and_unit(std::string_view cell) {
  std::string s = lower(cell);
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const std::size_t a = s.find(open);
    if (a != std::string::npos && !s.empty() && s.back() == close) {
      int ignored = 0;
      std::string name(trim(std::string_view(s).substr(0, a), ignored));
      std::string unit(trim(std::string_view(s).substr(a + 1, s.size() - a - 2), ignored));
      return {name, unit};
    }
  }
  for (std::size_t k = 0; k < kColumnNames.size(); ++k) {
    const std::string prefix = std::string(kColumnNames[k]) + "_";
    if (s.rfind(prefix, 0) == 0) {
      const std::string unit = s.substr(prefix.size());
      // `surge_lf_m` is another channel (analyze's low-frequency part), not surge in "lf_m".
      if (unit.find('_') == std::string::npos) return {std::string(kColumnNames[k]), unit};
    }
  }
  if (s == "t_s") return {"time", "s"};
  return {s == "t" ? "time" : s, ""};
}

class MotionParser {
 public:
  explicit MotionParser(std::string source) : source_(std::move(source)) {}

  MotionHistory parse(std::string_view text) {
    std::size_t start = 0;
    int line_number = 0;
    bool header_read = false;
    while (start <= text.size() && !stopped_) {
      const std::size_t end = text.find('\n', start);
      std::string_view line = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
      ++line_number;
      start = end == std::string_view::npos ? text.size() + 1 : end + 1;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      const std::size_t first = line.find_first_not_of(" \t");
      if (first == std::string_view::npos || line[first] == '#') continue;
      if (!header_read) {
        read_header(line, line_number);
        header_read = true;
        if (!issues_.empty()) break;  // rows cannot be read without their columns
      } else {
        read_row(line, line_number);
      }
    }
    if (!header_read) fail(1, 1, "", "empty_motion", "no header row: the file has no data (see docs/lines.md)");
    if (header_read && issues_.empty() && history_.time_s.size() < 2) {
      fail(line_number, 1, "", "motion_too_short",
           fmt::format("needs at least 2 rows of motion, got {}", history_.time_s.size()));
    }
    if (!issues_.empty()) throw InputError(std::move(issues_));
    history_.offset.resize(6, static_cast<Eigen::Index>(rows_.size()));
    for (std::size_t k = 0; k < rows_.size(); ++k) history_.offset.col(static_cast<Eigen::Index>(k)) = rows_[k];
    return std::move(history_);
  }

 private:
  void read_header(std::string_view line, int line_number) {
    delimiter_ = line.find(',') != std::string_view::npos    ? ','
                 : line.find(';') != std::string_view::npos  ? ';'
                 : line.find('\t') != std::string_view::npos ? '\t'
                                                             : 0;
    std::vector<std::string> ignored;
    int position = 0;  // a column's field index is its position in the header row
    for (const Field& cell : split(line, delimiter_)) {
      const int here = position++;
      const auto [name, unit] = name_and_unit(cell.text);
      std::optional<std::size_t> kind;
      for (std::size_t k = 0; k < kColumnNames.size(); ++k)
        if (name == kColumnNames[k]) kind = k;
      if (!kind) {
        ignored.emplace_back(cell.text);
        continue;
      }
      const std::string column_name(kColumnNames[*kind]);
      named_[*kind] = true;
      if (index_[*kind] >= 0) {
        fail(line_number, cell.column, column_name, "motion_column_repeated",
             fmt::format("column {} appears twice (first as field {})", column_name, index_[*kind] + 1));
        continue;
      }
      const bool rotation = *kind >= 4;
      double scale = rotation ? std::numbers::pi / 180.0 : 1.0;
      if (unit.empty() || unit == kColumnUnits[*kind] || (rotation && (unit == "degree" || unit == "degrees"))) {
        if (rotation && unit.empty()) defaulted_deg_.push_back(column_name);
      } else if (rotation && (unit == "rad" || unit == "radian" || unit == "radians")) {
        scale = 1.0;
      } else {
        fail(line_number, cell.column, column_name, "motion_unit_unknown",
             fmt::format("unit \"{}\" not understood for {}; write {}", unit, column_name,
                         rotation ? "deg or rad" : kColumnUnits[*kind]));
        continue;
      }
      index_[*kind] = here;
      scale_[*kind] = scale;
    }
    std::vector<std::string> missing;
    for (std::size_t k = 0; k < kColumnNames.size(); ++k)
      if (!named_[k]) missing.emplace_back(kColumnNames[k]);
    if (!missing.empty()) {
      fail(line_number, 1, "", "motion_column_missing",
           fmt::format("the header has no column {}: it must name time, surge, sway, heave, roll, pitch and yaw "
                       "(units s, m, m, m, deg, deg, deg; see docs/lines.md)",
                       fmt::join(missing, ", ")));
    }
    if (!ignored.empty()) history_.notes.push_back(fmt::format("columns not read: {}", fmt::join(ignored, ", ")));
    if (!defaulted_deg_.empty())
      history_.notes.push_back(fmt::format("{} without a unit read in deg", fmt::join(defaulted_deg_, ", ")));
  }

  void read_row(std::string_view line, int line_number) {
    const std::vector<Field> fields = split(line, delimiter_);
    Eigen::Matrix<double, 6, 1> offset;
    double time_s = 0.0;
    bool ok = true;
    for (std::size_t k = 0; k < kColumnNames.size(); ++k) {
      const auto at = static_cast<std::size_t>(index_[k]);
      const std::string column_name(kColumnNames[k]);
      if (at >= fields.size()) {
        fail(line_number, static_cast<int>(line.size()) + 1, column_name, "motion_row_short",
             fmt::format("the row has {} fields, the header names {} as field {}", fields.size(), column_name, at + 1));
        return;
      }
      const Field& f = fields[at];
      double value = 0.0;
      const char* first = f.text.data();
      const char* last = first + f.text.size();
      if (!f.text.empty() && *first == '+') ++first;
      const auto [end, error] = std::from_chars(first, last, value);
      if (f.text.empty() || error != std::errc() || end != last || !std::isfinite(value)) {
        fail(line_number, f.column, column_name, "motion_value_not_a_number",
             fmt::format("\"{}\" is not a finite number ({})", f.text, kColumnUnits[k]));
        ok = false;
        continue;
      }
      if (k == 0) {
        time_s = value;
      } else {
        offset(static_cast<Eigen::Index>(k - 1)) = value * scale_[k];
      }
    }
    if (!ok) return;
    if (!history_.time_s.empty() && !(time_s > history_.time_s.back())) {
      fail(line_number, fields[static_cast<std::size_t>(index_[0])].column, "time", "motion_time_not_increasing",
           fmt::format("time {} s does not follow {} s of the row before: times must increase", time_s,
                       history_.time_s.back()));
      return;
    }
    history_.time_s.push_back(time_s);
    rows_.push_back(offset);
  }

  void fail(int line, int column, const std::string& path, std::string problem, std::string message) {
    if (stopped_) return;
    if (issues_.size() + 1 >= kMaxMotionIssues) {
      issues_.push_back({source_, line, column, "", InputOrigin::file, "more problems follow; fix these first",
                         "motion_too_many_issues"});
      stopped_ = true;
      return;
    }
    issues_.push_back({source_, line, column, path, InputOrigin::file, std::move(message), std::move(problem)});
  }

  std::string source_;
  char delimiter_ = ',';
  std::array<int, 7> index_{-1, -1, -1, -1, -1, -1, -1};
  std::array<double, 7> scale_{1, 1, 1, 1, 1, 1, 1};
  std::array<bool, 7> named_{};
  std::vector<std::string> defaulted_deg_;
  MotionHistory history_;
  std::vector<Eigen::Matrix<double, 6, 1>> rows_;
  std::vector<InputIssue> issues_;
  bool stopped_ = false;
};

}  // namespace

MotionHistory parse_motion_history(std::string_view text, const std::string& source_name) {
  return MotionParser(source_name).parse(text);
}

MotionHistory read_motion_history(const std::filesystem::path& file) {
  if (std::filesystem::is_directory(file)) {
    throw InputError({{file.string(), std::nullopt, std::nullopt, "", InputOrigin::file,
                       "is a folder, not a motion history", "missing_file"}});
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError({{file.string(), std::nullopt, std::nullopt, "", InputOrigin::file,
                       "cannot read the motion history (missing or unreadable)", "missing_file"}});
  }
  std::stringstream text;
  text << in.rdbuf();
  return parse_motion_history(text.str(), file.string());
}

}  // namespace spiral::design
