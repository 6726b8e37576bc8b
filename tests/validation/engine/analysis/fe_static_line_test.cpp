// The FE line as a StaticLine: agrees with the catenary line without current,
// its 3×3 attachment stiffness matches finite differences, and current pushes
// the hull downstream.
#include <gtest/gtest.h>

#include "engine/analysis/fe_static_line.hpp"
#include "engine/analysis/line_array.hpp"
#include "support/oc4_mooring.hpp"

namespace spiral::engine {
namespace {

// FE vs catenary on the OC4 line with 40 elements and a stiff seabed: the FE
// statics are frictionless and converge to ~1e-6 (tests/validation/engine/lines/fe_statics_catenary_test.cpp).
constexpr double kFeVsCatenary = 1e-4;
// End stiffness vs central differences when the touchdown node follows the
// touchdown point (the solver's default r-adaptivity): every perturbed solve
// is on a slightly different mesh, and the fixed-mesh tangent misses that
// node motion — up to 0.4 % at 40 elements, shrinking with the mesh.
constexpr double kStiffnessVsMovingMesh = 1e-2;
// The same on a fixed mesh: the condensed tangent is the exact derivative of
// the discrete equilibrium, so only the central difference's own error
// remains. The perturbation is of the attachment (end-B) position, which every
// free DOF follows through a re-solved equilibrium. Measured on the case
// below (‖K − K_fd‖/‖K_fd‖): truncation ∝ h² — 1.9e-6 at 3 mm, 2.1e-7 at 1 mm,
// 4.9e-8 at 0.5 mm (C ≈ 0.2 m⁻²; about 10× the C of the same line without
// the offset and cross-flow); then round-off
// ∝ 1/h from the solves' force floor (nodal residual ≈ 5e-6 N, Newton
// converges past the 1e-10 tolerance): 2.5e-8 at 0.1 mm, 8.9e-8 at 0.03 mm.
// The minimum lies at h ≈ 0.2 mm (9.5e-9), the step taken; 1e-6 leaves two
// decades for other machines and compilers.
constexpr double kFdStep_m = 2e-4;
constexpr double kStiffnessVsFixedMesh = 1e-6;

std::unique_ptr<FeStaticLine> oc4_fe_line(double current_m_per_s, FeStaticsOptions options = {}) {
  const test::Oc4Line oc4 = test::oc4_lines(0.0).front();
  const FeLineModel model = test::oc4_fe_chain_model();
  FeEnvironment environment;
  environment.seabed_z_m = -200.0;
  environment.seabed_stiffness_N_per_m2 = 1e7;
  environment.current = {{-200.0, {current_m_per_s, 0.0, 0.0}}, {0.0, {current_m_per_s, 0.0, 0.0}}};
  return std::make_unique<FeStaticLine>(oc4.name, oc4.anchor_g, oc4.fairlead_b, model, environment, std::move(options));
}

TEST(FeStaticLine, AgreesWithTheCatenaryWithoutCurrent) {
  auto fe = oc4_fe_line(0.0);
  auto catenary = test::oc4_static_lines(0.0);
  const Eigen::Vector3d attachment = fe->attachment_b() + Eigen::Vector3d(2.0, -1.0, 0.0);
  const auto a = fe->solve(attachment);
  const auto b = catenary.front()->solve(attachment);
  EXPECT_LT((a.force_g - b.force_g).norm(), kFeVsCatenary * b.force_g.norm())
      << a.force_g.transpose() << " vs " << b.force_g.transpose();
}

/// −dF/dx of the line's force at `attachment` by central differences of step
/// `step_m`, each solve warm-started from the previous one.
Eigen::Matrix3d finite_difference_stiffness(FeStaticLine& line, const Eigen::Vector3d& attachment, double step_m) {
  Eigen::Matrix3d fd;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d plus = attachment, minus = attachment;
    plus(j) += step_m;
    minus(j) -= step_m;
    fd.col(j) = -(line.solve(plus).force_g - line.solve(minus).force_g) / (2.0 * step_m);
  }
  return fd;
}

TEST(FeStaticLine, StiffnessMatchesFiniteDifferencesOnAMovingMesh) {
  auto fe = oc4_fe_line(0.5);
  const Eigen::Vector3d attachment = fe->attachment_b();
  const Eigen::Matrix3d k = fe->solve(attachment).stiffness_g;
  const Eigen::Matrix3d fd = finite_difference_stiffness(*fe, attachment, 0.01);
  EXPECT_LT((k - fd).norm(), kStiffnessVsMovingMesh * fd.norm()) << k << "\n\n" << fd;
}

TEST(FeStaticLine, StiffnessMatchesFiniteDifferencesOnAFixedMesh) {
  // OC4 line L1 (azimuth 60°), 40 elements, part on a stiff seabed, 0.5 m/s
  // current along +x (across the line), fairlead moved off its rest point;
  // the mesh held (no touchdown node move), so both sides see one discrete model.
  FeStaticsOptions options;
  options.snap_node_to_touchdown = false;
  auto fe = oc4_fe_line(0.5, options);
  const Eigen::Vector3d attachment = fe->attachment_b() + Eigen::Vector3d(3.0, -2.0, 0.5);
  const Eigen::Matrix3d k = fe->solve(attachment).stiffness_g;
  ASSERT_TRUE(fe->last_result()->touchdown.has_value());  // the contact terms are exercised
  const Eigen::Matrix3d fd = finite_difference_stiffness(*fe, attachment, kFdStep_m);
  const double difference = (k - fd).norm() / fd.norm();
  std::printf("FE line K vs central differences (h = %.0e m, fixed mesh): %.2e (‖K‖ %.3e N/m)\n", kFdStep_m, difference,
              fd.norm());
  EXPECT_LT(difference, kStiffnessVsFixedMesh) << k << "\n\n" << fd;
}

TEST(FeStaticLine, CurrentAlongTheLinePushesTheFairleadForce) {
  // L1 runs from its anchor at 60° towards the hull: a current towards −x
  // drags the suspended chain towards the hull side and changes the pull.
  auto still = oc4_fe_line(0.0);
  auto flowing = oc4_fe_line(-1.0);
  const Eigen::Vector3d attachment = still->attachment_b();
  const auto a = still->solve(attachment);
  const auto b = flowing->solve(attachment);
  EXPECT_LT(b.force_g.x(), a.force_g.x());  // drag adds a −x pull at the fairlead
}

TEST(FeStaticLine, StateHasTheMeshAsProfile) {
  auto fe = oc4_fe_line(0.0);
  const auto state = fe->state(fe->attachment_b(), 0);
  EXPECT_EQ(state.regime, LineRegime::touchdown);
  EXPECT_GT(state.laid_length_m, 200.0);
  EXPECT_GE(state.profile.size(), 41u);
  EXPECT_NEAR(state.profile.back().tension_N, state.top.top_tension_N, 1e-3 * state.top.top_tension_N);
}

// With a reuse distance, solve() takes the end-B stiffness of the last solve
// that computed one while within that distance of it (the force is always
// solved where asked), and a fresh one beyond; an adopted line brings its
// source's. Without one (the default), the stiffness is always exact. A
// warm and a cold solve at one attachment end on slightly different meshes
// (the touchdown node follows the touchdown point): their stiffness agrees
// to kStiffnessVsMovingMesh, their force to 1e-6. This line's stiffness
// changes by 3.9 % over the 0.67 m between `at` and `near`.
TEST(FeStaticLine, ReusedStiffnessStaysWithinItsDistance) {
  auto line = oc4_fe_line(0.5);
  const Eigen::Vector3d at = line->attachment_b() + Eigen::Vector3d(2.0, 0.0, 0.0);
  const Eigen::Vector3d near = at + Eigen::Vector3d(0.6, 0.3, 0.0), far = at + Eigen::Vector3d(3.0, 0.0, 0.0);
  const auto relative = [](const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return (a - b).norm() / b.norm(); };
  const LineEndResponse first = line->solve(at);
  const LineEndResponse exact_near = oc4_fe_line(0.5)->solve(near);
  ASSERT_GT(relative(first.stiffness_g, exact_near.stiffness_g), 3.0 * kStiffnessVsMovingMesh);

  line->set_stiffness_reuse_distance(1.0);
  const LineEndResponse reused = line->solve(near);
  EXPECT_EQ(reused.stiffness_g, first.stiffness_g);
  EXPECT_LT((reused.force_g - exact_near.force_g).norm(), 1e-6 * exact_near.force_g.norm());
  const LineEndResponse fresh = line->solve(far);
  EXPECT_LT(relative(fresh.stiffness_g, oc4_fe_line(0.5)->solve(far).stiffness_g), kStiffnessVsMovingMesh);

  // An adopted line: the source's last solve at `near` without a stiffness
  // of its own, the source's most recent one (at `at`) with it.
  auto source = oc4_fe_line(0.5);
  source->solve(at);
  source->solve_force(near);
  auto adopting = oc4_fe_line(0.5);
  adopting->adopt(*source);
  adopting->set_stiffness_reuse_distance(1.0);
  EXPECT_EQ(adopting->solve(near).stiffness_g, first.stiffness_g);
  adopting->set_stiffness_reuse_distance(0.0);
  EXPECT_LT(relative(adopting->solve(near).stiffness_g, exact_near.stiffness_g), kStiffnessVsMovingMesh);
}

}  // namespace
}  // namespace spiral::engine
