#pragma once
// Runs independent tasks on a few threads (an atomic work queue): load cases,
// lines, SOZ directions. Each task writes only its own result slot, so the
// outcome does not depend on the thread count or the scheduling.

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace spiral::engine {

/// Threads to use for `count` tasks: all hardware threads, at most one per task.
inline int worker_count(int count) {
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, std::min(hardware, count));
}

/// Runs task(i) for i in [0, count) on `threads` threads. If tasks throw, the
/// exception of the lowest failing index is rethrown after all have run (the
/// same error for any thread count).
template <class Task>
void parallel_for(int count, int threads, const Task& task) {
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(count, 0)));
  const auto worker = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        task(i);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min(threads, count); ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace spiral::engine
