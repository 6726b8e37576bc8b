#pragma once
// The results store of a spiral run (DESIGN.md §10; docs/results-store.md):
// one SQLite database, `results.sqlite`, per run folder. Every finished task
// — done or failed — is written in its own transaction (WAL journal), so a
// run stopped at any moment (Ctrl-C, kill -9) keeps every finished task and
// no half-written one, and the next run on the folder resumes: it looks each
// planned task up by its key and computes only what is missing.
//
// A task's key is the fingerprint of what decides its result: the content
// hash of the validated project and its data files (project_content_hash),
// the kind of task, the load case, the level, the seed and the options. Not
// the stage that asked for it: the intermediate stage takes the preliminary
// stage's static cases from the store instead of solving them again.
//
// Besides each task's full record (stage_record.hpp), the store keeps what a
// user queries with sqlite3 or pandas: per task its status, error, wall time
// and solver statistics; the statistics of every storm channel; every
// criterion checked; per run the stages' verdicts and the iterations of the
// spiral with their payouts.
//
// One connection per store, guarded by a mutex: the tasks of a run finish on
// worker threads and each writes its row as it ends.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "design/results/stage_record.hpp"

struct sqlite3;

namespace spiral::design {

/// The layout of the database; a store of another version is refused.
inline constexpr int kResultsStoreSchemaVersion = 1;

/// What identifies a task (its key is the hash of all of it).
struct TaskIdentity {
  std::string model_hash;  ///< project_content_hash of the project it ran on
  std::string kind;        ///< mooring-overview, static-case, soz, storm, verification
  std::string case_name;   ///< "" when the task has no load case
  std::string level;       ///< "" for static tasks
  std::uint64_t seed = 0;  ///< 0 for static tasks
  std::string options;     ///< anything else that changes the result (text, canonical)
};

/// The task's key: FNV-1a 64 of its identity fields, 16 hex digits.
std::string task_key(const TaskIdentity& identity);

enum class TaskStatus { done, failed };

/// One row of the channel statistics table.
struct StoredChannel {
  std::string channel, unit;
  double mean = 0.0, std_dev = 0.0, minimum = 0.0, maximum = 0.0;
  std::optional<double> mpm_max, mpm_min;  ///< absent when the channel has no extremes
};

/// One criterion checked by a task (one row of the checks table).
struct StoredCheck {
  std::string check;      ///< e.g. mooring code, riser criteria, dynamic tension
  std::string item;       ///< line or riser, "" for the offset
  std::string criterion;  ///< what the utilization measures
  double utilization = 0.0;
  bool pass = true;
};

struct TaskResult {
  TaskIdentity identity;
  std::string stage;  ///< the stage that ran it
  int iteration = 1;  ///< of the spiral, when it ran
  TaskStatus status = TaskStatus::done;
  /// The solver's message: of a failed task, or of a done task whose
  /// analysis recorded a failure in its result (its record is kept).
  std::string error;
  double wall_s = 0.0;
  std::string solver;  ///< solver statistics, as text (e.g. "steps=…"), may be empty
  RecordBytes record;  ///< done: the full result (stage_record.hpp)
  std::vector<StoredChannel> channels;
  std::vector<StoredCheck> checks;
};

/// A finished task as the store has it.
struct StoredTask {
  std::string key;
  TaskStatus status = TaskStatus::done;
  std::string error;
  double wall_s = 0.0;
  RecordBytes record;
};

/// A stage's verdict in one run and iteration.
struct StageVerdict {
  std::string stage;
  int iteration = 1;
  std::string model_hash;
  bool pass = false;
  std::string governing;
  int tasks_done = 0, tasks_failed = 0, tasks_reused = 0;
  double wall_s = 0.0;
};

/// One iteration of the spiral: the model it ran on and why it was made.
struct SpiralIteration {
  int iteration = 1;
  std::string stage;  ///< the stage that started it
  std::string model_hash;
  std::string project_file;  ///< the project the iteration ran on
  std::string payouts_json;  ///< {"group": payout_m, …}; "{}" for the first
  std::string reason;
};

struct StoreSummary {
  int schema_version = 0;
  int runs = 0;
  int tasks_done = 0, tasks_failed = 0;
  struct StageCounts {
    std::string stage;
    int done = 0, failed = 0;
  };
  std::vector<StageCounts> stages;          ///< by the stage that ran the task
  std::vector<StageVerdict> last_run;       ///< the verdicts of the latest run
  std::vector<SpiralIteration> iterations;  ///< of the latest run
  std::string last_run_outcome;             ///< pass, fail, interrupted, error, or running
  /// (task, error) of every task with an error: failed tasks, and done ones
  /// whose analysis recorded a solver failure (a coupled verification run).
  std::vector<std::pair<std::string, std::string>> failures;
};

class ResultsStore {
 public:
  /// Opens (or creates) the store. `fresh`: delete what is there first.
  /// Throws OutputError naming the file when it cannot be opened or written,
  /// or when it holds another schema version (the message says which).
  ResultsStore(const std::filesystem::path& file, bool fresh);
  ~ResultsStore();
  ResultsStore(const ResultsStore&) = delete;
  ResultsStore& operator=(const ResultsStore&) = delete;

  const std::filesystem::path& file() const { return file_; }

  /// The finished task with this key, if any.
  std::optional<StoredTask> find(const std::string& key) const;
  /// Writes a finished task (replacing any row of the same key) in one transaction.
  void put(const TaskResult& task);

  /// A new run; returns its id.
  int begin_run(const std::string& project_file, const std::string& model_hash, int jobs, const std::string& version);
  void finish_run(int run, const std::string& outcome);
  void put_iteration(int run, const SpiralIteration& iteration);
  void put_stage(int run, const StageVerdict& verdict);

  StoreSummary summary() const;

 private:
  void execute(const char* sql) const;
  std::filesystem::path file_;
  sqlite3* db_ = nullptr;
  mutable std::mutex mutex_;
};

/// The file of the store in a run folder.
std::filesystem::path results_store_file(const std::filesystem::path& run_folder);

/// Opens an existing store for reading (summary, find). Throws OutputError
/// when there is none or it cannot be read.
std::unique_ptr<ResultsStore> open_existing_store(const std::filesystem::path& run_folder);

}  // namespace spiral::design
