// The static stage composes the design analyses: a case per load case plus
// still water, the code check with the right safety factor, restoring curves.
#include "design/stages/static_stage.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include <Eigen/Geometry>

#include "design/project/model_hash.hpp"

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
    EXPECT_DOUBLE_EQ(check.safety_factor, r.cases[i].integrity == LineIntegrity::damaged ? 1.43 : 2.0);
    for (std::size_t l = 0; l < check.lines.size(); ++l) {
      EXPECT_DOUBLE_EQ(check.lines[l].utilization, r.cases[i].lines[l].utilization * check.safety_factor);
      EXPECT_EQ(check.lines[l].pass, check.lines[l].utilization <= 1.0);
    }
    ASSERT_TRUE(check.offset_limit_m.has_value());
    EXPECT_DOUBLE_EQ(*check.offset_limit_m, 0.08 * 1800.0);
  }
  ASSERT_EQ(r.restoring.size(), 2u);
  for (const RestoringCurve& c : r.restoring) {
    ASSERT_EQ(c.offset_m.size(), static_cast<std::size_t>(kRestoringSteps + 1)) << c.stopped.value_or("");
    EXPECT_DOUBLE_EQ(c.offset_m.back(), kRestoringMaxOffsetFractionOfDepth * 1800.0);
    for (std::size_t i = 1; i < c.force_N.size(); ++i) EXPECT_GT(c.force_N[i], c.force_N[i - 1]);
  }
  EXPECT_EQ(r.cases.front().risers.size(), project.project.risers.size());

  // The SOZ of the stage: the screening default (catenary, 15°), one offset
  // check per load case against the platform zone, folded into the case verdict.
  ASSERT_TRUE(r.soz.has_value());
  EXPECT_EQ(r.soz->options.model, SozModel::catenary);
  EXPECT_DOUBLE_EQ(r.soz->options.step_deg, 15.0);
  EXPECT_EQ(r.soz->directions_deg.size(), 24u);
  ASSERT_EQ(r.soz->offset_checks.size(), project.project.load_cases.size());
  EXPECT_FALSE(r.checks.front().soz.has_value());  // still water
  for (std::size_t i = 1; i < r.cases.size(); ++i) {
    ASSERT_TRUE(r.checks[i].soz.has_value());
    const OffsetCheck& c = *r.checks[i].soz;
    EXPECT_EQ(c.case_name, r.cases[i].case_name);
    EXPECT_DOUBLE_EQ(c.offset_m, r.cases[i].offset_summary.horizontal_m);
    EXPECT_DOUBLE_EQ(c.allowable_m,
                     polygon_allowable(r.soz->directions_deg, r.soz->platform.allowable_offset_m, c.direction_deg));
    EXPECT_EQ(r.checks[i].pass,
              r.checks[i].lines_pass && r.checks[i].offset_pass && r.checks[i].risers_pass && r.checks[i].soz_pass);
  }

  // The S-C storm of the governing case: 3 h at 0.5 s, nine channels, and
  // the dynamic tension check recomputed from its own channel.
  ASSERT_TRUE(r.dynamics.has_value());
  const StageDynamics& d = *r.dynamics;
  EXPECT_EQ(d.case_name, r.cases[static_cast<std::size_t>(std::max(1, r.worst_case))].case_name);
  EXPECT_EQ(d.level, AnalysisLevel::semi_coupled_enhanced);
  EXPECT_EQ(d.times_s.size(), 21601u);
  ASSERT_EQ(d.channels.size(), 9u);
  ASSERT_NE(d.tension(), nullptr);
  EXPECT_EQ(d.tension(), &d.channels[4]);
  EXPECT_EQ(d.tension()->name, "tension " + d.most_loaded_line);
  for (const char* name : {"surge", "sway", "yaw", "offset", "heave", "roll", "pitch"})
    EXPECT_NE(d.channel(name), nullptr) << name;
  EXPECT_TRUE(d.channels.back().name.starts_with(kHangOffHeavePrefix)) << d.channels.back().name;
  for (const StormChannel& c : d.channels) {
    EXPECT_EQ(c.values.size(), d.times_s.size()) << c.name;
    ASSERT_TRUE(c.mpm_max().has_value()) << c.name << ": " << c.extremes_note;
    EXPECT_GT(*c.mpm_max(), c.moments().mean) << c.name;
    EXPECT_GT(c.statistics.spectrum.density.size(), 0) << c.name;
  }
  // The hang-off channel: heave plus the rotation's vertical component of
  // the hang-off's lever arm (Rz leaves z alone, so yaw does not enter), at
  // the riser whose vertical motion varies most.
  const auto vertical = [&](const Riser& riser) {
    std::vector<double> z(d.times_s.size());
    for (std::size_t k = 0; k < z.size(); ++k) {
      const double roll = d.channel("roll")->values[k] * std::numbers::pi / 180.0;
      const double pitch = d.channel("pitch")->values[k] * std::numbers::pi / 180.0;
      const Eigen::Vector3d arm =
          (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX())) *
          riser.hang_off_b;
      z[k] = d.channel("heave")->values[k] + arm.z() - riser.hang_off_b.z();
    }
    return z;
  };
  const StormChannel& stroke = d.channels.back();
  double largest_std = 0.0;
  for (const Riser& riser : project.project.risers) {
    const std::vector<double> z = vertical(riser);
    const double s = engine::channel_moments(z).std_dev;
    largest_std = std::max(largest_std, s);
    if (stroke.name != std::string(kHangOffHeavePrefix) + riser.name) continue;
    for (std::size_t k = 0; k < z.size(); k += 97) EXPECT_NEAR(stroke.values[k], z[k], 1e-9) << riser.name << " " << k;
  }
  EXPECT_NEAR(stroke.moments().std_dev, largest_std, 1e-9);
  EXPECT_GT(largest_std, d.channel("heave")->moments().std_dev);  // pitch adds to heave at the column hang-offs

  const StormChannel& t = *d.tension();
  const double sf_dynamic = d.integrity == LineIntegrity::damaged ? 1.25 : 1.67;  // the scenario's API RP 2SK factors
  EXPECT_NEAR(d.tension_utilization, *t.mpm_max() * sf_dynamic / d.fairlead_mbl_N, 1e-12);
  ASSERT_TRUE(d.extreme_offset.has_value());
  EXPECT_EQ(d.extreme_offset->kind, OffsetCheckKind::extreme);
  // The one extreme-offset rule (soz.hpp), the same as `spiral soz --extreme`
  // applies: the Weibull 3-h MPM of offset/allowable, shown as an offset.
  ASSERT_TRUE(d.extreme_offset->extreme.has_value());
  EXPECT_DOUBLE_EQ(d.extreme_offset->ratio, d.extreme_offset->extreme->ratio_mpm_weibull);
  EXPECT_DOUBLE_EQ(d.extreme_offset->offset_m, d.extreme_offset->ratio * d.extreme_offset->allowable_m);
  ASSERT_TRUE(r.soz.has_value());
  Eigen::Matrix<double, 6, Eigen::Dynamic> motion = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, d.times_s.size());
  for (std::size_t k = 0; k < d.times_s.size(); ++k) {
    motion(0, static_cast<Eigen::Index>(k)) = d.channels[0].values[k];  // surge
    motion(1, static_cast<Eigen::Index>(k)) = d.channels[1].values[k];  // sway
  }
  const Eigen::VectorXd times =
      Eigen::Map<const Eigen::VectorXd>(d.times_s.data(), static_cast<Eigen::Index>(d.times_s.size()));
  StaticCaseResult named;
  named.case_name = d.case_name;
  std::string fit_note;
  const OffsetCheck same = extreme_offset_check(*r.soz, named, motion, times, "still-water", fit_note);
  EXPECT_TRUE(fit_note.empty()) << fit_note;
  EXPECT_DOUBLE_EQ(same.ratio, d.extreme_offset->ratio);
  EXPECT_DOUBLE_EQ(same.direction_deg, d.extreme_offset->direction_deg);

  // The verdict's governing check is a failing one when the stage fails.
  EXPECT_EQ(r.governing.pass, r.pass);
}

TEST(StaticStage, DynamicTensionCheckFollowsTheCode) {
  MooringCriteria api;
  api.code = MooringCode::api_rp_2sk;
  EXPECT_DOUBLE_EQ(dynamic_tension_check(api, false, 1e6, 2e6, 1e7).utilization, 2e6 * 1.67 / 1e7);
  EXPECT_DOUBLE_EQ(dynamic_tension_check(api, true, 1e6, 2e6, 1e7).factor, 1.25);
  MooringCriteria dnv;
  dnv.code = MooringCode::dnv_os_e301;
  dnv.dnv_os_e301 = dnv_os_e301_defaults(1);
  // ULS class 1: (1.10 T_mean + 1.50 (T_mpm - T_mean)) / (0.95 MBL).
  EXPECT_NEAR(dynamic_tension_check(dnv, false, 1e6, 2e6, 1e7).utilization, (1.1e6 + 1.5e6) / 0.95e7, 1e-12);
  // ALS: 1.00 and 1.10.
  EXPECT_NEAR(dynamic_tension_check(dnv, true, 1e6, 2e6, 1e7).utilization, (1.0e6 + 1.1e6) / 0.95e7, 1e-12);
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
