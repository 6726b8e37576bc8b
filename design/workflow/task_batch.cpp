#include "design/workflow/task_batch.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "engine/common/parallel_for.hpp"
#include "engine/common/solver_error.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

/// Longest kinds first, so that the last task of a batch is a short one
/// (DESIGN.md §10: hand out the longest first); stable within a kind.
int expected_length(const std::string& kind) {
  if (kind == "verification") return 0;
  if (kind == "optimization") return 1;
  if (kind == "storm") return 2;
  if (kind == "soz") return 3;
  return 4;
}

// A task's row between MPI ranks, in CBOR.
Bytes encode_row(const TaskResult& row, const std::string& fatal) {
  nlohmann::json channels = nlohmann::json::array(), checks = nlohmann::json::array();
  for (const StoredChannel& c : row.channels)
    channels.push_back({c.channel, c.unit, c.mean, c.std_dev, c.minimum, c.maximum, c.mpm_max.has_value(),
                        c.mpm_max.value_or(0.0), c.mpm_min.has_value(), c.mpm_min.value_or(0.0)});
  for (const StoredCheck& c : row.checks) checks.push_back({c.check, c.item, c.criterion, c.utilization, c.pass});
  const nlohmann::json j{{"failed", row.status == TaskStatus::failed},
                         {"fatal", fatal},
                         {"error", row.error},
                         {"wall_s", row.wall_s},
                         {"solver", row.solver},
                         {"record", nlohmann::json::binary(row.record)},
                         {"channels", channels},
                         {"checks", checks}};
  return nlohmann::json::to_cbor(j);
}

TaskResult decode_row(const Bytes& bytes, std::string& fatal) {
  const nlohmann::json j = nlohmann::json::from_cbor(bytes);
  TaskResult row;
  row.status = j.at("failed").get<bool>() ? TaskStatus::failed : TaskStatus::done;
  fatal = j.at("fatal").get<std::string>();
  row.error = j.at("error").get<std::string>();
  row.wall_s = j.at("wall_s").get<double>();
  row.solver = j.at("solver").get<std::string>();
  row.record = j.at("record").get_binary();
  for (const auto& c : j.at("channels")) {
    StoredChannel s{c[0], c[1], c[2], c[3], c[4], c[5], std::nullopt, std::nullopt};
    if (c[6].get<bool>()) s.mpm_max = c[7].get<double>();
    if (c[8].get<bool>()) s.mpm_min = c[9].get<double>();
    row.channels.push_back(std::move(s));
  }
  for (const auto& c : j.at("checks")) row.checks.push_back({c[0], c[1], c[2], c[3], c[4]});
  return row;
}

void stop_monitor(std::thread& monitor, std::condition_variable& wake, std::mutex& mutex, bool& finished) {
  {
    std::lock_guard lock(mutex);
    finished = true;
  }
  wake.notify_all();
  if (monitor.joinable()) monitor.join();
}

}  // namespace

std::string task_name(const TaskIdentity& id) { return id.case_name.empty() ? id.kind : id.kind + " " + id.case_name; }

TaskResult TaskBatch::compute_row(Slot& slot, std::any& value) const {
  TaskResult row;
  row.identity = slot.identity;
  row.stage = stage_;
  row.iteration = iteration_;
  engine::Stopwatch start;
  try {
    value = slot.compute(row);
  } catch (const engine::SolverError& e) {
    row.status = TaskStatus::failed;
    row.error = e.what();
    row.record.clear();
    row.channels.clear();
    row.checks.clear();
  }
  row.wall_s = start.seconds();
  return row;
}

void TaskBatch::run(ResultsStore* store, int jobs, const std::function<void(const BatchProgress&)>& progress,
                    const Cluster* cluster) {
  if (cluster && cluster->size() > 1)
    run_distributed(store, progress, *cluster);
  else
    run_threads(*store, jobs, progress);
}

