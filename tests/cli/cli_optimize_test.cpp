// End-to-end runs of `spiral optimize` and `spiral study pretension` on the
// OC4 semi with a steady current: exit codes, the documents, and the written
// project checked by an independent `spiral equilibrium` / `spiral statics`.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace spiral::test {
namespace {

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

std::string insert_after(std::string text, const std::string& anchor, const std::string& what) {
  const std::size_t at = text.find(anchor);
  EXPECT_NE(at, std::string::npos) << anchor;
  if (at != std::string::npos) text.insert(at + anchor.size(), what);
  return text;
}

/// The OC4 scenario with hull current coefficients, a steady current, two
/// current cases (intact, L1 removed) and an optimization section; the data
/// files referenced by absolute path so that the project can live anywhere.
std::string oc4_optimization_text(const std::string& optimization, bool one_group_per_line = true) {
  const std::string source = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/";
  std::string text = read_text(source + "oc4-semisubmersible.yaml");
  text = replace_all(text, "file: data/hydro/", "file: " + source + "data/hydro/");
  // One payout per line (the scenario's only group holds all three).
  if (one_group_per_line) text = replace_all(text, "  groups:\n    - {name: all, lines: [L1, L2, L3]}\n", "");
  text = insert_after(text, "\nhull:\n",
                      "  current_coefficients:\n"
                      "    headings_deg: [0.0, 90.0, 180.0, 270.0]\n"
                      "    surge: [3000.0, 0.0, -3000.0, 0.0]\n"
                      "    sway: [0.0, 3000.0, 0.0, -3000.0]\n"
                      "    yaw: [0.0, 0.0, 0.0, 0.0]\n");
  text = insert_after(text, "\nenvironments:\n",
                      "  - name: steady-current\n"
                      "    current: {heading_deg: 0.0, profile: [[0.0, 0.5], [-200.0, 0.5]]}\n");
  text = insert_after(text, "\nload_cases:\n",
                      "  - {name: current, environment: steady-current}\n"
                      "  - {name: current-damaged-L1, environment: steady-current, damaged_line: L1, condition: "
                      "survival}\n");
  return text + "\noptimization:\n" + optimization;
}

/// A folder of its own per test, holding the project (the optimized file is written beside it).
std::filesystem::path fresh_folder(const std::string& name) { return fresh_temp_folder("spiral-optimize-" + name); }

std::filesystem::path write_project(const std::filesystem::path& dir, const std::string& text) {
  const auto file = dir / "oc4.yaml";
  std::ofstream(file) << text;
  return file;
}

TEST(CliOptimize, OptimumHoldsWhenTheWrittenProjectIsSolvedAgain) {
  const auto dir = fresh_folder("optimum");
  // A 3-line spread with a line removed drifts tens of metres: an offset
  // limit of 50 % of the depth keeps the damaged case in the problem.
  const auto project = write_project(dir, replace_all(oc4_optimization_text("  objective: min_max_offset\n"
                                                                            "  cases: [current, current-damaged-L1]\n"
                                                                            "  payout_limit_pct: 1.5\n"),
                                                      "max_offset_pct_depth: 10.0", "max_offset_pct_depth: 50.0"));
  const auto run = run_spiral("optimize --json '" + project.string() + "' --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(run.exit_code, app::kExitOk) << run.err << run.out;
  const auto doc = nlohmann::json::parse(run.out);
  EXPECT_EQ(doc["format"], "spiral.optimization");
  EXPECT_EQ(doc["status"], "optimal");
  EXPECT_LE(doc["objective"]["best"].get<double>(), doc["objective"]["start"].get<double>());
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "optimization.json"));
  const auto written = dir / "oc4.optimized.yaml";
  ASSERT_TRUE(std::filesystem::exists(written)) << run.err;
  EXPECT_EQ(read_text(written).rfind("# Written by spiral optimize from", 0), 0u);

