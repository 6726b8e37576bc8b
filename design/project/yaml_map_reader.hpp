#pragma once
// Internal to the project loader (not a public design API): the strict YAML
// map reader every section of the project file is read through. One reader
// does all the strictness, so an unknown key, a duplicate key, a wrong type
// or a missing required key is reported the same way everywhere, with the
// position of the offending node. Nothing here throws: issues are collected
// in a Context and the loader throws them together at the end. (The approach
// follows Drake's common/yaml/yaml_read_archive.)
//
// Units: a key `<name>_deg` is read in degrees and returned in radians
// (MapReader::angle, MapReader::angles); every other number is returned as
// written, in the unit its message names.

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include <fmt/format.h>

#include <cstddef>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "design/project/input_error.hpp"
#include "design/project/project.hpp"

namespace spiral::design::loader_detail {

inline constexpr double kDegToRad = std::numbers::pi / 180.0;

enum class Presence { required, optional };
inline constexpr Presence kRequired = Presence::required;
inline constexpr Presence kOptional = Presence::optional;

/// Collects issues and node positions while the file is read.
struct Context {
  std::string file;
  std::vector<InputIssue> issues;
  SourceMap positions;
  /// Top-level section -> the file it comes from, for the sections a
  /// variation takes from its base file (`extends`); the rest are `file`'s.
  std::map<std::string, std::string, std::less<>> section_files;

  /// The file the field at `path` was written in.
  const std::string& file_of(std::string_view path) const;

  void add(const YAML::Mark& mark, std::string path, std::string message, std::string problem);
  /// The same, in `in_file` (a base file's own problems, `extends`).
  void add_in(std::string in_file, const YAML::Mark& mark, std::string path, std::string message, std::string problem);
  void record(const std::string& path, const YAML::Mark& mark);
};

/// Short description of what a node holds, for "got ..." parts of messages.
std::string describe(const YAML::Node& node);

/// " (did you mean "x"?)" when one candidate is close to `word`, else "".
std::string suggestion(std::string_view word, const std::vector<std::string_view>& candidates);

/// `parent.key`, or `key` at the top level.
std::string join_path(const std::string& parent, std::string_view key);
/// `parent[index]`.
std::string index_path(const std::string& parent, std::size_t index);

// ---------------------------------------------------------------- scalars ----
// Each returns the value, or reports a wrong_type issue at the node and
// returns nothing.

/// A finite number written plainly (a quoted "12" is text in YAML).
std::optional<double> to_number(Context& ctx, const YAML::Node& node, const std::string& path, std::string_view unit);
std::optional<int> to_integer(Context& ctx, const YAML::Node& node, const std::string& path);
/// A non-empty scalar.
std::optional<std::string> to_string_value(Context& ctx, const YAML::Node& node, const std::string& path);

template <typename E>
using EnumTable = std::vector<std::pair<std::string_view, E>>;

/// One of the names of `table` (bad_enum with a suggestion otherwise).
template <typename E>
std::optional<E> to_enum(Context& ctx, const YAML::Node& node, const std::string& path, const EnumTable<E>& table) {
  std::vector<std::string_view> names;
  for (const auto& [name, value] : table) names.push_back(name);
  const std::string allowed = fmt::format("{}", fmt::join(names, " | "));
  if (!node.IsScalar()) {
    ctx.add(node.Mark(), path, fmt::format("expected one of {}, got {}", allowed, describe(node)), "wrong_type");
    return std::nullopt;
  }
  for (const auto& [name, value] : table) {
    if (node.Scalar() == name) return value;
  }
  ctx.add(node.Mark(), path,
          fmt::format("unknown value \"{}\"; allowed: {}{}", node.Scalar(), allowed, suggestion(node.Scalar(), names)),
          "bad_enum");
  return std::nullopt;
}

/// " in <unit>", or "" without a unit.
std::string with_unit(std::string_view unit);

/// A fixed-size list of numbers, e.g. [x, y, z].
template <int N>
std::optional<Eigen::Matrix<double, N, 1>> to_vector(Context& ctx, const YAML::Node& node, const std::string& path,
                                                     std::string_view unit) {
  if (!node.IsSequence() || node.size() != static_cast<std::size_t>(N)) {
    ctx.add(node.Mark(), path,
            fmt::format("expected a list of {} numbers{}, got {}{}", N, with_unit(unit), describe(node),
                        node.IsSequence() ? fmt::format(" of {} items", node.size()) : ""),
            "wrong_type");
    return std::nullopt;
  }
  Eigen::Matrix<double, N, 1> out;
  bool ok = true;
  for (int i = 0; i < N; ++i) {
    const auto value = to_number(ctx, node[i], index_path(path, i), unit);
    ok = ok && value.has_value();
    if (value) out[i] = *value;
  }
  return ok ? std::optional(out) : std::nullopt;
}

/// A list of numbers of any length, e.g. [0, 30, 60]; item positions are recorded.
std::optional<std::vector<double>> to_number_list(Context& ctx, const YAML::Node& node, const std::string& path,
                                                  std::string_view unit);

/// A list of rows of numbers, [[...], [...]]; rows may differ in length here
/// (the validation pass checks them against the table's axes).
std::optional<std::vector<std::vector<double>>> to_number_rows(Context& ctx, const YAML::Node& node,
                                                               const std::string& path, std::string_view unit);

// ------------------------------------------------------------------ maps ----

/// Reads one YAML map: every key must be looked up, or it is reported as
/// unknown (with a suggestion among the keys looked up) when the reader goes
/// out of scope. The typed getters return nothing when the key is absent or
/// its value was reported.
class MapReader {
 public:
  /// Reports keys that are not plain names and keys given twice.
  MapReader(Context& ctx, const YAML::Node& node, std::string path);
  MapReader(const MapReader&) = delete;
  MapReader& operator=(const MapReader&) = delete;
  ~MapReader();

