// Speed of solve_catenary: the OC4-DeepCwind line (MAP++ deck, single chain
// segment with touchdown and friction) and a deep-water taut chain-polyester-chain
// line, cold (standard initial guess) and warm-started from the previous solution
// after a 0.1 m fairlead move (alternating), as in an equilibrium or time-domain
// loop. Speed is measured here, not asserted.

#include <benchmark/benchmark.h>

#include <numbers>

#include "engine/lines/catenary.hpp"

namespace {

using spiral::engine::CatenaryGeometry;
using spiral::engine::CatenaryGuess;
using spiral::engine::CatenaryLine;
using spiral::engine::CatenarySolution;
using spiral::engine::solve_catenary;

struct Case {
  CatenaryLine line;
  CatenaryGeometry geometry;
};

Case oc4() {
  Case c;
  const double w = (113.35 - 1025.0 * std::numbers::pi / 4.0 * 0.0766 * 0.0766) * 9.80665;
  c.line.segments = {{835.35, w, 7.536e8}};
  c.line.seabed_friction = 1.0;
  c.geometry = {837.6 - 40.868, 200.0 - 14.0, 0.0};
  return c;
}

// 1800 m water depth, fairlead 28 m below the surface, anchor 2118 m away:
// bottom chain 150 m, polyester 2490 m, top chain 100 m (anchor -> fairlead).
Case chain_polyester_chain() {
  Case c;
  c.line.segments = {{150.0, 3664.0, 1.725e9}, {2490.0, 111.0, 2.423e8}, {100.0, 3664.0, 1.725e9}};
  c.line.seabed_friction = 1.0;
  c.geometry = {2118.0, 1800.0 - 28.0, 0.0};
  return c;
}

void cold(benchmark::State& state, const Case& c) {
  int iterations = 0;
  for (auto _ : state) {
    const CatenarySolution s = solve_catenary(c.line, c.geometry);
    iterations = s.iterations;
    benchmark::DoNotOptimize(s.fairlead_horizontal_N);
  }
  state.counters["newton_iterations"] = iterations;
}

void warm(benchmark::State& state, const Case& c) {
  CatenarySolution s = solve_catenary(c.line, c.geometry);
  CatenaryGeometry g = c.geometry;
  long total_iterations = 0, solves = 0;
  double sign = 1.0;
  for (auto _ : state) {
    g.horizontal_span_m += sign * 0.1;
    sign = -sign;
    s = solve_catenary(c.line, g, {}, CatenaryGuess{s.fairlead_horizontal_N, s.fairlead_vertical_N});
    total_iterations += s.iterations;
    ++solves;
    benchmark::DoNotOptimize(s.fairlead_horizontal_N);
  }
  state.counters["newton_iterations"] = static_cast<double>(total_iterations) / std::max(solves, 1L);
}

void BM_Oc4Cold(benchmark::State& state) { cold(state, oc4()); }
void BM_Oc4Warm(benchmark::State& state) { warm(state, oc4()); }
void BM_ChainPolyesterChainCold(benchmark::State& state) { cold(state, chain_polyester_chain()); }
void BM_ChainPolyesterChainWarm(benchmark::State& state) { warm(state, chain_polyester_chain()); }

BENCHMARK(BM_Oc4Cold);
BENCHMARK(BM_Oc4Warm);
BENCHMARK(BM_ChainPolyesterChainCold);
BENCHMARK(BM_ChainPolyesterChainWarm);

}  // namespace
