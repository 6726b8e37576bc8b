// The spiral on OC4 (three chains, 200 m; the advanced stage's coupled runs
// shortened to 60 s): every stage from tasks in one store, a second run
// taken wholly from the store with the same verdicts, the job count not
// changing a stored number, and the feedback iteration on a variant built to
// fail its offset limit.
#include "design/workflow/spiral_run.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "design/project/input_error.hpp"
#include "design/results/results_store.hpp"
#include "support/temp_folder.hpp"

namespace spiral::design {
namespace {

std::string oc4_text() {
  std::ifstream in(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  std::size_t at = 0;
  bool any = false;
  while ((at = text.find(from, at)) != std::string::npos) {
    text.replace(at, from.size(), to);
    at += to.size();
    any = true;
  }
  EXPECT_TRUE(any) << from;
  return text;
}

/// The OC4 scenario in a temporary folder, its data files by absolute path.
std::filesystem::path oc4_variant(const std::string& name, const std::string& from = {}, const std::string& to = {}) {
  const auto dir = spiral::test::scratch_root() / ("spiral-run-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::string text = replaced(oc4_text(), "data/hydro/", std::string(SPIRAL_SOURCE_DIR) + "/scenarios/data/hydro/");
  text = replaced(text, "  - {name: advanced}", "  - {name: advanced, duration: 60}");
  if (!from.empty()) text = replaced(text, from, to);
  std::ofstream(dir / "oc4.yaml") << text;
  return dir / "oc4.yaml";
}

/// The stored numbers: every channel statistic and every check, by task key
/// (the records also hold wall-clock times, which no two runs share).
std::vector<std::string> stored_numbers(const std::filesystem::path& store) {
  std::vector<std::string> rows;
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(store.c_str(), &db), SQLITE_OK);
  for (const char* sql :
       {"SELECT task_key, channel, unit, mean, std_dev, minimum, maximum, mpm_max, mpm_min FROM channel_statistics "
        "ORDER BY task_key, channel",
        "SELECT task_key, seq, check_name, item, criterion, utilization, pass FROM checks ORDER BY task_key, seq",
        "SELECT key, kind, case_name, status, error FROM tasks ORDER BY key"}) {
    sqlite3_stmt* q = nullptr;
    EXPECT_EQ(sqlite3_prepare_v2(db, sql, -1, &q, nullptr), SQLITE_OK);
    while (sqlite3_step(q) == SQLITE_ROW) {
      std::string row;
      for (int c = 0; c < sqlite3_column_count(q); ++c) {
        // Doubles as their bits: equal means bitwise equal.
        if (sqlite3_column_type(q, c) == SQLITE_FLOAT) {
          const double v = sqlite3_column_double(q, c);
          std::uint64_t bits = 0;
          std::memcpy(&bits, &v, sizeof bits);
          row += std::to_string(bits) + "|";
        } else {
          const auto* t = sqlite3_column_text(q, c);
          row += (t ? reinterpret_cast<const char*>(t) : "null") + std::string("|");
        }
      }
      rows.push_back(row);
    }
    sqlite3_finalize(q);
  }
  sqlite3_close(db);
  return rows;
}

/// Every done task's record by key.
std::map<std::string, std::vector<unsigned char>> records(const std::filesystem::path& store) {
  std::map<std::string, std::vector<unsigned char>> out;
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(store.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* q = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(db, "SELECT key, record FROM tasks WHERE status = 'done'", -1, &q, nullptr), SQLITE_OK);
  while (sqlite3_step(q) == SQLITE_ROW) {
    const auto* p = static_cast<const unsigned char*>(sqlite3_column_blob(q, 1));
    out[reinterpret_cast<const char*>(sqlite3_column_text(q, 0))] =
        std::vector<unsigned char>(p, p + sqlite3_column_bytes(q, 1));
  }
  sqlite3_finalize(q);
  sqlite3_close(db);
  return out;
}

TEST(SpiralRun, EveryStageFromOneStoreThenResumedWhole) {
  const auto project = oc4_variant("stages");
  SpiralRunOptions options;
  options.out_folder = project.parent_path() / "out";
  options.jobs = 2;
  std::vector<std::string> seen;
  const SpiralRunResult first = run_spiral(project, options, [&](const StageRun& s) { seen.push_back(s.stage); });
  ASSERT_TRUE(first.completed);
  EXPECT_TRUE(first.pass);
  EXPECT_FALSE(first.solver_failures);
  EXPECT_EQ(seen, (std::vector<std::string>{"preliminary", "intermediate", "advanced"}));
  ASSERT_EQ(first.stages.size(), 3u);
  const StageRun& preliminary = first.stages[0];
  const StageRun& intermediate = first.stages[1];
  const StageRun& advanced = first.stages[2];
  ASSERT_TRUE(preliminary.preliminary && intermediate.intermediate && advanced.advanced);
  // Preliminary: overview, still water, 2 load cases, the governing case's storm.
  EXPECT_EQ(preliminary.tasks, 5);
  EXPECT_EQ(preliminary.tasks_reused, 0);
  // Intermediate: the same static tasks and that storm from the store, one new storm.
  EXPECT_EQ(intermediate.tasks, 6);
  EXPECT_EQ(intermediate.tasks_reused, 5);
  EXPECT_EQ(intermediate.intermediate->ranked.size(), 2u);
  EXPECT_EQ(advanced.advanced->cases.size(), 2u);  // both cases are in the top 3
  EXPECT_DOUBLE_EQ(advanced.advanced->duration_s, 60.0);
  // The preliminary storm is the intermediate storm of the same case, reason aside.
  const StageDynamics& storm = *preliminary.preliminary->dynamics;
  for (const RankedCase& c : intermediate.intermediate->ranked) {
    if (c.storm.case_name != storm.case_name) continue;
    EXPECT_EQ(c.storm.channels[0].values, storm.channels[0].values);
    EXPECT_NE(c.storm.selection, storm.selection);
  }
  const auto stored = records(results_store_file(options.out_folder));
  EXPECT_EQ(stored.size(), 8u);
  const auto numbers = stored_numbers(results_store_file(options.out_folder));

  const SpiralRunResult second = run_spiral(project, options);
  ASSERT_EQ(second.stages.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(second.stages[i].tasks_reused, second.stages[i].tasks) << second.stages[i].stage;
    EXPECT_EQ(second.stages[i].pass, first.stages[i].pass);
    EXPECT_EQ(second.stages[i].governing, first.stages[i].governing);
  }
  EXPECT_EQ(second.stages[2].advanced->cases[0].lines[0].mpm_N, first.stages[2].advanced->cases[0].lines[0].mpm_N);
  EXPECT_EQ(records(results_store_file(options.out_folder)), stored);

  // --fresh computes everything again, to the same numbers.
  options.fresh = true;
  const SpiralRunResult fresh = run_spiral(project, options);
  EXPECT_EQ(fresh.stages[0].tasks_reused, 0);
  EXPECT_EQ(stored_numbers(results_store_file(options.out_folder)), numbers);
}

TEST(SpiralRun, JobCountDoesNotChangeAStoredNumber) {
  const auto project = oc4_variant("jobs");
  SpiralRunOptions one;
  one.out_folder = project.parent_path() / "one";
  one.jobs = 1;
  one.until = "intermediate";
  SpiralRunOptions two = one;
  two.out_folder = project.parent_path() / "two";
  two.jobs = 2;
  run_spiral(project, one);
  run_spiral(project, two);
  EXPECT_EQ(records(results_store_file(one.out_folder)).size(), 6u);
  const auto a = stored_numbers(results_store_file(one.out_folder));
  EXPECT_GT(a.size(), 20u);
  EXPECT_EQ(a, stored_numbers(results_store_file(two.out_folder)));
}

TEST(SpiralRun, ACommentEditKeepsTheStoreAValueEditDoesNot) {
  const auto project = oc4_variant("hash");
  SpiralRunOptions options;
  options.out_folder = project.parent_path() / "out";
  options.until = "preliminary";
  run_spiral(project, options);
  std::string text;
  {
    std::ifstream in(project);
    std::stringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  std::ofstream(project) << "# a comment the results do not depend on\n" << text;
  EXPECT_EQ(run_spiral(project, options).stages[0].tasks_reused, 5);
  std::ofstream(project) << replaced(text, "hs: 8.5 ", "hs: 8.0 ");
  const SpiralRunResult changed = run_spiral(project, options);
  EXPECT_EQ(changed.stages[0].tasks_reused, 0);
}

TEST(SpiralRun, FeedbackOptimizesTheFailingOffsetAndTheNextIterationPasses) {
  // An offset limit of 0.5 % of depth (1 m) that the intact storm case's
  // static offset (1.18 m) exceeds; hauling the chains in can meet it.
  const auto project = oc4_variant("feedback", "max_offset_pct_depth: 10.0", "max_offset_pct_depth: 0.5");
  SpiralRunOptions options;
  options.out_folder = project.parent_path() / "out";
  options.until = "preliminary";
  const SpiralRunResult r = run_spiral(project, options);
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_FALSE(r.stages[0].pass);
  EXPECT_NE(r.stages[0].governing.find("offset limit"), std::string::npos) << r.stages[0].governing;
  EXPECT_EQ(r.stages[1].iteration, 2);
  EXPECT_TRUE(r.stages[1].pass) << r.stages[1].governing;
  EXPECT_NE(r.stages[1].model_hash, r.stages[0].model_hash);
  ASSERT_EQ(r.feedback.size(), 1u);
  EXPECT_TRUE(r.feedback[0].applied);
  EXPECT_NE(r.feedback[0].reason.find("offset limit"), std::string::npos);
  ASSERT_TRUE(std::filesystem::exists(r.feedback[0].project_file));
  for (const auto& [line, payout] : r.feedback[0].payouts_m) EXPECT_LT(payout, -1.0) << line << " is hauled in";
  EXPECT_TRUE(r.pass);

  const StoreSummary s = open_existing_store(options.out_folder)->summary();
  ASSERT_EQ(s.iterations.size(), 2u);
  EXPECT_NE(s.iterations[1].payouts_json, "{}");
  // Resumed: the optimizer is a stored task too; nothing runs again.
  const SpiralRunResult again = run_spiral(project, options);
  ASSERT_EQ(again.stages.size(), 2u);
  EXPECT_EQ(again.stages[1].tasks_reused, again.stages[1].tasks);
  EXPECT_EQ(again.stages[1].model_hash, r.stages[1].model_hash);
}

TEST(SpiralRun, AProjectNamedWithoutItsFolderIteratesToo) {
  // `spiral run project.yaml` from the project's own folder: the file's
  // parent path is empty, and the feedback iteration must still write and
  // load its project file (it once stopped with "cannot make absolute path").
  const auto project = oc4_variant("bare-name", "max_offset_pct_depth: 10.0", "max_offset_pct_depth: 0.5");
  const std::filesystem::path working = std::filesystem::current_path();
  std::filesystem::current_path(project.parent_path());
  SpiralRunOptions options;
  options.out_folder = project.parent_path() / "out";
  options.until = "preliminary";
  SpiralRunResult r;
  try {
    r = run_spiral(project.filename(), options);
  } catch (...) {
    std::filesystem::current_path(working);
    throw;
  }
  std::filesystem::current_path(working);
  ASSERT_EQ(r.feedback.size(), 1u);
  EXPECT_TRUE(r.feedback[0].applied);
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_TRUE(r.stages[1].pass) << r.stages[1].governing;
}

TEST(SpiralRun, AdvancedRiserTopTensionFailuresAreRiserDesignFindings) {
  // Two critical cases: E2 fails in both on its dynamic range (mean within
  // the limit), P1 in one with its mean already over it; P2 passes, and a
  // riser without a limit is never a finding.
  const auto check = [](std::string riser, double mean_kN, double mpm_kN, std::optional<double> limit_kN) {
    FinalRiserCheck c;
    c.riser = std::move(riser);
    c.mean_N = mean_kN * 1e3;
    c.mpm_N = c.max_N = mpm_kN * 1e3;
    if (limit_kN) c.limit_N = *limit_kN * 1e3;
    c.utilization = limit_kN ? mpm_kN / *limit_kN : 0.0;
    c.pass = c.utilization <= 1.0;
    return c;
  };
  AdvancedStageResults r;
  r.cases.resize(2);
  r.cases[0].case_name = "lc1";
  r.cases[0].risers = {check("E2", 3500.0, 5000.0, 4000.0), check("P2", 2500.0, 3000.0, 4000.0),
                       check("F1", 2500.0, 9000.0, std::nullopt)};
  r.cases[1].case_name = "lc2";
  r.cases[1].risers = {check("E2", 3520.0, 5736.0, 4000.0), check("P1", 4100.0, 4400.0, 4000.0)};
  const std::vector<std::string> f = advanced_riser_findings(r, 2);
  ASSERT_EQ(f.size(), 2u);  // by riser name: E2, P1
  EXPECT_NE(f[0].find("riser E2 exceeds its maximum top tension in the coupled storms of 2 of 2 critical case(s), "
                      "worst 1.434 in lc2 (3-h MPM 5736 kN against 4000 kN)"),
            std::string::npos)
      << f[0];
  EXPECT_NE(f[0].find("its mean (3520 kN) is within the limit, the storm's dynamic range (2216 kN"), std::string::npos)
      << f[0];
  EXPECT_NE(f[0].find("advanced stage, iteration 2"), std::string::npos) << f[0];
  EXPECT_NE(f[1].find("riser P1 exceeds its maximum top tension in the coupled storms of 1 of 2"), std::string::npos)
      << f[1];
  EXPECT_NE(f[1].find("its mean top tension alone exceeds the limit"), std::string::npos) << f[1];
}

TEST(SpiralRun, AnOptimizationTheProjectAsksForRunsOnceOnAPassingDesign) {
  // OC4 passes its preliminary checks as given; stages[].optimize asks for
  // the optimizer anyway (max SOZ margin). One optimization, one more
  // iteration that passes, and no third: the request is met, nothing fails.
  const auto project = oc4_variant("asked", "  - {name: preliminary}", "  - {name: preliminary, optimize: true}");
  SpiralRunOptions options;
  options.out_folder = project.parent_path() / "out";
  options.until = "preliminary";
  const SpiralRunResult r = run_spiral(project, options);
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_TRUE(r.stages[0].pass) << r.stages[0].governing;
  EXPECT_TRUE(r.stages[1].pass) << r.stages[1].governing;
  EXPECT_EQ(r.stages[1].iteration, 2);
  ASSERT_EQ(r.feedback.size(), 1u);
  EXPECT_NE(r.feedback[0].reason.find("the project asks"), std::string::npos) << r.feedback[0].reason;
  EXPECT_TRUE(r.feedback[0].applied);
  ASSERT_TRUE(r.feedback[0].optimization);
  // The optimizer improved what it was asked for.
  EXPECT_LT(r.feedback[0].optimization->objective_best, r.feedback[0].optimization->objective_start);
  for (const std::string& f : r.findings) EXPECT_EQ(f.find("did not bring"), std::string::npos) << f;
  EXPECT_TRUE(r.pass);
}

TEST(SpiralRun, EveryStormOfACaseUsesItsSeed) {
  const auto project = oc4_variant("seed", "{name: intact-raft-jonswap, environment: raft-jonswap}",
                                   "{name: intact-raft-jonswap, environment: raft-jonswap, seed: 3}");
  SpiralRunOptions options;
  options.out_folder = project.parent_path() / "out";
  const SpiralRunResult r = run_spiral(project, options);
  ASSERT_TRUE(r.completed);
  EXPECT_EQ(r.stages[0].preliminary->dynamics->seed, 3u);
  for (const RankedCase& c : r.stages[1].intermediate->ranked)
    EXPECT_EQ(c.storm.seed, c.storm.case_name == "intact-raft-jonswap" ? 3u : 1u) << c.storm.case_name;
  for (const CriticalCaseVerification& v : r.stages[2].advanced->cases)
    EXPECT_EQ(v.comparison.seed, v.case_name == "intact-raft-jonswap" ? 3u : 1u) << v.case_name;
}

// A load case listed twice under two names (as a matrix may list a case the
// project also names) is verified once at the advanced stage: one coupled
// task, and the second case carries the first's results under its own name
// and rank, saying whose they are.
TEST(SpiralRun, ACaseListedTwiceIsVerifiedOnce) {
  const auto project = oc4_variant("twice", "  - {name: intact-raft-jonswap, environment: raft-jonswap}\n",
                                   "  - {name: intact-raft-jonswap, environment: raft-jonswap}\n"
                                   "  - {name: raft-jonswap-again, environment: raft-jonswap}\n");
  SpiralRunOptions options;
  options.out_folder = project.parent_path() / "out";
  const SpiralRunResult r = run_spiral(project, options);
  ASSERT_TRUE(r.completed);
  const AdvancedStageResults& advanced = *r.stages.back().advanced;
  ASSERT_EQ(advanced.cases.size(), 3u);  // every case is in the top 3
  const CriticalCaseVerification* ran = nullptr;
  const CriticalCaseVerification* shared = nullptr;
  for (const CriticalCaseVerification& c : advanced.cases) {
    if (c.case_name == "intact-still-water") {
      EXPECT_TRUE(c.shared_with.empty());
      continue;
    }
    (c.shared_with.empty() ? ran : shared) = &c;
  }
  ASSERT_NE(ran, nullptr);
  ASSERT_NE(shared, nullptr);
  EXPECT_EQ(shared->shared_with, ran->case_name);
  EXPECT_LT(ran->rank, shared->rank);
  EXPECT_DOUBLE_EQ(shared->wall_s, 0.0);
  ASSERT_TRUE(ran->coupled && shared->coupled && shared->sc);
  EXPECT_EQ(shared->coupled->case_name, shared->case_name);
  EXPECT_EQ(shared->comparison.case_name, shared->case_name);
  EXPECT_NE(shared->coupled->selection.find("#" + std::to_string(shared->rank)), std::string::npos);
  ASSERT_EQ(shared->coupled->channels.size(), ran->coupled->channels.size());
  for (std::size_t i = 0; i < ran->coupled->channels.size(); ++i)
    EXPECT_EQ(shared->coupled->channels[i].values, ran->coupled->channels[i].values);
  ASSERT_EQ(shared->lines.size(), ran->lines.size());
  for (std::size_t i = 0; i < ran->lines.size(); ++i) EXPECT_EQ(shared->lines[i].mpm_N, ran->lines[i].mpm_N);
  EXPECT_EQ(shared->pass, ran->pass);
  // The intermediate storms of the two names are the same, bit for bit: the
  // premise of sharing.
  const auto& ranked = r.stages[1].intermediate->ranked;
  const auto storm = [&](const std::string& name) {
    for (const RankedCase& c : ranked)
      if (c.storm.case_name == name) return c.storm.channels[0].values;
    ADD_FAILURE() << name;
    return std::vector<double>{};
  };
  EXPECT_EQ(storm("intact-raft-jonswap"), storm("raft-jonswap-again"));
  // Two coupled verification tasks in the store, not three.
  int verifications = 0;
  for (const std::string& row : stored_numbers(results_store_file(options.out_folder)))
    verifications += row.find("|verification|") != std::string::npos ? 1 : 0;
  EXPECT_EQ(verifications, 2);
}

TEST(SpiralRun, AnUnknownLastStageIsARequestError) {
  const auto project = oc4_variant("until");
  SpiralRunOptions options;
  options.out_folder = project.parent_path() / "out";
  options.until = "final";
  try {
    run_spiral(project, options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown stage 'final'"), std::string::npos) << e.what();
    EXPECT_EQ(e.issues().at(0).path, "until");
  }
  EXPECT_FALSE(std::filesystem::exists(results_store_file(options.out_folder))) << "nothing written for a bad request";
}

}  // namespace
}  // namespace spiral::design
