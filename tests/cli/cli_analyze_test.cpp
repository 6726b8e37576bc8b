// End-to-end runs of `spiral analyze`: CSV time series and JSON summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace spiral::test {
namespace {

TEST(CliAnalyze, ScRunWritesCsvAndJson) {
  const auto out = spiral::test::scratch_root() / ("spiral-analyze-" + std::to_string(::getpid()));
  std::filesystem::remove_all(out);
  const auto result =
      run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                 " --case intact-raft-jonswap --level sc --duration 1200 --seed 3 --out '" + out.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_EQ(result.err.find("dynamics ["), std::string::npos) << "no progress bar when stderr is not a terminal";
  const std::string csv = read_text(out / "time_series.csv");
  ASSERT_EQ(csv.rfind("time_s,surge_m,sway_m,heave_m,roll_deg,pitch_deg,yaw_deg,surge_lf_m", 0), 0u)
      << csv.substr(0, 200);
  EXPECT_NE(csv.find(",qs_tension_L1_N"), std::string::npos);
  EXPECT_NE(csv.find(",fairlead_L3_x_m,fairlead_L3_y_m,fairlead_L3_z_m"), std::string::npos);
  // 1200 s at 0.5 s: 2401 rows + header.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2402);
  const auto doc = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(doc["format"], "spiral.dynamic_analysis");
  EXPECT_EQ(doc["level"], "sc");
  EXPECT_EQ(doc["seed"], 3);
  EXPECT_EQ(doc["load_case"], "intact-raft-jonswap");
  EXPECT_FALSE(doc["wave_frequency_motions"].get<bool>());
  bool wf_note = false;
  for (const auto& n : doc["notes"])
    wf_note = wf_note || n.get<std::string>().find("no wave-frequency") != std::string::npos;
  EXPECT_TRUE(wf_note) << "OC4 has no .3/.4: the summary must say so";
  ASSERT_GE(doc["channels"].size(), 15u);
  const auto& surge = doc["channels"][0];
  EXPECT_EQ(surge["name"], "surge_m");
  EXPECT_GT(surge["std"].get<double>(), 0.0);
  EXPECT_TRUE(surge.contains("mpm_max_3h")) << surge.dump();
  // The spectrum: frequencies and densities of one length, its sum·dw the variance (Welch, Parseval).
  const auto& freq = surge["spectrum"]["frequency_rad_per_s"];
  const auto& dens = surge["spectrum"]["density_per_rad_per_s"];
  ASSERT_EQ(freq.size(), dens.size());
  ASSERT_GT(freq.size(), 4u);
  double variance = 0.0;
  for (const auto& s : dens) variance += s.get<double>() * (freq[1].get<double>() - freq[0].get<double>());
  const double sd = surge["std"].get<double>();
  EXPECT_NEAR(variance, sd * sd, 0.3 * sd * sd);  // Welch windowing and segment means lose some variance
  for (const char* step : {"equilibrium", "reduction", "dynamics", "tensions"}) {
    EXPECT_GE(doc["timing_s"][step].get<double>(), 0.0) << step;
  }
  EXPECT_GT(doc["solver"]["steps"].get<long>(), 0);
  // OC4's hull has no viscous damping and the plain S-C no line damping: its
  // slow surge is all but undamped, which the run reports and warns of.
  EXPECT_LT(doc["low_frequency_damping"]["surge"]["damping_ratio"].get<double>(), 1e-3);
  EXPECT_NEAR(doc["low_frequency_damping"]["surge"]["natural_period_s"].get<double>(), 110.0, 5.0);
  EXPECT_NE(result.out.find("\n  warning: all but undamped at the natural period: surge ("), std::string::npos)
      << result.out;
  std::filesystem::remove_all(out);
}

TEST(CliAnalyze, LineDynamicsWritesDynamicTensions) {
  const auto out = spiral::test::scratch_root() / ("spiral-analyze-dyn-" + std::to_string(::getpid()));
  std::filesystem::remove_all(out);
  const auto result =
      run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                 " --case intact-raft-jonswap --duration 60 --line-dynamics --out '" + out.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.out.find("quasi-static vs dynamic"), std::string::npos) << result.out;
  const std::string csv = read_text(out / "time_series.csv");
  for (const char* line : {"L1", "L2", "L3"})
    EXPECT_NE(csv.find(std::string(",tension_") + line + "_N"), std::string::npos) << line;
  const auto doc = nlohmann::json::parse(read_text(out / "summary.json"));
  ASSERT_EQ(doc["line_dynamics_solver"].size(), 3u);
  EXPECT_GT(doc["line_dynamics_solver"][0]["steps"].get<long>(), 0);
  EXPECT_GT(doc["timing_s"]["line_dynamics"].get<double>(), 0.0);
  bool found = false;
  for (const auto& c : doc["channels"]) {
    if (c["name"] == "tension_L2_N") {
      found = true;
      EXPECT_GT(c["mean"].get<double>(), 5e5) << c.dump();  // ~1.1 MN pretension
    }
  }
  EXPECT_TRUE(found);
  std::filesystem::remove_all(out);
}

