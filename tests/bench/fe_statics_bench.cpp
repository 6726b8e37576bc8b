// Time per FE static solve (cold start from the default catenary shape, and
// warm start from a converged state as in offset sweeps / stiffness reduction).

#include <cmath>

#include <benchmark/benchmark.h>

#include "engine/lines/fe_line_statics.hpp"

namespace spiral::engine {
namespace {

FeLineSection section(double length_m, double w, double EA, double d, double cdn, double cdt, double h,
                      double EI = 0.0) {
  FeLineSection s;
  s.length_m = length_m;
  s.weight_N_per_m = w;
  s.EA_N = EA;
  s.EI_Nm2 = EI;
  s.hydro_diameter_m = d;
  s.drag_normal = cdn;
  s.drag_tangential = cdt;
  s.element_length_m = h;
  s.mass_kg_per_m = 100.0;
  return s;
}

void BM_Oc4Line(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double w = (113.35 - 1025.0 * M_PI / 4.0 * 0.0766 * 0.0766) * 9.80665;
  FeLineModel m;
  m.sections = {section(835.35, w, 7.536e8, 0.0766 * 1.8, 1.1, 0.2, 835.35 / n)};
  FeEnvironment env;
  env.seabed_z_m = -200.0;
  env.seabed_stiffness_N_per_m2 = 1e7;
  const FeLineEnds ends{{-837.6, 0.0, -200.0}, {-40.868, 0.0, -14.0}};
  int iterations = 0;
  for (auto _ : state) {
    auto r = solve_fe_line_statics(m, env, ends);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r);
  }
  state.counters["newton_iterations"] = iterations;
}
BENCHMARK(BM_Oc4Line)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMillisecond);

// Deep-water chain–polyester–chain line, 1800 m depth, anchor radius 2200 m,
// fairlead radius 81.736 m at z = −28 m, 1.5 m/s surface current with a 1/7
// power profile, heading 30° from the line's plane. 10 + 63 + 10 elements.
struct DeepWater {
  FeLineModel model;
  FeEnvironment env;
  FeLineEnds ends;
};
DeepWater deep_water(bool current) {
  DeepWater d;
  d.model.sections = {section(150.0, 3664.0, 1.725e9, 0.2646, 1.333, 0.4, 15.0),
                      section(2490.0, 111.0, 2.423e8, 0.201, 2.021, 0.05, 40.0),
                      section(100.0, 3664.0, 1.725e9, 0.2646, 1.333, 0.4, 10.0)};
  d.env.seabed_z_m = -1800.0;
  d.env.seabed_stiffness_N_per_m2 = 1e6;
  if (current) {
    const Eigen::Vector3d dir(std::cos(M_PI / 6), std::sin(M_PI / 6), 0.0);
    for (int i = 0; i <= 20; ++i) {
      const double z = -1800.0 + 90.0 * i;
      d.env.current.push_back({z, 1.5 * std::pow((z + 1800.0) / 1800.0, 1.0 / 7.0) * dir});
    }
  }
  d.ends = {{-2200.0, 0.0, -1800.0}, {-81.736, 0.0, -28.0}};
  return d;
}

void BM_DeepWaterChainPolyesterChain(benchmark::State& state) {
  const DeepWater d = deep_water(state.range(0) != 0);
  int iterations = 0;
  double fairlead_tension_N = 0.0, laid_m = 0.0;
  for (auto _ : state) {
    auto r = solve_fe_line_statics(d.model, d.env, d.ends);
    iterations = r.iterations;
    fairlead_tension_N = r.end_B_force_N.norm();
    laid_m = r.touchdown ? r.touchdown->arc_length_m : 0.0;
    benchmark::DoNotOptimize(r);
  }
  state.counters["newton_iterations"] = iterations;
  state.counters["fairlead_tension_kN"] = fairlead_tension_N / 1e3;
  state.counters["touchdown_arc_m"] = laid_m;
}
BENCHMARK(BM_DeepWaterChainPolyesterChain)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_DeepWaterWarmStartOffset(benchmark::State& state) {
  // A 1 m fairlead offset from the converged mean position, warm started.
  const DeepWater d = deep_water(true);
  const auto base = solve_fe_line_statics(d.model, d.env, d.ends);
  FeStaticsOptions o;
  o.warm_start_state = base.state;
  o.warm_start_node_arc_length_m = base.node_arc_length_m;
  o.warm_start_tangent = base.tangent;
  auto ends = d.ends;
  ends.end_B_m.x() += 1.0;
  int iterations = 0, remeshes = 0;
  for (auto _ : state) {
    auto r = solve_fe_line_statics(d.model, d.env, ends, o);
    iterations = r.iterations;
    remeshes = r.touchdown_remeshes;
    benchmark::DoNotOptimize(r);
  }
  state.counters["newton_iterations"] = iterations;
  state.counters["touchdown_remeshes"] = remeshes;
}
BENCHMARK(BM_DeepWaterWarmStartOffset)->Unit(benchmark::kMillisecond);

