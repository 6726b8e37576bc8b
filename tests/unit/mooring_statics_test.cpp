// Unit tests of the 6-DOF quasi-static mooring force: symmetry, signs,
// consistency with the single-line catenary and with the moment arm.
#include <gtest/gtest.h>

#include <numbers>

#include "engine/analysis/mooring_statics.hpp"
#include "support/oc4_mooring.hpp"

namespace spiral::engine {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
// Force balance of a symmetric spread at zero offset: limited by the catenary
// closure tolerance (1e-9 m) times the line stiffness, far below 1e-6 N per MN.
constexpr double kSymmetryTolerance_N = 1e-3;

Vector6d offset(double x, double y, double z, double rx_deg, double ry_deg, double rz_deg) {
  Vector6d o;
  o << x, y, z, rx_deg * kDegToRad, ry_deg * kDegToRad, rz_deg * kDegToRad;
  return o;
}

TEST(MooringStatics, SymmetricSpreadHasNoHorizontalForceAtRest) {
  const auto result = solve_mooring_statics(test::oc4_mooring_system(), Vector6d::Zero());
  EXPECT_NEAR(result.hull_force(0), 0.0, kSymmetryTolerance_N);
  EXPECT_NEAR(result.hull_force(1), 0.0, kSymmetryTolerance_N);
  EXPECT_NEAR(result.hull_force(5), 0.0, kSymmetryTolerance_N * 50.0);  // arm 40.9 m
  double vertical = 0.0;
  for (const auto& line : result.lines) vertical += line.solution.fairlead_vertical_N;
  EXPECT_NEAR(result.hull_force(2), -vertical, 1e-6 * vertical);
}

TEST(MooringStatics, LineForceEqualsItsCatenarySolution) {
  const auto system = test::oc4_mooring_system();
  const auto result = solve_mooring_statics(system, offset(5.0, -3.0, 0.0, 0.0, 0.0, 0.0));
  const auto& line = result.lines[0];
  const Eigen::Vector3d chord = line.fairlead_g - system.lines[0].anchor_g;
  const auto direct = solve_catenary(system.lines[0].line,
                                     {std::hypot(chord.x(), chord.y()), chord.z(), 0.0});
  EXPECT_NEAR(line.fairlead_force_g.head<2>().norm(), direct.fairlead_horizontal_N,
              1e-9 * direct.fairlead_tension_N);
  EXPECT_NEAR(-line.fairlead_force_g.z(), direct.fairlead_vertical_N,
              1e-9 * direct.fairlead_tension_N);
  // The horizontal pull points from the fairlead towards the anchor.
  const Eigen::Vector2d towards_anchor = -chord.head<2>().normalized();
  EXPECT_GT(line.fairlead_force_g.head<2>().normalized().dot(towards_anchor), 1.0 - 1e-12);
}

TEST(MooringStatics, TranslationsAreRestored) {
  const auto system = test::oc4_mooring_system();
  EXPECT_LT(solve_mooring_statics(system, offset(10, 0, 0, 0, 0, 0)).hull_force(0), 0.0);
  EXPECT_LT(solve_mooring_statics(system, offset(0, 10, 0, 0, 0, 0)).hull_force(1), 0.0);
  EXPECT_LT(solve_mooring_statics(system, offset(0, 0, 0, 0, 0, 5)).hull_force(5), 0.0);
}

TEST(MooringStatics, PureYawKeepsTheThreeFoldSymmetry) {
  // Yawing a 120-degree-symmetric spread about its centre keeps that symmetry:
  // no net horizontal force, a restoring yaw moment, unchanged vertical load.
  const auto system = test::oc4_mooring_system();
  const auto rest = solve_mooring_statics(system, Vector6d::Zero());
  const auto yawed = solve_mooring_statics(system, offset(0, 0, 0, 0, 0, 5.0));
  EXPECT_NEAR(yawed.hull_force(0), 0.0, kSymmetryTolerance_N);
  EXPECT_NEAR(yawed.hull_force(1), 0.0, kSymmetryTolerance_N);
  EXPECT_LT(yawed.hull_force(5), 0.0);
  EXPECT_NEAR(yawed.hull_force(3), 0.0, kSymmetryTolerance_N * 50.0);
  EXPECT_NEAR(yawed.hull_force(4), 0.0, kSymmetryTolerance_N * 50.0);
  // Yaw stretches every line equally: the vertical load grows, it does not vanish.
  EXPECT_LT(yawed.hull_force(2), rest.hull_force(2));
}

TEST(MooringStatics, MomentIsArmCrossForce) {
  const auto system = test::oc4_mooring_system();
  const Vector6d o = offset(3.0, 2.0, -1.0, 2.0, -3.0, 25.0);
  const auto result = solve_mooring_statics(system, o);
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  const Eigen::Vector3d reference = system.reference_point_g + o.head<3>();
  for (const auto& line : result.lines) moment += (line.fairlead_g - reference).cross(line.fairlead_force_g);
  EXPECT_LT((moment - result.hull_force.tail<3>()).norm(), 1e-9 * moment.norm());
}

TEST(MooringStatics, TranslationalStiffnessIsSymmetric) {
  // Without seabed friction the lines are conservative (elastic energy plus
  // weight), so the translational block of -dF/dx is a Hessian: symmetric.
  // (Friction dissipates: the friction model is not derived from a potential.)
  auto system = test::oc4_mooring_system();
  for (auto& line : system.lines) line.line.seabed_friction = 0.0;
  const Vector6d base = offset(8.0, 5.0, 0.5, 0.0, 0.0, 0.0);
  constexpr double kStep_m = 0.01;
  Eigen::Matrix3d k;
  for (int j = 0; j < 3; ++j) {
    Vector6d plus = base, minus = base;
    plus(j) += kStep_m;
    minus(j) -= kStep_m;
    k.col(j) = -(solve_mooring_statics(system, plus).hull_force.head<3>() -
                 solve_mooring_statics(system, minus).hull_force.head<3>()) / (2.0 * kStep_m);
  }
  // Central differences with a 1 cm step: O(h^2) error ~1e-6 relative to K11.
  EXPECT_LT((k - k.transpose()).norm(), 1e-5 * k.norm());
}

TEST(MooringStatics, FailingLineIsNamed) {
  auto system = test::oc4_mooring_system();
  system.lines[1].line.segments[0].length_m = 100.0;  // far too short for an 800 m span
  try {
    solve_mooring_statics(system, Vector6d::Zero());
    FAIL() << "expected SolverError";
  } catch (const SolverError& error) {
    EXPECT_NE(std::string(error.what()).find("mooring line 'L2'"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace spiral::engine
