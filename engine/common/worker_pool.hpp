#pragma once
// A fixed set of worker threads for fine-grained parallel loops that run
// thousands of times per second — the coupled hull + lines system evaluates
// its lines in parallel at every residual and Newton solve (≈ 0.1–1 ms of
// work each), where starting threads per loop (parallel_for) would cost as
// much as the work. Same contract as parallel_for: task(i) for i in
// [0, count), each task writes only its own slots, and the exception of the
// lowest failing index is rethrown after all tasks ran.

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace spiral::engine {

class WorkerPool {
 public:
  /// `threads` >= 1 threads in all, the caller's included.
  explicit WorkerPool(int threads) { grow_to(threads); }
  ~WorkerPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    start_.notify_all();
    for (std::thread& t : workers_) t.join();
  }
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  /// Adds workers until there are `threads` in all (never fewer): a long
  /// run started beside other work takes the cores that work frees. Call
  /// from the owning thread between runs.
  void grow_to(int threads) {
    while (this->threads() < threads)
      workers_.emplace_back([this, seen = generation_.load(std::memory_order_acquire)] { work(seen); });
  }

  template <class Task>
  void run(int count, const Task& task) {
    if (count <= 0) return;
    errors_.assign(static_cast<std::size_t>(count), nullptr);
    if (workers_.empty() || count == 1) {
      for (int i = 0; i < count; ++i) guarded(task, i);
    } else {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        job_ = [&task, this](int i) { guarded(task, i); };
        count_ = count;
        next_ = 0;
        busy_ = static_cast<int>(workers_.size());
        ++generation_;
      }
      start_.notify_all();
      drain();
      spin_until([this] { return busy_.load(std::memory_order_acquire) == 0; });
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, [this] { return busy_ == 0; });
      job_ = nullptr;
    }
    for (const std::exception_ptr& e : errors_) {
      if (e) std::rethrow_exception(e);
    }
  }

 private:
  template <class Task>
  void guarded(const Task& task, int i) {
    try {
      task(i);
    } catch (...) {
      errors_[static_cast<std::size_t>(i)] = std::current_exception();
    }
  }

  void drain() {
    for (int i = next_++; i < count_; i = next_++) job_(i);
  }

  // A short spin before sleeping on the condition variable: the loops come
  // every few hundred microseconds, and a futex sleep and wake-up costs tens
  // of microseconds each way (docs/decisions/coupled-dynamics-performance.md).
  // Bounded, so an idle pool sleeps.
  template <class Ready>
  static void spin_until(const Ready& ready) {
    for (int i = 0; i < kSpinChecks && !ready(); ++i) std::this_thread::yield();
  }
  static constexpr int kSpinChecks = 200;

  /// `seen`: the last job generation before this worker started (it takes
  /// the next one on).
  void work(long seen) {
    for (;;) {
      spin_until([&] { return generation_.load(std::memory_order_acquire) != seen; });
      {
        std::unique_lock<std::mutex> lock(mutex_);
        start_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
      }
      drain();
      {
        std::lock_guard<std::mutex> lock(mutex_);
        --busy_;
      }
      done_.notify_one();
    }
  }

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  std::function<void(int)> job_;
  std::vector<std::exception_ptr> errors_;
  std::atomic<int> next_{0};
  int count_ = 0;
  std::atomic<int> busy_{0};
  std::atomic<long> generation_{0};
  bool stop_ = false;
};

}  // namespace spiral::engine
