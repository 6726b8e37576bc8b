#pragma once
// Long runs from Python (analyze, soz, optimize, and the equilibria): the
// design function runs on a worker thread with the GIL released, so other
// Python threads go on; the calling thread meanwhile checks for signals
// (Ctrl-C) and hands the run's progress to the caller's callback. All Python
// calls stay on the calling thread, so the design layer's hooks, which may
// be called from its own worker threads, only touch the atomics of a
// RunMonitor.
//
// Stopping: a signal, or an exception raised by the callback, asks the run
// to stop; the design function's progress hook (RunMonitor::hook) then
// throws RunStopped at its next report, which leaves the design function
// like any failure (its solver adapters and worker pools pass exceptions
// on), and the Python exception (KeyboardInterrupt for Ctrl-C) is raised
// once the worker has finished. A run without a hook stops when it returns.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace spiral::python {

/// Thrown by RunMonitor::hook when the caller asked the run to stop. Not a
/// std::exception, so that no `catch (const std::exception&)` on the way
/// out (a per-case boundary that reports a failed case and goes on) takes
/// it for the failure of one case.
struct RunStopped {};

/// What a run and its Python caller share.
class RunMonitor {
 public:
  /// The design function's progress hook (fraction done, 0..1), safe to call
  /// from any thread: records the fraction (the largest reported: threads
  /// that report out of order do not move it back); throws RunStopped once
  /// stop() was called.
  std::function<void(double)> hook() {
    return [this](double fraction) {
      double seen = fraction_.load(std::memory_order_relaxed);
      while (fraction > seen && !fraction_.compare_exchange_weak(seen, fraction, std::memory_order_relaxed)) {
      }
      if (stop_.load(std::memory_order_relaxed)) throw RunStopped{};
    };
  }
  double fraction() const { return fraction_.load(std::memory_order_relaxed); }
  void stop() { stop_.store(true, std::memory_order_relaxed); }

  void finish() {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
    finished_signal_.notify_all();
  }
  /// True when the run finished within `timeout`.
  bool wait_finished(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    return finished_signal_.wait_for(lock, timeout, [this] { return finished_; });
  }

 private:
  std::atomic<double> fraction_{0.0};
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable finished_signal_;
  bool finished_ = false;
};

/// How often the calling thread looks for Ctrl-C and reports progress: well
/// under a human's reaction time, and rare enough to cost nothing.
inline constexpr std::chrono::milliseconds kPollInterval{50};

/// `work(monitor)` on a worker thread, the GIL released; `progress` (a
/// Python callable taking the fraction done, or None) is called on this
/// thread when the fraction has changed, and with 1.0 at the end of a run
/// that finished. Call with the GIL held. Returns what `work` returns;
/// rethrows its exception, or raises the Python error that stopped it.
template <class Work>
auto run_interruptible(Work work, const pybind11::object& progress) {
  namespace py = pybind11;
  using Result = decltype(work(std::declval<RunMonitor&>()));
  RunMonitor monitor;
  std::optional<Result> result;
  std::exception_ptr failure;
  std::optional<py::error_already_set> python_error;
  double reported = -1.0;
  const auto report = [&](double fraction) {
    if (progress.is_none() || fraction == reported) return;
    reported = fraction;
    progress(fraction);
  };
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        result.emplace(work(monitor));
      } catch (...) {
        failure = std::current_exception();
      }
      monitor.finish();
    });
    while (!monitor.wait_finished(kPollInterval)) {
      py::gil_scoped_acquire acquire;
      if (python_error) continue;  // stopping: wait for the worker
      try {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        report(monitor.fraction());
      } catch (py::error_already_set& error) {
        python_error.emplace(std::move(error));
        monitor.stop();
      }
    }
    worker.join();
  }
  if (python_error) throw std::move(*python_error);
  if (failure) std::rethrow_exception(failure);
  report(1.0);
  return std::move(*result);
}

}  // namespace spiral::python