// Steel catenary riser (OD 0.2731 m, WT 0.0254 m, oil-filled, 1800 m depth,
// 12° hang-off): 20 m elements, zone_element_m in a 200 m zone around the
// touchdown point; optionally a 1.5 m/s surface current (1/7 power profile)
// at 45° to the riser plane.
struct Scr {
  FeLineModel model;
  FeEnvironment env;
  FeLineEnds ends;
};
Scr steel_catenary_riser(double zone_element_m, bool current) {
  constexpr double od = 0.2731, wt = 0.0254, E = 207e9, g = 9.80665;
  const double id = od - 2.0 * wt;
  const double a_steel = M_PI / 4.0 * (od * od - id * id);
  const double w = (7850.0 * a_steel + 800.0 * M_PI / 4.0 * id * id - 1025.0 * M_PI / 4.0 * od * od) * g;
  const double EI = E * M_PI / 64.0 * (std::pow(od, 4) - std::pow(id, 4));
  const double phi = 78.0 * M_PI / 180.0, a = 1780.0 / (1.0 / std::cos(phi) - 1.0);
  const double length = 500.0 + a * std::tan(phi), span = 500.0 + a * std::asinh(std::tan(phi));
  Scr r;
  r.model.sections = {section(length, w, E * a_steel, od, 1.0, 0.0, 20.0, EI)};
  r.model.refinement = FeRefinementZone{400.0, 200.0, zone_element_m};
  r.env.seabed_z_m = -1800.0;
  r.env.seabed_stiffness_N_per_m2 = 1e7;
  if (current) {
    const Eigen::Vector3d dir(std::cos(M_PI / 4), std::sin(M_PI / 4), 0.0);
    for (int i = 0; i <= 18; ++i) {
      const double z = -1800.0 + 100.0 * i;
      r.env.current.push_back({z, 1.5 * std::pow((z + 1800.0) / 1800.0, 1.0 / 7.0) * dir});
    }
  }
  r.ends = {{-span, 0.0, -1800.0}, {0.0, 0.0, -20.0}};
  return r;
}

void BM_SteelCatenaryRiser(benchmark::State& state) {
  const Scr scr = steel_catenary_riser(static_cast<double>(state.range(0)) / 10.0, false);
  int iterations = 0, elements = 0, jacobians = 0;
  for (auto _ : state) {
    auto r = solve_fe_line_statics(scr.model, scr.env, scr.ends);
    iterations = r.iterations;
    jacobians = r.jacobian_evaluations;
    elements = static_cast<int>(r.element_tension_N.size());
    benchmark::DoNotOptimize(r);
  }
  state.counters["newton_iterations"] = iterations;
  state.counters["jacobians"] = jacobians;
  state.counters["elements"] = elements;
}
BENCHMARK(BM_SteelCatenaryRiser)->Arg(20)->Arg(10)->Unit(benchmark::kMillisecond);

// The 225-element SCR with the 1.5 m/s current: cold (continuations on the
// current and the seabed stiffness), and warm started from the converged
// state and tangent after a 0.5 m hang-off move (arg 1: in x, the riser
// plane; arg 2: in x and y) — the solves of the coupled static equilibrium
// and of an offset sweep.
void BM_SteelCatenaryRiserCurrentCold(benchmark::State& state) {
  const Scr scr = steel_catenary_riser(2.0, true);
  int iterations = 0, jacobians = 0;
  for (auto _ : state) {
    auto r = solve_fe_line_statics(scr.model, scr.env, scr.ends);
    iterations = r.iterations;
    jacobians = r.jacobian_evaluations;
    benchmark::DoNotOptimize(r);
  }
  state.counters["newton_iterations"] = iterations;
  state.counters["jacobians"] = jacobians;
}
BENCHMARK(BM_SteelCatenaryRiserCurrentCold)->Unit(benchmark::kMillisecond);

void BM_SteelCatenaryRiserWarmMove(benchmark::State& state) {
  const bool current = state.range(0) != 0;
  const Scr scr = steel_catenary_riser(2.0, current);
  const auto base = solve_fe_line_statics(scr.model, scr.env, scr.ends);
  FeStaticsOptions o;
  o.warm_start_state = base.state;
  o.warm_start_node_arc_length_m = base.node_arc_length_m;
  o.warm_start_tangent = base.tangent;
  auto ends = scr.ends;
  ends.end_B_m.x() += 0.5;
  if (state.range(1) == 2) ends.end_B_m.y() += 0.5;
  int iterations = 0, jacobians = 0, remeshes = 0;
  for (auto _ : state) {
    auto r = solve_fe_line_statics(scr.model, scr.env, ends, o);
    iterations = r.iterations;
    jacobians = r.jacobian_evaluations;
    remeshes = r.touchdown_remeshes;
    benchmark::DoNotOptimize(r);
  }
  state.counters["newton_iterations"] = iterations;
  state.counters["jacobians"] = jacobians;
  state.counters["touchdown_remeshes"] = remeshes;
}
BENCHMARK(BM_SteelCatenaryRiserWarmMove)
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({1, 2})
    ->ArgNames({"current", "axes"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace spiral::engine
