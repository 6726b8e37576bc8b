#include "design/project/project_edit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "design/project/project_loader.hpp"

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

/// Length of the scalar that starts at `at`: a quoted one to its closing
/// quote, a plain one to a flow or comment delimiter or the line's end.
std::size_t scalar_length(const std::string& text, std::size_t at) {
  if (at < text.size() && (text[at] == '"' || text[at] == '\'')) {
    const char quote = text[at];
    std::size_t end = at + 1;
    while (end < text.size() && text[end] != quote && text[end] != '\n') end += text[end] == '\\' ? 2 : 1;
    return std::min(end + 1, text.size()) - at;
  }
  std::size_t end = at;
  while (end < text.size() && std::string_view(",}]#\n\r").find(text[end]) == std::string_view::npos) ++end;
  while (end > at && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  return end - at;
}

/// `value` in the shortest form that reads back as the same double (fmt's
/// round trip), with a decimal point where it would have none (2492.0, not 2492).
std::string yaml_number(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

/// A name as a YAML scalar: plain when YAML reads it back as that string,
/// double-quoted otherwise.
std::string yaml_string(const std::string& name) {
  static const std::regex plain("[A-Za-z_./][A-Za-z0-9_./\\-]*");
  static const std::regex reserved("(?:true|false|yes|no|on|off|null|y|n)", std::regex::icase);
  if (std::regex_match(name, plain) && !std::regex_match(name, reserved)) return name;
  std::string quoted = "\"";
  for (const char c : name) quoted += (c == '"' || c == '\\') ? std::string{'\\', c} : std::string{c};
  return quoted + '"';
}

/// The file references of a project by their field paths (resolved paths).
std::vector<std::pair<std::string, std::filesystem::path>> file_references(const Project& p) {
  std::vector<std::pair<std::string, std::filesystem::path>> refs;
  const Hull& h = p.hull;
  if (h.hydrostatics_file) refs.emplace_back("hull.hydrostatics_file", *h.hydrostatics_file);
  if (h.mean_drift) {
    if (const auto* f = std::get_if<MeanDriftFile>(&*h.mean_drift)) refs.emplace_back("hull.mean_drift.file", f->file);
  }
  if (h.hydrodynamics) {
    const HullHydrodynamics& d = *h.hydrodynamics;
    if (!d.radiation_file.empty()) refs.emplace_back("hull.hydrodynamics.radiation_file", d.radiation_file);
    if (d.excitation_file) refs.emplace_back("hull.hydrodynamics.excitation_file", *d.excitation_file);
    if (d.rao_file) refs.emplace_back("hull.hydrodynamics.rao_file", *d.rao_file);
  }
  if (h.geometry && h.geometry->panel_mesh) refs.emplace_back("hull.geometry.panel_mesh", *h.geometry->panel_mesh);
  return refs;
}

/// `file` as a reference written in a project file in `folder`: relative
/// where the two share a folder below the root (`../data/x.1`), absolute
/// where only the root is common (a path up to the root and down again
/// says nothing the absolute one does not).
std::filesystem::path reference_from(const std::filesystem::path& file, const std::filesystem::path& folder) {
  const std::filesystem::path a = std::filesystem::weakly_canonical(std::filesystem::absolute(file));
  const std::filesystem::path b = std::filesystem::weakly_canonical(std::filesystem::absolute(folder));
  const auto first_below_root = [](const std::filesystem::path& p) {
    const std::filesystem::path below = p.relative_path();
    return below.empty() ? std::filesystem::path() : *below.begin();
  };
  if (first_below_root(a) != first_below_root(b)) return a;
  return a.lexically_relative(b);
}

/// The scalar written at `path` in `text`, as written (quotes included).
std::string written_scalar(const std::string& text, const Project& project, const std::string& path) {
  const auto position = project.source_map.find(path);
  if (position == project.source_map.end() || !position->second.file.empty()) return {};
  const std::size_t at = offset_of(text, position->second.line, position->second.column);
  return text.substr(at, scalar_length(text, at));
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ignored;
  return std::filesystem::weakly_canonical(a, ignored) == std::filesystem::weakly_canonical(b, ignored);
}

/// Why `written` (read back from the new text) is not `edited`, or empty.
std::string difference(const Project& edited, const Project& written) {
  const auto& a = edited.mooring.lines;
  const auto& b = written.mooring.lines;
  if (a.size() != b.size()) return "mooring.lines: lines were added or removed";
  for (std::size_t l = 0; l < a.size(); ++l) {
    if (a[l].segments.size() != b[l].segments.size())
      return fmt::format("mooring.lines[{}].segments: segments were added or removed", l);
    for (std::size_t s = 0; s < a[l].segments.size(); ++s) {
      const std::string at = fmt::format("mooring.lines[{}].segments[{}]", l, s);
      if (a[l].segments[s].length_m != b[l].segments[s].length_m)
        return fmt::format(
            "{}.length: reads back as {} m instead of {} m (is the value shared with another "
            "field through a YAML anchor?)",
            at, b[l].segments[s].length_m, a[l].segments[s].length_m);
      if (a[l].segments[s].type != b[l].segments[s].type)
        return fmt::format(
            "{}.type: reads back as '{}' instead of '{}' (is the value shared with another field "
            "through a YAML anchor?)",
            at, b[l].segments[s].type, a[l].segments[s].type);
    }
  }
  const auto refs_a = file_references(edited);
  const auto refs_b = file_references(written);
  for (std::size_t i = 0; i < refs_a.size() && i < refs_b.size(); ++i) {
    if (!same_file(refs_a[i].second, refs_b[i].second))
      return fmt::format("{}: would name {} instead of {}", refs_a[i].first, refs_b[i].second.string(),
                         refs_a[i].second.string());
  }
  return {};
}

/// `text`, the file `file` of the project ("": the project's own file), with
/// each edit's scalar replaced in place.
std::string edited_in_place(const std::string& text, const Project& project, const std::vector<FieldEdit>& edits,
                            const std::string& file) {
  std::vector<Edit> replacements;
  for (const FieldEdit& edit : edits) {
    const auto position = project.source_map.find(edit.path);
    if (position == project.source_map.end())
      throw std::invalid_argument(
          fmt::format("{}: the file has no value of its own there to replace (a default, or a project built in "
                      "code)",
                      edit.path));
    if (position->second.file != file)
      throw std::invalid_argument(
          fmt::format("{}: written in the base file {} (extends), not in {}: edit the base, or give the section in "
                      "this file",
                      edit.path, position->second.file.empty() ? project.source_file : position->second.file,
                      file.empty() ? project.source_file : file));
    const std::size_t at = offset_of(text, position->second.line, position->second.column);
    replacements.push_back({at, scalar_length(text, at), edit.value});
  }
  std::sort(replacements.begin(), replacements.end(), [](const Edit& a, const Edit& b) { return a.offset > b.offset; });
  std::string out = text;
  for (const Edit& e : replacements) out.replace(e.offset, e.length, e.value);
  return out;
}

/// The length edits of the payouts: each line's top (fairlead-end) segment.
std::vector<FieldEdit> payout_edits(const Project& project, const std::map<std::string, double>& payouts_m) {
  std::vector<FieldEdit> edits;
  for (const auto& entry : payouts_m) {
    // Not a structured binding: clang 14 (Debian 12's, the fuzz build's) cannot capture one in a lambda.
    const std::string& name = entry.first;
    const double payout = entry.second;
    const auto it = std::find_if(project.mooring.lines.begin(), project.mooring.lines.end(),
                                 [&](const MooringLine& l) { return l.name == name; });
    if (it == project.mooring.lines.end() || it->segments.empty())
      throw std::invalid_argument(fmt::format("no mooring line named '{}'", name));
    const auto line_index = static_cast<std::size_t>(it - project.mooring.lines.begin());
    const std::size_t top = it->segments.size() - 1;
    edits.push_back({fmt::format("mooring.lines[{}].segments[{}].length", line_index, top),
                     fmt::format("{:.4f}", it->segments[top].length_m + payout)});
  }
  return edits;
}

std::string commented(const std::string& header) {
  std::ostringstream out;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) out << (line.empty() ? "#" : "# " + line) << '\n';
  return out.str();
}

/// The top-level `key:` section of a YAML text, from its key line to the
/// next top-level key (trailing blank and comment lines left to the next).
std::string top_level_section(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    const bool top_level = !line.empty() && line[0] != ' ' && line[0] != '\t' && line[0] != '#' && line[0] != '\r';
    if (top_level) {
      if (inside) break;
      inside = line.rfind(key + ":", 0) == 0;
    }
    if (inside) lines.push_back(line);
  }
  while (!lines.empty() && (lines.back().find_first_not_of(" \t\r") == std::string::npos ||
                            lines.back()[lines.back().find_first_not_of(" \t\r")] == '#'))
    lines.pop_back();
  if (lines.empty()) throw std::invalid_argument(fmt::format("{}: no top-level section in the file", key));
  std::string out;
  for (const std::string& line : lines) out += line + '\n';
  return out;
}

}  // namespace

