// The design spiral on the default scenario (design/workflow/spiral_run.hpp),
// fresh store each time: wall time per stage (counters), tasks per second,
// and the speed-up from 1 to 2 jobs. The whole spiral (advanced stage's
// coupled verifications included) is BM_SpiralDefault/all; the MPI speed-up is
// measured with mpirun (README).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <optional>

#include "design/workflow/spiral_run.hpp"

namespace {

using namespace spiral;

const std::string kScenario = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml";

void run(benchmark::State& state, const std::optional<std::string>& until) {
  design::SpiralRunOptions options;
  options.out_folder = std::filesystem::temp_directory_path() / ("spiral-bench-run-" + std::to_string(::getpid()));
  options.jobs = static_cast<int>(state.range(0));
  options.until = until;
  options.fresh = true;
  int tasks = 0;
  std::map<std::string, double> stage_s;
  for (auto _ : state) {
    const design::SpiralRunResult r = design::run_spiral(kScenario, options);
    tasks = 0;
    for (const design::StageRun& s : r.stages) {
      tasks += s.tasks - s.tasks_reused;
      stage_s[s.stage] = s.wall_s;
    }
  }
  for (const auto& [stage, seconds] : stage_s) state.counters[stage + "_s"] = seconds;
  state.counters["tasks"] = tasks;
  state.counters["tasks_per_s"] =
      benchmark::Counter(tasks * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  std::filesystem::remove_all(options.out_folder);
}

void BM_SpiralDefault_UntilIntermediate(benchmark::State& state) { run(state, "intermediate"); }
BENCHMARK(BM_SpiralDefault_UntilIntermediate)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

void BM_SpiralDefault_All(benchmark::State& state) { run(state, std::nullopt); }
BENCHMARK(BM_SpiralDefault_All)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace
