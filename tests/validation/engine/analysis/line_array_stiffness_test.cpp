// The line array's analytic 6×6 tangent stiffness against central finite
// differences of the line forces, and the symmetries a spread mooring must show.
#include <gtest/gtest.h>

#include <array>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "engine/analysis/line_array.hpp"
#include "support/expect_near.hpp"
#include "support/oc4_mooring.hpp"

namespace spiral::engine {
namespace {

// Analytic vs finite differences: FD round-off (closure 1e-9 m over a 1e-2 m
// step) and truncation (O(h²) over metres) both stay below 1e-7 of the
// matrix norm; 1e-6 leaves a decade of margin.
constexpr double kAnalyticVsFiniteDifference = 1e-6;
// Symmetry of the spread at rest: exact up to the catenary closure tolerance.
constexpr double kSymmetry = 1e-7;

double relative_difference(const Matrix6d& a, const Matrix6d& b) { return (a - b).norm() / b.norm(); }

TEST(LineArrayStiffness, AnalyticEqualsFiniteDifferencesAtRest) {
  const auto lines = test::oc4_static_lines();
  const HullPose pose;
  const auto analytic = evaluate_line_array(lines, pose).stiffness;
  const auto fd = finite_difference_stiffness(lines, pose);
  EXPECT_LT(relative_difference(analytic, fd), kAnalyticVsFiniteDifference) << "analytic\n"
                                                                            << analytic << "\nFD\n"
                                                                            << fd;
}

TEST(LineArrayStiffness, AnalyticEqualsFiniteDifferencesAtAnOffsetAttitude) {
  const auto lines = test::oc4_static_lines();
  Vector6d offset;
  offset << 12.0, -7.0, -0.5, 0.02, -0.03, 0.3;  // m, rad: 17° yaw
  const HullPose pose = pose_from_offset(Eigen::Vector3d::Zero(), offset);
  const auto analytic = evaluate_line_array(lines, pose).stiffness;
  const auto fd = finite_difference_stiffness(lines, pose);
  EXPECT_LT(relative_difference(analytic, fd), kAnalyticVsFiniteDifference) << "analytic\n"
                                                                            << analytic << "\nFD\n"
                                                                            << fd;
}

TEST(LineArrayStiffness, SymmetricSpreadAtRest) {
  // Without seabed friction the lines are conservative, so K is a Hessian.
  // (Jonkman's friction model is not derived from a potential: with it the
  // in-plane tangent dH/dZF differs from dV/dXF and K15 from K51 by ~1.5 %.)
  const auto lines = test::oc4_static_lines(0.0);
  const auto response = evaluate_line_array(lines, HullPose{});
  const Matrix6d& k = response.stiffness;
  const double scale = k.cwiseAbs().maxCoeff();
  // No net moment at rest: the whole matrix is symmetric.
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), kSymmetry * scale) << k;
  // Three lines 120° apart: isotropic in the horizontal plane.
  EXPECT_NEAR(k(0, 0), k(1, 1), kSymmetry * k(0, 0));
  EXPECT_NEAR(k(3, 3), k(4, 4), kSymmetry * k(3, 3));
  // Couplings that symmetry forbids (surge–sway, surge–heave, sway–heave, translation–yaw).
  for (auto [i, j] : {std::pair{0, 1}, {0, 2}, {1, 2}, {0, 5}, {1, 5}, {2, 5}, {2, 3}, {2, 4}}) {
    EXPECT_NEAR(k(i, j), 0.0, kSymmetry * scale) << "K(" << i + 1 << "," << j + 1 << ")";
  }
  // Surge–pitch and sway–roll couple with opposite signs (fairleads below the origin).
  EXPECT_NEAR(k(0, 4), -k(1, 3), kSymmetry * scale);
  // Positive definite in surge, sway, yaw.
  Eigen::Matrix3d horizontal;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) horizontal(a, b) = k(std::array{0, 1, 5}[a], std::array{0, 1, 5}[b]);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(horizontal).eigenvalues().minCoeff(), 0.0);
}

TEST(LineArrayStiffness, MatchesTheOc4DefinitionReport) {
  // Robertson et al. 2014, Eq. 5-15 (reference-platforms.md §1.6), ±1 %:
  // the report's three significant figures and its own discretisation.
  constexpr double kReport = 0.01;
  const auto k = evaluate_line_array(test::oc4_static_lines(), HullPose{}).stiffness;
  EXPECT_NEAR(k(0, 0), 7.08e4, kReport * 7.08e4);
  EXPECT_NEAR(k(2, 2), 1.91e4, kReport * 1.91e4);
  EXPECT_NEAR(k(4, 4), 8.73e7, kReport * 8.73e7);
  // Derived in the sheet from the same catenary: K66 = 1.17e8 N·m/rad.
  EXPECT_NEAR(k(5, 5), 1.17e8, kReport * 1.17e8);
}

}  // namespace
}  // namespace spiral::engine
