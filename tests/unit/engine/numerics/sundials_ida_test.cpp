// The IDA adapter on systems with known solutions: a damped oscillator
// written as an implicit DAE (q' − v = 0, v' + 2ζω v + ω² q = 0) with its
// 2×2 Newton matrix solved by the system, and an algebraic (prescribed)
// component excluded from the error test.

#include "engine/numerics/sundials_ida.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/common/worker_pool.hpp"

namespace spiral::engine {
namespace {

// x(t) of x'' + 2ζω x' + ω² x = 0, x(0) = 1, x'(0) = 0 (underdamped).
double damped_oscillator(double t, double omega, double zeta) {
  const double wd = omega * std::sqrt(1.0 - zeta * zeta);
  return std::exp(-zeta * omega * t) * (std::cos(wd * t) + zeta * omega / wd * std::sin(wd * t));
}

class Oscillator : public ImplicitSystem {
 public:
  Oscillator(double omega, double zeta) : w_(omega), z_(zeta) {}
  void residual(double t, const VectorConstRef& y, const VectorConstRef& yp, VectorRef r) override {
    r[0] = yp[0] - y[1];
    r[1] = yp[1] + 2.0 * z_ * w_ * y[1] + w_ * w_ * y[0];
    r[2] = y[2] - std::sin(t);  // algebraic: a prescribed value
  }
  bool setup_newton_matrix(double, const VectorConstRef&, const VectorConstRef&, double cj) override {
    J_ << cj, -1.0, 0.0, w_ * w_, cj + 2.0 * z_ * w_, 0.0, 0.0, 0.0, 1.0;
    lu_.compute(J_);
    ++setups;
    return true;
  }
  void solve_newton_system(double, Eigen::Ref<Eigen::VectorXd> b) override { b = lu_.solve(Eigen::Vector3d(b)); }
  int setups = 0;

 private:
  double w_, z_;
  Eigen::Matrix3d J_;
  Eigen::PartialPivLU<Eigen::Matrix3d> lu_;
};

TEST(SundialsIda, DampedOscillatorMatchesTheAnalyticSolution) {
  const double omega = 2.0 * M_PI / 10.0, zeta = 0.05;
  Oscillator system(omega, zeta);
  IdaOptions options;
  options.relative_tolerance = 1e-9;
  options.absolute_tolerance = 1e-11;
  options.differential_id = Eigen::Vector3d(1.0, 1.0, 0.0);
  const Eigen::Vector3d y0(1.0, 0.0, 0.0), yp0(0.0, -omega * omega, 0.0);
  IdaIntegrator ida(system, 0.0, y0, yp0, options);
  double max_error = 0.0;
  for (int k = 1; k <= 100; ++k) {
    const double t = 0.5 * k;
    ida.advance_to(t);
    max_error = std::max(max_error, std::abs(ida.state()[0] - damped_oscillator(t, omega, zeta)));
    // Outputs are IDA's interpolating polynomial between steps, so the
    // algebraic component is exact at the steps only (≈ rtol·h² between).
    EXPECT_NEAR(ida.state()[2], std::sin(t), 1e-8);
  }
  // Tolerance: rtol 1e-9 over 5 periods; BDF global error grows ~linearly
  // with the number of steps, 1e-6 leaves a decade of margin.
  EXPECT_LT(max_error, 1e-6);
  const IdaStatistics s = ida.statistics();
  EXPECT_GT(s.steps, 0);
  EXPECT_GT(s.newton_matrix_setups, 0);
  EXPECT_EQ(s.newton_matrix_setups, system.setups);
  EXPECT_LE(s.newton_matrix_setups, s.steps);  // matrices are reused across steps
}

TEST(SundialsIda, OrderTwoStaysStableOnAnUndampedOscillatorAtLargeSteps) {
  // BDF2 is A-stable: an oscillation far shorter than the steps is damped
  // out, never amplified.
  const double omega = 2.0 * M_PI / 0.01;
  Oscillator system(omega, 0.0);
  IdaOptions options;
  options.max_order = 2;
  options.relative_tolerance = 1e-3;
  options.absolute_tolerance = 1e-3;
  options.initial_step_s = 0.05;
  options.differential_id = Eigen::Vector3d(1.0, 1.0, 0.0);
  IdaIntegrator ida(system, 0.0, Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, -omega * omega, 0.0), options);
  ida.advance_to(20.0);
  EXPECT_LE(std::abs(ida.state()[0]), 1.0 + 1e-9);
}

/// n uncoupled damped oscillators of different frequencies, x_i'' + 2ζω_i x_i'
/// + ω_i² x_i = 0, states [x_1, v_1, x_2, v_2, …], the 2×2 blocks of the
/// Newton matrix solved in closed form.
class ManyOscillators : public ImplicitSystem {
 public:
  explicit ManyOscillators(int n) : omega_(Eigen::VectorXd::LinSpaced(n, 0.5, 3.0)) {}
  /// y0, y'0 of every oscillator released at rest from x = 1.
  std::pair<Eigen::VectorXd, Eigen::VectorXd> released_from_unit_displacement() const {
    Eigen::VectorXd y0 = Eigen::VectorXd::Zero(2 * omega_.size()), yp0 = Eigen::VectorXd::Zero(2 * omega_.size());
    for (Eigen::Index i = 0; i < omega_.size(); ++i) {
      y0[2 * i] = 1.0;
      yp0[2 * i + 1] = -omega_[i] * omega_[i];
    }
    return {y0, yp0};
  }
  void residual(double, const VectorConstRef& y, const VectorConstRef& yp, VectorRef r) override {
    for (Eigen::Index i = 0; i < omega_.size(); ++i) {
      const double w = omega_[i];
      r[2 * i] = yp[2 * i] - y[2 * i + 1];
      r[2 * i + 1] = yp[2 * i + 1] + 2.0 * kZeta * w * y[2 * i + 1] + w * w * y[2 * i];
    }
  }
  bool setup_newton_matrix(double, const VectorConstRef&, const VectorConstRef&, double cj) override {
    cj_ = cj;
    return true;
  }
  void solve_newton_system(double, Eigen::Ref<Eigen::VectorXd> b) override {
    for (Eigen::Index i = 0; i < omega_.size(); ++i) {
      const double w = omega_[i];
      Eigen::Matrix2d J;
      J << cj_, -1.0, w * w, cj_ + 2.0 * kZeta * w;
      b.segment<2>(2 * i) = J.inverse() * Eigen::Vector2d(b.segment<2>(2 * i));
    }
  }

