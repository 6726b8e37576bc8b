// The warm-start plan of the optimizer's full evaluations: each scenario
// starts from the nearest solved state of its environment, chains through
// close neighbours, and never across environments.

#include "design/optimization/warm_start_plan.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace spiral::design {
namespace {

/// One riser whose top is at (x, y, 0) now (predicted) and was at (ox, oy, 0).
WarmStartNode node(int environment, double x, double y, std::optional<Eigen::Vector2d> own = std::nullopt) {
  WarmStartNode n;
  n.environment = environment;
  n.predicted_tops_g = {Eigen::Vector3d(x, y, 0.0)};
  if (own) n.own_tops_g = {Eigen::Vector3d(own->x(), own->y(), 0.0)};
  return n;
}

TEST(WarmStartPlan, AClusterMovedTogetherPaysOneLongMove) {
  // Four scenarios 0.5 m apart, each moved 20 m: the first starts from its
  // own state, the others chain from it.
  std::vector<WarmStartNode> nodes;
  for (int i = 0; i < 4; ++i) nodes.push_back(node(0, 20.0, 0.5 * i, Eigen::Vector2d(0.0, 0.5 * i)));
  const std::vector<WarmStart> plan = plan_warm_starts(nodes);
  EXPECT_FALSE(plan[0].donor.has_value());
  EXPECT_DOUBLE_EQ(plan[0].distance_m, 20.0);
  for (int i = 1; i < 4; ++i) {
    ASSERT_TRUE(plan[static_cast<std::size_t>(i)].donor.has_value());
    EXPECT_EQ(*plan[static_cast<std::size_t>(i)].donor, i - 1);
    EXPECT_EQ(plan[static_cast<std::size_t>(i)].wave, i);
    EXPECT_NEAR(plan[static_cast<std::size_t>(i)].distance_m, 0.5, 1e-12);
  }
  const std::vector<std::vector<int>> waves = warm_start_waves(plan);
  ASSERT_EQ(waves.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(waves[static_cast<std::size_t>(i)], std::vector<int>{i});
}

TEST(WarmStartPlan, AScenarioThatHardlyMovedKeepsItsOwnState) {
  // Scenario 1 is 0.1 m from its own state and 5 m from scenario 0.
  const std::vector<WarmStart> plan =
      plan_warm_starts({node(0, 0.0, 0.0, Eigen::Vector2d(30.0, 0.0)), node(0, 5.0, 0.0, Eigen::Vector2d(5.1, 0.0))});
  EXPECT_FALSE(plan[1].donor.has_value());
  EXPECT_EQ(plan[1].wave, 0);
  EXPECT_NEAR(plan[1].distance_m, 0.1, 1e-12);
  // Scenario 0 (30 m from its own) starts from scenario 1, 5 m away.
  ASSERT_TRUE(plan[0].donor.has_value());
  EXPECT_EQ(*plan[0].donor, 1);
  EXPECT_EQ(plan[0].wave, 1);
}

TEST(WarmStartPlan, NeverStartsFromAnotherEnvironment) {
  // Scenario 1 lies on scenario 0 but in another current: its own state, 40 m off.
  const std::vector<WarmStart> plan =
      plan_warm_starts({node(0, 0.0, 0.0, Eigen::Vector2d(0.0, 0.0)), node(1, 0.0, 0.0, Eigen::Vector2d(40.0, 0.0))});
  EXPECT_FALSE(plan[1].donor.has_value());
  EXPECT_NEAR(plan[1].distance_m, 40.0, 1e-12);
}

TEST(WarmStartPlan, TheDistanceIsTheRiserThatMovesMost) {
  // Two risers: a yaw moves one top 3 m and the other not at all.
  WarmStartNode a;
  a.predicted_tops_g = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 3, 0)};
  a.own_tops_g = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 0, 0)};
  EXPECT_NEAR(plan_warm_starts({a})[0].distance_m, 3.0, 1e-12);
}

TEST(WarmStartPlan, AScenarioNeverSolvedStartsFromItsEnvironment) {
  const std::vector<WarmStart> plan =
      plan_warm_starts({node(0, 0.0, 0.0, Eigen::Vector2d(0.0, 0.0)), node(0, 2.0, 0.0)});
  ASSERT_TRUE(plan[1].donor.has_value());
  EXPECT_EQ(*plan[1].donor, 0);
  EXPECT_THROW(plan_warm_starts({node(0, 0.0, 0.0)}), std::invalid_argument);
  EXPECT_THROW(plan_warm_starts({node(0, 0.0, 0.0, Eigen::Vector2d(0.0, 0.0)), node(1, 0.0, 0.0)}),
               std::invalid_argument);
}

TEST(WarmStartPlan, RiserCountsMustAgreeWithinAnEnvironment) {
  WarmStartNode two = node(0, 0.0, 0.0, Eigen::Vector2d(0.0, 0.0));
  two.predicted_tops_g.push_back(Eigen::Vector3d::Zero());
  two.own_tops_g.push_back(Eigen::Vector3d::Zero());
  EXPECT_THROW(plan_warm_starts({node(0, 1.0, 0.0, Eigen::Vector2d(0.0, 0.0)), two}), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::design
