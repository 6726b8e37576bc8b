// WorkerPool: every task runs once whatever the thread count, the lowest
// failing task's exception comes back, and a pool grown between runs runs
// its new workers (the coupled level takes the cores another run frees).
#include "engine/common/worker_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace spiral::engine {
namespace {

TEST(WorkerPool, EveryTaskRunsOnceAndTheLowestFailureIsRethrown) {
  WorkerPool pool(2);
  std::vector<int> runs(1000, 0);
  pool.run(1000, [&](int i) { ++runs[static_cast<std::size_t>(i)]; });
  for (int r : runs) EXPECT_EQ(r, 1);
  try {
    pool.run(10, [](int i) {
      if (i == 3 || i == 7) throw std::runtime_error("task " + std::to_string(i));
    });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 3");
  }
}

/// Whether `count` tasks of one run were all running at the same time: each
/// waits (up to 10 s) until all have started. With fewer threads than tasks
/// the first ones time out.
bool all_ran_at_once(WorkerPool& pool, int count) {
  std::atomic<int> started{0};
  std::atomic<bool> together{true};
  pool.run(count, [&](int) {
    ++started;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (started.load() < count) {
      if (std::chrono::steady_clock::now() > deadline) {
        together = false;
        return;
      }
      std::this_thread::yield();
    }
  });
  return together;
}

TEST(WorkerPool, AGrownPoolRunsItsNewWorkers) {
  WorkerPool pool(2);
  EXPECT_TRUE(all_ran_at_once(pool, 2));  // a job done before: the new workers wait for the next
  pool.grow_to(3);
  EXPECT_EQ(pool.threads(), 3);
  EXPECT_TRUE(all_ran_at_once(pool, 3));
  pool.grow_to(2);  // never shrinks
  EXPECT_EQ(pool.threads(), 3);
  std::vector<int> runs(500, 0);
  pool.run(500, [&](int i) { ++runs[static_cast<std::size_t>(i)]; });
  for (int r : runs) EXPECT_EQ(r, 1);
}

}  // namespace
}  // namespace spiral::engine
