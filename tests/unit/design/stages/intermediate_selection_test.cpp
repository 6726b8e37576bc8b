// The intermediate stage's critical cases: the N most severe by each ranking
// measure and every failing case — a case that is the worst in offset but
// mild in tension still goes to the coupled verification.
#include <gtest/gtest.h>

#include <map>

#include "design/stages/intermediate_stage.hpp"

namespace spiral::design {
namespace {

CaseStorm storm(std::size_t index, double tension, double offset_ratio) {
  CaseStorm s;
  s.case_index = index;
  s.storm.case_name = "lc" + std::to_string(index);
  s.storm.tension_utilization = tension;
  OffsetCheck check;
  check.ratio = offset_ratio;
  check.passes = offset_ratio <= 1.0;
  s.storm.extreme_offset = check;
  return s;
}

TEST(IntermediateSelection, TopNByEachMeasureAndEveryFailingCase) {
  StaticStageResults statics;
  statics.cases.resize(6);
  statics.checks.resize(6);
  std::vector<CaseStorm> storms{storm(1, 0.90, 0.10), storm(2, 0.80, 0.20), storm(3, 0.30, 0.95), storm(4, 0.20, 0.30),
                                storm(5, 1.20, 0.10)};
  const IntermediateStageResults r = reduce_intermediate_stage(statics, storms, 1);
  EXPECT_EQ(r.critical_per_measure, 1u);
  std::map<std::string, bool> critical;
  for (const RankedCase& c : r.ranked) critical[c.storm.case_name] = c.critical;
  EXPECT_TRUE(critical["lc5"]);   // fails (and the worst tension)
  EXPECT_TRUE(critical["lc3"]);   // the worst offset, mild tension
  EXPECT_FALSE(critical["lc1"]);  // second in tension: not in the top 1
  EXPECT_FALSE(critical["lc2"]);
  EXPECT_FALSE(critical["lc4"]);
  EXPECT_EQ(r.ranked.front().storm.case_name, "lc5");
  EXPECT_FALSE(r.pass);

  const IntermediateStageResults three = reduce_intermediate_stage(statics, storms);
  int n = 0;
  for (const RankedCase& c : three.ranked) n += c.critical ? 1 : 0;
  EXPECT_EQ(n, 5);  // top 3 in tension (5, 1, 2) and in offset (3, 4, 2)
}

}  // namespace
}  // namespace spiral::design
