// The load-case matrix: its expansion (names, turned headings, damaged lines,
// conditions), its validation with positions, and load_validated_project
// appending the generated cases.

#include "design/project/load_case_matrix.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "design/project/project_loader.hpp"
#include "design/project/project_validation.hpp"
#include "design/project/validated_project.hpp"
#include "support/project_fixture.hpp"
#include "support/temp_folder.hpp"

namespace spiral::design {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

std::string with_matrix(const std::string& matrix) {
  std::string text = replace(kMinimal, "  - name: calm\n",
                             "  - name: calm\n"
                             "  - name: storm\n"
                             "    waves: {spectrum: jonswap, hs: 6.0, tp: 11.0, heading_deg: 10.0}\n"
                             "    current: {heading_deg: 350.0, profile: [[0.0, 1.0], [-100.0, 0.5]]}\n");
  text = replace(text, "mooring:\n  lines:\n",
                 "mooring:\n  lines:\n"
                 "    - name: L0\n"
                 "      anchor: {radius: 500.0, azimuth_deg: 180.0}\n"
                 "      fairlead: [-10.0, 0.0, -10.0]\n"
                 "      segments:\n"
                 "        - {type: c, length: 550.0}\n");
  return text + "load_case_matrix:\n" + matrix;
}

std::string report(const std::string& text) {
  std::string out;
  for (const InputIssue& issue : check_project(parse_project(text, "test.yaml"), {})) out += format_issue(issue) + "\n";
  return out;
}

TEST(LoadCaseMatrix, ExpandsHeadingsAndDamagedLinesWithReproducibleNames) {
  Project p =
      parse_project(with_matrix("  - {environment: storm, headings_deg: [0.0, 45.0, 90.5], condition: extreme,\n"
                                "     damaged: every_line, damaged_condition: survival}\n"),
                    "test.yaml");
  ASSERT_EQ(report(with_matrix("  - {environment: storm, headings_deg: [0.0, 45.0, 90.5], damaged: every_line}\n")),
            "");
  const std::size_t cases_before = p.load_cases.size();
  expand_load_case_matrix(p);
  // 3 headings × (intact + 2 lines removed).
  ASSERT_EQ(p.load_cases.size(), cases_before + 9);
  const LoadCase& first = p.load_cases[cases_before];
  EXPECT_EQ(first.name, "storm@h000");
  EXPECT_EQ(first.condition, DesignCondition::extreme);
  EXPECT_FALSE(first.damaged_line.has_value());
  const LoadCase& damaged = p.load_cases[cases_before + 4];
  EXPECT_EQ(damaged.name, "storm@h045-without-L0");
  EXPECT_EQ(damaged.environment, "storm@h045");
  EXPECT_EQ(damaged.damaged_line, std::string("L0"));
  EXPECT_EQ(damaged.condition, DesignCondition::survival);
  EXPECT_EQ(p.load_cases.back().name, "storm@h90.5-without-L1");
  // Every heading of the sea turns together (waves 10° -> 55°, current 350° -> 35°).
  const Environment& turned = *std::find_if(p.environments.begin(), p.environments.end(),
                                            [](const Environment& e) { return e.name == "storm@h045"; });
  EXPECT_NEAR(turned.waves->heading_rad, 55.0 * kDegToRad, 1e-12);
  EXPECT_NEAR(turned.current->heading_rad, 35.0 * kDegToRad, 1e-12);
}

TEST(LoadCaseMatrix, ListedLinesOnly) {
  Project p =
      parse_project(with_matrix("  - {environment: storm, headings_deg: [30.0], damaged: [L1]}\n"), "test.yaml");
  const std::vector<LoadCase> cases = matrix_load_cases(p, p.load_case_matrix[0]);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[1].name, "storm@h030-without-L1");
}

// seeds: one case per seed (the realization), named so; a written case has its own seed.
TEST(LoadCaseMatrix, SeedsMakeACasePerSeedAndCasesKeepTheirSeed) {
  Project p = parse_project(
      with_matrix("  - {environment: storm, headings_deg: [0.0], damaged: [L1], seeds: [3, 7]}\n"), "test.yaml");
  const std::vector<LoadCase> cases = matrix_load_cases(p, p.load_case_matrix[0]);
  ASSERT_EQ(cases.size(), 4u);
  EXPECT_EQ(cases[0].name, "storm@h000-seed3");
  EXPECT_EQ(cases[0].seed, 3);
  EXPECT_EQ(cases[1].name, "storm@h000-without-L1-seed3");
  EXPECT_EQ(cases[3].name, "storm@h000-without-L1-seed7");
  EXPECT_EQ(cases[3].seed, 7);
  EXPECT_EQ(cases[3].environment, "storm@h000");
  // One seed keeps the plain names.
  Project one = parse_project(with_matrix("  - {environment: storm, headings_deg: [0.0], seeds: [5]}\n"), "test.yaml");
  EXPECT_EQ(matrix_load_cases(one, one.load_case_matrix[0])[0].name, "storm@h000");
  EXPECT_EQ(matrix_load_cases(one, one.load_case_matrix[0])[0].seed, 5);
  // A written case: seed 1 unless it says.
  EXPECT_EQ(parse_project(kMinimal, "test.yaml").load_cases[0].seed, 1);
  EXPECT_EQ(
      parse_project(replace(kMinimal, "{name: lc1, environment: calm}", "{name: lc1, environment: calm, seed: 4}"),
                    "test.yaml")
          .load_cases[0]
          .seed,
      4);
  const std::string issues =
      report(with_matrix("  - {environment: storm, headings_deg: [0.0], seeds: [2, 0, 2]}\n") + "");
  EXPECT_NE(issues.find("load_case_matrix[0].seeds[1]: must be >= 1, got 0"), std::string::npos) << issues;
  EXPECT_NE(issues.find("load_case_matrix[0].seeds[2]: repeats seed 2 (seeds[0])"), std::string::npos) << issues;
  const std::string written =
      report(replace(kMinimal, "{name: lc1, environment: calm}", "{name: lc1, environment: calm, seed: 0}"));
  EXPECT_NE(written.find("load_cases[0].seed: must be >= 1, got 0"), std::string::npos) << written;
}