// The coupled level end to end: hull + the three FE chains in one system,
// its integrator statistics in the summary and the coupled tensions as
// channels.
TEST(CliAnalyze, CoupledLevelWritesItsSolverAndTensions) {
  const auto out = spiral::test::scratch_root() / ("spiral-coupled-" + std::to_string(::getpid()));
  const auto result = run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                                 " --case intact-raft-jonswap --level coupled --duration 120 --out " + out.string());
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.out.find("coupled: 3 lines"), std::string::npos) << result.out;
  const nlohmann::json j = nlohmann::json::parse(read_text((out / "summary.json").string()));
  EXPECT_EQ(j["level"], "coupled");
  EXPECT_EQ(j["coupled_solver"]["lines"], 3);
  EXPECT_GT(j["coupled_solver"]["steps"].get<long>(), 0);
  // One name per quantity: the coupled run's FE tensions are tension_, the
  // catenary's at the same fairleads qs_tension_ (as in compare).
  int dynamic = 0, quasi_static = 0;
  for (const auto& c : j["channels"]) {
    if (c["name"].get<std::string>().rfind("tension_", 0) == 0) ++dynamic;
    if (c["name"].get<std::string>().rfind("qs_tension_", 0) == 0) ++quasi_static;
  }
  EXPECT_EQ(dynamic, 3);
  EXPECT_EQ(quasi_static, 3);
  std::filesystem::remove_all(out);
}

// The default FPS's coupled level on its 40 m global-analysis mesh, and on
// the lines' own meshes with --detailed-mesh: the summary says which, the
// state count shows it.
TEST(CliAnalyze, TheCoupledLevelRunsOnTheGlobalMeshUnlessAskedForTheDetailedOne) {
  const auto out = spiral::test::scratch_root() / ("spiral-global-mesh-" + std::to_string(::getpid()));
  const std::string run = "analyze " + scenario("deepwater-fps.yaml") +
                          " --case lc5-operating-45deg --level coupled --duration 4 --out " + out.string();
  const auto global = run_spiral(run + "/global");
  ASSERT_EQ(global.exit_code, app::kExitOk) << global.err;
  const auto detailed = run_spiral(run + "/detailed --detailed-mesh");
  ASSERT_EQ(detailed.exit_code, app::kExitOk) << detailed.err;
  const nlohmann::json g = nlohmann::json::parse(read_text((out / "global" / "summary.json").string()));
  const nlohmann::json d = nlohmann::json::parse(read_text((out / "detailed" / "summary.json").string()));
  EXPECT_EQ(g["line_element_length_m"], 40.0);
  EXPECT_TRUE(d["line_element_length_m"].is_null());
  EXPECT_NE(global.out.find("global-analysis mesh"), std::string::npos) << global.out;
  EXPECT_EQ(detailed.out.find("global-analysis mesh"), std::string::npos) << detailed.out;
  EXPECT_LT(g["coupled_solver"]["states"].get<long>() * 5, d["coupled_solver"]["states"].get<long>());
  std::filesystem::remove_all(out);
}

// `spiral compare`: the four levels on one realization, a table on the
// terminal and comparison.json with the keys the issue names.
TEST(CliCompare, FourLevelsSideBySide) {
  const auto out = spiral::test::scratch_root() / ("spiral-compare-" + std::to_string(::getpid()));
  const auto result =
      run_spiral("compare " + scenario("oc4-semisubmersible.yaml") +
                 " --case intact-raft-jonswap --duration 300 --line-reduction dynamic --out " + out.string());
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.out.find("speed-up vs coupled"), std::string::npos) << result.out;
  const nlohmann::json j = nlohmann::json::parse(read_text((out / "comparison.json").string()));
  EXPECT_EQ(j["sc_enhanced_line_reduction"], "dynamic");
  for (const char* level : {"uncoupled", "sc", "sc-enhanced", "coupled"}) {
    ASSERT_TRUE(j["levels"].contains(level)) << level;
    EXPECT_GT(j["levels"][level]["wall_s"].get<double>(), 0.0) << level;
    EXPECT_GT(j["levels"][level]["max_offset_m"].get<double>(), 0.0) << level;
  }
  EXPECT_GT(j["levels"]["sc"]["speedup_vs_coupled"].get<double>(), 1.0);
  EXPECT_TRUE(j["levels"]["sc"]["channels"]["offset_m"].contains("diff_pct_vs_coupled"));
  EXPECT_TRUE(j["levels"]["coupled"]["channels"].contains("tension_L2_N"));
  // OC4's hull has no viscous damping: its slow surge is damped by the lines
  // alone, which only the enhanced S-C reduces to a damping.
  EXPECT_LT(j["levels"]["sc"]["low_frequency_damping"]["surge"]["damping_ratio"].get<double>(), 1e-3);
  EXPECT_GT(j["levels"]["sc-enhanced"]["low_frequency_damping"]["surge"]["damping_ratio"].get<double>(), 0.02);
  EXPECT_FALSE(j["levels"]["coupled"].contains("low_frequency_damping"));
  EXPECT_NE(result.out.find("surge LF damping [%]"), std::string::npos) << result.out;
  // The trade-off plot beside the table (cairo writes the text as glyphs).
  const std::string svg = read_text((out / "comparison.svg").string());
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_GT(svg.size(), 10000u);
  std::filesystem::remove_all(out);
}

