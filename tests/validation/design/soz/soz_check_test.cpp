// The offset check of run_soz (design/soz/soz_check.cpp): the extreme offsets of
// the enhanced S-C analysis against the platform zone (default deep-water
// scenario), and the zone per current condition (SOZ test project).

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>

#include "design/model/environment_loads.hpp"
#include "design/soz/soz.hpp"
#include "support/soz_project.hpp"
#include "support/temp_folder.hpp"

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
  // The screening model carries no current: the cases' zones differ by design
  // condition only — extreme and survival (normal is the still-water one).
  ASSERT_EQ(r.zones.size(), 2u);
  EXPECT_FALSE(r.zones[0].conditions.current || r.zones[1].conditions.current);
  std::map<std::string, const OffsetCheck*> statics, extremes;
  for (const OffsetCheck& c : r.offset_checks)
    (c.kind == OffsetCheckKind::static_mean ? statics : extremes)[c.case_name] = &c;
  ASSERT_EQ(statics.size(), p.project.load_cases.size());
  ASSERT_EQ(extremes.size(), p.project.load_cases.size());
  for (const LoadCase& lc : p.project.load_cases) {
    SCOPED_TRACE(lc.name);
    const OffsetCheck& s = *statics.at(lc.name);
    const OffsetCheck& e = *extremes.at(lc.name);
    ASSERT_TRUE(e.extreme.has_value());
    EXPECT_FALSE(s.extreme.has_value());
    EXPECT_EQ(e.integrity, s.integrity);
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

/// The SOZ test project (risers A at 0°, B at 180°) with a third case whose
/// environment has another name but the same current as lc2.
ValidatedProject two_risers_three_cases() {
  std::string text =
      test::soz_project_yaml(test::soz_riser_yaml("A", 0.0, 20.0) + test::soz_riser_yaml("B", 180.0, 20.0));
  const std::string env =
      "  - name: current-east\n    current:\n      heading_deg: 0.0\n"
      "      profile: [[0.0, 1.0], [-400.0, 0.5]]\n";
  const auto at = text.find(env);
  EXPECT_NE(at, std::string::npos);
  text.insert(at + env.size(),
              "  - name: same-current\n    current:\n      heading_deg: 0.0\n"
              "      profile: [[0.0, 1.0], [-400.0, 0.5]]\n");
  const std::string lc2 = "  - {name: lc2, environment: current-east, condition: extreme}\n";
  text.insert(text.find(lc2) + lc2.size(), "  - {name: lc3, environment: same-current, condition: extreme}\n");
  const std::filesystem::path file = spiral::test::scratch_root() / fmt::format("spiral-{}-soz-zones.yaml", ::getpid());
  std::ofstream(file) << text;
  ValidatedProject p = load_validated_project(file);
  std::filesystem::remove(file);
  return p;
}

TEST(SozCheck, EachCaseIsCheckedAgainstTheZoneOfItsOwnCurrent) {
  const ValidatedProject p = two_risers_three_cases();
  ASSERT_EQ(p.project.load_cases.size(), 3u);
  SozOptions o;
  o.step_deg = 45.0;
  const SozResult r = run_soz(p, o);
  // lc1 (calm, normal = the still-water condition) uses the still-water
  // zone; lc2 and lc3 share one zone: the same current and condition.
  ASSERT_EQ(r.zones.size(), 1u);
  const SozZone& zone = r.zones.front();
  EXPECT_EQ(zone.cases, (std::vector<std::string>{"lc2", "lc3"}));
  EXPECT_EQ(zone.conditions.condition, DesignCondition::extreme);
  ASSERT_TRUE(zone.conditions.current.has_value());
  ASSERT_EQ(r.offset_checks.size(), 3u);
  EXPECT_EQ(r.offset_checks[0].zone, "still-water");
  EXPECT_EQ(r.offset_checks[1].zone, zone.name);
  EXPECT_EQ(r.offset_checks[2].zone, zone.name);
  // The zone is the one compute_soz gives for that current and condition
  // (bit for bit: same chunks, same warm starts), and the check reads it.
  std::vector<RiserDesign> designs;
  for (const Riser& riser : p.project.risers) designs.push_back(riser_design(p.project, riser));
  SozConditions conditions;
  conditions.current = current_profile_of(*p.project.environments[1].current);
  conditions.condition = DesignCondition::extreme;
  const SozResult own = compute_soz(p.project, designs, conditions, o);
  EXPECT_EQ(zone.platform.allowable_offset_m, own.platform.allowable_offset_m);
  EXPECT_NE(zone.platform.allowable_offset_m, r.platform.allowable_offset_m);  // current + factor differ
  const OffsetCheck& c = r.offset_checks[1];
  EXPECT_NEAR(c.allowable_m, platform_at(own, c.direction_deg), kSameArithmetic * c.allowable_m);
  // Solves add up over the zones.
  EXPECT_EQ(r.solves, std::accumulate(r.risers.begin(), r.risers.end(), 0, [](int n, const RiserSoz& z) {
                        return n + z.solves;
                      }) + zone.solves);
  // --still-water-only: every case against the still-water zone.
  o.zone_per_current = false;
  const SozResult still = run_soz(p, o);
  EXPECT_TRUE(still.zones.empty());
  for (const OffsetCheck& check : still.offset_checks) EXPECT_EQ(check.zone, "still-water");
}

// The pretension optimizer solves the cases itself and needs their zones
// only: zones_only gives the same zones, bit for bit, without the cases'
// equilibria and checks.
TEST(SozCheck, ZonesOnlyGivesTheCasesZonesWithoutTheirEquilibria) {
  const ValidatedProject p = two_risers_three_cases();
  SozOptions o;
  o.step_deg = 45.0;
  const SozResult checked = run_soz(p, o);
  o.zones_only = true;
  const SozResult zones = run_soz(p, o);
  EXPECT_TRUE(zones.offset_checks.empty());
  ASSERT_EQ(zones.zones.size(), checked.zones.size());
  for (std::size_t k = 0; k < zones.zones.size(); ++k) {
    EXPECT_EQ(zones.zones[k].name, checked.zones[k].name);
    EXPECT_EQ(zones.zones[k].cases, checked.zones[k].cases);
    EXPECT_EQ(zones.zones[k].platform.allowable_offset_m, checked.zones[k].platform.allowable_offset_m);
  }
  EXPECT_EQ(zones.platform.allowable_offset_m, checked.platform.allowable_offset_m);
  // The extreme offsets are part of the check: asking for them too is an error.
  o.extreme = SozExtremeOptions{600.0, 1};
  EXPECT_THROW(run_soz(p, o), InputError);
}

}  // namespace
}  // namespace spiral::design
