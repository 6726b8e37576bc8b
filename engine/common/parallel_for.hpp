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

namespace detail {
/// Threads of parallel_for loops now running tasks, process-wide.
inline std::atomic<int> busy_workers{0};
/// This thread is one of them.
inline thread_local bool counted_worker = false;
}  // namespace detail

/// Threads to use for `count` tasks: the hardware threads that no other
/// parallel_for worker holds, at most one per task, at least one. A loop
/// nested in a task of a loop that keeps every core busy (a scenario's lines
/// inside the optimizer's scenarios, a storm's lines inside a run's tasks)
/// then runs on its own thread; once the outer loop's queue is empty and its
/// threads finish, the tasks still running spread over the cores they free.
/// Nesting threads regardless oversubscribed the cores and, started per call,
/// cost their creation and fresh stack and heap pages every time (on the
/// optimizer's 69 scenarios: 14 % of the CPU time in the kernel clearing
/// pages; docs/decisions/pretension-optimization.md).
inline int worker_count(int count) {
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int elsewhere = detail::busy_workers.load(std::memory_order_relaxed) - (detail::counted_worker ? 1 : 0);
  return std::max(1, std::min(hardware - elsewhere, count));
}

/// Runs task(i) for i in [0, count) on `threads` threads. If tasks throw, the
/// exception of the lowest failing index is rethrown after all have run (the
/// same error for any thread count).
template <class Task>
void parallel_for(int count, int threads, const Task& task) {
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(count, 0)));
  const auto worker = [&] {
    // The calling thread of a nested loop is already counted.
    const bool counted = detail::counted_worker;
    if (!counted) {
      detail::busy_workers.fetch_add(1, std::memory_order_relaxed);
      detail::counted_worker = true;
    }
    for (int i = next++; i < count; i = next++) {
      try {
        task(i);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
      }
    }
    if (!counted) {
      detail::counted_worker = false;
      detail::busy_workers.fetch_sub(1, std::memory_order_relaxed);
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
