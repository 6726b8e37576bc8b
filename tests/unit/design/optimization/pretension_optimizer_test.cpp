// The pretension optimizer on problems whose answer is known: a symmetric
// spread (equal payouts by symmetry), a one-variable problem whose optimum a
// bisection on the active constraint finds, and an infeasible set-up.

#include "design/optimization/pretension_optimizer.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "design/optimization/pretension_problem.hpp"
#include "tests/unit/design/optimization/optimization_fixture.hpp"

namespace spiral::design {
namespace {

// Still water, three equal lines 120° apart: the least winching that lifts
// every fairlead tension to a minimum above the pretension hauls each line in
// by the same length (the problem is symmetric under the 120° turn), and the
// minimum-tension constraint is active on all three.
TEST(PretensionOptimizer, SymmetricSpreadGivesEqualPayouts) {
  ValidatedProject p = testing::oc4_optimization_project(0.0, 0.0, true);
  p.project.optimization->objective = OptimizationObjective::min_total_payout;
  p.project.optimization->cases = {"still"};
  p.project.optimization->min_tension_N = 1.30e6;  // OC4 pretension ≈ 1.13 MN
  p.project.criteria.max_offset_pct_depth.reset();
  const OptimizationResult r = optimize_pretension(p, {});
  ASSERT_EQ(r.status, OptimizationStatus::optimal) << r.stop_reason;
  ASSERT_EQ(r.payouts_m.size(), 3u);
  EXPECT_LT(r.payouts_m[0], -0.5);
  // Payout tolerance 0.05 m (the stopping rule); symmetry holds far tighter
  // since every line sees the same constraint.
  EXPECT_NEAR(r.payouts_m[1], r.payouts_m[0], 1e-3);
  EXPECT_NEAR(r.payouts_m[2], r.payouts_m[0], 1e-3);
  for (const ScenarioSummary& s : r.after) EXPECT_NEAR(s.min_fairlead_tension_N, 1.30e6, 1e-4 * 1.30e6);
  EXPECT_GT(r.evaluations, 1);
}

// One variable (all three lines together) against a current along +x:
// hauling in stiffens the spread (the offset falls) and loads the windward
// line (its utilization rises). Minimizing the offset subject to
// utilization ≤ 1 puts the optimum where the windward line's utilization
// reaches 1; the safety factor is set so that this happens at −5 m. A
// bisection on the utilization finds it independently.
TEST(PretensionOptimizer, OneVariableOptimumMatchesBisectionOnTheActiveConstraint) {
  ValidatedProject p = testing::oc4_optimization_project(1.5, 0.0);
  p.project.mooring.groups = {{"all", {"L1", "L2", "L3"}}};
  p.project.optimization->groups = {"all"};
  p.project.optimization->objective = OptimizationObjective::min_max_offset;
  p.project.optimization->cases = {"current"};
  p.project.optimization->bounds = {{"all", -12.0, 12.0}};
  p.project.criteria.max_offset_pct_depth.reset();

  // Scale the safety factor so that the worst utilization is 1 at −5 m.
  {
    PretensionProblem problem(p, {});
    const ProblemEvaluation e = problem.evaluate(Eigen::VectorXd::Constant(1, -5.0), false);
    const ScenarioSummary s = problem.summarize(0, e);
    p.project.criteria.mooring.api_rp_2sk->intact_quasi_static /= s.worst_utilization;
  }
  // Reference: bisection of worst utilization − 1 over the payout.
  PretensionProblem reference(p, {});
  const auto excess = [&](double payout) {
    const ProblemEvaluation e = reference.evaluate(Eigen::VectorXd::Constant(1, payout), false);
    return reference.summarize(0, e).worst_utilization - 1.0;
  };
  double lo = -12.0, hi = 0.0;  // utilization above 1 at lo, below at hi
  ASSERT_GT(excess(lo), 0.0);
  ASSERT_LT(excess(hi), 0.0);
  while (hi - lo > 1e-5) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) > 0.0 ? lo : hi) = mid;
  }
  const double expected = 0.5 * (lo + hi);
  EXPECT_NEAR(expected, -5.0, 1e-3);

  for (const OptimizationAlgorithm algorithm : {OptimizationAlgorithm::slsqp, OptimizationAlgorithm::ccsaq}) {
    OptimizationRequest request;
    request.algorithm = algorithm;
    const OptimizationResult r = optimize_pretension(p, request);
    SCOPED_TRACE(to_string(algorithm));
    ASSERT_EQ(r.status, OptimizationStatus::optimal) << r.stop_reason;
    EXPECT_NEAR(r.payouts_m[0], expected, 1e-3);
    EXPECT_LT(r.objective_best, r.objective_start);
    // The active constraint is the windward line's utilization, with a
    // positive multiplier (relaxing it would let the offset fall further).
    const auto active = std::find_if(r.active.begin(), r.active.end(), [](const ActiveConstraint& a) {
      return a.name.find("utilization of L2") != std::string::npos;
    });
    ASSERT_NE(active, r.active.end());
    EXPECT_GT(active->multiplier, 0.0);
  }
  // Gradient-free: coarser, same optimum to its stopping tolerance.
  OptimizationRequest cobyla;
  cobyla.algorithm = OptimizationAlgorithm::cobyla;
  const OptimizationResult r = optimize_pretension(p, cobyla);
  ASSERT_EQ(r.status, OptimizationStatus::optimal) << r.stop_reason;
  EXPECT_NEAR(r.payouts_m[0], expected, 0.05);
}

