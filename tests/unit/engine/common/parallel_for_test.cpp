// engine::worker_count gives a loop nested in parallel_for tasks only the
// cores the outer loop leaves free (engine/common/parallel_for.hpp).

#include "engine/common/parallel_for.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <latch>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace spiral::engine {
namespace {

int hardware() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

TEST(WorkerCount, OutsideAnyLoopItIsEveryCoreAtMostOnePerTask) {
  EXPECT_EQ(worker_count(1000), hardware());
  EXPECT_EQ(worker_count(1), 1);
  EXPECT_EQ(worker_count(0), 1);
}

TEST(WorkerCount, InsideALoopThatHoldsTwoThreadsTheNestedLoopGetsTheRest) {
  // Both tasks wait until both run, and until both have asked: two threads
  // are busy when they ask (a thread leaving its loop frees its core).
  std::latch both_running(2), both_asked(2);
  std::vector<int> nested(2, -1);
  parallel_for(2, 2, [&](int i) {
    both_running.arrive_and_wait();
    nested[static_cast<std::size_t>(i)] = worker_count(1000);
    both_asked.arrive_and_wait();
  });
  for (const int n : nested) EXPECT_EQ(n, std::max(1, hardware() - 1));
  EXPECT_EQ(worker_count(1000), hardware());  // released when the loop ends
}

TEST(WorkerCount, ASingleThreadLoopLeavesItsTaskEveryCore) {
  int nested = -1;
  parallel_for(1, 1, [&](int) { nested = worker_count(1000); });
  EXPECT_EQ(nested, hardware());
}

TEST(WorkerCount, ANestedLoopRunsEveryTaskAndRethrowsTheLowestFailure) {
  std::vector<int> done(12, 0);
  parallel_for(3, 2, [&](int i) {
    parallel_for(4, worker_count(4), [&](int k) { done[static_cast<std::size_t>(4 * i + k)] = 1; });
  });
  for (const int d : done) EXPECT_EQ(d, 1);
  try {
    parallel_for(5, 2, [](int i) {
      if (i >= 2) throw std::runtime_error(std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "2");
  }
}

}  // namespace
}  // namespace spiral::engine
