// `spiral run` end to end: the stages' reports and the summary, `spiral
// results`, a run killed with SIGKILL that resumes computing exactly the
// unfinished tasks to the numbers of an uninterrupted run, a recorded solver
// failure (exit 3), and bad requests (exit 2, 4).
#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace spiral::test {
namespace {

std::filesystem::path temp_folder(const std::string& name) { return fresh_temp_folder("spiral-cli-run-" + name); }

/// The OC4 scenario with absolute data paths and 60-s coupled runs.
std::filesystem::path oc4_project(const std::filesystem::path& dir) {
  std::string text = read_text(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  const std::string data = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/data/hydro/";
  for (std::size_t at = 0; (at = text.find("data/hydro/", at)) != std::string::npos; at += data.size())
    text.replace(at, 11, data);
  const std::string advanced = "  - {name: advanced}";
  text.replace(text.find(advanced), advanced.size(), "  - {name: advanced, duration: 60}");
  std::ofstream(dir / "oc4.yaml") << text;
  return dir / "oc4.yaml";
}

int count_tasks(const std::filesystem::path& store) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(db);
    return 0;
  }
  sqlite3_busy_timeout(db, 2000);
  sqlite3_stmt* q = nullptr;
  int n = 0;
  if (sqlite3_prepare_v2(db, "SELECT count(*) FROM tasks", -1, &q, nullptr) == SQLITE_OK &&
      sqlite3_step(q) == SQLITE_ROW)
    n = sqlite3_column_int(q, 0);
  sqlite3_finalize(q);
  sqlite3_close(db);
  return n;
}

/// Rows of the queryable tables, doubles as text of their bits (equal rows: equal numbers).
std::vector<std::string> numbers(const std::filesystem::path& store) {
  std::vector<std::string> rows;
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(store.c_str(), &db), SQLITE_OK);
  for (const char* sql :
       {"SELECT task_key, channel, mean, std_dev, minimum, maximum, mpm_max, mpm_min "
        "FROM channel_statistics ORDER BY task_key, channel",
        "SELECT task_key, seq, check_name, item, utilization, pass FROM checks ORDER BY task_key, seq",
        "SELECT key, status, error FROM tasks ORDER BY key"}) {
    sqlite3_stmt* q = nullptr;
    EXPECT_EQ(sqlite3_prepare_v2(db, sql, -1, &q, nullptr), SQLITE_OK);
    while (sqlite3_step(q) == SQLITE_ROW) {
      std::ostringstream row;
      row.precision(17);
      for (int c = 0; c < sqlite3_column_count(q); ++c) {
        if (sqlite3_column_type(q, c) == SQLITE_FLOAT)
          row << sqlite3_column_double(q, c) << '|';
        else if (const auto* t = sqlite3_column_text(q, c))
          row << reinterpret_cast<const char*>(t) << '|';
        else
          row << "null|";
      }
      rows.push_back(row.str());
    }
    sqlite3_finalize(q);
  }
  sqlite3_close(db);
  return rows;
}

