// The static stage composes the design analyses: a case per load case plus
// still water, the code check with the right safety factor, restoring curves.
#include "design/static_stage.hpp"

#include <gtest/gtest.h>

#include "design/model_hash.hpp"

namespace spiral::design {
namespace {

const std::string kScenario = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml";

TEST(StaticStage, DefaultScenarioCasesChecksAndCurves) {
  const ValidatedProject project = load_validated_project(kScenario);
  const StaticStageResults r = run_static_stage(project);
  ASSERT_EQ(r.cases.size(), project.project.load_cases.size() + 1);
  ASSERT_EQ(r.checks.size(), r.cases.size());
  EXPECT_EQ(r.cases.front().case_name, "still-water");
  EXPECT_EQ(r.pretension.lines.size(), project.project.mooring.lines.size());
  for (std::size_t i = 0; i < r.cases.size(); ++i) {
    const CaseCheck& check = r.checks[i];
    // API RP 2SK quasi-static factors of the scenario.
    EXPECT_DOUBLE_EQ(check.safety_factor, r.cases[i].condition == "damaged" ? 1.43 : 2.0);
    for (std::size_t l = 0; l < check.lines.size(); ++l) {
      EXPECT_DOUBLE_EQ(check.lines[l].utilization,
                       r.cases[i].lines[l].utilization * check.safety_factor);
      EXPECT_EQ(check.lines[l].pass, check.lines[l].utilization <= 1.0);
    }
    ASSERT_TRUE(check.offset_limit_m.has_value());
    EXPECT_DOUBLE_EQ(*check.offset_limit_m, 0.08 * 1800.0);
  }
  ASSERT_EQ(r.restoring.size(), 2u);
  for (const RestoringCurve& c : r.restoring) {
    ASSERT_EQ(c.offset_m.size(), static_cast<std::size_t>(kRestoringSteps + 1))
        << c.stopped.value_or("");
    EXPECT_DOUBLE_EQ(c.offset_m.back(), kRestoringMaxOffsetFractionOfDepth * 1800.0);
    for (std::size_t i = 1; i < c.force_N.size(); ++i) EXPECT_GT(c.force_N[i], c.force_N[i - 1]);
  }
  EXPECT_EQ(r.cases.front().risers.size(), project.project.risers.size());
}

TEST(ModelHash, Fnv1aKnownValues) {
  // Reference values of the FNV-1a 64 specification (draft-eastlake-fnv test vectors).
  EXPECT_EQ(fnv1a_64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a_64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(model_hash(kScenario).size(), 16u);
  EXPECT_EQ(model_hash(kScenario), model_hash(kScenario));
}

}  // namespace
}  // namespace spiral::design
