// YAML -> design::Project (format v1). One reader (MapReader) does all the
// strictness: every map is read through it, so an unknown key, a duplicate
// key, a wrong type or a missing required key is reported the same way
// everywhere, with the position of the offending node. Nothing here throws
// until the whole file has been read; then every issue goes into one
// InputError. (The approach follows Drake's common/yaml/yaml_read_archive.)
//
// The file is longer than the usual ~600 lines because the schema mapping of
// every section reads best in one place, next to the reader it uses.

#include "design/project/project_loader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <span>
#include <sstream>
#include <utility>

namespace spiral::design {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

enum class Presence { required, optional };
constexpr Presence kRequired = Presence::required;
constexpr Presence kOptional = Presence::optional;

/// Collects issues and node positions while the file is read.
struct Context {
  std::string file;
  std::vector<InputIssue> issues;
  SourceMap positions;

  void add(const YAML::Mark& mark, std::string path, std::string message, std::string condition) {
    InputIssue issue;
    issue.file = file;
    if (!mark.is_null()) {
      issue.line = mark.line + 1;
      issue.column = mark.column + 1;
    }
    issue.path = std::move(path);
    issue.message = std::move(message);
    issue.condition = std::move(condition);
    issues.push_back(std::move(issue));
  }
  void record(const std::string& path, const YAML::Mark& mark) {
    if (!mark.is_null()) positions[path] = SourcePosition{mark.line + 1, mark.column + 1};
  }
};

/// Short description of what a node holds, for "got ..." parts of messages.
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

std::string with_unit(std::string_view unit) {
  return unit.empty() ? std::string() : fmt::format(" in {}", unit);
}

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

/// " (did you mean "x"?)" when one candidate is close to `word`, else "".
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

std::string index_path(const std::string& parent, std::size_t index) {
  return fmt::format("{}[{}]", parent, index);
}

// ---------------------------------------------------------------- scalars ----

std::optional<double> to_number(Context& ctx, const YAML::Node& node, const std::string& path,
                                std::string_view unit) {
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
  ctx.add(node.Mark(), path,
          fmt::format("expected a finite number{}, got {}", with_unit(unit), describe(node)),
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
  ctx.add(node.Mark(), path, fmt::format("expected an integer, got {}", describe(node)),
          "wrong_type");
  return std::nullopt;
}

std::optional<std::string> to_string_value(Context& ctx, const YAML::Node& node,
                                           const std::string& path) {
  if (node.IsScalar() && !node.Scalar().empty()) return node.Scalar();
  ctx.add(node.Mark(), path, fmt::format("expected a text value, got {}", describe(node)),
          "wrong_type");
  return std::nullopt;
}

template <typename E>
using EnumTable = std::vector<std::pair<std::string_view, E>>;

template <typename E>
std::optional<E> to_enum(Context& ctx, const YAML::Node& node, const std::string& path,
                         const EnumTable<E>& table) {
  std::vector<std::string_view> names;
  for (const auto& [name, value] : table) names.push_back(name);
  const std::string allowed = fmt::format("{}", fmt::join(names, " | "));
  if (!node.IsScalar()) {
    ctx.add(node.Mark(), path, fmt::format("expected one of {}, got {}", allowed, describe(node)),
            "wrong_type");
    return std::nullopt;
  }
  for (const auto& [name, value] : table) {
    if (node.Scalar() == name) return value;
  }
  ctx.add(node.Mark(), path,
          fmt::format("unknown value \"{}\"; allowed: {}{}", node.Scalar(), allowed,
                      suggestion(node.Scalar(), names)),
          "bad_enum");
  return std::nullopt;
}

/// A fixed-size list of numbers, e.g. [x, y, z].
template <int N>
std::optional<Eigen::Matrix<double, N, 1>> to_vector(Context& ctx, const YAML::Node& node,
                                                     const std::string& path,
                                                     std::string_view unit) {
  if (!node.IsSequence() || node.size() != static_cast<std::size_t>(N)) {
    ctx.add(
        node.Mark(), path,
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
std::optional<std::vector<double>> to_number_list(Context& ctx, const YAML::Node& node,
                                                  const std::string& path, std::string_view unit) {
  if (!node.IsSequence()) {
    ctx.add(node.Mark(), path,
            fmt::format("expected a list of numbers{}, got {}", with_unit(unit), describe(node)),
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

/// A list of rows of numbers, [[...], [...]]; rows may differ in length here
/// (the validation pass checks them against the table's axes).
std::optional<std::vector<std::vector<double>>> to_number_rows(Context& ctx, const YAML::Node& node,
                                                               const std::string& path,
                                                               std::string_view unit) {
  if (!node.IsSequence()) {
    ctx.add(node.Mark(), path,
            fmt::format("expected a list of rows (lists of numbers{}), got {}", with_unit(unit),
                        describe(node)),
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

/// Reads one YAML map: every key must be looked up, or it is reported as
/// unknown when the reader goes out of scope.
class MapReader {
 public:
  MapReader(Context& ctx, const YAML::Node& node, std::string path)
      : ctx_(ctx), node_(node), path_(std::move(path)) {
    for (const auto& item : node) {
      const std::string key = item.first.IsScalar() ? item.first.Scalar() : std::string();
      if (key.empty()) {
        ctx_.add(item.first.Mark(), path_, "keys must be plain names", "wrong_type");
        continue;
      }
      const bool duplicate = std::any_of(entries_.begin(), entries_.end(),
                                         [&](const Entry& e) { return e.key == key; });
      if (duplicate) {
        ctx_.add(item.first.Mark(), join_path(path_, key), "key given more than once",
                 "duplicate_key");
        continue;
      }
      entries_.push_back(Entry{key, item.first.Mark(), item.second, false});
    }
  }
  MapReader(const MapReader&) = delete;
  MapReader& operator=(const MapReader&) = delete;

  ~MapReader() {
    std::vector<std::string_view> known(known_.begin(), known_.end());
    for (const auto& entry : entries_) {
      if (entry.used) continue;
      ctx_.add(entry.key_mark, join_path(path_, entry.key),
               fmt::format("unknown key \"{}\"{}", entry.key, suggestion(entry.key, known)),
               "unknown_key");
    }
  }

  Context& context() { return ctx_; }
  const std::string& path() const { return path_; }
  const YAML::Mark mark() const { return node_.Mark(); }
  std::string path_of(std::string_view key) const { return join_path(path_, key); }
  bool has(std::string_view key) const {
    return std::any_of(entries_.begin(), entries_.end(),
                       [&](const Entry& e) { return e.key == key; });
  }

  /// The value of `key`; reports a missing required key (at the map's position).
  std::optional<YAML::Node> child(std::string_view key, Presence presence,
                                  std::string_view what = {}) {
    known_.emplace_back(key);
    for (auto& entry : entries_) {
      if (entry.key != key) continue;
      entry.used = true;
      ctx_.record(path_of(key), entry.value.Mark());
      return entry.value;
    }
    if (presence == kRequired) {
      ctx_.add(node_.Mark(), path_of(key),
               what.empty() ? std::string("required key is missing")
                            : fmt::format("required key is missing ({})", what),
               "missing_key");
    }
    return std::nullopt;
  }

  std::optional<double> number(std::string_view key, std::string_view unit, Presence presence) {
    const auto node = child(key, presence, unit);
    return node ? to_number(ctx_, *node, path_of(key), unit) : std::nullopt;
  }
  /// Reads `<key>_deg` in degrees and returns radians.
  std::optional<double> angle(std::string_view key, Presence presence) {
    const auto value = number(fmt::format("{}_deg", key), "deg", presence);
    return value ? std::optional(*value * kDegToRad) : std::nullopt;
  }
  std::optional<int> integer(std::string_view key, Presence presence) {
    const auto node = child(key, presence);
    return node ? to_integer(ctx_, *node, path_of(key)) : std::nullopt;
  }
  std::optional<std::string> text(std::string_view key, Presence presence) {
    const auto node = child(key, presence);
    return node ? to_string_value(ctx_, *node, path_of(key)) : std::nullopt;
  }
  std::optional<std::vector<double>> numbers(std::string_view key, std::string_view unit,
                                             Presence presence) {
    const auto node = child(key, presence, unit);
    return node ? to_number_list(ctx_, *node, path_of(key), unit) : std::nullopt;
  }
  /// Reads the list `<key>_deg` in degrees and returns radians.
  std::optional<std::vector<double>> angles(std::string_view key, Presence presence) {
    auto values = numbers(fmt::format("{}_deg", key), "deg", presence);
    if (values) {
      for (double& v : *values) v *= kDegToRad;
    }
    return values;
  }
  std::optional<std::vector<std::vector<double>>> number_rows(std::string_view key,
                                                              std::string_view unit,
                                                              Presence presence) {
    const auto node = child(key, presence, unit);
    return node ? to_number_rows(ctx_, *node, path_of(key), unit) : std::nullopt;
  }
  template <typename E>
  std::optional<E> enumeration(std::string_view key, const EnumTable<E>& table, Presence presence) {
    const auto node = child(key, presence);
    return node ? to_enum(ctx_, *node, path_of(key), table) : std::nullopt;
  }
  template <int N>
  std::optional<Eigen::Matrix<double, N, 1>> vector(std::string_view key, std::string_view unit,
                                                    Presence presence) {
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
      ctx_.add(node->Mark(), path_of(key), fmt::format("expected a map, got {}", describe(*node)),
               "wrong_type");
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
        ctx_.add(item.Mark(), item_path, fmt::format("expected a map, got {}", describe(item)),
                 "wrong_type");
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
      ctx_.add(node->Mark(), list_path, fmt::format("expected a list, got {}", describe(*node)),
               "wrong_type");
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

std::optional<Eigen::Vector3d> MapReader::position(std::string_view key, Presence presence,
                                                   std::optional<double> z_default) {
  const auto node = child(key, presence, "m");
  if (!node) return std::nullopt;
  const std::string path = path_of(key);
  if (node->IsSequence()) return to_vector<3>(ctx_, *node, path, "m");
  if (!node->IsMap()) {
    ctx_.add(node->Mark(), path,
             fmt::format("expected a position [x, y, z] or {{radius, azimuth_deg, z}} in m, got {}",
                         describe(*node)),
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

// --------------------------------------------------------------- sections ----

const EnumTable<LineKind> kLineKinds = {{"chain", LineKind::chain},
                                        {"wire", LineKind::wire},
                                        {"polyester", LineKind::polyester},
                                        {"user", LineKind::user}};
const EnumTable<ChainGrade> kChainGrades = {{"R3", ChainGrade::R3},
                                            {"R3S", ChainGrade::R3S},
                                            {"R4", ChainGrade::R4},
                                            {"R4S", ChainGrade::R4S},
                                            {"R5", ChainGrade::R5}};
const EnumTable<ChainConstruction> kChainConstructions = {
    {"studless", ChainConstruction::studless}, {"studlink", ChainConstruction::studlink}};
const EnumTable<WireConstruction> kWireConstructions = {
    {"six_strand", WireConstruction::six_strand},
    {"spiral_strand", WireConstruction::spiral_strand}};
const EnumTable<AttachmentKind> kAttachmentKinds = {{"clump", AttachmentKind::clump},
                                                    {"buoy", AttachmentKind::buoy}};
const EnumTable<RiserKind> kRiserKinds = {{"scr", RiserKind::scr},
                                          {"lazy_wave", RiserKind::lazy_wave},
                                          {"flexible", RiserKind::flexible}};
const EnumTable<WaveSpectrum> kWaveSpectra = {
    {"jonswap", WaveSpectrum::jonswap}, {"pierson_moskowitz", WaveSpectrum::pierson_moskowitz}};
const EnumTable<WindSpectrum> kWindSpectra = {
    {"api", WindSpectrum::api}, {"npd", WindSpectrum::npd}, {"none", WindSpectrum::none}};
const EnumTable<LineModel> kLineModels = {{"catenary", LineModel::catenary}, {"fe", LineModel::fe}};
const EnumTable<DesignCondition> kDesignConditions = {{"normal", DesignCondition::normal},
                                                      {"extreme", DesignCondition::extreme},
                                                      {"survival", DesignCondition::survival}};
const EnumTable<StageSozModel> kStageSozModels = {{"catenary", StageSozModel::catenary},
                                                  {"fe", StageSozModel::fe}};
const EnumTable<MooringCode> kMooringCodes = {{"api_rp_2sk", MooringCode::api_rp_2sk},
                                              {"dnv_os_e301", MooringCode::dnv_os_e301}};

template <typename T>
void assign(T& target, const std::optional<T>& value) {
  if (value) target = *value;
}

Site read_site(MapReader& r) {
  Site site;
  assign(site.depth_m, r.number("depth", "m", kRequired));
  assign(site.water_density_kg_per_m3, r.number("water_density", "kg/m^3", kRequired));
  assign(site.gravity_m_per_s2, r.number("gravity", "m/s^2", kRequired));
  assign(site.air_density_kg_per_m3, r.number("air_density", "kg/m^3", kOptional));
  r.map("seabed", kRequired, [&](MapReader& s) {
    assign(site.seabed.friction_axial, s.number("friction_axial", "", kRequired));
    assign(site.seabed.friction_lateral, s.number("friction_lateral", "", kRequired));
    assign(site.seabed.normal_stiffness_Pa_per_m, s.number("normal_stiffness", "Pa/m", kRequired));
  });
  return site;
}

LineTypeInput read_line_type(MapReader& r) {
  LineTypeInput t;
  assign(t.name, r.text("name", kRequired));
  const auto kind = r.enumeration("kind", kLineKinds, kRequired);
  assign(t.kind, kind);
  assign(t.diameter_m, r.number("diameter", "m", kRequired));
  t.grade = r.enumeration("grade", kChainGrades, kOptional);
  // `construction` is a chain or a wire construction depending on `kind`.
  if (const auto node = r.child("construction", kOptional); node && kind) {
    const std::string path = r.path_of("construction");
    if (*kind == LineKind::chain) {
      t.chain_construction = to_enum(r.context(), *node, path, kChainConstructions);
    } else if (*kind == LineKind::wire) {
      t.wire_construction = to_enum(r.context(), *node, path, kWireConstructions);
    } else {
      r.context().add(node->Mark(), path,
                      fmt::format("applies to chain and wire line types only, got kind {}",
                                  *kind == LineKind::polyester ? "polyester" : "user"),
                      "key_not_applicable");
    }
  }
  t.mass_per_length_kg_per_m = r.number("mass_per_length", "kg/m", kOptional);
  t.submerged_weight_N_per_m = r.number("submerged_weight", "N/m", kOptional);
  t.hydrodynamic_diameter_m = r.number("hydrodynamic_diameter", "m", kOptional);
  t.axial_stiffness_N = r.number("axial_stiffness", "N", kOptional);
  t.breaking_load_N = r.number("breaking_load", "N", kOptional);
  t.static_stiffness_mbl = r.number("static_stiffness_mbl", "", kOptional);
  if (const auto ab = r.vector<2>("dynamic_stiffness_mbl", "", kOptional)) {
    t.dynamic_stiffness_mbl = std::array<double, 2>{(*ab)[0], (*ab)[1]};
  }
  t.drag_normal = r.number("drag_normal", "", kOptional);
  t.drag_axial = r.number("drag_axial", "", kOptional);
  t.added_mass_normal = r.number("added_mass_normal", "", kOptional);
  t.added_mass_axial = r.number("added_mass_axial", "", kOptional);
  return t;
}

/// `fe: {element_length, touchdown_refinement: {length, element_length}}`;
/// `mesh` holds the default element length on entry.
void read_fe_mesh(MapReader& r, FeMesh& mesh) {
  r.map("fe", kOptional, [&](MapReader& f) {
    assign(mesh.element_length_m, f.number("element_length", "m", kOptional));
    f.map("touchdown_refinement", kOptional, [&](MapReader& t) {
      TouchdownRefinement refinement;
      assign(refinement.length_m, t.number("length", "m", kRequired));
      assign(refinement.element_length_m, t.number("element_length", "m", kRequired));
      mesh.touchdown_refinement = refinement;
    });
  });
}

MooringLine read_mooring_line(MapReader& r, std::optional<double> seabed_z) {
  MooringLine line;
  assign(line.name, r.text("name", kRequired));
  assign(line.anchor_g, r.position("anchor", kRequired, seabed_z));
  assign(line.fairlead_b, r.position("fairlead", kRequired));
  r.list_of_maps("segments", kRequired, [&](MapReader& s) {
    LineSegment segment;
    assign(segment.type, s.text("type", kRequired));
    assign(segment.length_m, s.number("length", "m", kRequired));
    line.segments.push_back(segment);
  });
  r.list_of_maps("attachments", kOptional, [&](MapReader& a) {
    Attachment attachment;
    assign(attachment.after_segment, a.integer("after_segment", kRequired));
    assign(attachment.kind, a.enumeration("kind", kAttachmentKinds, kRequired));
    assign(attachment.mass_kg, a.number("mass", "kg", kRequired));
    assign(attachment.volume_m3, a.number("volume", "m^3", kRequired));
    line.attachments.push_back(attachment);
  });
  assign(line.model, r.enumeration("model", kLineModels, kOptional));
  read_fe_mesh(r, line.fe);
  return line;
}

void read_name(Context& ctx, const YAML::Node& node, const std::string& path,
               std::vector<std::string>& out) {
  if (auto name = to_string_value(ctx, node, path)) out.push_back(*name);
}

Mooring read_mooring(MapReader& r, std::optional<double> seabed_z) {
  Mooring mooring;
  r.list_of_maps("lines", kRequired,
                 [&](MapReader& l) { mooring.lines.push_back(read_mooring_line(l, seabed_z)); });
  r.list_of_maps("groups", kOptional, [&](MapReader& g) {
    LineGroup group;
    assign(group.name, g.text("name", kRequired));
    g.list("lines", kRequired, [&](const YAML::Node& item, const std::string& path) {
      read_name(g.context(), item, path, group.lines);
    });
    mooring.groups.push_back(group);
  });
  return mooring;
}

std::filesystem::path resolve(const std::string& file, const std::filesystem::path& base_folder) {
  const std::filesystem::path path(file);
  return path.is_absolute() ? path : base_folder / path;
}

/// `{headings_deg, surge, sway, yaw}`; equal lengths are checked in validation.
void read_load_coefficients(MapReader& r, HullLoadCoefficients& c) {
  assign(c.headings_rad, r.angles("headings", kRequired));
  assign(c.surge_m2, r.numbers("surge", "m^2", kRequired));
  assign(c.sway_m2, r.numbers("sway", "m^2", kRequired));
  assign(c.yaw_m3, r.numbers("yaw", "m^3", kRequired));
}

/// Either `{file, ulen}` (WAMIT .12d) or a table `{headings_deg, frequencies,
/// surge, sway, yaw}`; the presence of `file` chooses.
MeanDrift read_mean_drift(MapReader& r, const std::filesystem::path& base_folder) {
  static constexpr std::string_view kTableKeys[] = {"headings_deg", "frequencies", "surge", "sway",
                                                    "yaw"};
  if (r.has("file")) {
    MeanDriftFile f;
    if (const auto file = r.text("file", kRequired)) f.file = resolve(*file, base_folder);
    assign(f.ulen_m, r.number("ulen", "m", kOptional));
    assign(f.period_scale, r.number("period_scale", "-", kOptional));
    for (const auto key : kTableKeys) {
      const auto node = r.child(key, kOptional);
      if (!node) continue;
      r.context().add(node->Mark(), r.path_of(key),
                      fmt::format("give either file (WAMIT .12d) or a table (headings_deg, "
                                  "frequencies, surge, sway, yaw), not both; got {} with file",
                                  key),
                      "conflicting_keys");
    }
    return f;
  }
  r.child("file", kOptional);  // known key, for suggestions
  for (const char* key : {"ulen", "period_scale"}) {
    if (const auto node = r.child(key, kOptional)) {
      r.context().add(node->Mark(), r.path_of(key),
                      "applies to a WAMIT file (file: path.12d) only, got a table",
                      "key_not_applicable");
    }
  }
  MeanDriftTable t;
  assign(t.headings_rad, r.angles("headings", kRequired));
  assign(t.frequencies_rad_per_s, r.numbers("frequencies", "rad/s", kRequired));
  assign(t.surge_N_per_m2, r.number_rows("surge", "N/m^2", kRequired));
  assign(t.sway_N_per_m2, r.number_rows("sway", "N/m^2", kRequired));
  assign(t.yaw_N_m_per_m2, r.number_rows("yaw", "N m/m^2", kRequired));
  return t;
}

HullHydrodynamics read_hull_hydrodynamics(MapReader& r, const std::filesystem::path& base_folder) {
  static const EnumTable<FrequencyColumnKind> kColumns = {
      {"period", FrequencyColumnKind::period},
      {"angular_frequency", FrequencyColumnKind::angular_frequency}};
  static const EnumTable<HullHydrodynamicsModel> kModels = {
      {"bem", HullHydrodynamicsModel::bem}, {"morison", HullHydrodynamicsModel::morison}};
  static const EnumTable<RadiationModel> kRadiationModels = {
      {"low_frequency", RadiationModel::low_frequency}, {"memory", RadiationModel::memory}};
  // Keys of one model only: given with the other, key_not_applicable.
  static constexpr std::string_view kBemKeys[] = {
      "radiation_file", "frequency_column",     "ulen",      "period_scale",    "excitation_file",
      "rao_file",       "added_mass_frequency", "radiation", "memory_duration", "memory_time_step"};
  static constexpr std::string_view kMorisonKeys[] = {"strip_length"};
  HullHydrodynamics h;
  assign(h.model, r.enumeration("model", kModels, kOptional));
  const bool morison = h.model == HullHydrodynamicsModel::morison;
  for (const auto key : morison ? std::span<const std::string_view>(kBemKeys)
                                : std::span<const std::string_view>(kMorisonKeys)) {
    if (const auto node = r.child(key, kOptional)) {
      r.context().add(node->Mark(), r.path_of(key),
                      fmt::format("applies to model: {} only, got model: {}",
                                  morison ? "bem" : "morison", to_string(h.model)),
                      "key_not_applicable");
    }
  }
  if (morison) {
    assign(h.strip_length_m, r.number("strip_length", "m", kOptional));
  } else {
    if (const auto file = r.text("radiation_file", kRequired))
      h.radiation_file = resolve(*file, base_folder);
    assign(h.frequency_column, r.enumeration("frequency_column", kColumns, kOptional));
    assign(h.ulen_m, r.number("ulen", "m", kOptional));
    assign(h.period_scale, r.number("period_scale", "-", kOptional));
    if (const auto file = r.text("excitation_file", kOptional))
      h.excitation_file = resolve(*file, base_folder);
    if (const auto file = r.text("rao_file", kOptional)) h.rao_file = resolve(*file, base_folder);
    h.added_mass_frequency_rad_per_s = r.number("added_mass_frequency", "rad/s", kOptional);
    assign(h.radiation, r.enumeration("radiation", kRadiationModels, kOptional));
    assign(h.memory_duration_s, r.number("memory_duration", "s", kOptional));
    assign(h.memory_time_step_s, r.number("memory_time_step", "s", kOptional));
  }
  assign(h.linear_damping, r.vector<6>("linear_damping", "N s/m, N m s/rad", kOptional));
  assign(h.quadratic_damping,
         r.vector<6>("quadratic_damping", "N s^2/m^2, N m s^2/rad^2", kOptional));
  return h;
}

void read_member_coefficients(MapReader& r, MemberCoefficients& c) {
  assign(c.drag, r.number("drag", "-", kOptional));
  assign(c.added_mass, r.number("added_mass", "-", kOptional));
}

HullGeometry read_hull_geometry(MapReader& r, const std::filesystem::path& base_folder) {
  HullGeometry g;
  if (const auto file = r.text("panel_mesh", kOptional)) g.panel_mesh = resolve(*file, base_folder);
  r.list_of_maps("columns", kOptional, [&](MapReader& c) {
    HullColumn column;
    assign(column.center_b, c.vector<2>("center", "m", kRequired));
    assign(column.z_bottom_m, c.number("z_bottom", "m", kRequired));
    assign(column.z_top_m, c.number("z_top", "m", kRequired));
    assign(column.diameter_m, c.number("diameter", "m", kRequired));
    read_member_coefficients(c, column.coefficients);
    assign(column.end_added_mass, c.number("end_added_mass", "-", kOptional));
    assign(column.end_drag, c.number("end_drag", "-", kOptional));
    g.columns.push_back(column);
  });
  r.list_of_maps("pontoons", kOptional, [&](MapReader& p) {
    HullPontoon pontoon;
    assign(pontoon.from_b, p.position("from", kRequired));
    assign(pontoon.to_b, p.position("to", kRequired));
    assign(pontoon.diameter_m, p.number("diameter", "m", kRequired));
    read_member_coefficients(p, pontoon.coefficients);
    g.pontoons.push_back(pontoon);
  });
  return g;
}

Hull read_hull(MapReader& r, const std::filesystem::path& base_folder) {
  Hull hull;
  assign(hull.reference_point_g, r.position("reference_point", kRequired));
  assign(hull.mass_kg, r.number("mass", "kg", kRequired));
  assign(hull.center_of_gravity_b, r.position("center_of_gravity", kRequired));
  hull.radii_of_gyration_m = r.vector<3>("radii_of_gyration", "m", kOptional);
  if (const auto node = r.child("inertia", kOptional)) {
    // [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz], kg m^2 about the CoG.
    const std::string path = r.path_of("inertia");
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    if (node->IsSequence() && node->size() == 6) {
      if (const auto v = to_vector<6>(r.context(), *node, path, "kg m^2")) {
        inertia << (*v)[0], (*v)[3], (*v)[4], (*v)[3], (*v)[1], (*v)[5], (*v)[4], (*v)[5], (*v)[2];
        hull.inertia_kg_m2 = inertia;
      }
    } else if (const auto v = to_vector<3>(r.context(), *node, path, "kg m^2")) {
      inertia.diagonal() = *v;
      hull.inertia_kg_m2 = inertia;
    }
  }
  if (r.has("radii_of_gyration") == r.has("inertia")) {
    r.context().add(r.mark(), r.path_of("radii_of_gyration"),
                    "give exactly one of radii_of_gyration (m) or inertia (kg m^2), about the CoG",
                    r.has("inertia") ? "conflicting_keys" : "missing_key");
  }
  hull.displaced_volume_m3 = r.number("displaced_volume", "m^3", kOptional);
  hull.center_of_buoyancy_b = r.position("center_of_buoyancy", kOptional);
  hull.waterplane_area_m2 = r.number("waterplane_area", "m^2", kOptional);
  hull.waterplane_inertia_m4 = r.vector<2>("waterplane_inertia", "m^4", kOptional);
  if (const auto file = r.text("hydrostatics_file", kOptional)) {
    hull.hydrostatics_file = resolve(*file, base_folder);
  }
  r.map("wind_coefficients", kOptional, [&](MapReader& w) {
    WindCoefficients c;
    read_load_coefficients(w, c);
    assign(c.reference_height_m, w.number("reference_height", "m", kOptional));
    hull.wind_coefficients = c;
  });
  r.map("current_coefficients", kOptional, [&](MapReader& w) {
    HullLoadCoefficients c;
    read_load_coefficients(w, c);
    hull.current_coefficients = c;
  });
  r.map("mean_drift", kOptional,
        [&](MapReader& d) { hull.mean_drift = read_mean_drift(d, base_folder); });
  r.map("hydrodynamics", kOptional,
        [&](MapReader& d) { hull.hydrodynamics = read_hull_hydrodynamics(d, base_folder); });
  r.map("geometry", kOptional, [&](MapReader& g) { hull.geometry = read_hull_geometry(g, base_folder); });
  return hull;
}

RiserSection read_riser_section(MapReader& r) {
  RiserSection s;
  assign(s.length_m, r.number("length", "m", kRequired));
  assign(s.outer_diameter_m, r.number("outer_diameter", "m", kRequired));
  assign(s.contents_density_kg_per_m3, r.number("contents_density", "kg/m^3", kRequired));
  s.wall_thickness_m = r.number("wall_thickness", "m", kOptional);
  s.inner_diameter_m = r.number("inner_diameter", "m", kOptional);
  s.youngs_modulus_Pa = r.number("youngs_modulus", "Pa", kOptional);
  s.yield_stress_Pa = r.number("yield_stress", "Pa", kOptional);
  s.steel_density_kg_per_m3 = r.number("steel_density", "kg/m^3", kOptional);
  s.coating_thickness_m = r.number("coating_thickness", "m", kOptional);
  s.coating_density_kg_per_m3 = r.number("coating_density", "kg/m^3", kOptional);
  s.buoyancy_outer_diameter_m = r.number("buoyancy_outer_diameter", "m", kOptional);
  s.buoyancy_density_kg_per_m3 = r.number("buoyancy_density", "kg/m^3", kOptional);
  s.axial_stiffness_N = r.number("axial_stiffness", "N", kOptional);
  s.bending_stiffness_N_m2 = r.number("bending_stiffness", "N m^2", kOptional);
  s.mass_per_length_kg_per_m = r.number("mass_per_length", "kg/m", kOptional);
  assign(s.drag_normal, r.number("drag_normal", "", kOptional));
  assign(s.drag_axial, r.number("drag_axial", "", kOptional));
  assign(s.added_mass_normal, r.number("added_mass_normal", "", kOptional));
  assign(s.added_mass_axial, r.number("added_mass_axial", "", kOptional));
  return s;
}

/// The keys of `criteria.risers` and `risers[i].criteria`, all optional.
RiserCriteriaOverrides read_riser_criteria(MapReader& r) {
  RiserCriteriaOverrides c;
  r.map("design_factor", kOptional, [&](MapReader& f) {
    c.design_factor_normal = f.number("normal", "", kOptional);
    c.design_factor_extreme = f.number("extreme", "", kOptional);
    c.design_factor_survival = f.number("survival", "", kOptional);
  });
  c.min_effective_tension_N = r.number("min_effective_tension", "N", kOptional);
  c.max_top_tension_N = r.number("max_top_tension", "N", kOptional);
  c.max_top_angle_rad = r.angle("max_top_angle", kOptional);
  c.max_flex_joint_rotation_rad = r.angle("max_flex_joint_rotation", kOptional);
  c.min_bending_radius_m = r.number("min_bending_radius", "m", kOptional);
  c.max_touchdown_excursion_m = r.number("max_touchdown_excursion", "m", kOptional);
  return c;
}

Riser read_riser(MapReader& r) {
  Riser riser;
  assign(riser.name, r.text("name", kRequired));
  assign(riser.kind, r.enumeration("kind", kRiserKinds, kRequired));
  assign(riser.hang_off_b, r.position("hang_off", kRequired));
  assign(riser.azimuth_rad, r.angle("azimuth", kRequired));
  assign(riser.top_angle_rad, r.angle("top_angle", kRequired));
  r.list_of_maps("sections", kRequired,
                 [&](MapReader& s) { riser.sections.push_back(read_riser_section(s)); });
  assign(riser.internal_pressure_Pa, r.number("internal_pressure", "Pa", kOptional));
  read_fe_mesh(r, riser.fe);
  r.map("criteria", kOptional, [&](MapReader& c) { riser.criteria = read_riser_criteria(c); });
  return riser;
}

Environment read_environment(MapReader& r) {
  Environment env;
  assign(env.name, r.text("name", kRequired));
  r.map("waves", kOptional, [&](MapReader& w) {
    Waves waves;
    assign(waves.spectrum, w.enumeration("spectrum", kWaveSpectra, kRequired));
    assign(waves.hs_m, w.number("hs", "m", kRequired));
    assign(waves.tp_s, w.number("tp", "s", kRequired));
    waves.gamma = w.number("gamma", "", kOptional);
    assign(waves.heading_rad, w.angle("heading", kRequired));
    waves.spreading_s = w.number("spreading_s", "", kOptional);
    env.waves = waves;
  });
  r.map("wind", kOptional, [&](MapReader& w) {
    Wind wind;
    assign(wind.speed_m_per_s, w.number("speed", "m/s", kRequired));
    assign(wind.heading_rad, w.angle("heading", kRequired));
    assign(wind.spectrum, w.enumeration("spectrum", kWindSpectra, kRequired));
    assign(wind.reference_height_m, w.number("reference_height", "m", kOptional));
    env.wind = wind;
  });
  r.map("current", kOptional, [&](MapReader& c) {
    Current current;
    assign(current.heading_rad, c.angle("heading", kRequired));
    c.list("profile", kRequired, [&](const YAML::Node& item, const std::string& path) {
      if (const auto point = to_vector<2>(c.context(), item, path, "[z m, speed m/s]")) {
        current.profile.push_back(CurrentPoint{(*point)[0], (*point)[1]});
      }
    });
    env.current = current;
  });
  return env;
}

Criteria read_criteria(MapReader& r) {
  Criteria criteria;
  r.map("mooring", kRequired, [&](MapReader& m) {
    const auto code = m.enumeration("code", kMooringCodes, kRequired);
    assign(criteria.mooring.code, code);
    if (code == MooringCode::api_rp_2sk) {
      ApiRp2skFactors f;
      m.map("safety_factors", kOptional, [&](MapReader& s) {
        assign(f.intact_quasi_static, s.number("intact_quasi_static", "", kOptional));
        assign(f.intact_dynamic, s.number("intact_dynamic", "", kOptional));
        assign(f.damaged_quasi_static, s.number("damaged_quasi_static", "", kOptional));
        assign(f.damaged_dynamic, s.number("damaged_dynamic", "", kOptional));
      });
      criteria.mooring.api_rp_2sk = f;
    } else if (code == MooringCode::dnv_os_e301) {
      const auto cc_node = m.child("consequence_class", kRequired, "1 or 2");
      const auto cc = cc_node ? to_integer(m.context(), *cc_node, m.path_of("consequence_class"))
                              : std::nullopt;
      if (cc && *cc != 1 && *cc != 2) {
        m.context().add(cc_node->Mark(), m.path_of("consequence_class"),
                        fmt::format("must be 1 or 2, got {}", *cc), "bad_enum");
      }
      DnvOsE301Factors f = dnv_os_e301_defaults(cc.value_or(1));
      m.map("partial_factors", kOptional, [&](MapReader& p) {
        assign(f.uls_mean, p.number("uls_mean", "", kOptional));
        assign(f.uls_dynamic, p.number("uls_dynamic", "", kOptional));
        assign(f.als_mean, p.number("als_mean", "", kOptional));
        assign(f.als_dynamic, p.number("als_dynamic", "", kOptional));
      });
      criteria.mooring.dnv_os_e301 = f;
    }
  });
  r.map("risers", kOptional, [&](MapReader& x) {
    criteria.risers = read_riser_criteria(x);
  });
  criteria.max_offset_pct_depth = r.number("max_offset_pct_depth", "%", kOptional);
  return criteria;
}

void read_project(MapReader& r, Project& p, const std::filesystem::path& base_folder) {
  if (const auto version_node = r.child("version", kRequired, "format version, 1")) {
    const auto version = to_integer(r.context(), *version_node, "version");
    if (version && *version != kProjectFormatVersion) {
      r.context().add(version_node->Mark(), "version",
                      fmt::format("unsupported format version {}; this spiral reads version {}",
                                  *version, kProjectFormatVersion),
                      "unsupported_version");
    }
    assign(p.version, version);
  }
  assign(p.name, r.text("name", kRequired));
  p.description = r.text("description", kOptional);
  std::optional<double> seabed_z;
  r.map("site", kRequired, [&](MapReader& s) {
    p.site = read_site(s);
    if (s.has("depth")) seabed_z = -p.site.depth_m;
  });
  r.list_of_maps("line_types", kRequired,
                 [&](MapReader& t) { p.line_types.push_back(read_line_type(t)); });
  // Without a depth an anchor's default z is unknown; 0 keeps the reader going
  // (the missing depth is already reported).
  r.map("mooring", kRequired,
        [&](MapReader& m) { p.mooring = read_mooring(m, seabed_z.value_or(0.0)); });
  r.map("hull", kRequired, [&](MapReader& h) { p.hull = read_hull(h, base_folder); });
  r.list_of_maps("risers", kOptional, [&](MapReader& x) { p.risers.push_back(read_riser(x)); });
  r.list_of_maps("environments", kRequired,
                 [&](MapReader& e) { p.environments.push_back(read_environment(e)); });
  r.list_of_maps("load_cases", kRequired, [&](MapReader& c) {
    LoadCase load_case;
    assign(load_case.name, c.text("name", kRequired));
    assign(load_case.environment, c.text("environment", kRequired));
    load_case.damaged_line = c.text("damaged_line", kOptional);
    assign(load_case.condition, c.enumeration("condition", kDesignConditions, kOptional));
    p.load_cases.push_back(load_case);
  });
  r.map("criteria", kRequired, [&](MapReader& c) { p.criteria = read_criteria(c); });
  if (r.has("stages")) {
    r.list_of_maps("stages", kOptional, [&](MapReader& s) {
      Stage stage;
      assign(stage.name, s.text("name", kRequired));
      s.map("soz", kOptional, [&](MapReader& z) {
        assign(stage.soz.model, z.enumeration("model", kStageSozModels, kOptional));
        assign(stage.soz.step_deg, z.number("step_deg", "deg", kOptional));
      });
      stage.duration_s = s.number("duration", "s", kOptional);
      p.stages.push_back(stage);
    });
  } else {
    r.child("stages", kOptional);  // known key, for suggestions
    p.stages = {{"preliminary", {}, {}}, {"intermediate", {}, {}}, {"advanced", {}, {}}};
  }
}

[[noreturn]] void throw_issues(std::vector<InputIssue> issues) {
  std::stable_sort(issues.begin(), issues.end(), [](const InputIssue& a, const InputIssue& b) {
    return std::pair(a.line.value_or(0), a.column.value_or(0)) <
           std::pair(b.line.value_or(0), b.column.value_or(0));
  });
  throw InputError(std::move(issues));
}

}  // namespace

Project parse_project(std::string_view yaml_text, std::string source_name) {
  Context ctx{source_name, {}, {}};
  YAML::Node root;
  try {
    root = YAML::Load(std::string(yaml_text));
  } catch (const YAML::ParserException& e) {
    ctx.add(e.mark, "", fmt::format("YAML syntax error: {}", e.msg), "yaml_syntax");
    throw_issues(std::move(ctx.issues));
  }
  if (!root.IsMap()) {
    ctx.add(root.Mark(), "",
            fmt::format("a project file is a map of sections (version, name, site, ...), got {}",
                        describe(root)),
            "wrong_type");
    throw_issues(std::move(ctx.issues));
  }
  Project project;
  project.source_file = source_name;
  {
    MapReader reader(ctx, root, "");
    read_project(reader, project, std::filesystem::path(source_name).parent_path());
  }  // the reader reports unknown top-level keys here
  if (!ctx.issues.empty()) throw_issues(std::move(ctx.issues));
  project.source_map = std::move(ctx.positions);
  return project;
}

Project load_project(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    InputIssue issue;
    issue.file = file.string();
    issue.message =
        std::filesystem::exists(file) ? "cannot read the project file" : "project file not found";
    issue.condition = "missing_file";
    throw InputError({issue});
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_project(text.str(), file.string());
}

}  // namespace spiral::design
