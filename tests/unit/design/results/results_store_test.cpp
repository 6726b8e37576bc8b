// The results store: a task row written in one transaction reads back as it
// was; the schema version is checked; --fresh starts over; the summary
// counts per stage.
#include "design/results/results_store.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "design/results/output_error.hpp"
#include "support/temp_folder.hpp"

namespace spiral::design {
namespace {

std::filesystem::path temp_folder(const std::string& name) { return test::fresh_temp_folder("spiral-store-" + name); }

TaskResult sample_task(const std::string& case_name, TaskStatus status) {
  TaskResult t;
  t.identity = {"0123456789abcdef", "storm", case_name, "sc-enhanced", 1, "duration_s=10800"};
  t.stage = "intermediate";
  t.iteration = 2;
  t.status = status;
  t.wall_s = 1.5;
  if (status == TaskStatus::failed) {
    t.error = "IDA failed at t = 12 s";
  } else {
    t.record = {1, 2, 3, 255};
    t.channels.push_back({"surge", "m", 10.0, 2.0, 4.0, 17.0, 18.5, std::nullopt});
    t.checks.push_back({"dynamic tension", "L1", "MPM tension·SF/MBL", 0.8, true});
  }
  return t;
}

TEST(TaskKey, DependsOnEveryIdentityField) {
  const TaskIdentity base{"h", "storm", "lc1", "sc-enhanced", 1, "x"};
  const std::string key = task_key(base);
  EXPECT_EQ(key.size(), 16u);
  EXPECT_EQ(task_key(base), key);
  for (int field = 0; field < 6; ++field) {
    TaskIdentity other = base;
    switch (field) {
      case 0:
        other.model_hash = "g";
        break;
      case 1:
        other.kind = "static-case";
        break;
      case 2:
        other.case_name = "lc2";
        break;
      case 3:
        other.level = "coupled";
        break;
      case 4:
        other.seed = 2;
        break;
      case 5:
        other.options = "y";
        break;
    }
    EXPECT_NE(task_key(other), key) << field;
  }
  // Fields are kept apart: moving a character from one to the next changes the key.
  EXPECT_NE(task_key({"h", "ab", "c", "", 0, ""}), task_key({"h", "a", "bc", "", 0, ""}));
}

TEST(ResultsStore, TaskRowsRoundTripAndSurviveReopening) {
  const auto dir = temp_folder("roundtrip");
  const TaskResult done = sample_task("lc1", TaskStatus::done);
  const TaskResult failed = sample_task("lc2", TaskStatus::failed);
  {
    ResultsStore store(results_store_file(dir), false);
    const int run = store.begin_run("p.yaml", "0123456789abcdef", 2, "test");
    store.put(done);
    store.put(failed);
    store.put_iteration(run, {1, "preliminary", "0123456789abcdef", "p.yaml", "{}", "the project as given"});
    store.put_stage(run, {"intermediate", 2, "0123456789abcdef", false, "lc1: tension 1.2", 1, 1, 0, 3.0});
    store.finish_run(run, "fail");
  }
  ResultsStore store(results_store_file(dir), false);
  const auto a = store.find(task_key(done.identity));
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->status, TaskStatus::done);
  EXPECT_EQ(a->record, done.record);
  EXPECT_DOUBLE_EQ(a->wall_s, 1.5);
  const auto b = store.find(task_key(failed.identity));
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->status, TaskStatus::failed);
  EXPECT_EQ(b->error, "IDA failed at t = 12 s");
  EXPECT_TRUE(b->record.empty());
  EXPECT_FALSE(store.find("ffffffffffffffff").has_value());

  const StoreSummary s = store.summary();
  EXPECT_EQ(s.schema_version, kResultsStoreSchemaVersion);
  EXPECT_EQ(s.runs, 1);
  EXPECT_EQ(s.tasks_done, 1);
  EXPECT_EQ(s.tasks_failed, 1);
  ASSERT_EQ(s.stages.size(), 1u);
  EXPECT_EQ(s.stages[0].stage, "intermediate");
  EXPECT_EQ(s.last_run_outcome, "fail");
  ASSERT_EQ(s.last_run.size(), 1u);
  EXPECT_EQ(s.last_run[0].governing, "lc1: tension 1.2");
  ASSERT_EQ(s.iterations.size(), 1u);
  ASSERT_EQ(s.failures.size(), 1u);
  EXPECT_EQ(s.failures[0].second, "IDA failed at t = 12 s");

  // The queryable rows are plain SQL (docs/results-store.md).
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(results_store_file(dir).c_str(), &db), SQLITE_OK);
  sqlite3_stmt* q = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db,
                               "SELECT c.mean, c.mpm_max, c.mpm_min FROM channel_statistics c JOIN tasks t ON "
                               "t.key = c.task_key WHERE t.case_name = 'lc1' AND c.channel = 'surge'",
                               -1, &q, nullptr),
            SQLITE_OK);
  ASSERT_EQ(sqlite3_step(q), SQLITE_ROW);
  EXPECT_DOUBLE_EQ(sqlite3_column_double(q, 0), 10.0);
  EXPECT_DOUBLE_EQ(sqlite3_column_double(q, 1), 18.5);
  EXPECT_EQ(sqlite3_column_type(q, 2), SQLITE_NULL);
  sqlite3_finalize(q);
  sqlite3_close(db);
}

TEST(ResultsStore, ReplacingATaskKeepsOneRow) {
  const auto dir = temp_folder("replace");
  ResultsStore store(results_store_file(dir), false);
  TaskResult t = sample_task("lc1", TaskStatus::failed);
  store.put(t);
  t = sample_task("lc1", TaskStatus::done);
  store.put(t);
  EXPECT_EQ(store.summary().tasks_done, 1);
  EXPECT_EQ(store.summary().tasks_failed, 0);
}

TEST(ResultsStore, FreshStartsOver) {
  const auto dir = temp_folder("fresh");
  { ResultsStore(results_store_file(dir), false).put(sample_task("lc1", TaskStatus::done)); }
  ResultsStore store(results_store_file(dir), true);
  EXPECT_EQ(store.summary().tasks_done, 0);
}

TEST(ResultsStore, AnotherSchemaVersionIsRefusedWithTheFileAndBothVersions) {
  const auto dir = temp_folder("version");
  { ResultsStore(results_store_file(dir), false).put(sample_task("lc1", TaskStatus::done)); }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(results_store_file(dir).c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "UPDATE meta SET value = '99' WHERE key = 'schema_version'", nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  try {
    ResultsStore store(results_store_file(dir), false);
    FAIL() << "a store of schema 99 was opened";
  } catch (const OutputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(results_store_file(dir).string()), std::string::npos) << message;
    EXPECT_NE(message.find("schema version 99"), std::string::npos) << message;
    EXPECT_NE(message.find("--fresh"), std::string::npos) << message;
  }
  // The refused store is left as it was: --fresh replaces it.
  ResultsStore fresh(results_store_file(dir), true);
  EXPECT_EQ(fresh.summary().tasks_done, 0);
}

TEST(ResultsStore, NoStoreInAFolderIsAClearError) {
  const auto dir = temp_folder("none");
  try {
    open_existing_store(dir);
    FAIL();
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("no results store"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spiral::design
