#pragma once
// The tasks of one step of a stage, run against the results store: each task
// is looked up by its key first (a finished one is taken as it is, done or
// failed), the missing ones run on `jobs` threads, and each writes its row
// the moment it ends — so a run stopped at any point loses no finished task.
//
// A task that throws engine::SolverError is stored as failed with its
// message; the batch goes on. Anything else (bad input, a file that cannot be
// read) is not the task's result: it is rethrown after the running tasks have
// ended and been stored (under MPI as a std::runtime_error with its message,
// on every rank).

#include <any>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "design/results/results_store.hpp"
#include "design/workflow/cluster.hpp"

namespace spiral::design {

/// Progress of a batch: called after each task, and every
/// kHeartbeat_s while tasks run without one finishing (`heartbeat`), from a
/// worker or monitor thread, one call at a time.
struct BatchProgress {
  std::string stage;
  int finished = 0, total = 0;  ///< of the batch, reused ones included
  std::string last_task;        ///< "kind case" (not set by a heartbeat)
  double last_wall_s = 0.0;
  bool last_failed = false;
  bool last_reused = false;
  bool heartbeat = false;
  std::string slowest_running;  ///< the task running longest now, "" when none (threads only)
  double slowest_running_s = 0.0;
};

/// Seconds between heartbeats while tasks run (a coupled verification runs minutes).
inline constexpr double kHeartbeat_s = 15.0;

/// "kind case" (or "kind" for a task without a case), as progress and failures name a task.
std::string task_name(const TaskIdentity& identity);

class TaskBatch {
 public:
  TaskBatch(std::string stage, int iteration) : stage_(std::move(stage)), iteration_(iteration) {}

  /// Adds a task computing a T (a type stage_record.hpp encodes); `describe`
  /// fills the queryable rows (channels, checks, solver) of its store entry.
  /// Returns its index.
  template <class T>
  std::size_t add(TaskIdentity identity, std::function<T()> compute,
                  std::function<void(const T&, TaskResult&)> describe = {}) {
    Slot slot;
    slot.identity = std::move(identity);
    slot.compute = [compute = std::move(compute), describe = std::move(describe)](TaskResult& row) -> std::any {
      T value = compute();
      row.record = encode_record(value);
      if (describe) describe(value, row);
      return std::any(std::move(value));
    };
    slot.decode = [](const RecordBytes& bytes) -> std::any { return std::any(decode_record<T>(bytes)); };
    slots_.push_back(std::move(slot));
    return slots_.size() - 1;
  }

  /// Runs what the store does not have on `jobs` threads (≥ 1). With a
  /// cluster of several ranks (cluster.hpp) every rank calls it with the same
  /// tasks; only rank 0 has the store (the others pass none) and reports
  /// progress; the tasks are shared out over the ranks instead of threads,
  /// and every rank ends with every task's value.
  void run(ResultsStore* store, int jobs, const std::function<void(const BatchProgress&)>& progress = {},
           const Cluster* cluster = nullptr);

  /// Seconds between heartbeats (default kHeartbeat_s).
  void set_heartbeat(double seconds) { heartbeat_s_ = seconds; }

  std::size_t size() const { return slots_.size(); }
  /// The task's value; nullptr when it failed.
  template <class T>
  const T* value(std::size_t i) const {
    return std::any_cast<T>(&slots_.at(i).value);
  }
  /// The failure message of a failed task.
  const std::optional<std::string>& error(std::size_t i) const { return slots_.at(i).error; }
  const TaskIdentity& identity(std::size_t i) const { return slots_.at(i).identity; }

  int done() const;    ///< tasks with a value
  int failed() const;  ///< tasks with an error
  int reused() const;  ///< tasks taken from the store

 private:
  struct Slot {
    TaskIdentity identity;
    std::function<std::any(TaskResult&)> compute;
    std::function<std::any(const RecordBytes&)> decode;
    std::any value;
    std::optional<std::string> error;
    bool reused = false;
  };
  void run_threads(ResultsStore& store, int jobs, const std::function<void(const BatchProgress&)>& progress);
  void run_distributed(ResultsStore* store, const std::function<void(const BatchProgress&)>& progress,
                       const Cluster& cluster);
  /// Runs one task into its store row (solver failures as failed rows).
  TaskResult compute_row(Slot& slot, std::any& value) const;
  std::string stage_;
  int iteration_;
  double heartbeat_s_ = kHeartbeat_s;
  std::vector<Slot> slots_;
};

}  // namespace spiral::design
