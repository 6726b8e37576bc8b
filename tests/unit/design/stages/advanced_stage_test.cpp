// The advanced stage: every critical case of the intermediate ranking gets a
// coupled run and an sc-enhanced run of the same case and sea; the final
// checks come from the coupled run; a coupled run that fails is recorded and
// the other cases still finish. OC4 (two load cases, both critical as the
// top three) on a short record keeps it quick.
#include "design/stages/advanced_stage.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace spiral::design {
namespace {

const std::string kOc4 = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml";
constexpr double kShort_s = 120.0;

const ChannelSummary* channel(const LevelSummary& level, const std::string& name) {
  for (const ChannelSummary& c : level.channels)
    if (c.name == name) return &c;
  return nullptr;
}

TEST(AdvancedStage, CriticalCasesGetCoupledAndScResultsAndTheFinalChecks) {
  const ValidatedProject vp = load_validated_project(kOc4);
  AdvancedStageOptions options;
  options.duration_s = kShort_s;
  const AdvancedStageResults r = run_advanced_stage(vp, options);
  EXPECT_DOUBLE_EQ(r.duration_s, kShort_s);
  std::size_t critical = 0;
  for (const RankedCase& c : r.intermediate.ranked) critical += c.critical ? 1 : 0;
  ASSERT_EQ(r.cases.size(), critical);
  ASSERT_EQ(r.cases.size(), vp.project.load_cases.size());  // two cases, both in the top three
  EXPECT_EQ(r.failed_runs, 0);
  int previous_rank = 0;
  for (const CriticalCaseVerification& c : r.cases) {
    SCOPED_TRACE(c.case_name);
    EXPECT_GT(c.rank, previous_rank);  // rank order
    previous_rank = c.rank;
    EXPECT_FALSE(c.error.has_value()) << c.error.value_or("");
    ASSERT_TRUE(c.coupled.has_value());
    ASSERT_TRUE(c.sc.has_value());
    EXPECT_EQ(c.coupled->level, AnalysisLevel::coupled);
    EXPECT_EQ(c.coupled->tension_source, TensionSource::coupled);
    EXPECT_EQ(c.sc->level, AnalysisLevel::semi_coupled_enhanced);
    EXPECT_EQ(c.sc->tension_source, TensionSource::quasi_static);
    // Same sea and record: same seed and samples; the S-C tension channel is the coupled run's most loaded line.
    EXPECT_EQ(c.sc->seed, c.coupled->seed);
    EXPECT_EQ(c.sc->times_s.size(), c.coupled->times_s.size());
    EXPECT_DOUBLE_EQ(c.coupled->times_s.back(), kShort_s);
    EXPECT_EQ(c.sc->most_loaded_line, c.coupled->most_loaded_line);
    ASSERT_EQ(c.comparison.levels.size(), 2u);
    EXPECT_EQ(c.comparison.levels[0].level, AnalysisLevel::semi_coupled_enhanced);
    EXPECT_EQ(c.comparison.levels[1].level, AnalysisLevel::coupled);
    EXPECT_GT(c.comparison.levels[1].wall_s, 0.0);
    // Every intact mooring line checked from its coupled FE tension with the dynamic factor 1.67.
    ASSERT_EQ(c.lines.size(), vp.project.mooring.lines.size());
    for (const FinalLineCheck& l : c.lines) {
      const ChannelSummary* t = channel(c.comparison.levels[1], "tension_" + l.line + "_N");
      ASSERT_NE(t, nullptr) << l.line;
      EXPECT_DOUBLE_EQ(l.mpm_N, t->mpm);
      EXPECT_DOUBLE_EQ(l.dynamic_factor, 1.67);
      EXPECT_GT(l.mbl_N, 0.0);
      EXPECT_NEAR(l.utilization, l.mpm_N * 1.67 / l.mbl_N, 1e-12 * l.utilization);
      EXPECT_EQ(l.pass, l.utilization <= 1.0);
    }
    // Offset limit: 10 % of 200 m.
    ASSERT_TRUE(c.offset_limit_m.has_value());
    EXPECT_DOUBLE_EQ(*c.offset_limit_m, 20.0);
    EXPECT_DOUBLE_EQ(c.mpm_offset_m, channel(c.comparison.levels[1], "offset_m")->mpm);
    const bool all_pass = std::all_of(c.lines.begin(), c.lines.end(), [](const FinalLineCheck& l) { return l.pass; }) &&
                          c.offset_limit_pass;
    EXPECT_EQ(c.pass, all_pass);
  }
  // The storm case: the coupled FE tension is not the quasi-static S-C one (line dynamics, coupling).
  const auto storm = std::find_if(r.cases.begin(), r.cases.end(), [](const CriticalCaseVerification& c) {
    return c.case_name == "intact-raft-jonswap";
  });
  ASSERT_NE(storm, r.cases.end());
  const std::string line = storm->coupled->most_loaded_line;
  const ChannelSummary* coupled = channel(storm->comparison.levels[1], "tension_" + line + "_N");
  const ChannelSummary* sc = channel(storm->comparison.levels[0], "qs_tension_" + line + "_N");
  ASSERT_NE(coupled, nullptr);
  ASSERT_NE(sc, nullptr);
  EXPECT_NE(coupled->moments.std_dev, sc->moments.std_dev);
  EXPECT_GT(coupled->moments.std_dev, 0.0);
  EXPECT_FALSE(r.governing.empty());
}

TEST(AdvancedStage, AFailedCoupledRunIsRecordedAndTheOtherCasesFinish) {
  const ValidatedProject vp = load_validated_project(kOc4);
  AdvancedStageOptions options;
  options.duration_s = kShort_s;
  // Two integrator steps per 0.5 s output cannot carry the storm: IDA stops.
  options.coupled_max_steps_by_case["intact-raft-jonswap"] = 2;
  const AdvancedStageResults r = run_advanced_stage(vp, options);
  ASSERT_EQ(r.cases.size(), 2u);
  EXPECT_EQ(r.failed_runs, 1);
  EXPECT_FALSE(r.pass);
  for (const CriticalCaseVerification& c : r.cases) {
    SCOPED_TRACE(c.case_name);
    ASSERT_TRUE(c.sc.has_value());  // the S-C run of a failed case still stands
    ASSERT_EQ(c.comparison.levels.size(), 2u);
    if (c.case_name == "intact-raft-jonswap") {
      EXPECT_FALSE(c.coupled.has_value());
      ASSERT_TRUE(c.error.has_value());
      EXPECT_NE(c.error->find("intact-raft-jonswap"), std::string::npos) << *c.error;
      ASSERT_TRUE(c.comparison.levels[1].error.has_value());
      EXPECT_TRUE(c.comparison.levels[1].channels.empty());
      EXPECT_TRUE(c.lines.empty());
      EXPECT_FALSE(c.pass);  // not verified
    } else {
      EXPECT_TRUE(c.coupled.has_value()) << c.error.value_or("");
      EXPECT_FALSE(c.error.has_value());
      EXPECT_EQ(c.lines.size(), vp.project.mooring.lines.size());
    }
  }
  EXPECT_EQ(r.failed_cases, std::vector<std::string>{"intact-raft-jonswap"});
  // The governing check comes from the case that was verified.
  EXPECT_EQ(r.governing.rfind("intact-still-water: ", 0), 0u) << r.governing;
}

TEST(AdvancedStage, DurationFromTheProjectElseThreeHours) {
  Project p;
  p.stages.assign(2, Stage{});
  p.stages[0].name = "preliminary";
  p.stages[1].name = "advanced";
  EXPECT_DOUBLE_EQ(advanced_stage_duration(p), kAdvancedStageDuration_s);
  p.stages[1].duration_s = 900.0;
  EXPECT_DOUBLE_EQ(advanced_stage_duration(p), 900.0);
}

}  // namespace
}  // namespace spiral::design
