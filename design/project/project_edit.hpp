#pragma once
// Writing a changed project back as YAML text without losing what the user
// wrote: the values that change are replaced in place in the original text
// (found through the source map of the loaded project), so comments, order,
// flow style and every other number stay as they were.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "design/project/project.hpp"

namespace spiral::design {

/// A new value for one field of a project file: its field path as in the
/// source map (`mooring.lines[3].segments[1].length`) and the YAML scalar to
/// write there (a number, or a string as YAML reads it back).
struct FieldEdit {
  std::string path;
  std::string value;
};

/// `text` (the file `project` was loaded from) with the scalar of each edited
/// field replaced in place. Throws std::invalid_argument when the source map
/// has no position for a path (a project built in code, a default value).
std::string with_field_values(const std::string& text, const Project& project, const std::vector<FieldEdit>& edits);

/// The scalar `text` writes at the field `path` of `project` (loaded from
/// it), as written. Throws std::invalid_argument as with_field_values.
std::string field_value_text(const std::string& text, const Project& project, const std::string& path);

/// `text` with the top (fairlead-end) segment of each line in `payouts_m`
/// lengthened by its payout (m; negative hauls in), the new lengths printed
/// to 0.1 mm, and `header` (lines that become `# ` comments) put first.
/// Throws std::invalid_argument when a line is unknown or the source map has
/// no position for its length (a project built in code).
std::string with_line_payouts(const std::string& text, const Project& project,
                              const std::map<std::string, double>& payouts_m, const std::string& header);

/// Whether the project's mooring section comes from a base file (`extends`),
/// where with_line_payouts cannot reach it.
bool mooring_from_base_file(const Project& project);

/// For a variation whose mooring section is its base's: a new variation file
/// that `extends` the project file (the path written as is: relative to the
/// new file's folder, or absolute) and writes the mooring section as the
/// base writes it — comments and layout kept — with each payout applied in
/// place as with_line_payouts does, `header` first. Every other section
/// stays the project's. Throws std::invalid_argument when the project writes
/// its own mooring, a line is unknown, or the base cannot be read.
std::string mooring_variation_with_payouts(const Project& project, const std::map<std::string, double>& payouts_m,
                                           const std::string& header, const std::string& extends);

/// The project file of `edited`, a project loaded from `text` as `original`
/// and changed in memory (the Python API), to be written at `target`: the
/// segment lengths and line types that differ are written in place, lengths
/// in the shortest form that reads back as the same double, and every file
/// reference written relative to the original's folder is rewritten relative
/// to the target's (so the file still finds its hydrodynamic data). The text
/// is then read back and compared with `edited`; throws std::invalid_argument
/// naming the field when an edit cannot be written in place — a field with
/// no position of its own, a value shared through a YAML anchor, lines or
/// segments added or removed.
std::string edited_project_text(const std::string& text, const Project& original, const Project& edited,
                                const std::filesystem::path& target);

}  // namespace spiral::design
