// The strict YAML map reader of the project loader (yaml_map_reader.hpp).

#include "design/project/yaml_map_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace spiral::design::loader_detail {

const std::string& Context::file_of(std::string_view path) const {
  const std::string_view section = path.substr(0, path.find_first_of(".["));
  const auto it = section_files.find(section);
  return it == section_files.end() ? file : it->second;
}

void Context::add(const YAML::Mark& mark, std::string path, std::string message, std::string problem) {
  std::string in_file = file_of(path);  // before `path` is moved from
  add_in(std::move(in_file), mark, std::move(path), std::move(message), std::move(problem));
}

void Context::add_in(std::string in_file, const YAML::Mark& mark, std::string path, std::string message,
                     std::string problem) {
  InputIssue issue;
  issue.file = std::move(in_file);
  if (!mark.is_null()) {
    issue.line = mark.line + 1;
    issue.column = mark.column + 1;
  }
  issue.path = std::move(path);
  issue.message = std::move(message);
  issue.problem = std::move(problem);
  issues.push_back(std::move(issue));
}

void Context::record(const std::string& path, const YAML::Mark& mark) {
  if (mark.is_null()) return;
  const std::string& in = file_of(path);
  positions[path] = SourcePosition{mark.line + 1, mark.column + 1, in == file ? std::string() : in};
}

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "nothing (null)";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Scalar:
      return fmt::format("\"{}\"", node.Scalar());
    default:
      return "an undefined value";
  }
}

std::string with_unit(std::string_view unit) { return unit.empty() ? std::string() : fmt::format(" in {}", unit); }

namespace {

/// Optimal-string-alignment distance, for "did you mean" suggestions.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

std::string suggestion(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::string_view best;
  std::size_t best_distance = 3;  // more than two edits is not a typo
  for (auto candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance && distance * 2 < std::max<std::size_t>(candidate.size(), 2)) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best.empty() ? std::string() : fmt::format(" (did you mean \"{}\"?)", best);
}

std::string join_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : fmt::format("{}.{}", parent, key);
}

std::string index_path(const std::string& parent, std::size_t index) { return fmt::format("{}[{}]", parent, index); }

// ---------------------------------------------------------------- scalars ----

std::optional<double> to_number(Context& ctx, const YAML::Node& node, const std::string& path, std::string_view unit) {
  // A quoted scalar ("12") is a string in YAML; numbers must be written plainly.
  if (node.IsScalar() && node.Tag() != "!") {
    std::string_view text = node.Scalar();
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc() && end == text.data() + text.size() && std::isfinite(value)) {
      return value;
    }
  }
  ctx.add(node.Mark(), path, fmt::format("expected a finite number{}, got {}", with_unit(unit), describe(node)),
          "wrong_type");
  return std::nullopt;
}

std::optional<int> to_integer(Context& ctx, const YAML::Node& node, const std::string& path) {
  if (node.IsScalar() && node.Tag() != "!") {
    const std::string& text = node.Scalar();
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc() && end == text.data() + text.size()) return value;
  }
  ctx.add(node.Mark(), path, fmt::format("expected an integer, got {}", describe(node)), "wrong_type");
  return std::nullopt;
}

std::optional<std::string> to_string_value(Context& ctx, const YAML::Node& node, const std::string& path) {
  if (node.IsScalar() && !node.Scalar().empty()) return node.Scalar();
  ctx.add(node.Mark(), path, fmt::format("expected a text value, got {}", describe(node)), "wrong_type");
  return std::nullopt;
}

std::optional<std::vector<double>> to_number_list(Context& ctx, const YAML::Node& node, const std::string& path,
                                                  std::string_view unit) {
  if (!node.IsSequence()) {
    ctx.add(node.Mark(), path, fmt::format("expected a list of numbers{}, got {}", with_unit(unit), describe(node)),
            "wrong_type");
    return std::nullopt;
  }
  std::vector<double> out;
  bool ok = true;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string item_path = index_path(path, i);
    ctx.record(item_path, node[i].Mark());
    const auto value = to_number(ctx, node[i], item_path, unit);
    ok = ok && value.has_value();
    if (value) out.push_back(*value);
  }
  return ok ? std::optional(out) : std::nullopt;
}

std::optional<std::vector<std::vector<double>>> to_number_rows(Context& ctx, const YAML::Node& node,
                                                               const std::string& path, std::string_view unit) {
  if (!node.IsSequence()) {
    ctx.add(node.Mark(), path,
            fmt::format("expected a list of rows (lists of numbers{}), got {}", with_unit(unit), describe(node)),
            "wrong_type");
    return std::nullopt;
  }
  std::vector<std::vector<double>> out;
  bool ok = true;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string row_path = index_path(path, i);
    ctx.record(row_path, node[i].Mark());
    const auto row = to_number_list(ctx, node[i], row_path, unit);
    ok = ok && row.has_value();
    if (row) out.push_back(*row);
  }
  return ok ? std::optional(out) : std::nullopt;
}

