// The offset check of run_soz (design/soz_check.cpp) on the default
// deep-water scenario: the extreme offsets of the enhanced S-C analysis
// against the platform zone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "design/soz.hpp"

namespace spiral::design {
namespace {

const std::string kDeepwater = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml";
// offset_m = ratio × allowable_m and allowable_m = the zone at direction_deg
// are the same arithmetic in the test and in the check: round-off only.
constexpr double kSameArithmetic = 1e-9;

/// The platform zone of `r` in `direction_deg` as the check defines it: the
/// smallest riser polygon there.
double platform_at(const SozResult& r, double direction_deg) {
  double a = std::numeric_limits<double>::infinity();
  for (const RiserSoz& z : r.risers) {
    std::vector<double> allowable;
    for (const SozDirection& d : z.directions) allowable.push_back(d.allowable_offset_m);
    a = std::min(a, polygon_allowable(r.directions_deg, allowable, direction_deg));
  }
  return a;
}

TEST(SozCheck, ExtremeOffsetOfEveryCaseFromTheEnhancedScAnalysis) {
  const ValidatedProject p = load_validated_project(kDeepwater);
  SozOptions o;
  // The screening model and a 30° grid keep the zone cheap; the check's
  // arithmetic does not depend on how the zone was found.
  o.model = SozModel::catenary;
  o.step_deg = 30.0;
  o.extreme = SozExtremeOptions{3600.0, 7};  // 1 h record, MPM scaled to 3 h
  const SozResult r = run_soz(p, o);
  std::map<std::string, const OffsetCheck*> statics, extremes;
  for (const OffsetCheck& c : r.offset_checks) (c.kind == "static" ? statics : extremes)[c.case_name] = &c;
  ASSERT_EQ(statics.size(), p.project.load_cases.size());
  ASSERT_EQ(extremes.size(), p.project.load_cases.size());
  for (const LoadCase& lc : p.project.load_cases) {
    SCOPED_TRACE(lc.name);
    const OffsetCheck& s = *statics.at(lc.name);
    const OffsetCheck& e = *extremes.at(lc.name);
    ASSERT_TRUE(e.extreme.has_value());
    EXPECT_FALSE(s.extreme.has_value());
    EXPECT_EQ(e.condition, s.condition);
    EXPECT_EQ(e.damaged_line, s.damaged_line);
    // The storm moves the hull about its mean position: the 3-h MPM of the
    // offset and of the zone utilization exceed the static (mean) values.
    EXPECT_GT(e.extreme->offset_mpm_m, s.offset_m);
    EXPECT_GT(e.ratio, s.ratio);
    EXPECT_GT(e.extreme->ratio_mpm_weibull, 0.0);
    EXPECT_DOUBLE_EQ(e.ratio, e.extreme->ratio_mpm_weibull);  // the documented estimator
    // Ratio, offset and allowable are consistent with the zone polygon in
    // the reported direction.
    EXPECT_NEAR(e.allowable_m, platform_at(r, e.direction_deg), kSameArithmetic * e.allowable_m);
    EXPECT_NEAR(e.offset_m / e.allowable_m, e.ratio, kSameArithmetic * e.ratio);
    EXPECT_NEAR(e.margin_m, e.allowable_m - e.offset_m, kSameArithmetic * e.allowable_m);
    EXPECT_EQ(e.passes, e.ratio <= 1.0);
    EXPECT_FALSE(e.governing_riser.empty());
  }
}

}  // namespace
}  // namespace spiral::design