TEST(PretensionOptimizer, InfeasibleProblemNamesTheMostViolatedConstraint) {
  ValidatedProject p = testing::oc4_optimization_project(1.5, 0.0);
  p.project.optimization->objective = OptimizationObjective::min_max_utilization;
  p.project.optimization->cases = {"current"};
  p.project.criteria.max_offset_pct_depth = 0.05;  // 10 cm at 200 m: no payout holds a 1.5 m/s current that close
  const OptimizationResult r = optimize_pretension(p, {});
  EXPECT_EQ(r.status, OptimizationStatus::infeasible);
  ASSERT_TRUE(r.most_violated.has_value());
  EXPECT_EQ(r.most_violated->kind, "offset_limit");
  EXPECT_GT(r.most_violated->value, 0.0);
}

TEST(PretensionOptimizer, DamagedConditionsOfEveryLineAreScenarios) {
  ValidatedProject p = testing::oc4_optimization_project(1.0, 0.0);
  p.project.optimization->cases = {"current"};
  p.project.optimization->damaged = DamagedConditions::every_line;
  p.project.optimization->objective = OptimizationObjective::min_max_utilization;
  p.project.optimization->max_evaluations = 3;
  const OptimizationResult r = optimize_pretension(p, {});
  ASSERT_EQ(r.scenarios.size(), 4u);
  EXPECT_EQ(r.scenarios[1], "current without L1");
  EXPECT_LE(r.evaluations, 4);  // the start and the cap
}

}  // namespace
}  // namespace spiral::design

namespace spiral::design {
namespace {

// A riser that fails its criteria with the hull at rest has no zone: no
// pretension can help, and the optimizer says so, naming the riser and the
// criterion (a finding for the riser team), instead of optimizing against an
// empty zone.
TEST(PretensionOptimizer, RiserWithoutZoneIsAFindingNamingTheRiserAndCriterion) {
  ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  p.project.criteria.risers.max_top_tension_N = 1.0e6;  // at-rest top tensions are 2.8 to 3.0 MN
  p.project.optimization = Optimization{};
  p.project.optimization->cases = {"lc5-operating-45deg"};
  p.project.optimization->max_evaluations = 2;
  const OptimizationResult r = optimize_pretension(p, {});
  EXPECT_EQ(r.status, OptimizationStatus::infeasible);
  ASSERT_FALSE(r.findings.empty());
  EXPECT_NE(r.findings.front().find("fails max_top_tension already at zero offset"), std::string::npos)
      << r.findings.front();
  EXPECT_NE(r.findings.front().find("riser P"), std::string::npos) << r.findings.front();
  EXPECT_EQ(r.objective, OptimizationObjective::min_max_offset);  // no zone: the offset is the measure
}

}  // namespace
}  // namespace spiral::design

namespace spiral::design {
namespace {

// The dynamic level: the constraints on each case's enhanced S-C storm (OC4,
// the RAFT JONSWAP sea with current; short storms keep the test quick: the
// MPMs are still 3-h extremes, fitted to fewer cycles). The waves add to the
// static offset, so the MPM offset exceeds it; COBYLA is used whatever was
// asked, and every evaluation keeps the sea (same seed).
TEST(PretensionOptimizer, DynamicLevelConstrainsTheStormExtremes) {
  ValidatedProject p = testing::oc4_optimization_project(0.0, 0.0);
  p.project.load_cases.push_back({"raft", "raft-jonswap", std::nullopt, DesignCondition::extreme});
  p.project.optimization->cases = {"raft"};
  p.project.optimization->objective = OptimizationObjective::min_max_utilization;
  p.project.optimization->max_evaluations = 6;
  p.project.criteria.max_offset_pct_depth = 50.0;
  OptimizationRequest request;
  request.algorithm = OptimizationAlgorithm::slsqp;
  request.dynamic = DynamicLevelOptions{1200.0, 3};
  const OptimizationResult r = optimize_pretension(p, request);
  EXPECT_TRUE(r.dynamic);
  EXPECT_EQ(r.algorithm, OptimizationAlgorithm::cobyla);
  ASSERT_EQ(r.before.size(), 1u);
  ASSERT_TRUE(r.before[0].mpm_offset_m.has_value());
  EXPECT_GT(*r.before[0].mpm_offset_m, r.before[0].offset_m);
  ASSERT_TRUE(r.before[0].worst_dynamic_utilization.has_value());
  // The dynamic check of the worst line exceeds its quasi-static check of the
  // mean position (API RP 2SK: 1.67 on the MPM against 2.0 on the mean, and
  // the storm's peaks well above the mean).
  EXPECT_GT(*r.before[0].worst_dynamic_utilization, 0.0);
  EXPECT_LE(r.objective_best, r.objective_start + 1e-12);
  EXPECT_LE(r.evaluations, 7);
}

}  // namespace
}  // namespace spiral::design
