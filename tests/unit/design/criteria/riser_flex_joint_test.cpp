// Flex-joint rotation of riser_statics_row (design/model/riser_model.hpp): the
// angle between the riser's top tangent and the hull-fixed flex-joint axis,
// turned with the hull. On the SOZ test SCR (azimuth 0°, design top angle 12°).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "design/project/project_loader.hpp"
#include "design/soz/soz.hpp"
#include "design/criteria/riser_checks.hpp"
#include "engine/common/rigid_body.hpp"
#include "support/soz_project.hpp"

namespace spiral::design {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Pure geometry on one FE solution: the two formulas agree to round-off.
constexpr double kGeometry_deg = 1e-9;

struct Fixture {
  Project project = parse_project(test::soz_project_yaml(test::soz_riser_yaml("R", 0.0)), "fj.yaml");
  RiserDesign design = riser_design(project, project.risers.front());
};

TEST(RiserFlexJoint, HullPitchTowardsTheRiserReducesTheRotationOfAFarOffset) {
  const Fixture f;
  const RiserOffsetEvaluator evaluator(f.project, f.design, {}, SozModel::fe);
  // 30 m far (away from the riser's azimuth): the riser straightens, its top
  // angle grows past the 12° at which the joint was installed.
  const auto far = evaluator.evaluate({-30.0, 0.0}, nullptr);
  ASSERT_TRUE(far.solution);
  const engine::FeStaticsResult& solution = *far.solution;
  const double theta_deg = f.design.design_top_angle_rad * kRadToDeg;
  const double level =
      riser_statics_row(f.project, f.design, solution, DesignCondition::normal, Eigen::Matrix3d::Identity())
          .flex_joint_rotation_deg;
  const double alpha_deg = far.row.top_angle_deg;
  ASSERT_GT(alpha_deg, theta_deg + 1.0);
  // Level hull, in the riser plane: the rotation is the change of top angle.
  EXPECT_NEAR(level, alpha_deg - theta_deg, kGeometry_deg);
  // Pitch ψ about +y turns the joint axis in the x–z plane to θ − ψ from
  // vertical: ψ < 0 leans the keel (and the joint) towards the riser (+x)
  // and follows the straightened riser — less rotation; ψ > 0 more.
  for (const double pitch_deg : {-1.0, 1.0}) {
    const Eigen::Matrix3d R = engine::rotation_matrix({0.0, pitch_deg * kDegToRad, 0.0});
    const double rotation =
        riser_statics_row(f.project, f.design, solution, DesignCondition::normal, R).flex_joint_rotation_deg;
    EXPECT_NEAR(rotation, std::abs(alpha_deg - (theta_deg - pitch_deg)), kGeometry_deg) << pitch_deg;
  }
  // Yaw γ swings the joint about the vertical: the spherical angle between
  // tilt α at azimuth 0 and tilt θ at azimuth γ.
  const double yaw = 10.0 * kDegToRad;
  const double expected = std::acos(std::cos(alpha_deg * kDegToRad) * std::cos(theta_deg * kDegToRad) +
                                    std::sin(alpha_deg * kDegToRad) * std::sin(theta_deg * kDegToRad) * std::cos(yaw)) *
                          kRadToDeg;
  EXPECT_NEAR(riser_statics_row(f.project, f.design, solution, DesignCondition::normal,
                                engine::rotation_matrix({0.0, 0.0, yaw}))
                  .flex_joint_rotation_deg,
              expected, 1e-6);  // acos near 1 loses digits: 1e-6 deg
  EXPECT_GT(expected, level);
}

TEST(RiserFlexJoint, CrossOffsetSwingsTheRiserPlaneBeyondTheChangeOfTopAngle) {
  const Fixture f;
  const RiserOffsetEvaluator evaluator(f.project, f.design, {}, SozModel::fe);
  // 30 m across the riser plane: the plane turns about the foot by ≈ 30 m /
  // 450 m ≈ 4°, the top angle hardly changes; the joint sees the swing.
  const auto cross = evaluator.evaluate({0.0, 30.0}, nullptr);
  ASSERT_TRUE(cross.solution);
  const double change_of_top_angle_deg = std::abs(cross.row.top_angle_deg - f.design.design_top_angle_rad * kRadToDeg);
  EXPECT_GT(cross.row.flex_joint_rotation_deg, change_of_top_angle_deg + 0.2);
  // The criterion uses it: with a limit below it the riser fails there.
  ASSERT_TRUE(f.design.criteria.max_flex_joint_rotation_rad.has_value());  // scr default
  RiserDesign tight = f.design;
  tight.criteria.max_flex_joint_rotation_rad = 0.5 * cross.row.flex_joint_rotation_deg * kDegToRad;
  const RiserStaticsRow row =
      riser_statics_row(f.project, tight, *cross.solution, DesignCondition::normal, Eigen::Matrix3d::Identity());
  EXPECT_EQ(row.governing_criterion, "flex_joint_rotation");
  EXPECT_NEAR(row.utilization, 2.0, 1e-12);
  EXPECT_FALSE(row.passes);
}

}  // namespace
}  // namespace spiral::design
