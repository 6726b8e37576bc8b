#pragma once
// One call from a project file to a project every later stage may trust:
// parse (strict), resolve the line types, run the validation pass. Every
// problem found on the way is reported together in one InputError.

#include <filesystem>
#include <optional>
#include <vector>

#include "design/project/input_error.hpp"
#include "design/project/line_properties.hpp"
#include "design/project/project.hpp"

namespace spiral::design {

struct ValidatedProject {
  Project project;
  std::vector<LineTypeProperties> line_types;  ///< resolved, in the order of project.line_types
};

/// Throws InputError listing every problem (file, line, column, field path).
/// `data_folder`: as load_project.
ValidatedProject load_validated_project(const std::filesystem::path& file,
                                        const std::optional<std::filesystem::path>& data_folder = std::nullopt);

/// The same for a project already parsed (load_project, parse_project) and
/// perhaps edited in memory since (the Python API): the validation pass runs
/// on `project` as it is now, and its issues carry the positions of its
/// source map, i.e. where the edited values were written. Throws InputError.
ValidatedProject validate_loaded_project(Project project);

}  // namespace spiral::design
