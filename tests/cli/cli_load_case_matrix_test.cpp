// A load-case matrix reaches the commands: its generated cases can be run by name.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "app/exit_codes.hpp"
#include "support/project_fixture.hpp"
#include "support/run_command.hpp"

namespace spiral::test {
namespace {

TEST(CliLoadCaseMatrix, GeneratedCaseRunsByName) {
  std::string text = design::replace(design::kMinimal, "  - name: calm\n",
                                     "  - name: calm\n"
                                     "  - name: breeze\n"
                                     "    current: {heading_deg: 0.0, profile: [[0.0, 0.5], [-100.0, 0.5]]}\n");
  text += "load_case_matrix:\n  - {environment: breeze, headings_deg: [0.0, 90.0], damaged: every_line}\n";
  const std::string project = write_temp_project("matrix.yaml", text);
  const auto run = run_spiral("equilibrium --json " + project + " --case breeze@h090");
  ASSERT_EQ(run.exit_code, app::kExitOk) << run.err;
  EXPECT_EQ(nlohmann::json::parse(run.out)["case"], "breeze@h090");
  const auto unknown = run_spiral("equilibrium " + project + " --case breeze@h045");
  EXPECT_EQ(unknown.exit_code, app::kExitBadInput);
  EXPECT_NE(unknown.err.find("breeze@h090-without-L1"), std::string::npos) << unknown.err;  // the defined names
}

}  // namespace
}  // namespace spiral::test
