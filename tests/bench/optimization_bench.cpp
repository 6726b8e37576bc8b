// Pretension optimization of the default deep-water scenario (4 cluster
// groups, its 5 load cases, and with `every_line` each intact case with
// each of the 16 lines removed: 69 scenarios), static level: evaluations and
// wall time with the analytic gradients (SLSQP) and gradient-free (COBYLA),
// and the pretension study (4 groups × 21 points). Targets of the
// optimization issue: < 10 s (SLSQP, every_line) and < 30 s (study).
// Counters: evaluations (inner, on linearized risers), wall time of the SOZ.

#include <benchmark/benchmark.h>

#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_study.hpp"

namespace spiral::design {
namespace {

ValidatedProject default_scenario() {
  return load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
}

void optimize(benchmark::State& state, OptimizationAlgorithm algorithm, DamagedConditions damaged) {
  const ValidatedProject p = default_scenario();
  OptimizationRequest request;
  request.algorithm = algorithm;
  request.damaged = damaged;
  OptimizationResult result;
  for (auto _ : state) {
    result = optimize_pretension(p, request);
    benchmark::DoNotOptimize(result);
  }
  state.counters["scenarios"] = static_cast<double>(result.scenarios.size());
  state.counters["evaluations"] = result.evaluations;
  state.counters["optimal"] = result.status == OptimizationStatus::optimal ? 1 : 0;
  state.counters["objective"] = result.objective_best;
  state.counters["zone_s"] = result.zone_wall_s;
}

void BM_Optimize_DefaultScenario_Slsqp_LoadCases(benchmark::State& state) {
  optimize(state, OptimizationAlgorithm::slsqp, DamagedConditions::load_cases);
}
void BM_Optimize_DefaultScenario_Slsqp_EveryLine(benchmark::State& state) {
  optimize(state, OptimizationAlgorithm::slsqp, DamagedConditions::every_line);
}
void BM_Optimize_DefaultScenario_Cobyla_EveryLine(benchmark::State& state) {
  optimize(state, OptimizationAlgorithm::cobyla, DamagedConditions::every_line);
}

void BM_PretensionStudy_DefaultScenario_4GroupsBy21(benchmark::State& state) {
  const ValidatedProject p = default_scenario();
  PretensionStudyRequest request;
  request.groups = {"cluster45", "cluster135", "cluster225", "cluster315"};
  request.points = 21;
  PretensionStudyResult result;
  for (auto _ : state) {
    result = run_pretension_study(p, request);
    benchmark::DoNotOptimize(result);
  }
  state.counters["evaluations"] = result.evaluations;
}

BENCHMARK(BM_Optimize_DefaultScenario_Slsqp_LoadCases)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Optimize_DefaultScenario_Slsqp_EveryLine)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Optimize_DefaultScenario_Cobyla_EveryLine)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_PretensionStudy_DefaultScenario_4GroupsBy21)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace spiral::design