TEST(LoadCaseMatrix, BadEntriesAreReportedWithPositions) {
  const std::string issues =
      report(with_matrix("  - {environment: gale, headings_deg: [0.0]}\n"
                         "  - {environment: storm, headings_deg: [0.0, 360.0, 0.0], damaged: [L7]}\n"));
  EXPECT_NE(issues.find("load_case_matrix[0].environment: undefined environment \"gale\""), std::string::npos)
      << issues;
  EXPECT_NE(issues.find("load_case_matrix[1].headings_deg[1]: must be in [0, 360) deg, got 360 deg"), std::string::npos)
      << issues;
  EXPECT_NE(issues.find("load_case_matrix[1].headings_deg[2]: repeats heading 0 deg"), std::string::npos) << issues;
  EXPECT_NE(issues.find("load_case_matrix[1].damaged[0]: undefined mooring line \"L7\""), std::string::npos) << issues;
  EXPECT_NE(issues.find("test.yaml:"), std::string::npos) << issues;
  const std::string collision =
      report(with_matrix("  - {environment: storm, headings_deg: [0.0]}\n"
                         "  - {environment: storm, headings_deg: [0.0]}\n"));
  EXPECT_NE(collision.find("load_case_matrix[1]: generates \"storm@h000\", a name an earlier entry generates"),
            std::string::npos)
      << collision;
}

TEST(LoadCaseMatrix, LoadedProjectHoldsTheGeneratedCases) {
  const auto file = spiral::test::scratch_root() / ("spiral-matrix-" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(file) << with_matrix("  - {environment: storm, headings_deg: [0.0, 180.0], damaged: [L0]}\n");
  const ValidatedProject p = load_validated_project(file);
  std::filesystem::remove(file);
  ASSERT_EQ(p.project.load_cases.size(), 1u + 4u);
  EXPECT_EQ(p.project.load_cases[4].name, "storm@h180-without-L0");
  EXPECT_EQ(p.project.environments.size(), 2u + 2u);
}

// A matrix case turned onto a heading the project also names as its own
// environment is the same analysis (same_analysis_inputs), whatever the two
// environments are called; a different seed, damaged line, condition or
// heading is not.
TEST(LoadCaseMatrix, AMatrixCaseTurnedOntoANamedCaseIsTheSameAnalysis) {
  std::string text =
      with_matrix("  - {environment: storm0, headings_deg: [0.0, 45.0], damaged: [L0], damaged_condition: extreme}\n");
  text = replace(text, "  - name: calm\n",
                 "  - name: calm\n"
                 "  - name: storm0\n"
                 "    waves: {spectrum: jonswap, hs: 6.0, tp: 11.0, heading_deg: 0.0}\n"
                 "    wind: {speed: 20.0, heading_deg: 0.0, spectrum: api}\n"
                 "    current: {heading_deg: 0.0, profile: [[0.0, 1.0], [-100.0, 0.5]]}\n"
                 "  - name: storm45\n"
                 "    waves: {spectrum: jonswap, hs: 6.0, tp: 11.0, heading_deg: 45.0}\n"
                 "    wind: {speed: 20.0, heading_deg: 45.0, spectrum: api}\n"
                 "    current: {heading_deg: 45.0, profile: [[0.0, 1.0], [-100.0, 0.5]]}\n");
  text = replace(text, "  - {name: lc1, environment: calm}\n",
                 "  - {name: lc1, environment: calm}\n"
                 "  - {name: named45, environment: storm45}\n"
                 "  - {name: named45-seed2, environment: storm45, seed: 2}\n"
                 "  - {name: named45-without-L0, environment: storm45, damaged_line: L0}\n"
                 "  - {name: named45-survival, environment: storm45, condition: survival}\n");
  ASSERT_EQ(report(text), "");
  Project p = parse_project(text, "test.yaml");
  expand_load_case_matrix(p);
  const auto load_case = [&](const std::string& name) -> const LoadCase& {
    for (const LoadCase& c : p.load_cases)
      if (c.name == name) return c;
    ADD_FAILURE() << name;
    return p.load_cases.front();
  };
  const LoadCase& named = load_case("named45");
  EXPECT_TRUE(same_analysis_inputs(p, named, load_case("storm0@h045")));
  EXPECT_TRUE(same_analysis_inputs(p, load_case("named45-without-L0"), load_case("storm0@h045-without-L0")));
  EXPECT_FALSE(same_analysis_inputs(p, named, load_case("storm0@h000")));  // heading
  EXPECT_FALSE(same_analysis_inputs(p, named, load_case("named45-seed2")));
  EXPECT_FALSE(same_analysis_inputs(p, named, load_case("named45-without-L0")));
  EXPECT_FALSE(same_analysis_inputs(p, named, load_case("named45-survival")));
  EXPECT_FALSE(same_analysis_inputs(p, named, load_case("lc1")));  // calm: no sea at all
  EXPECT_TRUE(same_analysis_inputs(p, named, named));
}

}  // namespace
}  // namespace spiral::design
