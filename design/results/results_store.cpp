#include "design/results/results_store.hpp"

#include <fmt/format.h>
#include <sqlite3.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <map>

#include "design/project/model_hash.hpp"
#include "design/results/output_error.hpp"

namespace spiral::design {

namespace {

// Schema version 1 (docs/results-store.md documents every column).
constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS meta(
  key TEXT PRIMARY KEY,
  value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS runs(
  id INTEGER PRIMARY KEY,
  started_utc TEXT NOT NULL,
  finished_utc TEXT,
  project_file TEXT NOT NULL,
  model_hash TEXT NOT NULL,
  jobs INTEGER NOT NULL,
  version TEXT NOT NULL,
  outcome TEXT NOT NULL DEFAULT 'running');
CREATE TABLE IF NOT EXISTS iterations(
  run_id INTEGER NOT NULL REFERENCES runs(id),
  iteration INTEGER NOT NULL,
  stage TEXT NOT NULL,
  model_hash TEXT NOT NULL,
  project_file TEXT NOT NULL,
  payouts_json TEXT NOT NULL,
  reason TEXT NOT NULL,
  PRIMARY KEY(run_id, iteration));
CREATE TABLE IF NOT EXISTS stages(
  run_id INTEGER NOT NULL REFERENCES runs(id),
  stage TEXT NOT NULL,
  iteration INTEGER NOT NULL,
  model_hash TEXT NOT NULL,
  pass INTEGER NOT NULL,
  governing TEXT NOT NULL,
  tasks_done INTEGER NOT NULL,
  tasks_failed INTEGER NOT NULL,
  tasks_reused INTEGER NOT NULL,
  wall_s REAL NOT NULL,
  PRIMARY KEY(run_id, stage, iteration));
CREATE TABLE IF NOT EXISTS tasks(
  key TEXT PRIMARY KEY,
  model_hash TEXT NOT NULL,
  kind TEXT NOT NULL,
  case_name TEXT NOT NULL,
  level TEXT NOT NULL,
  seed INTEGER NOT NULL,
  options TEXT NOT NULL,
  stage TEXT NOT NULL,
  iteration INTEGER NOT NULL,
  status TEXT NOT NULL CHECK(status IN ('done', 'failed')),
  error TEXT NOT NULL,
  wall_s REAL NOT NULL,
  solver TEXT NOT NULL,
  finished_utc TEXT NOT NULL,
  record BLOB);
CREATE TABLE IF NOT EXISTS channel_statistics(
  task_key TEXT NOT NULL REFERENCES tasks(key) ON DELETE CASCADE,
  channel TEXT NOT NULL,
  unit TEXT NOT NULL,
  mean REAL, std_dev REAL, minimum REAL, maximum REAL,
  mpm_max REAL, mpm_min REAL,
  PRIMARY KEY(task_key, channel));
CREATE TABLE IF NOT EXISTS checks(
  task_key TEXT NOT NULL REFERENCES tasks(key) ON DELETE CASCADE,
  seq INTEGER NOT NULL,
  check_name TEXT NOT NULL,
  item TEXT NOT NULL,
  criterion TEXT NOT NULL,
  utilization REAL,
  pass INTEGER NOT NULL,
  PRIMARY KEY(task_key, seq));
)sql";

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buffer;
}

/// A prepared statement, finalized on scope exit.
class Statement {
 public:
  Statement(sqlite3* db, const char* sql, const std::filesystem::path& file) : db_(db), file_(file) {
    if (sqlite3_prepare_v2(db, sql, -1, &statement_, nullptr) != SQLITE_OK) fail("prepare");
  }
  ~Statement() { sqlite3_finalize(statement_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, const std::string& text) {
    check(sqlite3_bind_text(statement_, i, text.c_str(), static_cast<int>(text.size()), SQLITE_TRANSIENT));
    return *this;
  }
  Statement& bind(int i, double value) {
    check(sqlite3_bind_double(statement_, i, value));
    return *this;
  }
  Statement& bind(int i, std::int64_t value) {
    check(sqlite3_bind_int64(statement_, i, value));
    return *this;
  }
  Statement& bind(int i, int value) { return bind(i, static_cast<std::int64_t>(value)); }
  Statement& bind(int i, const std::optional<double>& value) {
    if (value) return bind(i, *value);
    check(sqlite3_bind_null(statement_, i));
    return *this;
  }
  Statement& bind(int i, const RecordBytes& bytes) {
    check(sqlite3_bind_blob64(statement_, i, bytes.data(), bytes.size(), SQLITE_TRANSIENT));
    return *this;
  }
  /// Steps once: true while a row is available.
  bool step() {
    const int rc = sqlite3_step(statement_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) fail("step");
    return false;
  }
  void run() {
    while (step()) {
    }
  }
  std::string text(int column) const {
    const auto* p = sqlite3_column_text(statement_, column);
    return p ? std::string(reinterpret_cast<const char*>(p)) : std::string();
  }
  double real(int column) const { return sqlite3_column_double(statement_, column); }
  int integer(int column) const { return sqlite3_column_int(statement_, column); }
  RecordBytes blob(int column) const {
    const auto* p = static_cast<const std::uint8_t*>(sqlite3_column_blob(statement_, column));
    return p ? RecordBytes(p, p + sqlite3_column_bytes(statement_, column)) : RecordBytes();
  }

 private:
  void check(int rc) {
    if (rc != SQLITE_OK) fail("bind");
  }
  [[noreturn]] void fail(const char* what) const {
    throw OutputError(fmt::format("results store {}: {} failed: {}", file_.string(), what, sqlite3_errmsg(db_)));
  }
  sqlite3* db_;
  sqlite3_stmt* statement_ = nullptr;
  const std::filesystem::path& file_;
};

const char* to_text(TaskStatus status) { return status == TaskStatus::done ? "done" : "failed"; }

}  // namespace

std::string task_key(const TaskIdentity& id) {
  // Unit separators keep the fields apart ("a","bc" differs from "ab","c").
  const std::string joined = fmt::format("{}\x1f{}\x1f{}\x1f{}\x1f{}\x1f{}", id.model_hash, id.kind, id.case_name,
                                         id.level, id.seed, id.options);
  return fmt::format("{:016x}", fnv1a_64(joined));
}

std::filesystem::path results_store_file(const std::filesystem::path& run_folder) {
  return run_folder / "results.sqlite";
}

ResultsStore::ResultsStore(const std::filesystem::path& file, bool fresh) : file_(file) {
  std::error_code ec;
  if (fresh) {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(file.string() + suffix, ec);
  }
  if (!file.parent_path().empty()) std::filesystem::create_directories(file.parent_path(), ec);
  if (sqlite3_open_v2(file.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                      nullptr) != SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw OutputError(fmt::format("results store {}: cannot be opened: {}", file.string(), message));
  }
  sqlite3_busy_timeout(db_, 10000);
  try {
    // WAL: a commit is one append to the log, readers do not block the
    // writer, and a killed process leaves the last committed state
    // (synchronous NORMAL: durable against a crash of the process; only a
    // power loss may take back the last commits).
    execute("PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL; PRAGMA foreign_keys=ON;");
    // An existing store of another layout is refused before anything is written to it.
    Statement has_meta(db_, "SELECT count(*) FROM sqlite_master WHERE type='table' AND name='meta'", file_);
    has_meta.step();
    if (has_meta.integer(0) == 1) {
      Statement version(db_, "SELECT value FROM meta WHERE key='schema_version'", file_);
      const std::string found = version.step() ? version.text(0) : "none";
      if (found != std::to_string(kResultsStoreSchemaVersion)) {
        throw OutputError(fmt::format(
            "results store {}: schema version {} (this spiral reads version {}); run with --fresh to start a new "
            "store, or use the spiral that wrote it",
            file.string(), found, kResultsStoreSchemaVersion));
      }
    }
    execute("BEGIN");
    execute(kSchema);
    Statement meta(db_, "INSERT OR IGNORE INTO meta(key, value) VALUES ('schema_version', ?1), ('created_utc', ?2)",
                   file_);
    meta.bind(1, std::to_string(kResultsStoreSchemaVersion)).bind(2, utc_now()).run();
    execute("COMMIT");
  } catch (...) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw;
  }
}

