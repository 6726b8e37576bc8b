#pragma once
// Reads a project file (format v1, docs/project-format.md) into a
// design::Project. Strict: an unknown key, a value of the wrong type, a bad
// enum string, a missing required key or a YAML syntax error is an error. All
// errors of the file are collected and thrown together as one InputError whose
// issues carry file, line, column and field path.
//
// Loading only maps the text to the model (plus structural rules of the
// format); the semantic checks (positive lengths, references, geometry) are a
// separate pass: validate_project() in design/project/project_validation.hpp.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "design/project/input_error.hpp"
#include "design/project/project.hpp"

namespace spiral::design {

/// Reads and parses `file`. Relative data-file references resolve against
/// `data_folder`, by default the folder of `file` (a spiral iteration's
/// project, written in the run folder, keeps the original's references); a
/// hull section taken from a base file (`extends`) resolves from the base's
/// folder. Throws InputError (naming the file) when it cannot be read or when the
/// text is not a valid project.
Project load_project(const std::filesystem::path& file,
                     const std::optional<std::filesystem::path>& data_folder = std::nullopt);

/// Parses project text. `source_name` names the text in messages and in
/// Project::source_file; relative file references resolve against
/// `data_folder`, by default its folder. Throws InputError with every issue found.
Project parse_project(std::string_view yaml_text, std::string source_name,
                      const std::optional<std::filesystem::path>& data_folder = std::nullopt);

}  // namespace spiral::design