TEST(CliCompare, UnknownCaseIsBadInput) {
  const auto result = run_spiral("compare " + scenario("oc4-semisubmersible.yaml") +
                                 " --case nosuch --duration 100 --out /tmp/spiral-never");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("nosuch"), std::string::npos) << result.err;
}

TEST(CliAnalyze, UnknownLevelIsBadInput) {
  const auto result = run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                                 " --case intact-raft-jonswap --level fully-coupled --out /tmp/spiral-never");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("--level"), std::string::npos) << result.err;
}

TEST(CliAnalyze, AZeroToleranceScaleIsBadInputNamingTheField) {
  const auto result = run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                                 " --case intact-raft-jonswap --level coupled --duration 10 --tolerance-scale 0"
                                 " --out /tmp/spiral-never");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("--tolerance-scale"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("oc4-semisubmersible.yaml"), std::string::npos) << result.err;
}

// A free decay: pulled 5 m in surge, released at 300 s; the summary gives
// the half cycles (OC4's surge period is about 113 s).
TEST(CliAnalyze, AFreeDecayReportsItsHalfCycles) {
  const auto out = spiral::test::scratch_root() / ("spiral-analyze-decay-" + std::to_string(::getpid()));
  std::filesystem::remove_all(out);
  const auto result = run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                                 " --case intact-still-water --level sc --duration 900 --decay 5,0,0,0,0,0"
                                 " --release 300 --out '" +
                                 out.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  const auto doc = nlohmann::json::parse(read_text(out / "summary.json"));
  ASSERT_TRUE(doc.contains("decay")) << doc.dump().substr(0, 400);
  EXPECT_EQ(doc["decay"]["release_s"].get<double>(), 300.0);
  EXPECT_EQ(doc["decay"]["displacement"]["surge_m"].get<double>(), 5.0);
  const auto& cycles = doc["decay"]["half_cycles"]["surge_m"];
  ASSERT_GE(cycles.size(), 5u) << doc["decay"].dump();
  EXPECT_NEAR(cycles[0]["period_s"].get<double>(), 113.0, 3.0);
  EXPECT_FALSE(doc["decay"]["half_cycles"].contains("sway_m")) << "only the displaced degrees of freedom";
  std::filesystem::remove_all(out);
}

TEST(CliAnalyze, AReleaseAfterTheRunIsBadInputNamingTheFlag) {
  const auto result = run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                                 " --case intact-still-water --duration 200 --decay 5,0,0,0,0,0 --release 300"
                                 " --out /tmp/spiral-never");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("--release"), std::string::npos) << result.err;
}

// The enhanced S-C with the lines' dynamic reduction: the summary carries
// its relaxations (OC4: three chains, no risers, so one group of two).
TEST(CliAnalyze, TheDynamicLineReductionWritesItsRelaxations) {
  const auto out = spiral::test::scratch_root() / ("spiral-analyze-reduction-" + std::to_string(::getpid()));
  std::filesystem::remove_all(out);
  const auto result = run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                                 " --case intact-raft-jonswap --level sc-enhanced --line-reduction dynamic"
                                 " --duration 300 --out '" +
                                 out.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  const auto doc = nlohmann::json::parse(read_text(out / "summary.json"));
  ASSERT_TRUE(doc.contains("line_relaxations")) << doc.dump().substr(0, 300);
  ASSERT_EQ(doc["line_relaxations"].size(), 2u);
  EXPECT_GT(doc["line_relaxations"][0]["time_constant_s"].get<double>(), 0.0);
  EXPECT_TRUE(doc.contains("line_damping"));
  const auto bad = run_spiral("analyze " + scenario("oc4-semisubmersible.yaml") +
                              " --case intact-raft-jonswap --level sc-enhanced --line-reduction sometimes"
                              " --out /tmp/spiral-never");
  EXPECT_EQ(bad.exit_code, app::kExitBadInput);
  EXPECT_NE(bad.err.find("--line-reduction"), std::string::npos) << bad.err;
  std::filesystem::remove_all(out);
}

TEST(CliAnalyze, MissingRadiationFileIsBadInputWithFile) {
  const auto dir = spiral::test::scratch_root() / ("spiral-analyze-bad-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string text = read_text(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  const std::string key = "radiation_file: data/hydro/oc4-semi/marin_semi.1";
  text.replace(text.find(key), key.size(), "radiation_file: nonexistent.1");
  const std::string drift = "data/hydro/oc4-semi/marin_semi.12d";
  text.replace(text.find(drift), drift.size(),
               std::string(SPIRAL_SCENARIO_DATA_DIR) + "/hydro/oc4-semi/marin_semi.12d");
  { std::ofstream(dir / "p.yaml") << text; }
  const auto result = run_spiral("analyze '" + (dir / "p.yaml").string() + "' --case intact-raft-jonswap");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("hull.hydrodynamics.radiation_file"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("nonexistent.1"), std::string::npos) << result.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace spiral::test