std::string with_field_values(const std::string& text, const Project& project, const std::vector<FieldEdit>& edits) {
  return edited_in_place(text, project, edits, "");
}

std::string field_value_text(const std::string& text, const Project& project, const std::string& path) {
  const auto position = project.source_map.find(path);
  if (position == project.source_map.end() || !position->second.file.empty())
    throw std::invalid_argument(
        fmt::format("{}: the file has no value of its own there (a default applies, or "
                    "its base file's, extends)",
                    path));
  const std::size_t at = offset_of(text, position->second.line, position->second.column);
  return text.substr(at, scalar_length(text, at));
}

bool mooring_from_base_file(const Project& project) {
  const auto position = project.source_map.find("mooring.lines[0].segments[0].length");
  return position != project.source_map.end() && !position->second.file.empty();
}

std::string with_line_payouts(const std::string& text, const Project& project,
                              const std::map<std::string, double>& payouts_m, const std::string& header) {
  return commented(header) + with_field_values(text, project, payout_edits(project, payouts_m));
}

std::string mooring_variation_with_payouts(const Project& project, const std::map<std::string, double>& payouts_m,
                                           const std::string& header, const std::string& extends) {
  if (!mooring_from_base_file(project))
    throw std::invalid_argument(
        fmt::format("{}: writes its own mooring section: edit it in place", project.source_file));
  const std::string base = project.source_map.at("mooring.lines[0].segments[0].length").file;
  std::ifstream in(base, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("{}: the base file that writes the mooring cannot be read", base));
  std::ostringstream base_text;
  base_text << in.rdbuf();
  const std::string edited = edited_in_place(base_text.str(), project, payout_edits(project, payouts_m), base);
  return commented(header) +
         commented(fmt::format("A variation of {}: its mooring section as {} writes it, with the payouts applied; "
                               "every other section is the base's.",
                               extends, base)) +
         fmt::format("extends: {}\n\n", yaml_string(extends)) + top_level_section(edited, "mooring");
}

