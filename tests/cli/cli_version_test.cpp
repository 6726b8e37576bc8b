// `spiral --version`: the CMake project version and the configure-time commit.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"

namespace spiral::test {
namespace {

TEST(CliVersion, PrintsProjectVersionAndCommit) {
  const auto result = run_spiral("--version");
  EXPECT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  // The version's dots are literal; the commit is a short hash, or "unknown" without git.
  const std::string version = std::regex_replace(SPIRAL_VERSION, std::regex(R"(\.)"), R"(\.)");
  EXPECT_TRUE(std::regex_match(result.out, std::regex("spiral " + version + R"( \(commit ([0-9a-f]{4,}|unknown)\)\n)")))
      << result.out;
}

}  // namespace
}  // namespace spiral::test
