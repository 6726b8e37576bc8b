// Time per call of the ANCF element kernels the FE line statics spend most of
// their time in (the every-line optimization's profile, 2026-12-07: forces
// 20 %, forces-with-tangent 30 %): one 5 m riser element of an SCR, inclined 20°
// from vertical and curved, in a sheared 1.5 m/s current, clear of the seabed
// (and, the "Touchdown" variants, crossing it).

#include <array>
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/lines/ancf_cable_element.hpp"
#include "engine/lines/ancf_dynamic_loads.hpp"

namespace spiral::engine {
namespace {

/// load.current points into the Setup: set by the benchmark once the Setup
/// has its final address (a returned copy would dangle).
struct Setup {
  ancf::ElementProperties element;
  std::vector<CurrentProfilePoint> current;
  ancf::LoadContext load;
  std::array<double, 12> q{};
};

Setup riser_element(bool touchdown) {
  Setup s;
  s.element.length_m = 5.0;
  s.element.EA_N = 7.6e9;
  s.element.EI_Nm2 = 2.9e7;
  s.element.weight_N_per_m = 1.9e3;
  s.element.normal_drag_N_s2_per_m3 = 0.5 * 1025.0 * 1.2 * 0.45;
  s.element.tangential_drag_N_s2_per_m3 = 0.5 * 1025.0 * 0.008 * M_PI * 0.45;
  s.current = {{-1500.0, Eigen::Vector3d(0.2, 0.0, 0.0)},
               {-200.0, Eigen::Vector3d(0.8, 0.1, 0.0)},
               {0.0, Eigen::Vector3d(1.5, 0.3, 0.0)}};
  s.load.seabed_z_m = touchdown ? -800.2 : -1500.0;
  s.load.seabed_stiffness_N_per_m2 = 1.0e5;
  // Stretched 1e-3 along a direction 20° from vertical; the slope at end b
  // turned 0.5° further (a curved element).
  const double angle_a = 20.0 * M_PI / 180.0, angle_b = 20.5 * M_PI / 180.0, stretch = 1.001;
  const std::array<double, 3> ta = {stretch * std::sin(angle_a), 0.02, stretch * std::cos(angle_a)};
  const std::array<double, 3> tb = {stretch * std::sin(angle_b), 0.02, stretch * std::cos(angle_b)};
  const std::array<double, 3> ra = {300.0, 2.0, -800.0};
  s.q = {ra[0],
         ra[1],
         ra[2],
         ta[0],
         ta[1],
         ta[2],
         ra[0] + 5.0 * 0.5 * (ta[0] + tb[0]),
         ra[1] + 5.0 * 0.02,
         ra[2] + 5.0 * 0.5 * (ta[2] + tb[2]),
         tb[0],
         tb[1],
         tb[2]};
  if (touchdown) {
    // Lying along the seabed, dipping through it.
    s.q = {300.0, 2.0, -800.1, 1.001, 0.0, -0.05, 305.0, 2.0, -800.3, 1.001, 0.0, 0.05};
  }
  return s;
}

void BM_AncfElementForces(benchmark::State& state) {
  Setup s = riser_element(state.range(0) != 0);
  s.load.current = &s.current;
  std::array<double, 12> g{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.q);
    ancf::element_forces<double>(s.element, s.load, s.q.data(), g.data());
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_AncfElementForces)->ArgName("touchdown")->Arg(0)->Arg(1);

// The residual kernel the statics assemble with: the same forces, the Gauss
// points side by side.
void BM_AncfElementForcesSideBySide(benchmark::State& state) {
  Setup s = riser_element(state.range(0) != 0);
  s.load.current = &s.current;
  ancf::GaussPointRows rows;
  rows.set(s.element.length_m);
  std::array<double, 12> g{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.q);
    ancf::element_forces_side_by_side(s.element, s.load, rows, s.q.data(), g.data());
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_AncfElementForcesSideBySide)->ArgName("touchdown")->Arg(0)->Arg(1);

void BM_AncfElementForcesAndTangent(benchmark::State& state) {
  Setup s = riser_element(state.range(0) != 0);
  s.load.current = &s.current;
  std::array<double, 12> g{};
  ancf::ElementTangent K{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.q);
    ancf::element_forces_and_tangent(s.element, s.load, s.q.data(), g.data(), K);
    benchmark::DoNotOptimize(K);
  }
}
BENCHMARK(BM_AncfElementForcesAndTangent)->ArgName("touchdown")->Arg(0)->Arg(1);

/// The same element moving in a wave- and current-driven flow, with added
/// mass, drag and seabed damping and friction: what the dynamics' kernels see.
struct MovingElement {
  ancf::DynamicElementProperties d;
  ancf::SeabedDynamics bed;
  ancf::ElementFluid fluid;
  std::array<double, 12> v = {0.3, 0.05, -0.2, 1e-4, 0.0, 2e-4, 0.35, 0.04, -0.25, 2e-4, 1e-5, 1e-4};
  std::array<double, 12> acc = {0.05, 0.01, -0.02, 1e-5, 0.0, 2e-5, 0.06, 0.01, -0.03, 2e-5, 1e-6, 1e-5};
};

MovingElement moving_element() {
  MovingElement m;
  m.d.mass_kg_per_m = 190.0;
  m.d.added_mass_normal_kg_per_m = 160.0;
  m.d.displaced_mass_kg_per_m = 160.0;
  m.bed.damping_N_s_per_m2 = 1.0e3;
  m.bed.axial_friction = 0.5;
  m.bed.lateral_friction = 0.5;
  for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp) {
    m.fluid.velocity[gp] = {1.2 + 0.05 * static_cast<double>(gp), 0.2, -0.1};
    m.fluid.acceleration[gp] = {0.1, 0.02, 0.05};
  }
  return m;
}

// The dynamics' residual kernel: every force on the element in one pass (the
// FE line dynamics and the coupled level evaluate it for every element at
// every residual; its cost per element, times the elements and the residuals
// per simulated second, is the floor under issue 17 §2 and §3:
// docs/decisions/coupled-dynamics-performance.md, "The floor").
void BM_AncfDynamicElementForces(benchmark::State& state) {
  Setup s = riser_element(state.range(0) != 0);
  const MovingElement m = moving_element();
  const ancf::GaussShapes shapes = ancf::gauss_shapes(s.element.length_m);
  std::array<double, 12> g{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.q);
    ancf::dynamic_element_forces(s.element, m.d, shapes, s.load, m.bed, &m.fluid, s.q.data(), m.v.data(), m.acc.data(),
                                 g.data());
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_AncfDynamicElementForces)->ArgName("touchdown")->Arg(0)->Arg(1);

// The dynamics' Newton matrices of the same element (M, C, K; the coupled
// level's full setups re-evaluate them for every element that moved: 14 % of
// the deep-water lc1 coupled profile, 2026-12-07).
void BM_AncfElementNewtonMatrices(benchmark::State& state) {
  Setup s = riser_element(state.range(0) != 0);
  const MovingElement m = moving_element();
  const ancf::GaussShapes shapes = ancf::gauss_shapes(s.element.length_m);
  ancf::ElementDynamicMatrices matrices;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.q);
    ancf::element_newton_matrices(s.element, m.d, shapes, s.load, m.bed, &m.fluid, s.q.data(), m.v.data(), matrices);
    benchmark::DoNotOptimize(matrices);
  }
}
BENCHMARK(BM_AncfElementNewtonMatrices)->ArgName("touchdown")->Arg(0)->Arg(1);

}  // namespace
}  // namespace spiral::engine