std::string edited_project_text(const std::string& text, const Project& original, const Project& edited,
                                const std::filesystem::path& target) {
  std::vector<FieldEdit> edits;
  const auto& before = original.mooring.lines;
  const auto& after = edited.mooring.lines;
  if (before.size() != after.size()) throw std::invalid_argument("mooring.lines: lines were added or removed");
  for (std::size_t l = 0; l < after.size(); ++l) {
    if (before[l].segments.size() != after[l].segments.size())
      throw std::invalid_argument(fmt::format("mooring.lines[{}].segments: segments were added or removed", l));
    for (std::size_t s = 0; s < after[l].segments.size(); ++s) {
      const LineSegment& a = before[l].segments[s];
      const LineSegment& b = after[l].segments[s];
      const std::string at = fmt::format("mooring.lines[{}].segments[{}]", l, s);
      if (a.length_m != b.length_m) edits.push_back({at + ".length", yaml_number(b.length_m)});
      if (a.type != b.type) edits.push_back({at + ".type", yaml_string(b.type)});
    }
  }
  // A relative file reference resolves against the file's own folder: written
  // elsewhere, it is rewritten to name the same file from there.
  const auto folder_of = [](const std::filesystem::path& file) {
    return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  };
  const std::filesystem::path to_folder = folder_of(target);
  if (!same_file(folder_of(original.source_file), to_folder)) {
    for (const auto& [path, resolved] : file_references(original)) {
      const std::string written = written_scalar(text, original, path);
      if (written.empty() || std::filesystem::path(written).is_absolute()) continue;
      edits.push_back({path, yaml_string(reference_from(resolved, to_folder).generic_string())});
    }
  }
  const std::string out = with_field_values(text, original, edits);
  const Project written = parse_project(out, target.string());
  if (const std::string why = difference(edited, written); !why.empty())
    throw std::invalid_argument(fmt::format("cannot write this edit into the project text: {}", why));
  return out;
}

}  // namespace spiral::design
