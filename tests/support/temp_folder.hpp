#pragma once
// Scratch space for tests: one folder per test process, removed when the
// process ends (ctest runs each test in its own process), so that a run of
// the suite leaves nothing behind in the system's temporary folder. A test
// that crashes leaves its folder, for a look at what it wrote.

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace spiral::test {

/// `<temp>/spiral-tests-<pid>`, created on the first call, removed at exit.
inline const std::filesystem::path& scratch_root() {
  struct Root {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("spiral-tests-" + std::to_string(::getpid()));
    Root() { std::filesystem::create_directories(path); }
    ~Root() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Root root;
  return root.path;
}

/// `<scratch root>/<name>`, emptied (removed and created again).
inline std::filesystem::path fresh_temp_folder(const std::string& name) {
  const std::filesystem::path dir = scratch_root() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace spiral::test
