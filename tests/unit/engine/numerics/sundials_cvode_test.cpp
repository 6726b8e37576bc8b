// The CVODE adapter: accuracy on closed-form ODEs for every method,
// statistics, and the error paths (fatal RHS exception rethrown, recoverable
// RHS failures, too much work, invalid options).

#include "engine/numerics/sundials_cvode.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/expect_near.hpp"

namespace spiral::engine {
namespace {

// rtol 1e-10 on a decaying exponential over 5 time constants: the global
// error stays within ~100 local tolerances.
constexpr double kExpRelTol = 1e-8;

class CvodeMethods : public testing::TestWithParam<CvodeMethod> {};

TEST_P(CvodeMethods, ExponentialDecayMatchesClosedForm) {
  CvodeOptions o;
  o.method = GetParam();
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-14;
  const std::vector<double> times{0.0, 1.0, 2.5, 5.0};
  const auto sol = integrate_ode([](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) { ydot = -y; }, 0.0,
                                 Eigen::VectorXd::Constant(1, 1.0), times, o);
  ASSERT_EQ(sol.states.cols(), 4);
  for (int k = 0; k < 4; ++k) EXPECT_REL_NEAR(sol.states(0, k), std::exp(-times[k]), kExpRelTol);
  EXPECT_GT(sol.statistics.steps, 0);
  EXPECT_GT(sol.statistics.rhs_evaluations, sol.statistics.steps / 2);
  if (GetParam() == CvodeMethod::adams_fixed_point) {
    EXPECT_EQ(sol.statistics.jacobian_evaluations, 0);
  } else {
    EXPECT_GT(sol.statistics.jacobian_evaluations, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(AllMethods, CvodeMethods,
                         testing::Values(CvodeMethod::bdf_newton_dense, CvodeMethod::adams_newton_dense,
                                         CvodeMethod::adams_fixed_point));

TEST(CvodeAdapter, FatalRhsExceptionIsRethrownUnchanged) {
  const auto rhs = [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    if (t > 0.5) throw std::out_of_range("table lookup beyond 0.5 s");
    ydot = -y;
  };
  CvodeIntegrator integrator(rhs, 0.0, Eigen::VectorXd::Ones(2));
  try {
    integrator.advance_to(1.0);
    FAIL() << "expected std::out_of_range";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "table lookup beyond 0.5 s");
  }
}

TEST(CvodeAdapter, RepeatedRecoverableFailuresBecomeIntegrationErrorWithContext) {
  const auto rhs = [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    if (t > 1.0) throw SolverError("line 3: catenary did not converge");
    ydot = -y;
  };
  // CVODE retries with ever smaller steps towards t = 1 s; a small step budget
  // keeps the test fast.
  CvodeOptions o;
  o.max_steps_between_outputs = 5000;
  CvodeIntegrator integrator(rhs, 0.0, Eigen::VectorXd::Ones(1), o);
  try {
    integrator.advance_to(2.0);
    FAIL() << "expected IntegrationError";
  } catch (const IntegrationError& e) {
    EXPECT_LE(e.time_reached_s(), 1.0 + 1e-12);
    EXPECT_GT(e.time_reached_s(), 0.5);
    EXPECT_NE(std::string(e.what()).find("line 3: catenary did not converge"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Hint"), std::string::npos) << e.what();
  }
  EXPECT_GT(integrator.statistics().recoverable_rhs_failures, 0);
}

TEST(CvodeAdapter, NonFiniteDerivativeIsRecoverableThenReported) {
  const auto rhs = [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
    ydot = -y;
    if (t > 1.0) ydot(0) = std::nan("");
  };
  CvodeOptions o;
  o.max_steps_between_outputs = 5000;
  EXPECT_THROW(integrate_ode(rhs, 0.0, Eigen::VectorXd::Ones(1), std::vector<double>{2.0}, o), IntegrationError);
}

TEST(CvodeAdapter, TooMuchWorkReportsTimeReachedAndStep) {
  CvodeOptions o;
  o.max_steps_between_outputs = 20;
  o.max_step_s = 0.01;
  CvodeIntegrator integrator([](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) { ydot = -y; }, 0.0,
                             Eigen::VectorXd::Ones(1), o);
  try {
    integrator.advance_to(100.0);
    FAIL() << "expected IntegrationError";
  } catch (const IntegrationError& e) {
    EXPECT_EQ(e.cvode_flag(), -1);  // CV_TOO_MUCH_WORK
    // 20 steps of at most 0.01 s (CVODE's first steps are smaller).
    EXPECT_GT(e.time_reached_s(), 0.0);
    EXPECT_LE(e.time_reached_s(), 0.2 + 1e-12);
    EXPECT_GT(e.last_step_s(), 0.0);
    EXPECT_NE(std::string(e.what()).find("CV_TOO_MUCH_WORK"), std::string::npos) << e.what();
  }
}

TEST(CvodeAdapter, StopTimeIsHonoured) {
  std::vector<double> seen;
  CvodeIntegrator integrator(
      [&seen](double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
        seen.push_back(t);
        ydot = -y;
      },
      0.0, Eigen::VectorXd::Ones(1));
  integrator.set_stop_time(1.0);
  integrator.advance_to(0.5);
  integrator.advance_to(1.0);
  for (double t : seen) EXPECT_LE(t, 1.0 + 1e-12);
  EXPECT_REL_NEAR(integrator.state()(0), std::exp(-1.0), 1e-6);
}

TEST(CvodeAdapter, InvalidInputsThrowInvalidArgument) {
  const OdeRightHandSide rhs = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) { ydot = y; };
  CvodeOptions bad;
  bad.relative_tolerance = 0.0;
  EXPECT_THROW(CvodeIntegrator(rhs, 0.0, Eigen::VectorXd::Ones(1), bad), std::invalid_argument);
  EXPECT_THROW(CvodeIntegrator(rhs, 0.0, Eigen::VectorXd(), {}), std::invalid_argument);
  CvodeOptions bad_atol;
  bad_atol.absolute_tolerances = Eigen::VectorXd::Ones(3);
  EXPECT_THROW(CvodeIntegrator(rhs, 0.0, Eigen::VectorXd::Ones(2), bad_atol), std::invalid_argument);
  EXPECT_THROW(integrate_ode(rhs, 0.0, Eigen::VectorXd::Ones(1), std::vector<double>{1.0, 0.5}), std::invalid_argument);
  CvodeIntegrator ok(rhs, 0.0, Eigen::VectorXd::Ones(1));
  EXPECT_THROW(ok.advance_to(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
