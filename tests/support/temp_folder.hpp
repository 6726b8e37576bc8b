#pragma once
// An empty scratch folder for a test, unique to the process.

#include <unistd.h>

#include <filesystem>
#include <string>

namespace spiral::test {

/// `<temp>/<name>-<pid>`, emptied (removed and created again).
inline std::filesystem::path fresh_temp_folder(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace spiral::test
