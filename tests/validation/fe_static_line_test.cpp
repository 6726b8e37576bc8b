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
// statics are frictionless and converge to ~1e-6 (tests/validation/fe_statics_catenary_test.cpp).
constexpr double kFeVsCatenary = 1e-4;
// End stiffness vs central differences (±1 cm): the FE tangent is the fixed-mesh
// one; the touchdown node's move changes it by up to 0.4 %.
constexpr double kStiffnessVsFiniteDifference = 1e-2;

std::unique_ptr<FeStaticLine> oc4_fe_line(double current_m_per_s) {
  const test::Oc4Line oc4 = test::oc4_lines(0.0).front();
  FeLineModel model;
  FeLineSection section;
  section.length_m = 835.35;
  section.EA_N = 7.536e8;
  section.weight_N_per_m = oc4.line.segments[0].weight_N_per_m;
  section.mass_kg_per_m = 113.35;
  section.hydro_diameter_m = 0.0766;
  section.drag_normal = 2.0;
  section.element_length_m = 835.35 / 40.0;
  model.sections = {section};
  FeEnvironment environment;
  environment.seabed_z_m = -200.0;
  environment.seabed_stiffness_N_per_m2 = 1e7;
  environment.current = {{-200.0, {current_m_per_s, 0.0, 0.0}}, {0.0, {current_m_per_s, 0.0, 0.0}}};
  return std::make_unique<FeStaticLine>(oc4.name, oc4.anchor_g, oc4.fairlead_b, model, environment);
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

TEST(FeStaticLine, StiffnessMatchesFiniteDifferences) {
  auto fe = oc4_fe_line(0.5);
  const Eigen::Vector3d attachment = fe->attachment_b();
  const Eigen::Matrix3d k = fe->solve(attachment).stiffness_g;
  Eigen::Matrix3d fd;
  constexpr double kStep_m = 0.01;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d plus = attachment, minus = attachment;
    plus(j) += kStep_m;
    minus(j) -= kStep_m;
    fd.col(j) = -(fe->solve(plus).force_g - fe->solve(minus).force_g) / (2.0 * kStep_m);
  }
  EXPECT_LT((k - fd).norm(), kStiffnessVsFiniteDifference * fd.norm()) << k << "\n\n" << fd;
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
  EXPECT_EQ(state.regime, "touchdown");
  EXPECT_GT(state.laid_length_m, 200.0);
  EXPECT_GE(state.profile.size(), 41u);
  EXPECT_NEAR(state.profile.back().tension_N, state.top.top_tension_N, 1e-3 * state.top.top_tension_N);
}

}  // namespace
}  // namespace spiral::engine
