// SOZ of every riser of the default deep-water scenario (12 SCRs in 1800 m)
// at 5° steps (target < 5 s on the 2-core project machine): FE reference and
// catenary screening. Counters: riser static solves, risers solved (not
// turned copies), time per solve. Wall time on a shared machine is noisy:
// note the load average, or compare the CPU time (user) of `spiral soz`.

#include <benchmark/benchmark.h>

#include <algorithm>

#include "design/soz/soz.hpp"

namespace spiral::design {
namespace {

void run(benchmark::State& state, SozModel model) {
  const ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  std::vector<RiserDesign> designs;
  for (const Riser& r : p.project.risers) designs.push_back(riser_design(p.project, r));
  SozOptions options;
  options.offset_check = false;
  options.model = model;
  SozResult result;
  for (auto _ : state) {
    result = compute_soz(p.project, designs, {}, options);
    benchmark::DoNotOptimize(result);
  }
  state.counters["solves"] = result.solves;
  // Risers solved (the others' zones are turned or mirrored copies,
  // soz_symmetry.hpp); a riser solved on one half counts one half.
  double solved = 0.0;
  for (const RiserSoz& z : result.risers) {
    if (z.zone_rotated_from.empty() && z.zone_mirrored_from.empty()) solved += z.zone_mirror_symmetric ? 0.5 : 1.0;
  }
  state.counters["risers_solved"] = solved;
  state.counters["threads"] = result.threads;
  state.counters["ms_per_solve_per_thread"] = 1e3 * result.zone_wall_s * result.threads / result.solves;
}

void BM_Soz_DefaultScenario_Fe(benchmark::State& state) { run(state, SozModel::fe); }
void BM_Soz_DefaultScenario_Catenary(benchmark::State& state) { run(state, SozModel::catenary); }
BENCHMARK(BM_Soz_DefaultScenario_Fe)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_Soz_DefaultScenario_Catenary)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace spiral::design
