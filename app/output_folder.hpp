#pragma once
// Where a command writes its files when no --out is given: one rule for all.
#include <filesystem>
#include <string>

namespace spiral::app {

/// `out` when given, else out/<project-stem>/<leaf> below the working directory
/// (leaf: the stage, analyze/<run> or compare/<run>).
std::filesystem::path output_folder(const std::string& out, const std::string& project_file,
                                    const std::filesystem::path& leaf);

}  // namespace spiral::app