ResultsStore::~ResultsStore() { sqlite3_close(db_); }

void ResultsStore::execute(const char* sql) const {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw OutputError(fmt::format("results store {}: {}", file_.string(), message));
  }
}

std::optional<StoredTask> ResultsStore::find(const std::string& key) const {
  std::lock_guard lock(mutex_);
  Statement q(db_, "SELECT status, error, wall_s, record FROM tasks WHERE key = ?1", file_);
  q.bind(1, key);
  if (!q.step()) return std::nullopt;
  StoredTask task;
  task.key = key;
  task.status = q.text(0) == "done" ? TaskStatus::done : TaskStatus::failed;
  task.error = q.text(1);
  task.wall_s = q.real(2);
  task.record = q.blob(3);
  return task;
}

void ResultsStore::put(const TaskResult& task) {
  std::lock_guard lock(mutex_);
  const std::string key = task_key(task.identity);
  execute("BEGIN IMMEDIATE");
  try {
    Statement del(db_, "DELETE FROM tasks WHERE key = ?1", file_);
    del.bind(1, key).run();
    Statement row(db_,
                  "INSERT INTO tasks(key, model_hash, kind, case_name, level, seed, options, stage, iteration, "
                  "status, error, wall_s, solver, finished_utc, record) "
                  "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15)",
                  file_);
    row.bind(1, key)
        .bind(2, task.identity.model_hash)
        .bind(3, task.identity.kind)
        .bind(4, task.identity.case_name)
        .bind(5, task.identity.level)
        .bind(6, static_cast<std::int64_t>(task.identity.seed))
        .bind(7, task.identity.options)
        .bind(8, task.stage)
        .bind(9, task.iteration)
        .bind(10, std::string(to_text(task.status)))
        .bind(11, task.error)
        .bind(12, task.wall_s)
        .bind(13, task.solver)
        .bind(14, utc_now())
        .bind(15, task.record)
        .run();
    for (const StoredChannel& c : task.channels) {
      Statement s(db_,
                  "INSERT INTO channel_statistics(task_key, channel, unit, mean, std_dev, minimum, maximum, "
                  "mpm_max, mpm_min) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)",
                  file_);
      s.bind(1, key)
          .bind(2, c.channel)
          .bind(3, c.unit)
          .bind(4, c.mean)
          .bind(5, c.std_dev)
          .bind(6, c.minimum)
          .bind(7, c.maximum)
          .bind(8, c.mpm_max)
          .bind(9, c.mpm_min)
          .run();
    }
    for (std::size_t i = 0; i < task.checks.size(); ++i) {
      const StoredCheck& c = task.checks[i];
      Statement s(db_,
                  "INSERT INTO checks(task_key, seq, check_name, item, criterion, utilization, pass) "
                  "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)",
                  file_);
      s.bind(1, key)
          .bind(2, static_cast<int>(i))
          .bind(3, c.check)
          .bind(4, c.item)
          .bind(5, c.criterion)
          .bind(6, c.utilization)
          .bind(7, c.pass ? 1 : 0)
          .run();
    }
    execute("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

int ResultsStore::begin_run(const std::string& project_file, const std::string& model_hash, int jobs,
                            const std::string& version) {
  std::lock_guard lock(mutex_);
  Statement s(db_, "INSERT INTO runs(started_utc, project_file, model_hash, jobs, version) VALUES (?1, ?2, ?3, ?4, ?5)",
              file_);
  s.bind(1, utc_now()).bind(2, project_file).bind(3, model_hash).bind(4, jobs).bind(5, version).run();
  return static_cast<int>(sqlite3_last_insert_rowid(db_));
}

void ResultsStore::finish_run(int run, const std::string& outcome) {
  std::lock_guard lock(mutex_);
  Statement s(db_, "UPDATE runs SET finished_utc = ?1, outcome = ?2 WHERE id = ?3", file_);
  s.bind(1, utc_now()).bind(2, outcome).bind(3, run).run();
}

void ResultsStore::put_iteration(int run, const SpiralIteration& it) {
  std::lock_guard lock(mutex_);
  Statement s(db_,
              "INSERT OR REPLACE INTO iterations(run_id, iteration, stage, model_hash, project_file, payouts_json, "
              "reason) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)",
              file_);
  s.bind(1, run)
      .bind(2, it.iteration)
      .bind(3, it.stage)
      .bind(4, it.model_hash)
      .bind(5, it.project_file)
      .bind(6, it.payouts_json)
      .bind(7, it.reason)
      .run();
}

void ResultsStore::put_stage(int run, const StageVerdict& v) {
  std::lock_guard lock(mutex_);
  Statement s(db_,
              "INSERT OR REPLACE INTO stages(run_id, stage, iteration, model_hash, pass, governing, tasks_done, "
              "tasks_failed, tasks_reused, wall_s) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)",
              file_);
  s.bind(1, run)
      .bind(2, v.stage)
      .bind(3, v.iteration)
      .bind(4, v.model_hash)
      .bind(5, v.pass ? 1 : 0)
      .bind(6, v.governing)
      .bind(7, v.tasks_done)
      .bind(8, v.tasks_failed)
      .bind(9, v.tasks_reused)
      .bind(10, v.wall_s)
      .run();
}

StoreSummary ResultsStore::summary() const {
  std::lock_guard lock(mutex_);
  StoreSummary out;
  out.schema_version = kResultsStoreSchemaVersion;
  {
    Statement q(db_, "SELECT count(*) FROM runs", file_);
    q.step();
    out.runs = q.integer(0);
  }
  {
    Statement q(db_, "SELECT stage, status, count(*) FROM tasks GROUP BY stage, status ORDER BY min(rowid)", file_);
    while (q.step()) {
      const std::string stage = q.text(0);
      auto it = std::find_if(out.stages.begin(), out.stages.end(), [&](const auto& s) { return s.stage == stage; });
      if (it == out.stages.end()) it = out.stages.insert(out.stages.end(), {stage, 0, 0});
      const bool done = q.text(1) == "done";
      (done ? it->done : it->failed) += q.integer(2);
      (done ? out.tasks_done : out.tasks_failed) += q.integer(2);
    }
  }
  int last_run = 0;
  {
    Statement q(db_, "SELECT id, outcome FROM runs ORDER BY id DESC LIMIT 1", file_);
    if (q.step()) {
      last_run = q.integer(0);
      out.last_run_outcome = q.text(1);
    }
  }
  {
    Statement q(db_,
                "SELECT stage, iteration, model_hash, pass, governing, tasks_done, tasks_failed, tasks_reused, wall_s "
                "FROM stages WHERE run_id = ?1 ORDER BY rowid",
                file_);
    q.bind(1, last_run);
    while (q.step()) {
      out.last_run.push_back({q.text(0), q.integer(1), q.text(2), q.integer(3) != 0, q.text(4), q.integer(5),
                              q.integer(6), q.integer(7), q.real(8)});
    }
  }
  {
    Statement q(db_,
                "SELECT iteration, stage, model_hash, project_file, payouts_json, reason FROM iterations "
                "WHERE run_id = ?1 ORDER BY iteration",
                file_);
    q.bind(1, last_run);
    while (q.step()) out.iterations.push_back({q.integer(0), q.text(1), q.text(2), q.text(3), q.text(4), q.text(5)});
  }
  {
    Statement q(db_, "SELECT kind || ' ' || case_name, error FROM tasks WHERE error != '' ORDER BY rowid", file_);
    while (q.step()) out.failures.emplace_back(q.text(0), q.text(1));
  }
  return out;
}

std::unique_ptr<ResultsStore> open_existing_store(const std::filesystem::path& run_folder) {
  const std::filesystem::path file = results_store_file(run_folder);
  if (!std::filesystem::is_regular_file(file))
    throw OutputError(fmt::format("{}: no results store here (expected {})", run_folder.string(), file.string()));
  return std::make_unique<ResultsStore>(file, false);
}

}  // namespace spiral::design
