// FE line dynamics (issue 5 benchmark): one OC4 chain line (200 m water,
// 835.35 m, EA 7.536e8 N) with a prescribed fairlead surge of 5 m at 100 s
// plus 1 m at 10 s (both ramped in over 100 s), 600 s simulated, 40 and 80
// elements. Reports the time per simulated second, the integrator statistics
// and the fairlead-tension error against a converged reference (160
// elements, rtol 1e-8), as the largest difference after the ramp, in % of
// the reference's largest tension.

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "engine/lines/fe_line_dynamics.hpp"
#include "support/oc4_fe_line.hpp"

namespace spiral::engine {
namespace {

constexpr double kDuration_s = 600.0, kSample_s = 0.1, kRamp_s = 100.0;

EndKinematics surge_at(const Eigen::Vector3d& rest, double t) {
  // Each component A r(t) sin(ω t), r the smooth ramp 3τ² − 2τ³ (τ = t/T_ramp).
  const double tau = std::min(t / kRamp_s, 1.0);
  const double r = tau < 1.0 ? tau * tau * (3.0 - 2.0 * tau) : 1.0;
  const double dr = tau < 1.0 ? 6.0 * tau * (1.0 - tau) / kRamp_s : 0.0;
  const double ddr = tau < 1.0 ? (6.0 - 12.0 * tau) / (kRamp_s * kRamp_s) : 0.0;
  EndKinematics k;
  k.position_m = rest;
  for (const auto [amplitude, period] : {std::pair{5.0, 100.0}, std::pair{1.0, 10.0}}) {
    const double w = 2.0 * std::numbers::pi / period, s = std::sin(w * t), c = std::cos(w * t);
    k.position_m.x() += amplitude * r * s;
    k.velocity_m_per_s.x() += amplitude * (dr * s + r * w * c);
    k.acceleration_m_per_s2.x() += amplitude * (ddr * s + 2.0 * dr * w * c - r * w * w * s);
  }
  return k;
}

struct Run {
  std::vector<double> tension_N;
  IdaStatistics stats;
};

Run run(int elements, double relative_tolerance, bool reference = false) {
  const FeLineModel model = test::oc4_fe_line(elements);
  const FeDynamicEnvironment env = test::oc4_dynamic_environment();
  const FeStaticsResult st = solve_fe_line_statics(model, env.statics, test::oc4_line_ends());
  FeDynamicsOptions o;
  const Eigen::Vector3d rest = st.node_position_m.back();
  o.end_B_motion = [rest](double t) { return surge_at(rest, t); };
  o.relative_tolerance = relative_tolerance;
  o.slope_tolerance = relative_tolerance;
  if (reference) o.velocity_tolerance_m_per_s = 1e-4;
  FeLineDynamics dyn(model, env, st, o);
  Run r;
  const int samples = static_cast<int>(kDuration_s / kSample_s);
  for (int k = 1; k <= samples; ++k) {
    dyn.advance_to(k * kSample_s);
    r.tension_N.push_back(dyn.end_B_force_N().norm());
  }
  r.stats = dyn.statistics();
  return r;
}

const Run& reference() {
  static const Run ref = run(160, 1e-8, true);
  return ref;
}

double error_pct(const Run& r) {
  const Run& ref = reference();
  double worst = 0.0, peak = 0.0;
  for (std::size_t i = static_cast<std::size_t>(kRamp_s / kSample_s); i < ref.tension_N.size(); ++i) {
    worst = std::max(worst, std::abs(r.tension_N[i] - ref.tension_N[i]));
    peak = std::max(peak, ref.tension_N[i]);
  }
  return 100.0 * worst / peak;
}

// Args: elements, −log10(rtol) × 10 (60: rtol 1e-6; 57: 2e-6, the default; 55: 3.2e-6).
void BM_Oc4LineDynamics600s(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  const double rtol = std::pow(10.0, -static_cast<double>(state.range(1)) / 10.0);
  reference();  // built outside the timed loop
  Run r;
  for (auto _ : state) {
    r = run(elements, rtol);
    benchmark::DoNotOptimize(r);
  }
  state.counters["s_per_simulated_s"] =
      benchmark::Counter(kDuration_s, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["tension_error_pct"] = error_pct(r);
  state.counters["steps"] = static_cast<double>(r.stats.steps);
  state.counters["residuals"] = static_cast<double>(r.stats.residual_evaluations);
  state.counters["jacobians"] = static_cast<double>(r.stats.newton_matrix_setups);
  state.counters["partial_updates"] = static_cast<double>(r.stats.newton_matrix_updates);
}
BENCHMARK(BM_Oc4LineDynamics600s)
    ->Args({40, 60})
    ->Args({80, 60})
    ->Args({80, 57})
    ->Args({80, 55})
    ->Args({80, 50})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace spiral::engine
