// The enhanced S-C's line damping with a current: the limits of its drag
// linearization (design/analysis/line_hydrodynamics.cpp) on OC4's three
// chains at rest.
#include "design/analysis/line_hydrodynamics.hpp"

#include <gtest/gtest.h>

#include "design/project/validated_project.hpp"

#include <string>
#include <vector>

namespace spiral::design {
namespace {

struct Oc4Mooring {
  ValidatedProject project =
      load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  LineArrayModel model = build_mooring_model(project.project);
  engine::HullPose rest = engine::pose_from_offset(model.reference_point_g, engine::Vector6d::Zero());

  engine::Matrix6d damping(double fairlead_velocity_std_m_per_s, const engine::CurrentProfile* current) {
    const double variance = fairlead_velocity_std_m_per_s * fairlead_velocity_std_m_per_s;
    const std::vector<Eigen::Matrix3d> covariance(model.lines.size(), variance * Eigen::Matrix3d::Identity());
    return line_hydrodynamics(model, rest, covariance, 1025.0, current).damping;
  }
};

engine::CurrentProfile uniform_current(double speed_m_per_s) {
  return {{-400.0, 0.0}, {speed_m_per_s, speed_m_per_s}, 0.3};
}

// A line that does not move (sigma = 0) in still water has no linearized
// drag; in a current its damping is the steady drag's slope, 2U along the
// normal current and U across it, so it is linear in U.
TEST(LineHydrodynamics, ACurrentDampsALineThatDoesNotMoveInProportionToItsSpeed) {
  Oc4Mooring oc4;
  EXPECT_EQ(oc4.damping(0.0, nullptr).norm(), 0.0);
  const engine::CurrentProfile slow = uniform_current(0.5), fast = uniform_current(1.0);
  const engine::Matrix6d b_slow = oc4.damping(0.0, &slow);
  const engine::Matrix6d b_fast = oc4.damping(0.0, &fast);
  EXPECT_GT(b_slow(0, 0), 0.0);
  EXPECT_LE((b_fast - 2.0 * b_slow).norm(), 1e-12 * b_fast.norm());
  EXPECT_LE((b_fast - b_fast.transpose()).norm(), 1e-12 * b_fast.norm()) << "symmetric";
}

// A current small against the line's velocity leaves Borgman's
// linearization (sqrt(8/pi) sigma) as it was: the formula is continuous at
// U = 0, to second order in U / sigma.
TEST(LineHydrodynamics, AFaintCurrentLeavesTheWaveDrivenDampingAsItWas) {
  Oc4Mooring oc4;
  const engine::CurrentProfile faint = uniform_current(1e-5);
  const engine::Matrix6d still = oc4.damping(0.3, nullptr);
  EXPECT_LE((oc4.damping(0.3, &faint) - still).norm(), 1e-6 * still.norm());
}

// A current as fast as the line's velocity scatter damps more than either
// alone (the expected slope of |u| u grows with both), and a strong one
// dominates: at U = 10 sigma the damping is within 1 % of the steady slope's.
TEST(LineHydrodynamics, CurrentAndMotionCombineAndTheStrongerDominates) {
  Oc4Mooring oc4;
  const engine::CurrentProfile moderate = uniform_current(0.3), strong = uniform_current(3.0);
  const engine::Matrix6d motion_only = oc4.damping(0.3, nullptr);
  const engine::Matrix6d both = oc4.damping(0.3, &moderate);
  EXPECT_GT(both(0, 0), motion_only(0, 0));
  EXPECT_GT(both(0, 0), oc4.damping(0.0, &moderate)(0, 0));
  const engine::Matrix6d steady = oc4.damping(0.0, &strong);
  EXPECT_LE((oc4.damping(0.03, &strong) - steady).norm(), 0.01 * steady.norm());
}

}  // namespace
}  // namespace spiral::design
