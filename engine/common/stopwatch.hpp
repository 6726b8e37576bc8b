#pragma once
// Wall-clock time of a piece of work, for the timings every analysis reports
// beside its results (DESIGN.md §1: each level shows its cost). A monotonic
// clock, so a change of the system time does not corrupt a measurement.

#include <chrono>

namespace spiral::engine {

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}

  /// Seconds since construction or the last restart.
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

  /// Seconds so far, then starts again from now (timing consecutive phases).
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return s;
  }

  void restart() { start_ = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace spiral::engine
