// `spiral lines` (design/analysis/motion_lines.hpp): what a line under a
// given motion history costs, and what recording the riser criteria at every
// output time adds to the riser's FE dynamics.
//  - BM_MotionLines_Oc4Chain600s: the OC4 chain L1 under the two-tone surge
//    of tests/data/motion (600 s at 0.5 s), read from its file as the command
//    reads it.
//  - BM_MotionLines_DeepwaterRiser600s/{0,1}: the default scenario's SCR P1
//    under the same history in case lc5 (current, no waves); 1: through
//    run_motion_lines (every output time's riser criteria, riser_checks),
//    0: the same riser's bare FE dynamics (run_line_dynamics, top tension only).
#include <benchmark/benchmark.h>

#include <string>

#include "design/analysis/motion_lines.hpp"
#include "design/import/motion_history.hpp"
#include "design/model/environment_loads.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {
namespace {

const std::string kMotion = std::string(SPIRAL_TEST_DATA_DIR) + "/motion/oc4-two-tone-surge.csv";

MotionLinesRequest request_for(const std::string& load_case, const std::string& line) {
  const MotionHistory history = read_motion_history(kMotion);
  MotionLinesRequest r;
  r.load_case = load_case;
  r.motion_times_s = history.time_s;
  r.motion = history.offset;
  r.lines = {line};
  r.waves_on_lines = false;
  return r;
}

void BM_MotionLines_Oc4Chain600s(benchmark::State& state) {
  const ValidatedProject vp =
      load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  for (auto _ : state) {
    const MotionLinesResult r = run_motion_lines(vp, request_for("intact-still-water", "L1"));
    state.counters["steps"] = static_cast<double>(r.lines.front().solver.steps);
    benchmark::DoNotOptimize(r.lines.front().fairlead_tension_N.back());
  }
}
BENCHMARK(BM_MotionLines_Oc4Chain600s)->Unit(benchmark::kSecond)->Iterations(3);

void BM_MotionLines_DeepwaterRiser600s(benchmark::State& state) {
  const ValidatedProject vp = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  const MotionLinesRequest request = request_for("lc5-operating-45deg", "P1");
  for (auto _ : state) {
    if (state.range(0) == 1) {
      const MotionLinesResult r = run_motion_lines(vp, request);
      state.counters["steps"] = static_cast<double>(r.risers.front().solver.steps);
    } else {
      const LoadCase& lc = vp.project.load_cases[4];
      LineDynamicsInput input;
      input.current = current_profile_of(environment_of(vp.project, lc));
      input.static_offset = request.motion.col(0);
      input.t0_s = request.motion_times_s.front();
      input.dt_s = request.output_step_s;
      input.motion = request.motion;
      input.motion_times_s = request.motion_times_s;
      input.ramp_s = request.ramp_s;
      input.only = request.lines;
      const std::vector<LineDynamicsSeries> s = run_line_dynamics(vp.project, input);
      state.counters["steps"] = static_cast<double>(s.front().solver.steps);
    }
  }
}
BENCHMARK(BM_MotionLines_DeepwaterRiser600s)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(2);

}  // namespace
}  // namespace spiral::design
