// End-to-end runs of `spiral lines`: mooring lines and risers under a motion
// history from a file. Exit codes (0 written, 2 bad motion file, bad case,
// line or option), the two output files, the summary's checks, and messages
// that name the file, line and column.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace spiral::test {
namespace {

const std::string kOc4 = std::string("'") + SPIRAL_SOURCE_DIR + "/scenarios/oc4-semisubmersible.yaml'";
const std::string kDeepwater = std::string("'") + SPIRAL_SOURCE_DIR + "/scenarios/deepwater-fps.yaml'";
const std::string kSurge = std::string("'") + SPIRAL_TEST_DATA_DIR + "/motion/oc4-two-tone-surge.csv'";
const std::string kUneven = std::string("'") + SPIRAL_TEST_DATA_DIR + "/motion/uneven-heave-pitch.txt'";

std::filesystem::path temp_folder(const std::string& name) {
  return spiral::test::scratch_root() / ("spiral-" + std::to_string(::getpid()) + "-" + name);
}

TEST(CliLines, Oc4LinesUnderASurgeHistoryWriteSeriesAndChecks) {
  const auto out = temp_folder("lines-oc4");
  const auto result = run_spiral("lines " + kOc4 + " --motion " + kSurge +
                                 " --case intact-still-water --lines L1,L2 --out '" + out.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.out.find("2 mooring lines, 0 risers"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("L1"), std::string::npos) << result.out;
  const std::string csv = read_text(out / "time_series.csv");
  EXPECT_EQ(csv.rfind("time_s,surge_m,sway_m,heave_m,roll_deg,pitch_deg,yaw_deg,fairlead_tension_L1_N,"
                      "anchor_tension_L1_N,anchor_uplift_L1_deg,laid_length_L1_m,fairlead_tension_L2_N",
                      0),
            0u)
      << csv.substr(0, 300);
  const nlohmann::json j = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(j["format"], "spiral.motion_lines");
  EXPECT_EQ(j["lines"].size(), 2u);
  EXPECT_EQ(j["risers"].size(), 0u);
  EXPECT_DOUBLE_EQ(j["end_s"].get<double>(), 600.0);
  // The shipped line carries 1.27 MN at most under this motion (the
  // validation tier's reference); its MBL is 4.884 MN, factor 1.67.
  const auto& check = j["lines"][0]["dynamic_tension_check"];
  EXPECT_EQ(check["basis"], "record_maximum");
  EXPECT_NEAR(check["extreme_N"].get<double>(), 1.2724e6, 0.01e6);
  EXPECT_NEAR(check["utilization"].get<double>(), check["extreme_N"].get<double>() * 1.67 / 4.884e6, 1e-3);
  EXPECT_TRUE(j["passes"].get<bool>());
  std::filesystem::remove_all(out);
}

TEST(CliLines, ARiserUnderAnUnevenTabSeparatedHistoryGetsItsCriteria) {
  const auto out = temp_folder("lines-riser");
  const auto result =
      run_spiral("lines " + kDeepwater + " --motion " + kUneven +
                 " --case lc5-operating-45deg --lines P1 --ramp 10 --step 1 --out '" + out.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  const nlohmann::json j = nlohmann::json::parse(read_text(out / "summary.json"));
  ASSERT_EQ(j["risers"].size(), 1u);
  const auto& riser = j["risers"][0];
  EXPECT_EQ(riser["name"], "P1");
  EXPECT_FALSE(riser["criteria"].empty());
  for (const auto& c : riser["criteria"]) EXPECT_GE(c["time_s"].get<double>(), 10.0);
  // Each criterion's worst is its channel's extreme over the same window: the
  // largest top angle, the lowest effective tension (a floor whose
  // utilization stays 0 while it holds).
  auto channel = [&](const std::string& name) {
    for (const auto& c : riser["channels"])
      if (c["name"] == name) return c;
    return nlohmann::json();
  };
  for (const auto& c : riser["criteria"]) {
    if (c["criterion"] == "max_top_angle") {
      EXPECT_DOUBLE_EQ(c["value"].get<double>(), channel("top_angle_P1_deg")["max"].get<double>());
    }
    if (c["criterion"] == "min_effective_tension") {
      EXPECT_DOUBLE_EQ(c["value"].get<double>(), channel("min_effective_tension_P1_N")["min"].get<double>());
    }
  }
  EXPECT_TRUE(riser.contains("governing_criterion"));
  EXPECT_TRUE(j["waves_on_lines"].get<bool>());
  // The reader's notes reach the summary: roll in rad, the rest in deg by default.
  EXPECT_NE(j["notes"].dump().find("pitch, yaw without a unit read in deg"), std::string::npos) << j["notes"];
  const std::string csv = read_text(out / "time_series.csv");
  EXPECT_NE(csv.find("von_mises_utilization_P1"), std::string::npos);
  std::filesystem::remove_all(out);
}

TEST(CliLines, BadMotionFileExitsTwoWithFileLineAndColumn) {
  const std::string motion = write_temp_project("bad-motion.csv",
                                                "time,surge,sway,heave,roll,pitch,yaw\n"
                                                "0,0,0,0,0,0,0\n"
                                                "1,0.5m,0,0,0,0,0\n");
  const auto result = run_spiral("lines " + kOc4 + " --motion " + motion + " --case intact-still-water");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("bad-motion.csv:3:3: surge: \"0.5m\" is not a finite number (m)"), std::string::npos)
      << result.err;
  const auto missing = run_spiral("lines " + kOc4 + " --motion /nonexistent/m.csv --case intact-still-water");
  EXPECT_EQ(missing.exit_code, app::kExitBadInput);
  EXPECT_NE(missing.err.find("/nonexistent/m.csv"), std::string::npos) << missing.err;
}

TEST(CliLines, UnknownLineRampTooLongAndZeroToleranceScaleExitTwoNamingTheirFlags) {
  const auto line = run_spiral("lines " + kOc4 + " --motion " + kSurge + " --case intact-still-water --lines L9");
  EXPECT_EQ(line.exit_code, app::kExitBadInput);
  EXPECT_NE(line.err.find("--lines: no mooring line or riser named \"L9\""), std::string::npos) << line.err;
  const auto ramp = run_spiral("lines " + kOc4 + " --motion " + kSurge + " --case intact-still-water --ramp 900");
  EXPECT_EQ(ramp.exit_code, app::kExitBadInput);
  EXPECT_NE(ramp.err.find("--ramp"), std::string::npos) << ramp.err;
  const auto scale =
      run_spiral("lines " + kOc4 + " --motion " + kSurge + " --case intact-still-water --tolerance-scale 0");
  EXPECT_EQ(scale.exit_code, app::kExitBadInput);
  EXPECT_NE(scale.err.find("--tolerance-scale: must be > 0, got 0"), std::string::npos) << scale.err;
}

}  // namespace
}  // namespace spiral::test
