// Lines under a motion history: what they record, and the request checked
// before any line runs.
#include "design/analysis/motion_lines.hpp"

#include <gtest/gtest.h>

#include <string>

#include "design/model/environment_loads.hpp"
#include "design/model/riser_model.hpp"
#include "design/project/input_error.hpp"

namespace spiral::design {
namespace {

const std::string kDeepwater = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml";

MotionLinesRequest at_rest(const std::string& load_case, double duration_s) {
  MotionLinesRequest r;
  r.load_case = load_case;
  r.motion_times_s = {0.0, duration_s / 2.0, duration_s};
  r.motion.setZero(6, 3);
  r.ramp_s = 5.0;
  r.output_step_s = 1.0;
  return r;
}

// A hull at rest with the case's current on the riser: the riser stays in its
// static equilibrium, so the criteria evaluated on its dynamic state are the
// static ones (riser_checks on the FE statics at the same hang-off). Bounds:
// the integrator holds the state to its tolerances (slope 2e-6: 1e-5 of the
// tension), the touchdown point to a fraction of the 1 m refined elements.
TEST(MotionLines, ARiserAtRestKeepsItsStaticCriteria) {
  const ValidatedProject vp = load_validated_project(kDeepwater);
  const Project& p = vp.project;
  MotionLinesRequest request = at_rest("lc5-operating-45deg", 20.0);
  request.lines = {"P1"};
  request.waves_on_lines = false;
  const MotionLinesResult result = run_motion_lines(vp, request);
  ASSERT_TRUE(result.lines.empty());
  ASSERT_EQ(result.risers.size(), 1u);
  const RiserMotionRecord& r = result.risers[0];

  const LoadCase& lc = p.load_cases[4];
  const RiserDesign design = riser_design(p, p.risers[0]);
  const Eigen::Vector3d hang_off = p.hull.reference_point_g + design.hang_off_b;
  const DynamicLineSetup setup = dynamic_riser(p, design, current_profile_of(environment_of(p, lc)), hang_off);
  const RiserStaticsRow row = riser_statics_row(p, design, setup.statics, lc.condition, Eigen::Matrix3d::Identity());
  ASSERT_EQ(r.top_tension_N.size(), 21u);
  for (std::size_t k = 0; k < r.top_tension_N.size(); ++k) {
    EXPECT_NEAR(r.top_tension_N[k], row.top_tension_N, 1e-4 * row.top_tension_N) << k;
    EXPECT_NEAR(r.top_angle_deg[k], row.top_angle_deg, 1e-3) << k;
    EXPECT_NEAR(r.flex_joint_rotation_deg[k], row.flex_joint_rotation_deg, 1e-3) << k;
    EXPECT_NEAR(r.touchdown_distance_m[k], row.touchdown_distance_m, 0.5) << k;
    EXPECT_NEAR(r.utilization[k], row.utilization, 1e-3 * row.utilization) << k;
    ASSERT_FALSE(r.max_von_mises_utilization.empty());
    EXPECT_NEAR(r.max_von_mises_utilization[k], *row.max_von_mises_utilization, 1e-3) << k;
  }
  ASSERT_EQ(r.extremes.size(), row.checks.size());
  for (std::size_t c = 0; c < row.checks.size(); ++c) {
    EXPECT_EQ(r.extremes[c].worst.criterion, row.checks[c].criterion);
    EXPECT_GE(r.extremes[c].time_s, result.statistics_from_s);
  }
  EXPECT_GT(r.solver.steps, 0);
}

// A moving hull moves the records: surge of 10 m towards L1's side slackens
// L1 and lengthens its laid part; the anchor sees the tension less the
// seabed and suspended weight between them.
TEST(MotionLines, AMooringLineRecordsItsAnchorAndLaidLength) {
  const ValidatedProject vp =
      load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  MotionLinesRequest request = at_rest("intact-still-water", 200.0);
  request.lines = {"L1"};
  request.motion_times_s = {0.0, 100.0, 200.0};
  request.motion(0, 1) = 0.5 * 10.0 * 0.5;  // towards L1 (anchor at 60°): +x has a 0.5 component
  request.motion(1, 1) = 0.5 * 10.0 * 0.866;
  request.motion(0, 2) = 10.0 * 0.5;
  request.motion(1, 2) = 10.0 * 0.866;
  request.ramp_s = 0.0;
  const MotionLinesResult r = run_motion_lines(vp, request);
  ASSERT_EQ(r.lines.size(), 1u);
  const MooringLineMotionRecord& l1 = r.lines[0];
  EXPECT_LT(l1.fairlead_tension_N.back(), 0.9 * l1.fairlead_tension_N.front());
  EXPECT_GT(l1.laid_length_m.back(), l1.laid_length_m.front() + 5.0);
  for (std::size_t k = 0; k < l1.anchor_tension_N.size(); ++k) {
    EXPECT_LT(l1.anchor_tension_N[k], l1.fairlead_tension_N[k]);
    EXPECT_LT(l1.anchor_uplift_deg[k], 1.0);  // the chain lies on the seabed at the anchor
  }
  EXPECT_GT(l1.fairlead_mbl_N, 1e6);
}

TEST(MotionLines, BadRequestsAreNamedBeforeAnyLineRuns) {
  const ValidatedProject vp = load_validated_project(kDeepwater);
  auto problem_path = [&](const MotionLinesRequest& r) {
    try {
      run_motion_lines(vp, r);
    } catch (const InputError& e) {
      return e.issues().front().path;
    }
    return std::string("no error");
  };
  MotionLinesRequest r = at_rest("lc3-survival-45deg-damaged-L10", 20.0);
  r.lines = {"L10"};
  EXPECT_EQ(problem_path(r), "lines");  // the damaged line
  r.lines = {"nope"};
  EXPECT_EQ(problem_path(r), "lines");
  r = at_rest("lc1-survival-collinear-0deg", 20.0);
  r.ramp_s = 20.0;
  EXPECT_EQ(problem_path(r), "ramp_s");
  r = at_rest("lc1-survival-collinear-0deg", 20.0);
  r.output_step_s = 0.0;
  EXPECT_EQ(problem_path(r), "output_step_s");
  r = at_rest("nope", 20.0);
  EXPECT_EQ(problem_path(r), "load_case");
}

}  // namespace
}  // namespace spiral::design