TEST(CliRun, Oc4ThroughEveryStageWithReportsAndAStoreThatResults) {
  const auto dir = temp_folder("oc4");
  const auto project = oc4_project(dir);
  const auto out = dir / "out";
  const CommandResult r = run_spiral("run '" + project.string() + "' --out '" + out.string() + "' --jobs 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("spiral of 'OC4-DeepCwind semisubmersible': PASS"), std::string::npos) << r.out;
  for (const char* stage : {"preliminary", "intermediate", "advanced", "summary"})
    EXPECT_TRUE(std::filesystem::exists(out / stage / "report.pdf")) << stage;
  EXPECT_TRUE(std::filesystem::exists(out / "summary" / "tables" / "spiral-stages.csv"));
  // Not a terminal: one plain line per finished task.
  EXPECT_NE(r.err.find("[intermediate storms 2/2]"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);

  const CommandResult summary = run_spiral("results '" + out.string() + "' --json");
  ASSERT_EQ(summary.exit_code, 0) << summary.err;
  const nlohmann::json j = nlohmann::json::parse(summary.out);
  EXPECT_EQ(j["format"], "spiral.results");
  EXPECT_EQ(j["schema_version"], 1);
  EXPECT_EQ(j["tasks"]["done"], 8);
  EXPECT_EQ(j["tasks"]["failed"], 0);
  EXPECT_EQ(j["last_run"]["outcome"], "pass");
  ASSERT_EQ(j["last_run"]["stages"].size(), 3u);
  EXPECT_EQ(j["last_run"]["stages"][2]["stage"], "advanced");

  // Again: everything from the store.
  const CommandResult again = run_spiral("run '" + project.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("advanced stage, iteration 1: PASS (2 tasks, 2 from the store"), std::string::npos)
      << again.err;

  // `spiral report` of a stage reads the same store: nothing is computed
  // again, and the stage's report is written where asked.
  const auto report_dir = dir / "advanced-report";
  const CommandResult report = run_spiral("report '" + project.string() + "' --stage advanced --run '" + out.string() +
                                          "' --out '" + report_dir.string() + "'");
  ASSERT_EQ(report.exit_code, 0) << report.err;
  EXPECT_NE(report.out.find("(2 of the stage's 2 tasks reused)"), std::string::npos) << report.out;
  EXPECT_NE(report.err.find("intermediate stage, iteration 1: PASS (6 tasks, 6 from the store"), std::string::npos)
      << report.err;
  EXPECT_TRUE(std::filesystem::exists(report_dir / "report.pdf"));
  EXPECT_EQ(count_tasks(out / "results.sqlite"), 8);
}

TEST(CliRun, AKilledRunResumesWithExactlyTheUnfinishedTasks) {
  const auto dir = temp_folder("kill");
  const std::string project = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml";
  const auto killed = dir / "killed";
  const auto whole = dir / "whole";
  const std::filesystem::path store = killed / "results.sqlite";
  constexpr int kFinishedBeforeKill = 3;

  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string log = (dir / "killed.log").string();
    freopen(log.c_str(), "w", stdout);
    freopen(log.c_str(), "a", stderr);
    execl(SPIRAL_EXECUTABLE, SPIRAL_EXECUTABLE, "run", project.c_str(), "--out", killed.c_str(), "--until",
          "intermediate", "--jobs", "1", static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (count_tasks(store) < kFinishedBeforeKill && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_EQ(kill(child, SIGKILL), 0);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed";
  const int finished = count_tasks(store);
  ASSERT_GE(finished, kFinishedBeforeKill);

  const CommandResult resumed =
      run_spiral("run '" + project + "' --out '" + killed.string() + "' --until intermediate --jobs 1");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const int total = count_tasks(store);
  // Every task line of the resumed run either came from the store or ran;
  // the ones that ran are exactly those the killed run had not finished.
  int computed = 0;
  std::istringstream lines(resumed.err);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("[") && line.find("(stored)") == std::string::npos &&
        line.find("]; running") == std::string::npos)
      ++computed;  // a finished task's line (not a heartbeat's)
  EXPECT_EQ(computed, total - finished) << resumed.err;

  const CommandResult uninterrupted =
      run_spiral("run '" + project + "' --out '" + whole.string() + "' --until intermediate --jobs 2");
  ASSERT_EQ(uninterrupted.exit_code, 0) << uninterrupted.err;
  EXPECT_EQ(numbers(store), numbers(whole / "results.sqlite"));
}

/// OC4 with an offset limit of 0.5 % of depth, which its storm case exceeds.
std::filesystem::path oc4_project_failing_its_offset_limit(const std::filesystem::path& dir) {
  const auto project = oc4_project(dir);
  std::string text = read_text(project);
  const std::string limit = "max_offset_pct_depth: 10.0";
  text.replace(text.find(limit), limit.size(), "max_offset_pct_depth: 0.5");
  std::ofstream(project) << text;
  return project;
}

// The feedback iteration end to end: OC4 with an offset limit of 0.5 % of
// depth fails in the storm case, the optimizer hauls the chains in, the
// second iteration passes, and the summary report shows both.
TEST(CliRun, TheSummaryReportShowsTheFeedbackIterations) {
  const auto dir = temp_folder("feedback");
  const auto project = oc4_project_failing_its_offset_limit(dir);
  const auto out = dir / "out";
  const CommandResult r = run_spiral("run '" + project.string() + "' --out '" + out.string() + "' --until preliminary");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("preliminary  iteration 2  PASS"), std::string::npos) << r.out;
  const std::string iterations = read_text(out / "summary" / "tables" / "spiral-iterations.csv");
  std::size_t rows = 0;
  for (char c : iterations) rows += c == '\n' ? 1 : 0;
  EXPECT_EQ(rows, 3u) << iterations;  // header + iterations 1 and 2
  const std::string payouts = read_text(out / "summary" / "tables" / "spiral-payouts-2.csv");
  EXPECT_NE(payouts.find("L1"), std::string::npos) << payouts;
  EXPECT_TRUE(std::filesystem::exists(out / "iterations" / "iteration-2.yaml"));
  // The written iteration is a valid project (its data found from the original folder).
  EXPECT_NE(read_text(out / "iterations" / "iteration-2.yaml").find("spiral run iteration 2"), std::string::npos);
  // Each iteration's stage report is kept: the second does not overwrite the first.
  EXPECT_TRUE(std::filesystem::exists(out / "preliminary" / "report.pdf"));
  EXPECT_TRUE(std::filesystem::exists(out / "preliminary-iteration-2" / "report.pdf"));
  EXPECT_NE(r.out.find("preliminary (iteration 2): " + (out / "preliminary-iteration-2").string()), std::string::npos)
      << r.out;
}

// The same feedback on a variation file whose mooring is its base's: the
// iteration is a variation of the variation that writes the mooring with
// the payouts (the shipped matrix scenario is such a file).
TEST(CliRun, AVariationWhoseMooringIsTheBasesIsFedBackToo) {
  const auto dir = temp_folder("feedback-variation");
  oc4_project_failing_its_offset_limit(dir);
  const auto variation = dir / "variation.yaml";
  std::ofstream(variation) << "version: 1\nextends: oc4.yaml\nname: OC4 variation\n";
  const auto out = dir / "out";
  const CommandResult r =
      run_spiral("run '" + variation.string() + "' --out '" + out.string() + "' --until preliminary");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("preliminary  iteration 2  PASS"), std::string::npos) << r.out;
  const std::string iteration = read_text(out / "iterations" / "iteration-2.yaml");
  EXPECT_NE(iteration.find("extends: " + std::filesystem::absolute(variation).string()), std::string::npos)
      << iteration;
  EXPECT_NE(iteration.find("\nmooring:"), std::string::npos) << iteration;
  EXPECT_EQ(iteration.find("\nhull:"), std::string::npos) << iteration;
  EXPECT_NE(read_text(out / "summary" / "tables" / "spiral-payouts-2.csv").find("L1"), std::string::npos);
}

TEST(CliRun, ASolverFailureIsRecordedReportedAndExitsThree) {
  const auto dir = temp_folder("failure");
  const auto project = oc4_project(dir);
  const auto out = dir / "out";
  const CommandResult r =
      run_spiral("run '" + project.string() + "' --out '" + out.string() + "' --coupled-max-steps 1");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  // The stage still finished and wrote its report; the summary names the failure.
  EXPECT_TRUE(std::filesystem::exists(out / "advanced" / "report.pdf"));
  EXPECT_NE(read_text(out / "summary" / "tables" / "spiral-failures.csv").find("verification"), std::string::npos);
  const CommandResult summary = run_spiral("results '" + out.string() + "'");
  EXPECT_NE(summary.out.find("failed: verification"), std::string::npos) << summary.out;
}

TEST(CliRun, ThreadsAndMpiRanksStoreTheSameNumbers) {
#ifndef SPIRAL_MPIEXEC
  GTEST_SKIP() << "spiral is built without MPI";
#else
  const auto dir = temp_folder("mpi");
  const auto project = oc4_project(dir);
  const std::string common = "run '" + project.string() + "' --until intermediate --out '";
  const CommandResult one = run_spiral(common + (dir / "one").string() + "' --jobs 1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const CommandResult two = run_spiral(common + (dir / "two").string() + "' --jobs 2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  // Three ranks on this machine's cores; CI runs as root on loopback.
  const std::string command = std::string("'") + SPIRAL_MPIEXEC + "' --oversubscribe --allow-run-as-root -n 3 '" +
                              SPIRAL_EXECUTABLE + "' " + common + (dir / "mpi").string() + "' > '" +
                              (dir / "mpi.log").string() + "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(dir / "mpi.log");
  const std::string log = read_text(dir / "mpi.log");
  EXPECT_NE(log.find("spiral run on 3 MPI ranks"), std::string::npos) << log;
  EXPECT_NE(log.find("intermediate stage, iteration 1: PASS"), std::string::npos) << log;
  const auto numbers_one = numbers(dir / "one" / "results.sqlite");
  EXPECT_GT(numbers_one.size(), 20u);
  EXPECT_EQ(numbers(dir / "two" / "results.sqlite"), numbers_one);
  EXPECT_EQ(numbers(dir / "mpi" / "results.sqlite"), numbers_one);
  // An MPI run resumes a threaded one: everything from the store.
  const std::string resume = std::string("'") + SPIRAL_MPIEXEC + "' --oversubscribe --allow-run-as-root -n 2 '" +
                             SPIRAL_EXECUTABLE + "' " + common + (dir / "one").string() + "' > '" +
                             (dir / "resume.log").string() + "' 2>&1";
  ASSERT_EQ(std::system(resume.c_str()), 0) << read_text(dir / "resume.log");
  EXPECT_NE(read_text(dir / "resume.log").find("(6 tasks, 6 from the store"), std::string::npos)
      << read_text(dir / "resume.log");
#endif
}

TEST(CliRun, BadRequestsSayWhichFlag) {
  const auto dir = temp_folder("bad");
  const auto project = oc4_project(dir);
  const CommandResult until =
      run_spiral("run '" + project.string() + "' --out '" + (dir / "o").string() + "' --until final");
  EXPECT_EQ(until.exit_code, 2);
  EXPECT_NE(until.err.find("--until"), std::string::npos) << until.err;
  EXPECT_NE(until.err.find("unknown stage 'final'"), std::string::npos) << until.err;
  const CommandResult both = run_spiral("run '" + project.string() + "' --fresh --resume");
  EXPECT_EQ(both.exit_code, 2);
  const CommandResult none = run_spiral("results '" + (dir / "nothing").string() + "'");
  EXPECT_EQ(none.exit_code, 4);
  EXPECT_NE(none.err.find("no results store"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace spiral::test
