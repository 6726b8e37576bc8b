// Speed of the wave realization at one point: surface elevation and Wheeler-
// stretched kinematics for a 200-component long-crested JONSWAP sea (Hs 6 m,
// Tp 12 s, 200 m depth) over a 3-hour record at 0.5 s (21,600 evaluations per
// iteration), and the first-order excitation series (6 DOF) with a synthetic
// single-heading table. Speed is measured here, not asserted.

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "engine/environment/fixed_point_wave_kinematics.hpp"
#include "engine/environment/wave_realization.hpp"
#include "engine/environment/wave_spectrum.hpp"
#include "engine/hull/first_order_wave_response.hpp"

namespace {

using namespace spiral::engine;

constexpr double kRecord_s = 10800.0;
constexpr double kDt_s = 0.5;

WaveRealization sea() {
  WaveRealizationInput in;
  in.spectrum = make_jonswap_spectrum({6.0, 12.0, 3.3});
  in.components_per_direction = 200;
  in.water_depth_m = 200.0;
  in.seed = 1;
  return make_wave_realization(in);
}

void BM_SurfaceElevation3h(benchmark::State& state) {
  const auto s = sea();
  for (auto _ : state) {
    double sum = 0.0;
    for (double t = 0.0; t < kRecord_s; t += kDt_s) sum += surface_elevation_m(s, 0.0, 0.0, t);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(kRecord_s / kDt_s));
}
BENCHMARK(BM_SurfaceElevation3h)->Unit(benchmark::kMillisecond);

void BM_Kinematics3h(benchmark::State& state) {
  const auto s = sea();
  const Eigen::Vector3d point(0.0, 0.0, -10.0);
  for (auto _ : state) {
    double sum = 0.0;
    for (double t = 0.0; t < kRecord_s; t += kDt_s) {
      const auto k = wave_kinematics(s, point, t);
      sum += k.velocity_m_per_s.x() + k.acceleration_m_per_s2.z() + k.dynamic_pressure_Pa;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(kRecord_s / kDt_s));
}
BENCHMARK(BM_Kinematics3h)->Unit(benchmark::kMillisecond);

void BM_RealizationSetup(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sea());
}
BENCHMARK(BM_RealizationSetup)->Unit(benchmark::kMillisecond);

void BM_FirstOrderExcitation3h(benchmark::State& state) {
  const auto s = sea();
  WaveTransferTable table;
  table.omega_rad_per_s = {0.1, 5.0};
  table.headings_rad = {0.0};
  for (auto& m : table.values) m = Eigen::MatrixXcd::Constant(1, 2, {1.0e6, 2.0e5});
  const auto series = prepare_first_order_series(s, table, {});
  for (auto _ : state) {
    Vector6d sum = Vector6d::Zero();
    for (double t = 0.0; t < kRecord_s; t += kDt_s) sum += evaluate_first_order(series, t);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(kRecord_s / kDt_s));
}
BENCHMARK(BM_FirstOrderExcitation3h)->Unit(benchmark::kMillisecond);

// Times the fixed-point kinematics of the deep-water survival sea (Hs 12 m,
// Tp 14 s, 1800 m, 200 components) at 1,000 points 1 m apart from the
// surface down to 1,000 m — the upper part of a riser or mooring line, where
// the components reach (deeper points drop out by the depth cutoff) —
// asked every step_s, sampled in time at sample_interval_s (0: summed at
// every time; < 0: the default interval).
void time_fixed_point_kinematics(benchmark::State& state, double sample_interval_s, double step_s) {
  WaveRealizationInput in;
  in.spectrum = make_jonswap_spectrum({12.0, 14.0, 3.01});
  in.components_per_direction = 200;
  in.water_depth_m = 1800.0;
  in.seed = 1;
  const auto sea = std::make_shared<const WaveRealization>(make_wave_realization(in));
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 1000; ++i) points.push_back({0.3 * i, 0.1 * i, -1.0 - 1.0 * i});
  const double interval_s =
      sample_interval_s < 0.0 ? FixedPointWaveKinematics::default_sample_interval_s(*sea) : sample_interval_s;
  const FixedPointWaveKinematics kinematics(sea, points, 1e-3, interval_s);
  std::vector<Eigen::Vector3d> u, a;
  double t = 0.0;
  for (auto _ : state) {
    kinematics.evaluate(t, u, a);
    benchmark::DoNotOptimize(u.data());
    t += step_s;
  }
  state.counters["interval_s"] = kinematics.sample_interval_s();
}

}  // namespace

// The fixed-point kinematics the dynamic FE lines use, summed at every time
// asked (one evaluation per IDA step and line).
void BM_FixedPointKinematics1000Points(benchmark::State& state) { time_fixed_point_kinematics(state, 0.0, 0.3); }
BENCHMARK(BM_FixedPointKinematics1000Points)->Unit(benchmark::kMicrosecond);

// The same points sampled in time at the default interval (0.28 s for this
// sea) and asked at the coupled storm's step of ≈ 0.06 s: one evaluation
// on average, the grid sums included.
void BM_FixedPointKinematicsSampled1000Points(benchmark::State& state) {
  time_fixed_point_kinematics(state, -1.0, 0.06);
}
BENCHMARK(BM_FixedPointKinematicsSampled1000Points)->Unit(benchmark::kMicrosecond);