 private:
  static constexpr double kZeta = 0.05;
  Eigen::VectorXd omega_;
  double cj_ = 0.0;
};

TEST(SundialsIda, VectorOperationsOnAPoolGiveTheSameSolution) {
  // 30,000 states in 30 error groups: above the size from which the
  // adapter splits IDA's vector operations over the pool. The elementwise
  // operations and each group's norm are the same arithmetic on the pool,
  // so the solution and IDA's step sequence must be identical bit for bit.
  const int n = 15000;
  auto run = [n](WorkerPool* pool) {
    ManyOscillators system(n);
    IdaOptions options;
    options.relative_tolerance = 1e-6;
    options.absolute_tolerance = 1e-8;
    for (int g = 0; g < 30; ++g) options.error_group_starts.push_back(1000 * g);
    options.vector_pool = pool;
    const auto [y0, yp0] = system.released_from_unit_displacement();
    IdaIntegrator ida(system, 0.0, y0, yp0, options);
    ida.advance_to(10.0);
    return std::make_pair(Eigen::VectorXd(ida.state()), ida.statistics().steps);
  };
  WorkerPool pool(2);
  const auto [alone, steps_alone] = run(nullptr);
  const auto [split, steps_split] = run(&pool);
  EXPECT_EQ(steps_alone, steps_split);
  EXPECT_TRUE(alone == split);
  // And it is the oscillators' motion (the slowest one, to the tolerance's order).
  EXPECT_NEAR(alone[0], damped_oscillator(10.0, 0.5, 0.05), 1e-3);
}

TEST(SundialsIda, GroupLocalErrorsNameTheBlockThatLimitsTheStep) {
  // 3,000 oscillators, w from 0.5 to 3 rad/s, in 10 error groups of
  // increasing frequency. The local error of a BDF step of order q scales
  // with w^(q+1) x amplitude: the fast groups limit the step, by far.
  const int n = 3000, groups = 10;
  ManyOscillators system(n);
  IdaOptions options;
  for (int g = 0; g < groups; ++g) options.error_group_starts.push_back(2 * (n / groups) * g);
  const auto [y0, yp0] = system.released_from_unit_displacement();
  IdaIntegrator ida(system, 0.0, y0, yp0, options);
  const std::vector<double> before = ida.group_local_errors();
  ASSERT_EQ(before.size(), static_cast<std::size_t>(groups));
  for (double e : before) EXPECT_EQ(e, 0.0);  // no step yet

  for (double t : {1.0, 5.0, 10.0}) {
    ida.advance_to(t);
    const std::vector<double> err = ida.group_local_errors();
    ASSERT_EQ(err.size(), static_cast<std::size_t>(groups));
    // An accepted step has each group's WRMS error <= 1, so no state of a
    // group of m states exceeds sqrt(m).
    for (double e : err) {
      EXPECT_TRUE(std::isfinite(e));
      EXPECT_LE(e, std::sqrt(2.0 * n / groups));
    }
    std::string values;
    for (double e : err) values += std::to_string(e) + " ";
    // Within a group the largest error moves with the oscillators' phases,
    // so the two fastest groups share the lead (at t = 5 s: 0.46 and 0.32,
    // the slowest 8e-5).
    EXPECT_GE(std::max_element(err.begin(), err.end()) - err.begin(), groups - 2) << "at t = " << t << ": " << values;
    const double slow = *std::max_element(err.begin(), err.begin() + 3);  // w < 1.25 rad/s
    const double fast = *std::max_element(err.end() - 3, err.end());      // w > 2.25 rad/s
    EXPECT_GT(fast, 10.0 * slow) << values;
  }
}

TEST(SundialsIda, OneGroupWithoutGroupStarts) {
  Oscillator system(1.0, 0.0);
  IdaIntegrator ida(system, 0.0, Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, -1.0, 1.0));
  ida.advance_to(1.0);
  const std::vector<double> err = ida.group_local_errors();
  ASSERT_EQ(err.size(), 1u);
  EXPECT_GT(err[0], 0.0);
  EXPECT_LE(err[0], std::sqrt(3.0));
}

