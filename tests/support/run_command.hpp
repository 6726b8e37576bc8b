#pragma once
// Runs the `spiral` executable for end-to-end tests and captures its exit
// code, standard output and standard error separately.

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/temp_folder.hpp"

namespace spiral::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// `arguments` is appended to the executable path as shell words (quote them yourself).
inline CommandResult run_spiral(const std::string& arguments) {
  static int counter = 0;
  const auto dir =
      spiral::test::scratch_root() / ("spiral-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::create_directories(dir);
  const std::string command = std::string("'") + SPIRAL_EXECUTABLE + "' " + arguments + " >'" + (dir / "out").string() +
                              "' 2>'" + (dir / "err").string() + "' </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(dir / "out");
  result.err = read_text(dir / "err");
  std::filesystem::remove_all(dir);
  return result;
}

/// Writes `text` to a file in the temporary folder (named after `name` and
/// this process) and returns its path quoted as one shell word.
inline std::string write_temp_project(const std::string& name, const std::string& text) {
  std::string file_name = "spiral-";
  file_name += std::to_string(::getpid());
  file_name += '-';
  file_name += name;
  const auto path = spiral::test::scratch_root() / file_name;
  std::ofstream(path) << text;
  std::string quoted = "'";
  quoted += path.string();
  quoted += '\'';
  return quoted;
}

inline std::string scenario(const std::string& name) {
  return std::string("'") + SPIRAL_SOURCE_DIR + "/scenarios/" + name + "'";
}

}  // namespace spiral::test
