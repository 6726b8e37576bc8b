// The 6-DOF quasi-static mooring force of the default deep-water scenario
// (16 chain-polyester-chain lines), cold and warm-started from the previous
// hull position as a time-domain or equilibrium iteration would.
#include <benchmark/benchmark.h>

#include "design/mooring_model.hpp"
#include "design/validated_project.hpp"
#include "engine/analysis/mooring_statics.hpp"

namespace {

using namespace spiral;

const design::MooringDesignModel& default_scenario_model() {
  static const design::MooringDesignModel model = design::build_mooring_model(
      design::load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml")
          .project);
  return model;
}

void BM_MooringForce6Dof_DefaultScenario_Cold(benchmark::State& state) {
  const auto& model = default_scenario_model();
  engine::Vector6d offset = engine::Vector6d::Zero();
  offset(0) = 20.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(engine::solve_mooring_statics(model.system, offset).hull_force);
  }
  state.counters["lines"] = static_cast<double>(model.system.lines.size());
}
BENCHMARK(BM_MooringForce6Dof_DefaultScenario_Cold)->Unit(benchmark::kMicrosecond);

void BM_MooringForce6Dof_DefaultScenario_Warm(benchmark::State& state) {
  const auto& model = default_scenario_model();
  engine::Vector6d offset = engine::Vector6d::Zero();
  offset(0) = 20.0;
  engine::MooringStaticResult previous = engine::solve_mooring_statics(model.system, offset);
  double sign = 1.0;
  for (auto _ : state) {
    // Alternate a 0.1 m surge / 0.05 deg yaw step, as between two time steps.
    offset(0) += sign * 0.1;
    offset(5) += sign * 8.7e-4;
    sign = -sign;
    previous = engine::solve_mooring_statics(model.system, offset, {}, &previous);
    benchmark::DoNotOptimize(previous.hull_force);
  }
  state.counters["lines"] = static_cast<double>(model.system.lines.size());
}
BENCHMARK(BM_MooringForce6Dof_DefaultScenario_Warm)->Unit(benchmark::kMicrosecond);

}  // namespace