  // An independent equilibrium of the written file: every constraint holds
  // (utilization with the code's factor, offset limit 50 % of 200 m) and the
  // offsets are the optimizer's own to the equilibrium's tolerance (the file
  // holds the lengths to 0.1 mm: a few 0.1 mm of offset).
  const double offset_limit_m = 100.0;
  for (const std::string& c : {"current", "current-damaged-L1"}) {
    const auto eq = run_spiral("equilibrium --json '" + written.string() + "' --case " + c);
    ASSERT_EQ(eq.exit_code, app::kExitOk) << eq.err;
    const auto e = nlohmann::json::parse(eq.out);
    const double factor = c == "current" ? 2.0 : 1.43;  // API RP 2SK quasi-static, intact / damaged
    for (const auto& line : e["lines"]) EXPECT_LE(factor * line["utilization"].get<double>(), 1.0 + 1e-6) << c;
    const double offset = e["offset"]["horizontal_m"].get<double>();
    EXPECT_LE(offset, offset_limit_m * (1.0 + 1e-6)) << c;
    const auto& after = doc["scenarios"]["after"];
    const auto it = std::find_if(after.begin(), after.end(), [&](const auto& s) { return s["scenario"] == c; });
    ASSERT_NE(it, after.end());
    EXPECT_NEAR(offset, (*it)["offset_m"].get<double>(), 1e-3) << c;
  }
  std::filesystem::remove_all(dir);
}