void TaskBatch::run_threads(ResultsStore& store, int jobs, const std::function<void(const BatchProgress&)>& progress) {
  std::mutex progress_mutex;
  BatchProgress state;
  state.stage = stage_;
  state.total = static_cast<int>(slots_.size());
  engine::Stopwatch clock;
  std::map<std::size_t, double> running;  ///< slot → start (clock s), under progress_mutex
  const auto slowest = [&] {
    state.slowest_running.clear();
    state.slowest_running_s = 0.0;
    for (const auto& [i, start_s] : running) {
      if (!state.slowest_running.empty() && clock.seconds() - start_s <= state.slowest_running_s) continue;
      state.slowest_running = task_name(slots_[i].identity);
      state.slowest_running_s = clock.seconds() - start_s;
    }
  };
  const auto report = [&](const Slot& slot, double wall_s) {
    if (!progress) return;
    std::lock_guard lock(progress_mutex);
    ++state.finished;
    state.heartbeat = false;
    state.last_task = task_name(slot.identity);
    state.last_wall_s = wall_s;
    state.last_failed = slot.error.has_value();
    state.last_reused = slot.reused;
    slowest();
    progress(state);
  };

  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    Slot& slot = slots_[i];
    const std::optional<StoredTask> stored = store.find(task_key(slot.identity));
    if (stored && stored->status == TaskStatus::failed) {
      slot.error = stored->error;
      slot.reused = true;
    } else if (stored) {
      try {
        slot.value = slot.decode(stored->record);
        slot.reused = true;
      } catch (const std::runtime_error&) {
        // A record this spiral cannot read (another record version): run the task again.
      }
    }
    if (slot.reused)
      report(slot, stored->wall_s);
    else
      pending.push_back(i);
  }
  std::stable_sort(pending.begin(), pending.end(), [&](std::size_t a, std::size_t b) {
    return expected_length(slots_[a].identity.kind) < expected_length(slots_[b].identity.kind);
  });

  // A heartbeat while long tasks run: what is running and for how long.
  std::condition_variable wake;
  bool finished = false;
  std::thread monitor;
  if (progress && !pending.empty()) {
    monitor = std::thread([&] {
      std::unique_lock lock(progress_mutex);
      while (!wake.wait_for(lock, std::chrono::duration<double>(heartbeat_s_), [&] { return finished; })) {
        if (running.empty()) continue;
        state.heartbeat = true;
        slowest();
        progress(state);
      }
    });
  }
  try {
    engine::parallel_for(static_cast<int>(pending.size()), std::max(1, jobs), [&](int k) {
      const std::size_t index = pending[static_cast<std::size_t>(k)];
      Slot& slot = slots_[index];
      {
        std::lock_guard lock(progress_mutex);
        running[index] = clock.seconds();
      }
      const TaskResult row = compute_row(slot, slot.value);
      if (row.status == TaskStatus::failed) slot.error = row.error;
      store.put(row);
      {
        std::lock_guard lock(progress_mutex);
        running.erase(index);
      }
      report(slot, row.wall_s);
    });
  } catch (...) {
    stop_monitor(monitor, wake, progress_mutex, finished);
    throw;
  }
  stop_monitor(monitor, wake, progress_mutex, finished);
}