// ------------------------------------------------------------------ maps ----

MapReader::MapReader(Context& ctx, const YAML::Node& node, std::string path)
    : ctx_(ctx), node_(node), path_(std::move(path)) {
  for (const auto& item : node) {
    const std::string key = item.first.IsScalar() ? item.first.Scalar() : std::string();
    if (key.empty()) {
      ctx_.add(item.first.Mark(), path_, "keys must be plain names", "wrong_type");
      continue;
    }
    const bool duplicate = std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; });
    if (duplicate) {
      ctx_.add(item.first.Mark(), join_path(path_, key), "key given more than once", "duplicate_key");
      continue;
    }
    entries_.push_back(Entry{key, item.first.Mark(), item.second, false});
  }
}

MapReader::~MapReader() {
  std::vector<std::string_view> known(known_.begin(), known_.end());
  for (const auto& entry : entries_) {
    if (entry.used) continue;
    ctx_.add(entry.key_mark, join_path(path_, entry.key),
             fmt::format("unknown key \"{}\"{}", entry.key, suggestion(entry.key, known)), "unknown_key");
  }
}

bool MapReader::has(std::string_view key) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; });
}

std::optional<YAML::Node> MapReader::child(std::string_view key, Presence presence, std::string_view what) {
  known_.emplace_back(key);
  for (auto& entry : entries_) {
    if (entry.key != key) continue;
    entry.used = true;
    ctx_.record(path_of(key), entry.value.Mark());
    return entry.value;
  }
  if (presence == kRequired) {
    ctx_.add(node_.Mark(), path_of(key),
             what.empty() ? std::string("required key is missing") : fmt::format("required key is missing ({})", what),
             "missing_key");
  }
  return std::nullopt;
}

std::optional<double> MapReader::number(std::string_view key, std::string_view unit, Presence presence) {
  const auto node = child(key, presence, unit);
  return node ? to_number(ctx_, *node, path_of(key), unit) : std::nullopt;
}

std::optional<double> MapReader::angle(std::string_view key, Presence presence) {
  const auto value = number(fmt::format("{}_deg", key), "deg", presence);
  return value ? std::optional(*value * kDegToRad) : std::nullopt;
}

std::optional<int> MapReader::integer(std::string_view key, Presence presence) {
  const auto node = child(key, presence);
  return node ? to_integer(ctx_, *node, path_of(key)) : std::nullopt;
}

std::optional<bool> MapReader::boolean(std::string_view key, Presence presence) {
  static const EnumTable<bool> kBooleans{{"true", true}, {"false", false}};
  return enumeration(key, kBooleans, presence);
}

std::optional<std::string> MapReader::text(std::string_view key, Presence presence) {
  const auto node = child(key, presence);
  return node ? to_string_value(ctx_, *node, path_of(key)) : std::nullopt;
}

std::optional<std::vector<double>> MapReader::numbers(std::string_view key, std::string_view unit, Presence presence) {
  const auto node = child(key, presence, unit);
  return node ? to_number_list(ctx_, *node, path_of(key), unit) : std::nullopt;
}

std::optional<std::vector<double>> MapReader::angles(std::string_view key, Presence presence) {
  auto values = numbers(fmt::format("{}_deg", key), "deg", presence);
  if (values) {
    for (double& v : *values) v *= kDegToRad;
  }
  return values;
}

std::optional<std::vector<std::vector<double>>> MapReader::number_rows(std::string_view key, std::string_view unit,
                                                                       Presence presence) {
  const auto node = child(key, presence, unit);
  return node ? to_number_rows(ctx_, *node, path_of(key), unit) : std::nullopt;
}

std::optional<Eigen::Vector3d> MapReader::position(std::string_view key, Presence presence,
                                                   std::optional<double> z_default) {
  const auto node = child(key, presence, "m");
  if (!node) return std::nullopt;
  const std::string path = path_of(key);
  if (node->IsSequence()) return to_vector<3>(ctx_, *node, path, "m");
  if (!node->IsMap()) {
    ctx_.add(node->Mark(), path,
             fmt::format("expected a position [x, y, z] or {{radius, azimuth_deg, z}} in m, got {}", describe(*node)),
             "wrong_type");
    return std::nullopt;
  }
  MapReader polar(ctx_, *node, path);
  const auto radius = polar.number("radius", "m", kRequired);
  const auto azimuth = polar.angle("azimuth", kRequired);
  auto z = polar.number("z", "m", z_default ? kOptional : kRequired);
  if (!z) z = z_default;
  if (!radius || !azimuth || !z) return std::nullopt;
  return Eigen::Vector3d(*radius * std::cos(*azimuth), *radius * std::sin(*azimuth), *z);
}

}  // namespace spiral::design::loader_detail
