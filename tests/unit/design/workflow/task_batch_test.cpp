// A batch runs only what the store lacks, stores a solver failure as a
// failed task with its message (and does not repeat it), and rethrows
// anything else after storing every task that finished.
#include "design/workflow/task_batch.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>
#include <vector>

#include "engine/common/solver_error.hpp"
#include "support/temp_folder.hpp"

namespace spiral::design {
namespace {

std::filesystem::path store_path(const std::string& name) {
  const auto dir = spiral::test::scratch_root() / ("spiral-batch-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return results_store_file(dir);
}

StaticCaseResult named(const std::string& name) {
  StaticCaseResult r;
  r.case_name = name;
  r.offset(0) = 1.0 / 3.0;
  return r;
}

TaskIdentity id(const std::string& case_name) { return {"hash", "static-case", case_name, "", 0, ""}; }

TEST(TaskBatch, RunsWhatIsMissingStoresFailuresAndReusesBoth) {
  ResultsStore store(store_path("reuse"), false);
  std::atomic<int> computed{0};
  const auto fill = [&](TaskBatch& batch) {
    for (const std::string name : {"a", "b", "c"}) {
      batch.add<StaticCaseResult>(id(name), [&computed, name] {
        ++computed;
        if (name == "b") throw engine::SolverError("equilibrium of b did not converge");
        return named(name);
      });
    }
  };
  TaskBatch first("preliminary", 1);
  fill(first);
  first.run(&store, 2);
  EXPECT_EQ(computed.load(), 3);
  EXPECT_EQ(first.done(), 2);
  EXPECT_EQ(first.failed(), 1);
  EXPECT_EQ(first.reused(), 0);
  ASSERT_NE(first.value<StaticCaseResult>(0), nullptr);
  EXPECT_EQ(first.value<StaticCaseResult>(0)->case_name, "a");
  EXPECT_EQ(first.value<StaticCaseResult>(1), nullptr);
  EXPECT_EQ(*first.error(1), "equilibrium of b did not converge");

  TaskBatch second("intermediate", 1);
  fill(second);
  int progress_calls = 0;
  second.run(&store, 1, [&](const BatchProgress& p) {
    ++progress_calls;
    EXPECT_TRUE(p.last_reused);
  });
  EXPECT_EQ(computed.load(), 3) << "nothing is computed again";
  EXPECT_EQ(progress_calls, 3);
  EXPECT_EQ(second.reused(), 3);
  EXPECT_EQ(second.value<StaticCaseResult>(2)->offset(0), 1.0 / 3.0);
  EXPECT_EQ(*second.error(1), "equilibrium of b did not converge");
}

TEST(TaskBatch, OtherErrorsAreRethrownAfterTheFinishedTasksAreStored) {
  ResultsStore store(store_path("rethrow"), false);
  TaskBatch batch("preliminary", 1);
  batch.add<StaticCaseResult>(id("ok"), [] { return named("ok"); });
  batch.add<StaticCaseResult>(id("bad"), []() -> StaticCaseResult { throw std::invalid_argument("bad input"); });
  EXPECT_THROW(batch.run(&store, 1), std::invalid_argument);
  EXPECT_TRUE(store.find(task_key(id("ok"))).has_value());
  EXPECT_FALSE(store.find(task_key(id("bad"))).has_value());
}

TEST(TaskBatch, HeartbeatsNameTheTaskRunningLongest) {
  ResultsStore store(store_path("heartbeat"), false);
  TaskBatch batch("advanced", 1);
  batch.set_heartbeat(0.05);
  batch.add<StaticCaseResult>(id("slow"), [] {
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    return named("slow");
  });
  std::vector<BatchProgress> calls;
  batch.run(&store, 1, [&](const BatchProgress& p) { calls.push_back(p); });
  ASSERT_GE(calls.size(), 2u);
  EXPECT_TRUE(calls.front().heartbeat);
  EXPECT_EQ(calls.front().slowest_running, "static-case slow");
  EXPECT_GT(calls.front().slowest_running_s, 0.0);
  EXPECT_FALSE(calls.back().heartbeat);
  EXPECT_EQ(calls.back().finished, 1);
  EXPECT_EQ(calls.back().slowest_running, "");
}

}  // namespace
}  // namespace spiral::design
