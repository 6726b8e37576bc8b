#pragma once
// What `spiral --version` prints and the reports carry. Defined in version.cpp
// alone, the only source compiled with the configure-time values, so a new
// commit recompiles one file.
namespace spiral::app {
extern const char* const kVersion;    ///< PROJECT_VERSION of the top CMakeLists.txt
extern const char* const kGitCommit;  ///< `git rev-parse --short HEAD` at configure time, or "unknown"
}  // namespace spiral::app
