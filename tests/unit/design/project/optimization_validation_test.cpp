// The `optimization` section: read with positions, and its bad values (bounds
// out of order, a haul-in that leaves a line too short, unknown groups and
// cases) reported as input errors with file:line:col and the field path.

#include <gtest/gtest.h>

#include <string>

#include "design/project/payout_groups.hpp"
#include "design/project/project_loader.hpp"
#include "design/project/project_validation.hpp"
#include "support/project_fixture.hpp"

namespace spiral::design {
namespace {

std::string report(const std::string& text) {
  std::string out;
  for (const InputIssue& issue : check_project(parse_project(text, "test.yaml"), {})) out += format_issue(issue) + "\n";
  return out;
}

std::string with_optimization(const std::string& section) { return kMinimal + "optimization:\n" + section; }

TEST(OptimizationSection, ReadsEveryKey) {
  const Project p = parse_project(with_optimization("  groups: []\n"
                                                    "  bounds: [{group: L1, min: -5.0, max: 7.5}]\n"
                                                    "  payout_limit_pct: 3.0\n"
                                                    "  objective: min_total_payout\n"
                                                    "  algorithm: cobyla\n"
                                                    "  cases: [lc1]\n"
                                                    "  damaged: every_line\n"
                                                    "  min_laid_length: 20.0\n"
                                                    "  min_tension: 1.0e5\n"
                                                    "  payout_tolerance: 0.01\n"
                                                    "  max_evaluations: 50\n"
                                                    "  target_pretension: [{group: L1, tension: 4.0e5}]\n"),
                                  "test.yaml");
  ASSERT_TRUE(p.optimization.has_value());
  const Optimization& o = *p.optimization;
  EXPECT_EQ(o.bounds.size(), 1u);
  EXPECT_DOUBLE_EQ(o.bounds[0].min_m, -5.0);
  EXPECT_DOUBLE_EQ(o.payout_limit_pct, 3.0);
  EXPECT_EQ(o.objective, OptimizationObjective::min_total_payout);
  EXPECT_EQ(o.algorithm, OptimizationAlgorithm::cobyla);
  EXPECT_EQ(o.damaged, DamagedConditions::every_line);
  EXPECT_EQ(o.cases, std::vector<std::string>{"lc1"});
  EXPECT_DOUBLE_EQ(*o.min_laid_length_m, 20.0);
  EXPECT_DOUBLE_EQ(*o.min_tension_N, 1.0e5);
  EXPECT_EQ(o.max_evaluations, 50);
  EXPECT_DOUBLE_EQ(o.target_pretension.at(0).tension_N, 4.0e5);
  EXPECT_EQ(report(with_optimization("  objective: min_total_payout\n")), "");
}

TEST(OptimizationSection, BoundsOutOfOrderAreAnInputError) {
  const std::string issues = report(with_optimization("  bounds: [{group: L1, min: 5.0, max: -5.0}]\n"));
  EXPECT_NE(issues.find("test.yaml:33:29:"), std::string::npos) << issues;
  EXPECT_NE(issues.find("optimization.bounds[0].min: must be below max (-5 m), got 5 m"), std::string::npos) << issues;
}

TEST(OptimizationSection, HaulInThatLeavesTheLineTooShortIsAnInputError) {
  // L1: 550 m against a 498.197 m anchor-fairlead distance at rest, EA 1e9 N,
  // MBL 5e6 N. Hauling in 60 m: straight, the 490 m line stretches 8.197 m,
  // 1.67e7 N; hauling in 52 m: 4e5 N, no error.
  const std::string issues = report(with_optimization("  bounds: [{group: L1, min: -60.0, max: 5.0}]\n"));
  EXPECT_NE(issues.find("test.yaml:33:29: optimization.bounds[0].min: hauling in 60 m leaves line L1 490 m long "
                        "against its anchor-fairlead distance 498.197 m at rest: even straight it would need "
                        "1.673e+07 N, above its breaking load 5e+06 N"),
            std::string::npos)
      << issues;
  EXPECT_EQ(report(with_optimization("  bounds: [{group: L1, min: -52.0, max: 5.0}]\n")), "");
  const std::string gone = report(with_optimization("  bounds: [{group: L1, min: -600.0, max: 5.0}]\n"));
  EXPECT_NE(gone.find("removes the whole top segment (550 m) of line L1"), std::string::npos) << gone;
}

TEST(OptimizationSection, UnknownGroupsAndCasesAreReported) {
  const std::string issues = report(
      with_optimization("  groups: [cluster9]\n  cases: [lc7]\n  target_pretension: [{group: g2, tension: 1.0}]\n"));
  EXPECT_NE(issues.find("optimization.groups[0]: undefined line group \"cluster9\""), std::string::npos) << issues;
  EXPECT_NE(issues.find("optimization.cases[0]: undefined load case \"lc7\""), std::string::npos) << issues;
  EXPECT_NE(issues.find("optimization.target_pretension[0].group: no optimization group \"g2\""), std::string::npos)
      << issues;
}

TEST(PayoutGroups, DefaultRuleSkipsOverlappingGroupsAndKeepsLoneLines) {
  Project p = parse_project(kMinimal, "test.yaml");
  MooringLine l2 = p.mooring.lines[0];
  l2.name = "L2";
  MooringLine l3 = p.mooring.lines[0];
  l3.name = "L3";
  p.mooring.lines.push_back(l2);
  p.mooring.lines.push_back(l3);
  p.mooring.groups = {{"pair", {"L1", "L2"}}, {"all", {"L1", "L2", "L3"}}};
  const std::vector<PayoutGroup> groups = payout_groups(p);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].name, "pair");
  EXPECT_EQ(groups[0].lines, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(groups[1].name, "L3");
  EXPECT_EQ(skipped_overlapping_groups(p), std::vector<std::string>{"all"});
}

}  // namespace
}  // namespace spiral::design