TEST(CliOptimize, InfeasibleProblemExitsThreeNamingTheConstraint) {
  const auto dir = fresh_folder("infeasible");
  // One payout for all three lines: hauling in stiffens the spread but cannot
  // hold a 0.5 m/s current within 10 cm (with one payout per line it can:
  // paying out the downstream lines shifts the neutral position upstream).
  std::string text = oc4_optimization_text("  objective: min_max_utilization\n  cases: [current]\n", false);
  text = replace_all(text, "max_offset_pct_depth: 10.0", "max_offset_pct_depth: 0.05");
  const auto project = write_project(dir, text);
  const auto run = run_spiral("optimize '" + project.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(run.exit_code, app::kExitSolverFailure) << run.err;
  EXPECT_NE(run.err.find("no feasible pretension: current: offset / offset limit"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "oc4.optimized.yaml"));
  std::filesystem::remove_all(dir);
}

TEST(CliOptimize, BadBoundsAreAnInputErrorWithPosition) {
  const auto dir = fresh_folder("bounds");
  const auto project = write_project(dir, oc4_optimization_text("  bounds: [{group: L1, min: 3.0, max: -3.0}]\n"));
  const auto run = run_spiral("optimize '" + project.string() + "'");
  EXPECT_EQ(run.exit_code, app::kExitBadInput);
  EXPECT_NE(run.err.find("oc4.yaml:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("optimization.bounds[0].min: must be below max (-3 m), got 3 m"), std::string::npos)
      << run.err;
  std::filesystem::remove_all(dir);
}

// Target-pretension mode: the written project, solved at rest by `spiral
// statics`, has the target on every line of the group (the solve converges
// to 1e-8; the file keeps 0.1 mm of length, 0.01 % of tension here).
TEST(CliOptimize, TargetPretensionIsReachedInTheWrittenProject) {
  const auto dir = fresh_folder("target");
  const auto project =
      write_project(dir, oc4_optimization_text("  target_pretension: [{group: L2, tension: 1.25e6}]\n"));
  const auto run = run_spiral("optimize --target-pretension --json '" + project.string() + "' --out '" +
                              (dir / "out").string() + "'");
  ASSERT_EQ(run.exit_code, app::kExitOk) << run.err;
  const auto doc = nlohmann::json::parse(run.out);
  ASSERT_EQ(doc["lines"].size(), 1u);
  EXPECT_LT(doc["lines"][0]["payout_m"].get<double>(), 0.0);  // above the OC4 pretension: haul in
  const auto statics = run_spiral("statics --json '" + (dir / "oc4.pretensioned.yaml").string() + "'");
  ASSERT_EQ(statics.exit_code, app::kExitOk) << statics.err;
  const auto s = nlohmann::json::parse(statics.out);
  EXPECT_NEAR(s["lines"][1]["fairlead_tension_N"].get<double>(), 1.25e6, 1e-3 * 1.25e6);
  std::filesystem::remove_all(dir);
}

TEST(CliStudy, PretensionSweepMarksTheFeasibleBand) {
  const auto dir = fresh_folder("study");
  const auto project = write_project(dir, oc4_optimization_text("  cases: [current]\n"));
  const auto run = run_spiral("study pretension --json --points 9 --with-optimum '" + project.string() + "' --out '" +
                              (dir / "out").string() + "'");
  ASSERT_EQ(run.exit_code, app::kExitOk) << run.err;
  const auto doc = nlohmann::json::parse(run.out);
  EXPECT_EQ(doc["format"], "spiral.pretension_study");
  ASSERT_EQ(doc["sweeps"].size(), 1u);
  const auto& points = doc["sweeps"][0]["points"];
  ASSERT_EQ(points.size(), 9u);
  // Hauling in (negative payout) raises the pretension and lowers the offset.
  EXPECT_GT(points[0]["pretension_N"].get<double>(), points[8]["pretension_N"].get<double>());
  EXPECT_LT(points[0]["max_offset_m"].get<double>(), points[8]["max_offset_m"].get<double>());
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "pretension_study.csv"));
  // The optimizer's point on it: one payout per line (three groups).
  ASSERT_TRUE(doc.contains("optimum")) << run.out;
  EXPECT_EQ(doc["optimum"]["payouts_m"].size(), 3u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace spiral::test

namespace spiral::test {
namespace {

TEST(CliReportOptimization, WritesTheOptimizationReport) {
  const auto dir = fresh_folder("report");
  const auto project = write_project(dir, oc4_optimization_text("  objective: min_max_offset\n  cases: [current]\n"));
  const auto run =
      run_spiral("report --stage optimization '" + project.string() + "' --out '" + (dir / "report").string() + "'");
  ASSERT_EQ(run.exit_code, app::kExitOk) << run.err << run.out;
  EXPECT_NE(run.out.find("optimization stage report"), std::string::npos) << run.out;
  for (const char* file :
       {"report.pdf", "index.html", "tables/payouts.csv", "tables/scenarios.csv", "figures/optimization-plan.svg",
        "figures/optimization-history.svg", "figures/study-all.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir / "report" / file)) << file;
  std::filesystem::remove_all(dir);
}

// With a run folder the optimization and the study are tasks of its results
// store: a second report takes both from it and writes the same tables.
TEST(CliReportOptimization, ASecondReportTakesBothTasksFromTheStore) {
  const auto dir = fresh_folder("report-store");
  const auto project = write_project(dir, oc4_optimization_text("  objective: min_max_offset\n  cases: [current]\n"));
  const std::string command = "report --stage optimization '" + project.string() + "' --run '" +
                              (dir / "run").string() + "' --out '" + (dir / "report").string();
  const auto first = run_spiral(command + "1'");
  ASSERT_EQ(first.exit_code, app::kExitOk) << first.err << first.out;
  EXPECT_NE(first.out.find("(0 of the 2 tasks reused)"), std::string::npos) << first.out;
  const auto second = run_spiral(command + "2'");
  ASSERT_EQ(second.exit_code, app::kExitOk) << second.err << second.out;
  EXPECT_NE(second.out.find("(2 of the 2 tasks reused)"), std::string::npos) << second.out;
  for (const char* table : {"tables/payouts.csv", "tables/scenarios.csv"})
    EXPECT_EQ(read_text(dir / "report1" / table), read_text(dir / "report2" / table)) << table;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace spiral::test