  Context& context() { return ctx_; }
  const std::string& path() const { return path_; }
  const YAML::Mark mark() const { return node_.Mark(); }
  std::string path_of(std::string_view key) const { return join_path(path_, key); }
  bool has(std::string_view key) const;

  /// The value of `key`; reports a missing required key (at the map's position).
  std::optional<YAML::Node> child(std::string_view key, Presence presence, std::string_view what = {});

  std::optional<double> number(std::string_view key, std::string_view unit, Presence presence);
  /// Reads `<key>_deg` in degrees and returns radians.
  std::optional<double> angle(std::string_view key, Presence presence);
  std::optional<int> integer(std::string_view key, Presence presence);
  /// YAML 1.2 core schema booleans only: true | false.
  std::optional<bool> boolean(std::string_view key, Presence presence);
  std::optional<std::string> text(std::string_view key, Presence presence);
  std::optional<std::vector<double>> numbers(std::string_view key, std::string_view unit, Presence presence);
  /// Reads the list `<key>_deg` in degrees and returns radians.
  std::optional<std::vector<double>> angles(std::string_view key, Presence presence);
  std::optional<std::vector<std::vector<double>>> number_rows(std::string_view key, std::string_view unit,
                                                              Presence presence);
  template <typename E>
  std::optional<E> enumeration(std::string_view key, const EnumTable<E>& table, Presence presence) {
    const auto node = child(key, presence);
    return node ? to_enum(ctx_, *node, path_of(key), table) : std::nullopt;
  }
  template <int N>
  std::optional<Eigen::Matrix<double, N, 1>> vector(std::string_view key, std::string_view unit, Presence presence) {
    const auto node = child(key, presence, unit);
    return node ? to_vector<N>(ctx_, *node, path_of(key), unit) : std::nullopt;
  }

  /// A position written as [x, y, z] or {radius, azimuth_deg, z}. Without
  /// `z_default`, z is required in the polar form.
  std::optional<Eigen::Vector3d> position(std::string_view key, Presence presence,
                                          std::optional<double> z_default = std::nullopt);

  /// Calls `read(MapReader&)` on the map under `key`.
  template <typename F>
  void map(std::string_view key, Presence presence, F&& read) {
    const auto node = child(key, presence);
    if (!node) return;
    if (!node->IsMap()) {
      ctx_.add(node->Mark(), path_of(key), fmt::format("expected a map, got {}", describe(*node)), "wrong_type");
      return;
    }
    MapReader reader(ctx_, *node, path_of(key));
    read(reader);
  }

  /// Calls `read(MapReader&)` on every map of the list under `key`.
  template <typename F>
  void list_of_maps(std::string_view key, Presence presence, F&& read) {
    list(key, presence, [&](const YAML::Node& item, const std::string& item_path) {
      if (!item.IsMap()) {
        ctx_.add(item.Mark(), item_path, fmt::format("expected a map, got {}", describe(item)), "wrong_type");
        return;
      }
      MapReader reader(ctx_, item, item_path);
      read(reader);
    });
  }

  /// Calls `read(node, path)` on every item of the list under `key`.
  template <typename F>
  void list(std::string_view key, Presence presence, F&& read) {
    const auto node = child(key, presence);
    if (!node) return;
    const std::string list_path = path_of(key);
    if (!node->IsSequence()) {
      ctx_.add(node->Mark(), list_path, fmt::format("expected a list, got {}", describe(*node)), "wrong_type");
      return;
    }
    for (std::size_t i = 0; i < node->size(); ++i) {
      const std::string item_path = index_path(list_path, i);
      ctx_.record(item_path, (*node)[i].Mark());
      read((*node)[i], item_path);
    }
  }

 private:
  struct Entry {
    std::string key;
    YAML::Mark key_mark;
    YAML::Node value;
    bool used = false;
  };
  Context& ctx_;
  YAML::Node node_;
  std::string path_;
  std::vector<Entry> entries_;
  std::vector<std::string> known_;
};

/// Sets `target` to `value` when there is one (a default stays otherwise).
template <typename T>
void assign(T& target, const std::optional<T>& value) {
  if (value) target = *value;
}

}  // namespace spiral::design::loader_detail
