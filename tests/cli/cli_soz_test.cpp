// End-to-end `spiral soz`: JSON contract, table, bad input and exit codes.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_command.hpp"
#include "support/soz_project.hpp"

namespace spiral::test {
namespace {

TEST(CliSoz, JsonHasTheDocumentedKeys) {
  const std::string file = write_temp_project(
      "soz-two.yaml", soz_project_yaml(soz_riser_yaml("A", 0.0, 20.0) + soz_riser_yaml("B", 180.0, 20.0)));
  const CommandResult r = run_spiral("soz " + file + " --step-deg 45 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "spiral.soz");
  EXPECT_EQ(j["directions_deg"].size(), 8u);
  ASSERT_EQ(j["risers"].size(), 2u);
  EXPECT_EQ(j["risers"][0]["allowable_offset_m"].size(), 8u);
  EXPECT_EQ(j["risers"][0]["governing_criterion"].size(), 8u);
  EXPECT_EQ(j["platform"]["allowable_offset_m"].size(), 8u);
  EXPECT_EQ(j["platform"]["governing_riser"].size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_LE(j["platform"]["allowable_offset_m"][k].get<double>(),
              j["risers"][0]["allowable_offset_m"][k].get<double>());
  }
  // Offset check of both load cases (the one mooring line pulls the hull
  // off: non-zero static offsets).
  ASSERT_EQ(j["offset_checks"].size(), 2u);
  const nlohmann::json& check = j["offset_checks"][0];
  EXPECT_EQ(check["case"], "lc1");
  EXPECT_EQ(check["condition"], "intact");
  EXPECT_NEAR(check["margin_m"].get<double>(), check["allowable_m"].get<double>() - check["offset_m"].get<double>(),
              1e-9);
  EXPECT_EQ(check["passes"].get<bool>(), check["ratio"].get<double>() <= 1.0);
  // lc2 has a current: its own zone, named in its check.
  EXPECT_EQ(check["zone"], "still-water");
  ASSERT_EQ(j["zones"].size(), 1u);
  EXPECT_EQ(j["offset_checks"][1]["zone"], j["zones"][0]["name"]);
  EXPECT_EQ(j["zones"][0]["platform"]["allowable_offset_m"].size(), 8u);
  EXPECT_EQ(j["zones"][0]["cases"][0], "lc2");
  EXPECT_GT(j["solves"].get<int>(), 0);
}

TEST(CliSoz, CaseBringsItsCurrentHullPositionAndCondition) {
  const std::string file = write_temp_project("soz-case-zone.yaml", soz_project_yaml(soz_riser_yaml("R", 0.0)));
  const CommandResult r = run_spiral("soz " + file + " --case lc2 --step-deg 90 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["conditions"]["name"], "lc2");
  EXPECT_TRUE(j["conditions"]["current"].get<bool>());
  EXPECT_EQ(j["conditions"]["design_condition"], "extreme");
  ASSERT_EQ(j["offset_checks"].size(), 1u);
  EXPECT_EQ(j["offset_checks"][0]["zone"], "case");
  EXPECT_EQ(j["offset_checks"][0]["case"], "lc2");
}

TEST(CliSoz, TableAndCsv) {
  const std::string file = write_temp_project("soz-one.yaml", soz_project_yaml(soz_riser_yaml("R", 0.0)));
  const CommandResult table = run_spiral("soz " + file + " --step-deg 90 --no-check");
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("Riser safe operational zones"), std::string::npos);
  EXPECT_NE(table.out.find("platform"), std::string::npos);
  EXPECT_NE(table.out.find("riser static solves"), std::string::npos);
  const CommandResult csv = run_spiral("soz " + file + " --step-deg 90 --no-check --csv");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("direction_deg,riser,allowable_offset_m", 0), 0u);
  EXPECT_NE(csv.out.find("\n180,platform,"), std::string::npos);
}

TEST(CliSoz, StepThatDoesNotDivide360IsBadInput) {
  const std::string file = write_temp_project("soz-step.yaml", soz_project_yaml(soz_riser_yaml("R", 0.0)));
  const CommandResult r = run_spiral("soz " + file + " --step-deg 7");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--step-deg: the direction step must divide 360 deg, got 7 deg"), std::string::npos) << r.err;
}

TEST(CliSoz, RiserFailingAtZeroOffsetIsBadInputNamingTheCriterion) {
  const std::string file =
      write_temp_project("soz-fail.yaml", soz_project_yaml(soz_riser_yaml("R", 0.0), "    max_top_tension: 3.0e5\n"));
  const CommandResult r = run_spiral("soz " + file + " --step-deg 90 --no-check");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("riser 'R' fails its criteria at zero offset"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("max_top_tension"), std::string::npos) << r.err;
}

TEST(CliSoz, FlexibleRiserWithoutBendingRadiusIsBadInput) {
  const std::string riser =
      "  - name: F\n    kind: flexible\n    hang_off: [0.0, 0.0, -20.0]\n    azimuth_deg: 0.0\n"
      "    top_angle_deg: 12.0\n    sections:\n"
      "      - {length: 700.0, outer_diameter: 0.3, inner_diameter: 0.2, contents_density: 800.0, "
      "axial_stiffness: "
      "5.0e8,\n"
      "         bending_stiffness: 5.0e4, mass_per_length: 150.0}\n";
  const std::string file = write_temp_project("soz-flex.yaml", soz_project_yaml(riser));
  const CommandResult r = run_spiral("soz " + file);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("min_bending_radius"), std::string::npos) << r.err;
}

TEST(CliSoz, ExtremeOptionsAreCheckedAsBadInput) {
  const std::string file = write_temp_project("soz-extreme.yaml", soz_project_yaml(soz_riser_yaml("R", 0.0)));
  const CommandResult zero = run_spiral("soz " + file + " --step-deg 90 --extreme --duration 0");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("--duration: must be > 0 s, got 0 s"), std::string::npos) << zero.err;
  const CommandResult unchecked = run_spiral("soz " + file + " --step-deg 90 --extreme --no-check");
  EXPECT_EQ(unchecked.exit_code, 2);
  EXPECT_NE(unchecked.err.find("--extreme"), std::string::npos) << unchecked.err;
  // --duration without --extreme is a usage error (CLI11 "needs").
  EXPECT_EQ(run_spiral("soz " + file + " --step-deg 90 --duration 600").exit_code, 2);
}

TEST(CliSoz, UnknownCaseIsBadInput) {
  const std::string file = write_temp_project("soz-case.yaml", soz_project_yaml(soz_riser_yaml("R", 0.0)));
  const CommandResult r = run_spiral("soz " + file + " --case nope");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no load case named \"nope\""), std::string::npos) << r.err;
}

}  // namespace
}  // namespace spiral::test
