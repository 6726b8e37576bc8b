#include "design/workflow/task_batch.hpp"

#include <mutex>
#include <stdexcept>

#include "engine/common/parallel_for.hpp"
#include "engine/common/solver_error.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

void TaskBatch::run(ResultsStore& store, int jobs, const std::function<void(const BatchProgress&)>& progress) {
  std::mutex progress_mutex;
  BatchProgress state;
  state.stage = stage_;
  state.total = static_cast<int>(slots_.size());
  const auto report = [&](const Slot& slot, double wall_s) {
    if (!progress) return;
    std::lock_guard lock(progress_mutex);
    ++state.finished;
    state.last_task = slot.identity.kind + (slot.identity.case_name.empty() ? "" : " " + slot.identity.case_name);
    state.last_wall_s = wall_s;
    state.last_failed = slot.error.has_value();
    state.last_reused = slot.reused;
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

  engine::parallel_for(static_cast<int>(pending.size()), std::max(1, jobs), [&](int k) {
    Slot& slot = slots_[pending[static_cast<std::size_t>(k)]];
    TaskResult row;
    row.identity = slot.identity;
    row.stage = stage_;
    row.iteration = iteration_;
    engine::Stopwatch start;
    try {
      slot.value = slot.compute(row);
    } catch (const engine::SolverError& e) {
      slot.error = e.what();
      row.status = TaskStatus::failed;
      row.error = e.what();
      row.record.clear();
      row.channels.clear();
      row.checks.clear();
    }
    row.wall_s = start.seconds();
    store.put(row);
    report(slot, row.wall_s);
  });
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
