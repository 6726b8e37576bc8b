// Validation of the hull's equivalent low-frequency oscillator
// (engine/analysis/low_frequency_damping.hpp) against linear vibration and
// the stochastic linearization of drag:
//  - a linear spring-mass-dashpot: ζ = B / (2 sqrt(K M)) (any vibration text,
//    e.g. Thomson & Dahleh, Theory of Vibration, ch. 2);
//  - quadratic damping b |q̇| q̇ under a Gaussian velocity: B = sqrt(8/π) σ b
//    (Atalik & Utku 1976; the expected slope 2 b E|q̇|);
//  - a Zener line relaxation: the natural frequency solves
//    M ω² = K + Δ (ωτ)²/(1 + (ωτ)²), the damping adds Δ τ/(1 + (ωτ)²);
//  - current drag on the hull: the ζ it gives equals the one a free decay in
//    that current shows (logarithmic decrement), the check that the
//    linearization is the physics the integrator sees.

#include "engine/analysis/low_frequency_damping.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "engine/numerics/free_decay.hpp"
#include "support/oc4_hull_dynamics.hpp"

namespace spiral::engine {
namespace {

constexpr std::array<int, 3> kHorizontal = {0, 1, 5};

// A record of `n` states at 1 s spacing: positions at the equilibrium, the
// given velocities in surge.
HullTimeSeries record_with_surge_velocity(const std::vector<double>& surge_velocity_m_per_s) {
  const auto n = static_cast<Eigen::Index>(surge_velocity_m_per_s.size());
  HullTimeSeries r;
  r.times_s = Eigen::VectorXd::LinSpaced(n, 0.0, static_cast<double>(n - 1));
  r.position.setZero(6, n);
  r.velocity.setZero(6, n);
  for (Eigen::Index k = 0; k < n; ++k) r.velocity(0, k) = surge_velocity_m_per_s[static_cast<std::size_t>(k)];
  return r;
}

TEST(LowFrequencyDamping, LinearOscillatorGivesTheClosedFormRatioAndPeriod) {
  const test::Oc4HullData oc4 = test::oc4_hull_dynamics();
  HullDynamicsModel model = oc4.model;
  model.linear_damping.diagonal() << 1.0e5, 2.0e5, 0.0, 0.0, 0.0, 3.0e8;
  const HullEquations eq = make_hull_equations(model, {oc4.lines, {}});
  const auto result = low_frequency_damping(eq, record_with_surge_velocity({0.0, 0.3, -0.2}), kHorizontal);
  ASSERT_EQ(result.size(), 3u);
  for (const DofDamping& r : result) {
    const int d = r.dof;
    const double m = eq.total_mass(d, d), k = oc4.lines.stiffness(d, d), b = model.linear_damping(d, d);
    // A linear model: the central differences are exact up to round-off.
    EXPECT_NEAR(r.mass, m, 1e-12 * m);
    EXPECT_NEAR(r.stiffness, k, 1e-6 * k) << d;
    EXPECT_NEAR(r.damping, b, 1e-6 * b) << d;
    EXPECT_NEAR(r.natural_period_s, 2.0 * std::numbers::pi * std::sqrt(m / k), 1e-6 * r.natural_period_s) << d;
    EXPECT_NEAR(r.damping_ratio, b / (2.0 * std::sqrt(k * m)), 1e-6 * r.damping_ratio) << d;
  }
  // OC4's surge alone: 2π sqrt((1.408e7 + 8.75e6 kg) / 7.08e4 N/m) = 112.8 s.
  EXPECT_NEAR(result[0].natural_period_s, 112.8, 0.1);
}

TEST(LowFrequencyDamping, QuadraticDampingIsLinearizedOnTheVelocitySpread) {
  const test::Oc4HullData oc4 = test::oc4_hull_dynamics();
  HullDynamicsModel model = oc4.model;
  const double b_quad = 4.0e6;  // N/(m/s)²
  model.quadratic_damping(0) = b_quad;
  const HullEquations eq = make_hull_equations(model, {oc4.lines, {}});
  const double sigma = 0.15;  // m/s
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss(0.0, sigma);
  std::vector<double> v(20000);
  double mean_abs = 0.0;
  for (double& x : v) {
    x = gauss(rng);
    mean_abs += std::abs(x);
  }
  mean_abs /= static_cast<double>(v.size());
  const std::array<int, 1> surge = {0};
  const DofDamping r =
      low_frequency_damping(eq, record_with_surge_velocity(v), surge, static_cast<int>(v.size())).front();
  // The expected slope over these very samples: 2 b E|v|, exact but for the
  // difference step's b h at samples within h of zero.
  EXPECT_NEAR(r.damping, 2.0 * b_quad * mean_abs, 1e-6 * r.damping);
  // And the Gaussian closed form: 20,000 samples estimate E|v| to 0.5 %
  // (its relative standard error sqrt(π/2 − 1)/sqrt(n)).
  EXPECT_NEAR(r.damping, std::sqrt(8.0 / std::numbers::pi) * sigma * b_quad, 0.02 * r.damping);
}

TEST(LowFrequencyDamping, LineRelaxationStiffensAndDampsAtTheNaturalFrequency) {
  const test::Oc4HullData oc4 = test::oc4_hull_dynamics();
  LinearizedLines lines = oc4.lines;
  LineRelaxation relaxation;
  relaxation.stiffness(0, 0) = 5.0e4;  // N/m, comparable with K11 = 7.08e4
  relaxation.time_constant_s = 20.0;   // ωτ ≈ 1.3 near OC4's surge frequency
  lines.relaxations.push_back(relaxation);
  const HullEquations eq = make_hull_equations(oc4.model, {lines, {}});
  const std::array<int, 1> surge = {0};
  const DofDamping r = low_frequency_damping(eq, record_with_surge_velocity({0.0}), surge).front();
  const double omega = 2.0 * std::numbers::pi / r.natural_period_s;
  const double wt = omega * relaxation.time_constant_s;
  const double k = oc4.lines.stiffness(0, 0) + 5.0e4 * wt * wt / (1.0 + wt * wt);
  EXPECT_NEAR(r.mass * omega * omega, k, 1e-8 * k);
  EXPECT_NEAR(r.stiffness, k, 1e-8 * k);
  EXPECT_NEAR(r.damping, 5.0e4 * relaxation.time_constant_s / (1.0 + wt * wt), 1e-8 * r.damping);
  EXPECT_GT(r.natural_period_s, 0.0);
  EXPECT_LT(r.natural_period_s, 2.0 * std::numbers::pi * std::sqrt(r.mass / oc4.lines.stiffness(0, 0)));
}

// OC4's surge in a 0.5 m/s current with a drag area of 200 m²: the drag on
// the relative velocity, ½ ρ CdA |U − q̇| (U − q̇), damps the slow surge by
// ρ CdA U = 1.0e5 N·s/m (ζ ≈ 4 %). The free decay's logarithmic decrement
// and the linearization over its own record must agree; the drag's
// quadratic part (q̇/U ≤ 0.12 here) and the decrement's reading leave about
// 1 %, so 3 %.
TEST(LowFrequencyDamping, CurrentDragRatioMatchesTheFreeDecayInThatCurrent) {
  const test::Oc4HullData oc4 = test::oc4_hull_dynamics();
  const double rho = 1025.0, drag_area_m2 = 200.0, current_m_per_s = 0.5;
  LinearizedLines lines = oc4.lines;
  // The lines hold the mean drag: the equilibrium stays at q = 0.
  lines.force_at_equilibrium(0) = -0.5 * rho * drag_area_m2 * current_m_per_s * current_m_per_s;
  HullLoads loads{lines, [=](double, const Vector6d&, const Vector6d& qd) {
                    Vector6d f = Vector6d::Zero();
                    const double u = current_m_per_s - qd(0);
                    f(0) = 0.5 * rho * drag_area_m2 * std::abs(u) * u;
                    return f;
                  }};
  HullSimulationOptions options;
  for (int k = 0; k <= 12000; ++k) options.output_times_s.push_back(0.1 * k);
  Vector6d start = Vector6d::Zero();
  start(0) = 1.0;  // m
  const HullTimeSeries decay = simulate_hull(oc4.model, loads, start, Vector6d::Zero(), options);

  const std::vector<double> surge(decay.position.row(0).begin(), decay.position.row(0).end());
  const auto cycles = free_decay_half_cycles(
      std::span<const double>(decay.times_s.data(), static_cast<std::size_t>(decay.times_s.size())), surge, 0.0, 0.0,
      0.02);
  ASSERT_GE(cycles.size(), 6u);
  double measured = 0.0;
  for (const DecayHalfCycle& c : cycles) measured += c.damping_ratio;
  measured /= static_cast<double>(cycles.size());

  const std::array<int, 1> dof = {0};
  const DofDamping r = low_frequency_damping(make_hull_equations(oc4.model, loads), decay, dof).front();
  EXPECT_NEAR(r.damping, rho * drag_area_m2 * current_m_per_s, 0.02 * r.damping);
  EXPECT_NEAR(r.damping_ratio, measured, 0.03 * measured) << "linearized " << r.damping_ratio;
  EXPECT_NEAR(measured, 0.04, 0.01);
  std::printf("current drag: zeta linearized %.5f, from the decay %.5f (%zu half cycles)\n", r.damping_ratio, measured,
              cycles.size());
}

TEST(LowFrequencyDamping, NoRestoringGivesNoPeriodAndBadInputThrows) {
  const test::Oc4HullData oc4 = test::oc4_hull_dynamics();
  LinearizedLines slack = oc4.lines;
  slack.stiffness.setZero();
  const HullEquations eq = make_hull_equations(oc4.model, {slack, {}});
  const std::array<int, 1> surge = {0};
  const DofDamping r = low_frequency_damping(eq, record_with_surge_velocity({0.0, 0.1}), surge).front();
  EXPECT_EQ(r.natural_period_s, 0.0);
  EXPECT_EQ(r.damping_ratio, 0.0);
  const std::array<int, 1> bad = {6};
  EXPECT_THROW(low_frequency_damping(eq, record_with_surge_velocity({0.0}), bad), std::invalid_argument);
  EXPECT_THROW(low_frequency_damping(eq, HullTimeSeries{}, surge), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
