// End-to-end runs of `spiral validate` and `spiral statics`: exit codes,
// machine output against the MAP++ reference, and error reporting.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace spiral::test {
namespace {

// MAP++ solution of the OC4 mooring at zero offset
// (shared/data/validation/oc4/5MW_OC4Semi_WSt_WavesWN_simpler.macos-gnu.MAP.sum, line 2).
constexpr double kMapFairleadTension_N = 1107283.735;
constexpr double kMapLaidLength_m = 242.345;
// The scenario reproduces the MAP++ deck; the engine is validated to 2e-5
// against it (tests/validation), the same bound holds end to end.
constexpr double kMapTolerance = 2e-5;

std::filesystem::path write_project(const std::string& name, const std::string& text) {
  const auto path = spiral::test::scratch_root() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(CliStatics, HelpOnEverySubcommand) {
  for (const char* sub : {"", "validate ", "statics "}) {
    const auto result = run_spiral(std::string(sub) + "--help");
    EXPECT_EQ(result.exit_code, app::kExitOk) << sub;
    EXPECT_NE(result.out.find("Exit codes"), std::string::npos) << result.out;
  }
}

TEST(CliStatics, ValidatesEveryScenario) {
  for (const char* name : {"oc4-semisubmersible.yaml", "deepwater-fps.yaml", "iea15-volturnus-s.yaml"}) {
    const auto result = run_spiral("validate " + scenario(name));
    EXPECT_EQ(result.exit_code, app::kExitOk) << result.err;
    EXPECT_NE(result.out.find("valid"), std::string::npos);
  }
}

// The VolturnUS-S scenario end to end (its numbers are validated in
// tests/validation/design/analysis/volturnus_s_published_test.cpp): three
// identical catenaries at rest, on the seabed.
TEST(CliStatics, VolturnUsSStaticsRuns) {
  const auto result = run_spiral("statics --json " + scenario("iea15-volturnus-s.yaml"));
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  const auto doc = nlohmann::json::parse(result.out);
  ASSERT_EQ(doc["lines"].size(), 3u);
  for (const auto& line : doc["lines"]) EXPECT_EQ(line["regime"], "touchdown");
}

TEST(CliStatics, Oc4JsonMatchesMap) {
  const auto result = run_spiral("statics --json " + scenario("oc4-semisubmersible.yaml"));
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  const auto doc = nlohmann::json::parse(result.out);
  EXPECT_EQ(doc["format"], "spiral.statics");
  ASSERT_EQ(doc["lines"].size(), 3u);
  for (const auto& line : doc["lines"]) {
    EXPECT_NEAR(line["fairlead_tension_N"].get<double>(), kMapFairleadTension_N, kMapTolerance * kMapFairleadTension_N);
    EXPECT_NEAR(line["laid_length_m"].get<double>(), kMapLaidLength_m, kMapTolerance * 835.35);
    EXPECT_EQ(line["regime"], "touchdown");
  }
  ASSERT_EQ(doc["hull_force_6dof"].size(), 6u);
  EXPECT_LT(doc["hull_force_6dof"][2].get<double>(), 0.0);  // the lines pull the hull down
}

TEST(CliStatics, SurgeOffsetIsRestored) {
  const auto result = run_spiral("statics --json --offset 10,0,0,0,0,0 " + scenario("oc4-semisubmersible.yaml"));
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  const auto doc = nlohmann::json::parse(result.out);
  EXPECT_LT(doc["hull_force_6dof"][0].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(doc["offset_6dof"][0].get<double>(), 10.0);
}

TEST(CliStatics, TableNamesEveryLine) {
  const auto result = run_spiral("statics " + scenario("deepwater-fps.yaml"));
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.out.find("Mooring force on the hull"), std::string::npos);
}

TEST(CliStatics, MissingFileIsBadInput) {
  const auto result = run_spiral("statics /nonexistent/project.yaml");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("/nonexistent/project.yaml"), std::string::npos) << result.err;
}

TEST(CliStatics, WrongOffsetArityIsBadInput) {
  const auto result = run_spiral("statics --offset 1,2,3 " + scenario("oc4-semisubmersible.yaml"));
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
}

TEST(CliStatics, ImpossibleOffsetIsSolverFailureNamingTheLine) {
  // 500 m of surge stretches the 835 m line at 180 degrees over a 1.3 km chord.
  const auto result = run_spiral("statics --offset 500,0,0,0,0,0 " + scenario("oc4-semisubmersible.yaml"));
  EXPECT_EQ(result.exit_code, app::kExitSolverFailure);
  EXPECT_NE(result.err.find("line 'L2'"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace spiral::test

namespace spiral::test {
namespace {

// One end-to-end case per class of bad input: the CLI exits with 2 and the
// message names the file, the line, the field path and the problem.
struct BadInputCase {
  const char* name;
  const char* replace;   // text of the valid project to replace
  const char* with;      // its faulty version
  const char* expected;  // fragment the message must contain
  int line;              // line the message must point at
};

constexpr const char* kValidProject = R"(version: 1
name: cli bad-input base
site: {depth: 200.0, water_density: 1025.0, gravity: 9.80665,
       seabed: {friction_axial: 1.0, friction_lateral: 1.0, normal_stiffness: 1.0e5}}
line_types:
  - {name: c, kind: user, mass_per_length: 113.35, diameter: 0.0766, axial_stiffness: 7.536e8, breaking_load: 6.0e6}
mooring:
  lines:
    - name: L1
      anchor: [837.6, 0.0, -200.0]
      fairlead: [40.868, 0.0, -14.0]
      segments:
        - {type: c, length: 835.35}
hull: {reference_point: [0, 0, 0], mass: 1.0e7, center_of_gravity: [0, 0, -10], radii_of_gyration: [30, 30, 30],
       displaced_volume: 1.0e4, center_of_buoyancy: [0, 0, -12], waterplane_area: 370.0,
       waterplane_inertia: [1.4e5, 1.4e5]}
environments: [{name: calm}]
load_cases: [{name: still, environment: calm}]
criteria: {mooring: {code: api_rp_2sk}}
)";

class CliBadInput : public ::testing::TestWithParam<BadInputCase> {};

TEST_P(CliBadInput, ExitsTwoAndNamesFileLineAndField) {
  const BadInputCase& c = GetParam();
  std::string text = kValidProject;
  const auto at = text.find(c.replace);
  ASSERT_NE(at, std::string::npos) << c.replace;
  text.replace(at, std::string(c.replace).size(), c.with);
  const auto path = write_project(std::string("spiral-cli-") + c.name + ".yaml", text);
  const auto result = run_spiral("statics '" + path.string() + "'");
  EXPECT_EQ(result.exit_code, app::kExitBadInput) << result.err;
  EXPECT_NE(result.err.find(path.filename().string() + ":" + std::to_string(c.line) + ":"), std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find(c.expected), std::string::npos) << result.err;
}

INSTANTIATE_TEST_SUITE_P(
    EveryErrorClass, CliBadInput,
    ::testing::Values(BadInputCase{"negative-length", "length: 835.35", "length: -20.0",
                                   "mooring.lines[0].segments[0].length: must be > 0 m, got -20 m", 13},
                      BadInputCase{"unknown-key", "gravity: 9.80665", "gravty: 9.80665", "site.gravty: unknown key", 3},
                      BadInputCase{"wrong-type", "depth: 200.0", "depth: deep", "site.depth", 3},
                      BadInputCase{"bad-enum", "kind: user", "kind: usr", "line_types[0].kind", 6},
                      BadInputCase{"undefined-type", "{type: c, length: 835.35}", "{type: chain, length: 835.35}",
                                   "mooring.lines[0].segments[0].type", 13},
                      BadInputCase{"anchor-below-seabed", "anchor: [837.6, 0.0, -200.0]",
                                   "anchor: [837.6, 0.0, -210.0]", "mooring.lines[0].anchor", 10},
                      BadInputCase{"fairlead-above-water", "fairlead: [40.868, 0.0, -14.0]",
                                   "fairlead: [40.868, 0.0, 4.0]", "mooring.lines[0].fairlead", 11},
                      BadInputCase{"line-too-short", "length: 835.35", "length: 500.0", "too short", 13},
                      BadInputCase{"line-too-long", "length: 835.35", "length: 1500.0", "slack", 13},
                      BadInputCase{"duplicate-name", "environments: [{name: calm}]",
                                   "environments: [{name: calm}, {name: calm}]", "environments[1].name", 17},
                      BadInputCase{"undefined-environment", "environment: calm}", "environment: storm}",
                                   "load_cases[0].environment", 18}),
    [](const ::testing::TestParamInfo<BadInputCase>& info) {
      std::string name = info.param.name;
      for (char& ch : name)
        if (ch == '-') ch = '_';
      return name;
    });

}  // namespace
}  // namespace spiral::test
