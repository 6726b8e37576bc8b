// Coupled static equilibrium of the default deep-water scenario with every
// mooring line and riser as an FE model under the 100-year current, then the
// 6×6 stiffness at the equilibrium (issue 3 targets: < 1 s and < 50 ms).
#include <benchmark/benchmark.h>

#include "design/analysis/static_case.hpp"

namespace {

using namespace spiral;

void run(benchmark::State& state, bool fe_mooring) {
  auto project = design::load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  if (fe_mooring) {
    for (auto& line : project.project.mooring.lines) line.model = design::LineModel::fe;
  }
  design::StaticCaseRequest request;
  request.load_case = "lc2-survival-collinear-45deg";
  double equilibrium_s = 0.0, stiffness_s = 0.0;
  int iterations = 0;
  for (auto _ : state) {
    const auto result = design::run_static_case(project, request);
    equilibrium_s = result.equilibrium_wall_s;
    stiffness_s = result.stiffness_wall_s;
    iterations = result.equilibrium_iterations;
  }
  state.counters["equilibrium_s"] = equilibrium_s;
  state.counters["stiffness_s"] = stiffness_s;
  state.counters["newton_iterations"] = iterations;
}

void BM_CoupledStatics_DefaultScenario_FeRisers_CatenaryMooring_Current(benchmark::State& state) { run(state, false); }
BENCHMARK(BM_CoupledStatics_DefaultScenario_FeRisers_CatenaryMooring_Current)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_CoupledStatics_DefaultScenario_AllFe_Current(benchmark::State& state) { run(state, true); }
BENCHMARK(BM_CoupledStatics_DefaultScenario_AllFe_Current)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