void TaskBatch::run_distributed(ResultsStore* store, const std::function<void(const BatchProgress&)>& progress,
                                const Cluster& cluster) {
  const bool root = cluster.rank() == 0;
  // 1. Rank 0 looks every task up and tells the ranks what is missing.
  std::vector<std::optional<StoredTask>> stored(slots_.size());
  nlohmann::json plan = nlohmann::json::array();
  if (root) {
    std::vector<std::size_t> pending;
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      stored[i] = store->find(task_key(slots_[i].identity));
      if (stored[i] && stored[i]->status == TaskStatus::done) {
        try {
          (void)slots_[i].decode(stored[i]->record);
        } catch (const std::runtime_error&) {
          stored[i].reset();  // unreadable record: run it again
        }
      }
      if (!stored[i]) pending.push_back(i);
    }
    std::stable_sort(pending.begin(), pending.end(), [&](std::size_t a, std::size_t b) {
      return expected_length(slots_[a].identity.kind) < expected_length(slots_[b].identity.kind);
    });
    plan = pending;
  }
  Bytes plan_bytes = root ? nlohmann::json::to_cbor(plan) : Bytes{};
  cluster.broadcast(plan_bytes);
  const auto order = nlohmann::json::from_cbor(plan_bytes).get<std::vector<std::size_t>>();

  // 2. The missing tasks over the ranks; rank 0 stores each as it arrives.
  BatchProgress state;
  state.stage = stage_;
  state.total = static_cast<int>(slots_.size());
  const auto report = [&](const Slot& slot, double wall_s, bool failed, bool reused) {
    if (!progress) return;
    ++state.finished;
    state.last_task = task_name(slot.identity);
    state.last_wall_s = wall_s;
    state.last_failed = failed;
    state.last_reused = reused;
    progress(state);
  };
  if (root)
    for (std::size_t i = 0; i < slots_.size(); ++i)
      if (stored[i]) report(slots_[i], stored[i]->wall_s, stored[i]->status == TaskStatus::failed, true);
  std::vector<std::optional<TaskResult>> rows(slots_.size());
  std::string fatal;
  cluster.distribute(
      order,
      [&](std::size_t i) {
        std::any value;  // every rank takes the values from the records below
        std::string error;
        TaskResult row;
        try {
          row = compute_row(slots_[i], value);
        } catch (const std::exception& e) {
          error = e.what();
        }
        return encode_row(row, error);
      },
      [&](std::size_t i, Bytes bytes) {
        std::string task_fatal;
        TaskResult row = decode_row(bytes, task_fatal);
        row.identity = slots_[i].identity;
        row.stage = stage_;
        row.iteration = iteration_;
        if (!task_fatal.empty()) {
          if (fatal.empty()) fatal = task_fatal;
          return;
        }
        store->put(row);
        report(slots_[i], row.wall_s, row.status == TaskStatus::failed, false);
        rows[i] = std::move(row);
      });

  // 3. Every rank gets every task's outcome and decodes the same values.
  nlohmann::json outcome = nlohmann::json::array();
  if (root) {
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      if (stored[i])
        outcome.push_back({stored[i]->status == TaskStatus::failed, true, stored[i]->error,
                           nlohmann::json::binary(stored[i]->record)});
      else if (rows[i])
        outcome.push_back(
            {rows[i]->status == TaskStatus::failed, false, rows[i]->error, nlohmann::json::binary(rows[i]->record)});
      else
        outcome.push_back(nullptr);  // its rank hit a fatal error
    }
  }
  Bytes outcome_bytes = root ? nlohmann::json::to_cbor(nlohmann::json{{"fatal", fatal}, {"tasks", outcome}}) : Bytes{};
  cluster.broadcast(outcome_bytes);
  const nlohmann::json all = nlohmann::json::from_cbor(outcome_bytes);
  if (!all.at("fatal").get<std::string>().empty()) throw std::runtime_error(all.at("fatal").get<std::string>());
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    const nlohmann::json& t = all.at("tasks").at(i);
    Slot& slot = slots_[i];
    slot.reused = t[1].get<bool>();
    if (t[0].get<bool>())
      slot.error = t[2].get<std::string>();
    else
      slot.value = slot.decode(t[3].get_binary());
  }
}

int TaskBatch::done() const {
  int n = 0;
  for (const Slot& s : slots_) n += s.value.has_value() ? 1 : 0;
  return n;
}

int TaskBatch::failed() const {
  int n = 0;
  for (const Slot& s : slots_) n += s.error.has_value() ? 1 : 0;
  return n;
}

int TaskBatch::reused() const {
  int n = 0;
  for (const Slot& s : slots_) n += s.reused ? 1 : 0;
  return n;
}

}  // namespace spiral::design
