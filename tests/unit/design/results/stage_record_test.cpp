// Stage records are exact: encoding a decoded record gives the same bytes,
// and every double comes back bit for bit — NaN and infinities included
// (an offset check against an empty zone has an infinite ratio).
#include "design/results/stage_record.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "design/stages/intermediate_stage.hpp"

namespace spiral::design {
namespace {

const std::string kOc4 = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml";

template <class T>
void expect_exact_round_trip(const T& value) {
  const RecordBytes bytes = encode_record(value);
  const T back = decode_record<T>(bytes);
  EXPECT_EQ(encode_record(back), bytes);
}

TEST(StageRecord, StaticCaseOverviewAndStormRoundTripExactly) {
  const ValidatedProject vp = load_validated_project(kOc4);
  const MooringOverview overview = run_mooring_overview(vp);
  expect_exact_round_trip(overview);
  const StaticCaseResult still = run_stage_static_case(vp, std::nullopt);
  expect_exact_round_trip(still);
  const StaticCaseResult storm_case = run_stage_static_case(vp, vp.project.load_cases[1].name);
  const StaticCaseResult back = decode_record<StaticCaseResult>(encode_record(storm_case));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(back.offset(0)), std::bit_cast<std::uint64_t>(storm_case.offset(0)));
  EXPECT_EQ(back.stiffness, storm_case.stiffness);
  ASSERT_EQ(back.lines.size(), storm_case.lines.size());
  EXPECT_EQ(back.lines[0].profile.size(), storm_case.lines[0].profile.size());

  StaticStageOptions options;
  options.dynamics = false;
  const StaticStageResults statics = reduce_static_stage(vp, overview, {still, storm_case}, std::nullopt, {}, options);
  const StageDynamics storm = run_case_storm(vp, statics, 1);
  expect_exact_round_trip(storm);
  const StageDynamics storm_back = decode_record<StageDynamics>(encode_record(storm));
  ASSERT_EQ(storm_back.channels.size(), storm.channels.size());
  EXPECT_EQ(storm_back.channels[0].values, storm.channels[0].values);
  EXPECT_EQ(storm_back.channels[0].statistics.spectrum.density, storm.channels[0].statistics.spectrum.density);
}

TEST(StageRecord, NonFiniteValuesSurvive) {
  SozResult zone;
  zone.project = "p";
  OffsetCheck check;
  check.case_name = "lc1";
  check.ratio = std::numeric_limits<double>::infinity();
  check.margin_m = -std::numeric_limits<double>::infinity();
  check.allowable_m = std::numeric_limits<double>::quiet_NaN();
  check.offset_m = 0.1;  // not exact in binary32: kept in binary64
  zone.offset_checks.push_back(check);
  const SozResult back = decode_record<SozResult>(encode_record(zone));
  ASSERT_EQ(back.offset_checks.size(), 1u);
  EXPECT_TRUE(std::isinf(back.offset_checks[0].ratio) && back.offset_checks[0].ratio > 0);
  EXPECT_TRUE(std::isinf(back.offset_checks[0].margin_m) && back.offset_checks[0].margin_m < 0);
  EXPECT_TRUE(std::isnan(back.offset_checks[0].allowable_m));
  EXPECT_EQ(back.offset_checks[0].offset_m, 0.1);
}

TEST(StageRecord, ProfilesKeepEveryPointAndEveryOptional) {
  StaticCaseResult result;
  LineStaticsRow line;
  line.name = "L1";
  for (int i = 0; i < 3; ++i) {
    engine::LineProfilePoint p;
    p.position_g = Eigen::Vector3d(0.1 * i, -1.0 / 3.0, -200.0 + i);
    p.arc_length_m = 10.0 * i;
    p.tension_N = 1.0e6 + i;
    p.segment = i;
    p.on_seabed = i == 0;
    line.profile.push_back(p);
  }
  result.lines.push_back(line);
  RiserStaticsRow riser;
  riser.name = "E1";
  RiserProfilePoint flexible;  // no stress: the optionals stay empty
  flexible.section = 2;
  flexible.curvature_per_m = 1.0e-3;
  RiserProfilePoint steel;
  steel.von_mises_Pa = std::numeric_limits<double>::quiet_NaN();
  steel.von_mises_utilization = 0.0;  // present and zero, not absent
  steel.wall_tension_N = -5.0;
  riser.profile = {flexible, steel};
  result.risers.push_back(riser);

  const StaticCaseResult back = decode_record<StaticCaseResult>(encode_record(result));
  ASSERT_EQ(back.lines.at(0).profile.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const engine::LineProfilePoint& p = back.lines[0].profile[i];
    EXPECT_EQ(p.position_g, line.profile[i].position_g);
    EXPECT_EQ(p.arc_length_m, line.profile[i].arc_length_m);
    EXPECT_EQ(p.tension_N, line.profile[i].tension_N);
    EXPECT_EQ(p.segment, i);
    EXPECT_EQ(p.on_seabed, i == 0);
  }
  ASSERT_EQ(back.risers.at(0).profile.size(), 2u);
  EXPECT_EQ(back.risers[0].profile[0].section, 2);
  EXPECT_EQ(back.risers[0].profile[0].curvature_per_m, 1.0e-3);
  EXPECT_FALSE(back.risers[0].profile[0].von_mises_Pa.has_value());
  EXPECT_FALSE(back.risers[0].profile[0].von_mises_utilization.has_value());
  ASSERT_TRUE(back.risers[0].profile[1].von_mises_Pa.has_value());
  EXPECT_TRUE(std::isnan(*back.risers[0].profile[1].von_mises_Pa));
  ASSERT_TRUE(back.risers[0].profile[1].von_mises_utilization.has_value());
  EXPECT_EQ(*back.risers[0].profile[1].von_mises_utilization, 0.0);
  EXPECT_EQ(back.risers[0].profile[1].wall_tension_N, -5.0);
  expect_exact_round_trip(result);
}

TEST(StageRecord, ARecordOfAnotherTypeIsRefused) {
  SozResult zone;
  const RecordBytes bytes = encode_record(zone);
  EXPECT_THROW(decode_record<StageDynamics>(bytes), std::runtime_error);
  EXPECT_THROW(decode_record<StageDynamics>(RecordBytes{0x01, 0x02}), std::runtime_error);
}

}  // namespace
}  // namespace spiral::design
