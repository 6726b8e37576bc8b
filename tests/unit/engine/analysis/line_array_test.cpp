// Unit tests of the line array's 6-DOF force: symmetry, signs, consistency
// with the single-line catenary, and failures that name the line.
#include <gtest/gtest.h>

#include <numbers>

#include "engine/analysis/line_array.hpp"
#include "support/oc4_mooring.hpp"

namespace spiral::engine {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
// Force balance of a symmetric spread: limited by the catenary closure
// tolerance (1e-9 m) times the line stiffness (~1e5 N/m): far below 1 mN.
constexpr double kSymmetryTolerance_N = 1e-3;

HullPose pose(double x, double y, double z, double rx_deg, double ry_deg, double rz_deg) {
  Vector6d o;
  o << x, y, z, rx_deg * kDegToRad, ry_deg * kDegToRad, rz_deg * kDegToRad;
  return pose_from_offset(Eigen::Vector3d::Zero(), o);
}

TEST(LineArray, SymmetricSpreadHasNoHorizontalForceAtRest) {
  const auto lines = test::oc4_static_lines();
  const auto result = evaluate_line_array(lines, HullPose{});
  EXPECT_NEAR(result.force(0), 0.0, kSymmetryTolerance_N);
  EXPECT_NEAR(result.force(1), 0.0, kSymmetryTolerance_N);
  EXPECT_NEAR(result.force(5), 0.0, kSymmetryTolerance_N * 50.0);  // arm 40.9 m
  double vertical = 0.0;
  for (const auto& line : result.lines) vertical += line.end.force_g.z();
  EXPECT_NEAR(result.force(2), vertical, 1e-12 * std::abs(vertical));
  EXPECT_LT(result.force(2), 0.0);  // the lines pull the hull down
}

TEST(LineArray, LineForceEqualsItsCatenarySolution) {
  const auto oc4 = test::oc4_lines();
  const auto lines = test::oc4_static_lines();
  const auto result = evaluate_line_array(lines, pose(5.0, -3.0, 0.0, 0.0, 0.0, 0.0));
  const auto& line = result.lines[0];
  const Eigen::Vector3d chord = line.attachment_g - oc4[0].anchor_g;
  const auto direct = solve_catenary(oc4[0].line, {std::hypot(chord.x(), chord.y()), chord.z(), 0.0});
  EXPECT_NEAR(line.end.force_g.head<2>().norm(), direct.fairlead_horizontal_N, 1e-9 * direct.fairlead_tension_N);
  EXPECT_NEAR(-line.end.force_g.z(), direct.fairlead_vertical_N, 1e-9 * direct.fairlead_tension_N);
  // The horizontal pull points from the fairlead towards the anchor.
  const Eigen::Vector2d towards_anchor = -chord.head<2>().normalized();
  EXPECT_GT(line.end.force_g.head<2>().normalized().dot(towards_anchor), 1.0 - 1e-12);
}

TEST(LineArray, DisplacementsAreRestored) {
  const auto lines = test::oc4_static_lines();
  EXPECT_LT(evaluate_line_array(lines, pose(10, 0, 0, 0, 0, 0)).force(0), 0.0);
  EXPECT_LT(evaluate_line_array(lines, pose(0, 10, 0, 0, 0, 0)).force(1), 0.0);
  EXPECT_LT(evaluate_line_array(lines, pose(0, 0, 0, 0, 0, 5)).force(5), 0.0);
}

TEST(LineArray, PureYawKeepsTheThreeFoldSymmetry) {
  // Yawing a 120°-symmetric spread about its centre keeps that symmetry: no
  // net horizontal force or heel moment, a restoring yaw moment, a larger
  // vertical load (every line is stretched equally).
  const auto lines = test::oc4_static_lines();
  const auto rest = evaluate_line_array(lines, HullPose{});
  const auto yawed = evaluate_line_array(lines, pose(0, 0, 0, 0, 0, 5.0));
  EXPECT_NEAR(yawed.force(0), 0.0, kSymmetryTolerance_N);
  EXPECT_NEAR(yawed.force(1), 0.0, kSymmetryTolerance_N);
  EXPECT_NEAR(yawed.force(3), 0.0, kSymmetryTolerance_N * 50.0);
  EXPECT_NEAR(yawed.force(4), 0.0, kSymmetryTolerance_N * 50.0);
  EXPECT_LT(yawed.force(5), 0.0);
  EXPECT_LT(yawed.force(2), rest.force(2));
}

TEST(LineArray, StateAgreesWithTheSolveAndHasAProfile) {
  const auto lines = test::oc4_static_lines();
  const Eigen::Vector3d attachment(40.868 * 0.5 + 3.0, 40.868 * std::sqrt(3.0) / 2.0, -14.0);
  const LineEndResponse end = lines[0]->solve(attachment);
  const LineState state = lines[0]->state(attachment, 4);
  EXPECT_LT((state.top.force_g - end.force_g).norm(), 1e-9 * end.force_g.norm());
  ASSERT_FALSE(state.profile.empty());
  EXPECT_LT((state.profile.front().position_g - test::oc4_lines()[0].anchor_g).norm(), 1e-9);
  EXPECT_LT((state.profile.back().position_g - attachment).norm(), 1e-6);
  EXPECT_NEAR(state.profile.back().tension_N, end.top_tension_N, 1e-9 * end.top_tension_N);
  EXPECT_EQ(state.regime, LineRegime::touchdown);
  EXPECT_GT(state.laid_length_m, 0.0);
}

TEST(LineArray, FailingLineIsNamed) {
  auto oc4 = test::oc4_lines();
  std::vector<std::unique_ptr<StaticLine>> lines;
  oc4[1].line.segments[0].length_m = 100.0;  // far too short for an 800 m span
  for (const auto& l : oc4)
    lines.push_back(std::make_unique<CatenaryStaticLine>(l.name, l.anchor_g, l.fairlead_b, 0.0, l.line));
  try {
    evaluate_line_array(lines, HullPose{});
    FAIL() << "expected SolverError";
  } catch (const SolverError& error) {
    EXPECT_NE(std::string(error.what()).find("line 'L2'"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace spiral::engine
