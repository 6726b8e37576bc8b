#pragma once
// Errors in command-line options that refer into the project (`--case`,
// `--damaged`, `--exclude`, option ranges), reported like input errors:
// the project file, the option as the field path, and what is wrong.

#include <string>

#include "design/project/input_error.hpp"
#include "design/project/project.hpp"

namespace spiral::design {

/// An InputError naming `option` of a command run on `project`.
InputError command_line_error(const Project& project, const std::string& option, const std::string& message,
                              const std::string& condition = "command_line_reference");

/// The load case named `name`; throws command_line_error on `--case`
/// listing the defined names when there is none.
const LoadCase& find_load_case(const Project& project, const std::string& name);

}  // namespace spiral::design
