// The scenario model's analytic payout sensitivities against central
// differences of whole equilibria, at random payout vectors, intact and with
// a line removed.

#include "design/optimization/scenario_model.hpp"

#include <gtest/gtest.h>

#include <random>

#include "design/model/hull_model.hpp"
#include "design/project/validated_project.hpp"
#include "tests/unit/design/optimization/optimization_fixture.hpp"

namespace spiral::design {
namespace {

// The reference is central differences of equilibria solved to 1e-9 of the
// force scale (a few mN on OC4), with a 5 cm payout step: the equilibrium's
// round-off then moves a tension slope by ~1e-4 N/m, while the O(h²)
// truncation, measured on OC4 between 3 cm and 10 cm steps, stays below 3e-6
// of the slope (a 1 cm step is already round-off limited: 5e-5). The
// analytic side is exact to the solver tolerances. Hence 2e-5 of the
// quantity's gradient norm; a missed term (a line's own weight, the
// environment's yaw stiffness, the Euler-rate map of the rotations) is
// 1e-4 to 1.
constexpr double kRelative = 2e-5;

void expect_close(const Eigen::VectorXd& analytic, const Eigen::VectorXd& numeric, const std::string& what) {
  const double scale = std::max(numeric.norm(), 1e-12);
  EXPECT_LE((analytic - numeric).norm(), kRelative * scale)
      << what << "\n analytic " << analytic.transpose() << "\n numeric  " << numeric.transpose();
}

void check_scenario(const ValidatedProject& p, const Scenario& scenario, int points) {
  const std::vector<PayoutGroup> groups = payout_groups(p.project);
  ASSERT_EQ(groups.size(), 3u);
  const HullModel hull = build_hull_model(p.project);
  ScenarioModel model(p.project, hull, groups, scenario);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> payout(-10.0, 10.0);
  for (int k = 0; k < points; ++k) {
    Eigen::VectorXd x(3);
    for (int g = 0; g < 3; ++g) x(g) = payout(rng);
    const ScenarioResponse analytic = model.evaluate(x, true);
    const ScenarioResponse numeric = model.evaluate_by_differences(x, 0.05);
    SCOPED_TRACE(scenario.label() + " at payouts " + std::to_string(x(0)) + ", " + std::to_string(x(1)) + ", " +
                 std::to_string(x(2)));
    expect_close(analytic.d_horizontal_offset.row(0).transpose(), numeric.d_horizontal_offset.row(0).transpose(),
                 "d surge");
    expect_close(analytic.d_horizontal_offset.row(1).transpose(), numeric.d_horizontal_offset.row(1).transpose(),
                 "d sway");
    ASSERT_EQ(analytic.lines.size(), numeric.lines.size());
    for (std::size_t i = 0; i < analytic.lines.size(); ++i) {
      const LineResponse& a = analytic.lines[i];
      const LineResponse& n = numeric.lines[i];
      expect_close(a.d_fairlead_tension_N, n.d_fairlead_tension_N, a.name + " d tension");
      expect_close(a.d_utilization, n.d_utilization, a.name + " d utilization");
      expect_close(a.d_laid_length_m, n.d_laid_length_m, a.name + " d laid length");
    }
  }
}

TEST(ScenarioModel, AnalyticPayoutGradientsMatchDifferencesIntact) {
  const ValidatedProject p = testing::oc4_optimization_project(1.5, 30.0);
  check_scenario(p, {"current", std::nullopt, DesignCondition::extreme}, 3);
}

TEST(ScenarioModel, AnalyticPayoutGradientsMatchDifferencesDamaged) {
  const ValidatedProject p = testing::oc4_optimization_project(0.6, 30.0);
  // Without L1 (anchor at 60°) L2 and L3 hold a current towards 30°.
  check_scenario(p, {"current", std::string("L1"), DesignCondition::survival}, 2);
}

TEST(ScenarioModel, PayingOutSlackensTheLineAndMovesTheHullAway) {
  const ValidatedProject p = testing::oc4_optimization_project(0.0, 0.0, true);
  const std::vector<PayoutGroup> groups = payout_groups(p.project);
  const HullModel hull = build_hull_model(p.project);
  ScenarioModel model(p.project, hull, groups, {"still", std::nullopt, DesignCondition::extreme});
  const ScenarioResponse at_rest = model.evaluate(Eigen::VectorXd::Zero(3), true);
  // L2 (anchor at 180°) paid out: its tension falls, and the hull drifts
  // towards +x, away from L2's anchor.
  EXPECT_LT(at_rest.lines[1].d_fairlead_tension_N(1), 0.0) << at_rest.lines[1].d_fairlead_tension_N.transpose();
  EXPECT_GT(at_rest.d_horizontal_offset(0, 1), 0.0) << at_rest.d_horizontal_offset;
  // By symmetry the three equal lines hold the hull at zero horizontal offset.
  EXPECT_NEAR(std::hypot(at_rest.offset(0), at_rest.offset(1)), 0.0, 1e-7) << at_rest.offset.transpose();
}

// A scenario the study removed a line from, started at its load case's
// intact equilibrium (the intact risers' FE solutions and offset), reaches
// the same equilibrium as when it is solved cold: both are converged to the
// solver's 1e-9 relative residual, so they agree to far better than the
// 1e-6 of a tension or 1 mm of offset asked here (the default scenario: 12
// FE SCRs under the 1.5 m/s current).
TEST(ScenarioModel, ADamagedScenarioStartedFromItsIntactCaseReachesTheColdEquilibrium) {
  const ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  const std::vector<PayoutGroup> groups = payout_groups(p.project);
  const HullModel hull = build_hull_model(p.project);
  const std::string name = "lc2-survival-collinear-45deg";
  const Scenario damaged{name, std::string("L9"), DesignCondition::extreme, true};
  ScenarioModel intact(p.project, hull, groups, {name, std::nullopt, DesignCondition::extreme});
  ScenarioModel warm(p.project, hull, groups, damaged);
  ScenarioModel cold(p.project, hull, groups, damaged);
  Eigen::VectorXd payouts = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(groups.size()));
  payouts(0) = -5.0;
  intact.evaluate(payouts, false);
  warm.start_from(intact);
  const ScenarioResponse a = warm.evaluate(payouts, false);
  const ScenarioResponse b = cold.evaluate(payouts, false);
  EXPECT_LT((a.offset.head<3>() - b.offset.head<3>()).norm(), 1e-3);
  ASSERT_EQ(a.lines.size(), b.lines.size());
  for (std::size_t k = 0; k < a.lines.size(); ++k)
    EXPECT_NEAR(a.lines[k].fairlead_tension_N, b.lines[k].fairlead_tension_N, 1e-6 * b.lines[k].fairlead_tension_N)
        << a.lines[k].name;
  // The damaged hull moves: the start was not simply kept.
  EXPECT_GT(b.offset.head<2>().norm(), 1.0);
}

// The optimizer's waves (warm_start_plan.hpp): a scenario whose risers start
// from a neighbouring scenario's solution (lc2 without L10, solved at the
// new payouts) reaches the equilibrium it reaches from its own last state,
// to the solver tolerance (same bounds as above). The prediction on
// linearized risers that places the full solve's start lands within a tenth
// of the hull's move.
TEST(ScenarioModel, RisersStartedFromANeighbourReachTheSameEquilibrium) {
  const ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  const std::vector<PayoutGroup> groups = payout_groups(p.project);
  const HullModel hull = build_hull_model(p.project);
  const std::string name = "lc2-survival-collinear-45deg";
  ScenarioModel intact(p.project, hull, groups, {name, std::nullopt, DesignCondition::extreme});
  ScenarioModel own(p.project, hull, groups, {name, std::string("L9"), DesignCondition::extreme, true});
  ScenarioModel borrowed(p.project, hull, groups, {name, std::string("L9"), DesignCondition::extreme, true});
  ScenarioModel neighbour(p.project, hull, groups, {name, std::string("L10"), DesignCondition::extreme, true});
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(groups.size()));
  intact.evaluate(zero, false);
  for (ScenarioModel* m : {&own, &borrowed, &neighbour}) {
    m->start_from(intact);
    m->evaluate(zero, false);
  }
  const engine::Vector6d before = own.evaluate(zero, false).offset;
  Eigen::VectorXd payouts = zero;
  payouts(0) = -12.0;
  payouts(2) = -12.0;
  neighbour.evaluate(payouts, false);

  const std::optional<engine::HullPose> predicted = own.predict(payouts);
  ASSERT_TRUE(predicted.has_value());
  const ScenarioResponse a = own.evaluate(payouts, false);
  ASSERT_TRUE(borrowed.predict(payouts).has_value());
  borrowed.start_risers_from(neighbour);
  const ScenarioResponse b = borrowed.evaluate(payouts, false);

  EXPECT_LT((a.offset.head<3>() - b.offset.head<3>()).norm(), 1e-3);
  ASSERT_EQ(a.lines.size(), b.lines.size());
  for (std::size_t k = 0; k < a.lines.size(); ++k)
    EXPECT_NEAR(a.lines[k].fairlead_tension_N, b.lines[k].fairlead_tension_N, 1e-6 * b.lines[k].fairlead_tension_N)
        << a.lines[k].name;
  const double moved_m = (a.offset.head<3>() - before.head<3>()).norm();
  EXPECT_GT(moved_m, 5.0);
  const Eigen::Vector3d predicted_offset = predicted->reference_point_g - hull.statics.reference_point_at_rest_g;
  EXPECT_LT((predicted_offset - a.offset.head<3>()).norm(), 0.1 * moved_m);
}

}  // namespace
}  // namespace spiral::design