// y' = −k(t)·(y − sin t), a stiff relaxation onto sin t whose stiffness
// grows 100× (1e3 → 1e5 /s, far above c_j ≈ 1.5/h) over half a second.
// The Newton matrix cj + k(t_setup) is kept between setups (cj changes by
// < 25 %, fewer than 20 steps), so after the
// ramp starts it underestimates k: for this linear residual each Newton
// iteration multiplies the error by (k − k_setup)/(cj + k_setup), above
// IDA's divergence limit 0.9 once k has grown ≈ 2× since the setup.
class StiffeningRelaxation : public ImplicitSystem {
 public:
  static double stiffness_per_s(double t) {
    const double s = std::clamp((t - 1.0) / 0.5, 0.0, 1.0);
    return 1e3 * std::exp(std::log(100.0) * s * s * (3.0 - 2.0 * s));  // smoothstep in log k
  }
  void residual(double t, const VectorConstRef& y, const VectorConstRef& yp, VectorRef r) override {
    r[0] = yp[0] + stiffness_per_s(t) * (y[0] - std::sin(t));
  }
  bool setup_newton_matrix(double t, const VectorConstRef&, const VectorConstRef&, double cj) override {
    matrix_ = cj + stiffness_per_s(t);
    return true;
  }
  void solve_newton_system(double, Eigen::Ref<Eigen::VectorXd> b) override { b /= matrix_; }

 private:
  double matrix_ = 1.0;
};

struct RelaxationRun {
  IdaStatistics statistics;
  double y_end = 0.0;
};

RelaxationRun run_relaxation(bool restart, double rtol) {
  StiffeningRelaxation system;
  IdaOptions options;
  options.relative_tolerance = rtol;
  options.absolute_tolerance = 1e-3 * rtol;
  options.max_order = 2;
  options.restart_newton_on_fresh_matrix = restart;
  // Consistent start on the slow manifold: y ≈ sin t − cos t / k.
  const double k0 = StiffeningRelaxation::stiffness_per_s(0.0);
  const Eigen::VectorXd y0 = Eigen::VectorXd::Constant(1, -1.0 / k0);
  const Eigen::VectorXd yp0 = Eigen::VectorXd::Constant(1, -k0 * y0[0]);
  IdaIntegrator ida(system, 0.0, y0, yp0, options);
  ida.advance_to(3.0);
  return {ida.statistics(), ida.state()[0]};
}

TEST(SundialsIda, ANewtonSolveThatDivergesOnAStaleMatrixGoesOnOnAFreshOne) {
  const RelaxationRun without = run_relaxation(false, 1e-6);
  const RelaxationRun with = run_relaxation(true, 1e-6);
  const RelaxationRun reference = run_relaxation(true, 1e-11);
  // The premise: on the stale matrix the solves diverge and each failure is
  // a step retried 4× smaller.
  EXPECT_GT(without.statistics.nonlinear_convergence_failures, 0);
  EXPECT_EQ(without.statistics.newton_restarts, 0);
  // Going on with a fresh matrix at the iterate converges: no step fails.
  EXPECT_GT(with.statistics.newton_restarts, 0);
  EXPECT_EQ(with.statistics.nonlinear_convergence_failures, 0);
  EXPECT_LT(with.statistics.steps, without.statistics.steps);
  // Both are solutions to the tolerance: rtol 1e-6 on |y| ≤ 1, the stiff
  // relaxation damping the local errors (measured 1e-8 and 2e-9).
  EXPECT_NEAR(with.y_end, reference.y_end, 1e-6);
  EXPECT_NEAR(without.y_end, reference.y_end, 1e-6);
}

TEST(SundialsIda, RejectsInconsistentSizes) {
  Oscillator system(1.0, 0.0);
  EXPECT_THROW(IdaIntegrator(system, 0.0, Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero()), std::invalid_argument);
  IdaOptions bad;
  bad.max_order = 6;
  EXPECT_THROW(IdaIntegrator(system, 0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), bad),
               std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
