// The 6-DOF quasi-static mooring force (and 6×6 stiffness) of the default
// deep-water scenario (16 chain–polyester–chain lines), warm-started from the
// previous hull position as a time-domain or equilibrium iteration would,
// and cold (every line from its default initial guess).
#include <benchmark/benchmark.h>

#include "design/model/mooring_model.hpp"
#include "design/project/validated_project.hpp"
#include "engine/analysis/line_array.hpp"

namespace {

using namespace spiral;

design::LineArrayModel default_scenario_model() {
  return design::build_mooring_model(
      design::load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml").project);
}

void BM_MooringForce6Dof_DefaultScenario_Cold(benchmark::State& state) {
  auto model = default_scenario_model();
  engine::Vector6d offset = engine::Vector6d::Zero();
  offset(0) = 20.0;
  const auto pose = engine::pose_from_offset(model.reference_point_g, offset);
  for (auto _ : state) {
    for (auto& line : model.lines) line->reset();
    benchmark::DoNotOptimize(engine::evaluate_line_array(model.lines, pose).force);
  }
  state.counters["lines"] = static_cast<double>(model.lines.size());
}
BENCHMARK(BM_MooringForce6Dof_DefaultScenario_Cold)->Unit(benchmark::kMicrosecond);

void BM_MooringForce6Dof_DefaultScenario_Warm(benchmark::State& state) {
  auto model = default_scenario_model();
  engine::Vector6d offset = engine::Vector6d::Zero();
  offset(0) = 20.0;
  double sign = 1.0;
  for (auto _ : state) {
    // Alternate a 0.1 m surge / 0.05° yaw step, as between two time steps.
    offset(0) += sign * 0.1;
    offset(5) += sign * 8.7e-4;
    sign = -sign;
    benchmark::DoNotOptimize(
        engine::evaluate_line_array(model.lines, engine::pose_from_offset(model.reference_point_g, offset)).force);
  }
  state.counters["lines"] = static_cast<double>(model.lines.size());
}
BENCHMARK(BM_MooringForce6Dof_DefaultScenario_Warm)->Unit(benchmark::kMicrosecond);

}  // namespace
