#pragma once
// A stable fingerprint of a project file, printed on reports and stored with
// results so that a result can be traced to the exact input that produced it.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "design/project/project.hpp"

namespace spiral::design {

/// FNV-1a, 64 bit (Fowler, Noll, Vo; IETF draft-eastlake-fnv), of `bytes`.
std::uint64_t fnv1a_64(std::string_view bytes);

/// FNV-1a 64 of the file's bytes as 16 lowercase hex digits. Throws
/// std::runtime_error naming the file when it cannot be read.
std::string model_hash(const std::filesystem::path& file);

/// The fingerprint of what a project computes: its YAML tree re-emitted
/// without comments or layout, and the bytes of every data file it names
/// (hydrodynamics, hydrostatics, mean drift, panel mesh), and a variation's
/// base files (`extends`, Project::base_files) the same way. A comment edit
/// keeps it; an edited value or data file changes it. 16 hex digits. Throws
/// std::runtime_error naming a file that cannot be read.
std::string project_content_hash(const std::filesystem::path& project_file, const Project& project);

}  // namespace spiral::design
