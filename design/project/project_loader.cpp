// YAML -> design::Project (format v1): the top level of the file, in file
// order. Every map is read through the strict MapReader
// (yaml_map_reader.hpp) and every section through its mapping
// (project_loader_sections.hpp). Nothing throws until the whole file has been
// read; then every issue goes into one InputError, in file order.

#include "design/project/project_loader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "design/project/project_loader_sections.hpp"
#include "design/project/yaml_map_reader.hpp"

namespace spiral::design {
namespace {

using namespace loader_detail;

void read_project(MapReader& r, Project& p, const std::filesystem::path& base_folder) {
  r.child("extends", kOptional);  // resolved before the sections are read (with_bases)
  if (const auto version_node = r.child("version", kRequired, "format version, 1")) {
    const auto version = to_integer(r.context(), *version_node, "version");
    if (version && *version != kProjectFormatVersion) {
      r.context().add(
          version_node->Mark(), "version",
          fmt::format("unsupported format version {}; this spiral reads version {}", *version, kProjectFormatVersion),
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
  r.list_of_maps("line_types", kRequired, [&](MapReader& t) { p.line_types.push_back(read_line_type(t)); });
  // Without a depth an anchor's default z is unknown; 0 keeps the reader going
  // (the missing depth is already reported).
  r.map("mooring", kRequired, [&](MapReader& m) { p.mooring = read_mooring(m, seabed_z.value_or(0.0)); });
  r.map("hull", kRequired, [&](MapReader& h) { p.hull = read_hull(h, base_folder); });
  r.list_of_maps("risers", kOptional, [&](MapReader& x) { p.risers.push_back(read_riser(x)); });
  r.list_of_maps("environments", kRequired, [&](MapReader& e) { p.environments.push_back(read_environment(e)); });
  r.list_of_maps("load_cases", kRequired, [&](MapReader& c) { p.load_cases.push_back(read_load_case(c)); });
  r.list_of_maps("load_case_matrix", kOptional,
                 [&](MapReader& m) { p.load_case_matrix.push_back(read_load_case_matrix_entry(m)); });
  r.map("criteria", kRequired, [&](MapReader& c) { p.criteria = read_criteria(c); });
  if (r.has("stages")) {
    r.list_of_maps("stages", kOptional, [&](MapReader& s) { p.stages.push_back(read_stage(s)); });
  } else {
    r.child("stages", kOptional);  // known key, for suggestions
    p.stages.assign(3, Stage{});
    p.stages[0].name = "preliminary";
    p.stages[1].name = "intermediate";
    p.stages[2].name = "advanced";
  }
  r.map("optimization", kOptional, [&](MapReader& o) { p.optimization = read_optimization(o); });
  r.map("global_analysis", kOptional,
        [&](MapReader& g) { p.global_analysis.element_length_m = g.number("element_length", "m", kOptional); });
}

[[noreturn]] void throw_issues(std::vector<InputIssue> issues) {
  sort_in_file_order(issues);
  throw InputError(std::move(issues));
}

// A chain of variations deeper than this is a mistake, not a design.
constexpr int kMaxBaseDepth = 8;

/// Top-level section -> the file it was written in.
using SectionOrigins = std::map<std::string, std::string, std::less<>>;

/// `root` (the map of `file`) with the sections of its base file (`extends`,
/// a path relative to `file`'s folder) that it does not write itself, and so
/// on down the chain — a variation file in the manner of OrcaFlex's
/// BaseFile: whole top-level sections are replaced, never merged inside.
/// `origins` names each section's file; `bases` collects the base files,
/// nearest first. Problems with the chain are issues at the `extends` that
/// names the base; a base's own problems are the base file's.
YAML::Node with_bases(const YAML::Node& root, const std::string& file, Context& ctx, SectionOrigins& origins,
                      std::vector<std::string>& bases, std::vector<std::filesystem::path>& chain) {
  for (const auto& entry : root) origins[entry.first.Scalar()] = file;
  const YAML::Node extends = root["extends"];
  if (!extends) return root;
  if (!extends.IsScalar() || extends.Scalar().empty()) {
    ctx.add_in(file, extends.Mark(), "extends",
               fmt::format("expected the base project file, got {}", describe(extends)), "wrong_type");
    return root;
  }
  std::filesystem::path base = extends.Scalar();
  if (base.is_relative()) base = std::filesystem::path(file).parent_path() / base;
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(base, ec);
  if (std::find(chain.begin(), chain.end(), canonical) != chain.end()) {
    ctx.add_in(file, extends.Mark(), "extends",
               fmt::format("{} extends itself through its bases (a cycle)", base.string()), "extends_cycle");
    return root;
  }
  if (static_cast<int>(chain.size()) > kMaxBaseDepth) {
    ctx.add_in(file, extends.Mark(), "extends", fmt::format("more than {} base files in a chain", kMaxBaseDepth),
               "extends_depth");
    return root;
  }
  // A regular file only: a device or FIFO could be read forever.
  std::ifstream in(base, std::ios::binary);
  if (!in || !std::filesystem::is_regular_file(base, ec)) {
    ctx.add_in(file, extends.Mark(), "extends", fmt::format("base project file not found: {}", base.string()),
               "missing_file");
    return root;
  }
  std::ostringstream text;
  text << in.rdbuf();
  YAML::Node base_root;
  try {
    base_root = YAML::Load(text.str());
  } catch (const YAML::ParserException& e) {
    ctx.add_in(base.string(), e.mark, "extends", fmt::format("YAML syntax error: {}", e.msg), "yaml_syntax");
    return root;
  }
  if (!base_root.IsMap()) {
    ctx.add_in(base.string(), base_root.Mark(), "extends",
               fmt::format("a base project file is a map of sections, got {}", describe(base_root)), "wrong_type");
    return root;
  }
  bases.push_back(base.string());
  chain.push_back(canonical);
  SectionOrigins base_origins;
  const YAML::Node base_tree = with_bases(base_root, base.string(), ctx, base_origins, bases, chain);
  YAML::Node merged(YAML::NodeType::Map);
  for (const auto& entry : base_tree) {
    const std::string key = entry.first.Scalar();
    if (key == "extends" || root[key]) continue;
    merged[key] = entry.second;
    origins[key] = base_origins[key];
  }
  for (const auto& entry : root) merged[entry.first.Scalar()] = entry.second;
  return merged;
}

}  // namespace

Project parse_project(std::string_view yaml_text, std::string source_name,
                      const std::optional<std::filesystem::path>& data_folder) {
  Context ctx{source_name, {}, {}};
  YAML::Node root;
  try {
    root = YAML::Load(std::string(yaml_text));
  } catch (const YAML::ParserException& e) {
    ctx.add(e.mark, "", fmt::format("YAML syntax error: {}", e.msg), "yaml_syntax");
    throw_issues(std::move(ctx.issues));
  }
  if (!root.IsMap()) {
    // An empty or comment-only text has no node to point at (a null mark):
    // say line 1, where the map should begin, so the message has a line.
    YAML::Mark mark = root.Mark();
    if (mark.is_null()) mark.pos = mark.line = mark.column = 0;
    ctx.add(mark, "",
            fmt::format("a project file is a map of sections (version, name, site, ...), got {}", describe(root)),
            "wrong_type");
    throw_issues(std::move(ctx.issues));
  }
  Project project;
  project.source_file = source_name;
  {
    SectionOrigins origins;
    std::error_code ec;
    std::vector<std::filesystem::path> chain{std::filesystem::weakly_canonical(source_name, ec)};
    root = with_bases(root, source_name, ctx, origins, project.base_files, chain);
    if (!ctx.issues.empty()) throw_issues(std::move(ctx.issues));
    for (const auto& [section, file] : origins)
      if (file != source_name) ctx.section_files[section] = file;
  }
  {
    MapReader reader(ctx, root, "");
    // Data files resolve from the file that holds the hull section: a base's
    // hull from the base's folder; this file's from `data_folder` when given
    // (a spiral-run iteration file written elsewhere), else its own folder.
    const std::string& hull_file = ctx.file_of("hull");
    const std::filesystem::path hull_folder = std::filesystem::path(hull_file).parent_path();
    read_project(reader, project, hull_file == source_name ? data_folder.value_or(hull_folder) : hull_folder);
  }  // the reader reports unknown top-level keys here
  if (!ctx.issues.empty()) throw_issues(std::move(ctx.issues));
  project.source_map = std::move(ctx.positions);
  return project;
}

Project load_project(const std::filesystem::path& file, const std::optional<std::filesystem::path>& data_folder) {
  std::ifstream in(file, std::ios::binary);
  // A folder opens as an empty stream on Linux: say what it is.
  std::error_code ec;
  const bool folder = std::filesystem::is_directory(file, ec);
  if (!in || folder) {
    InputIssue issue;
    issue.file = file.string();
    issue.message = folder                          ? "is a folder, not a project file (give the .yaml file in it)"
                    : std::filesystem::exists(file) ? "cannot read the project file"
                                                    : "project file not found";
    issue.problem = folder ? "not_a_file" : "missing_file";
    throw InputError({issue});
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_project(text.str(), file.string(), data_folder);
}

}  // namespace spiral::design
