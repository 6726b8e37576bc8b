#pragma once
// A stable fingerprint of a project file, printed on reports and stored with
// results so that a result can be traced to the exact input that produced it.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace spiral::design {

/// FNV-1a, 64 bit (Fowler, Noll, Vo; IETF draft-eastlake-fnv), of `bytes`.
std::uint64_t fnv1a_64(std::string_view bytes);

/// FNV-1a 64 of the file's bytes as 16 lowercase hex digits. Throws
/// std::runtime_error naming the file when it cannot be read.
std::string model_hash(const std::filesystem::path& file);

}  // namespace spiral::design
