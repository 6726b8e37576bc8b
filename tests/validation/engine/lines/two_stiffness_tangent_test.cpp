// The static–dynamic (two-stiffness) tangent of fibre-rope lines: the mean
// state on the static EA, the strain changes about it on the dynamic EA
// (DNV-OS-E301 ch. 2 sec. 2 [2.4]). Checked against the analytic axial
// stiffness of a taut vertical line, against the static tangent when the
// incremental EA is the static one, the catenary's closed form against the
// FE line's condensed tangent on a taut chain–polyester–chain leg, and that
// tangent against the FE line *dynamics* with its dynamic EA (what the
// coupled level integrates) under a slow end displacement: the S-C levels'
// linearized lines and the coupled level's FE lines carry the same convention.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/lines/catenary.hpp"
#include "engine/lines/fe_line_dynamics.hpp"
#include "engine/lines/fe_line_statics.hpp"
#include "engine/numerics/sampled_trajectory.hpp"

namespace spiral::engine {
namespace {

constexpr double kStaticEA_N = 2.4e8;   // polyester, post-installation (static) EA
constexpr double kDynamicEA_N = 4.0e8;  // its dynamic EA, ≈ 1.65× (DNV-RP-E305 range 1.3–2.5×)

FeLineSection section(double length_m, double weight_N_per_m, double EA_N, double element_length_m) {
  FeLineSection s;
  s.length_m = length_m;
  s.EA_N = EA_N;
  s.weight_N_per_m = weight_N_per_m;
  s.mass_kg_per_m = weight_N_per_m / 9.80665 * 1.3;
  s.element_length_m = element_length_m;
  return s;
}

// A 1000 m polyester tendon hanging from its top, anchored 30 m above the
// seabed (no contact), stretched 1 %: straight and vertical. An axial end
// displacement δ changes every element's strain by δ / L (the weight fixes
// the tension's gradient, not its change), so dN = EA_inc δ / L all along and
// K_zz = EA_inc / L exactly; a lateral one stretches it only at second order,
// so K_xx is the tension's alone and does not depend on the axial EA.
TEST(TwoStiffnessTangent, VerticalTendonTakesTheIncrementalEAAlongItsAxis) {
  constexpr double kLength_m = 1000.0;
  FeLineModel model;
  model.sections = {section(kLength_m, 50.0, kStaticEA_N, 25.0)};
  const FeLineEnds ends{{0.0, 0.0, -1200.0}, {0.0, 0.0, -1200.0 + 1.01 * kLength_m}};
  const FeStaticsResult r = solve_fe_line_statics(model, FeEnvironment{}, ends);

  const Eigen::Matrix3d k_static = fe_line_incremental_end_B_stiffness(model, FeEnvironment{}, r, {kStaticEA_N});
  const Eigen::Matrix3d k_dynamic = fe_line_incremental_end_B_stiffness(model, FeEnvironment{}, r, {kDynamicEA_N});
  // The FE condensation is dF_B/dx_B: −EA/L along the axis. Tolerance: the
  // cubic Hermite element represents the linear tension gradient exactly;
  // 1e-8 leaves room for the condensation's round-off.
  EXPECT_NEAR(-k_static(2, 2), kStaticEA_N / kLength_m, 1e-8 * kStaticEA_N / kLength_m);
  EXPECT_NEAR(-k_dynamic(2, 2), kDynamicEA_N / kLength_m, 1e-8 * kDynamicEA_N / kLength_m);
  EXPECT_NEAR(k_dynamic(0, 0), k_static(0, 0), 1e-8 * std::abs(k_static(0, 0)));
  EXPECT_LT(k_static(0, 0), 0.0) << "a taut line pulls its top back towards the vertical";
  // The static tangent of the solve itself is the incremental one at the static EA.
  EXPECT_LE((k_static - r.end_B_stiffness_N_per_m).norm(), 1e-9 * r.end_B_stiffness_N_per_m.norm());
}

FeLineModel taut_leg_fe(double polyester_dynamic_EA_N) {
  FeLineModel model;
  model.sections = {section(150.0, 1300.0, 1.3e9, 10.0), section(2490.0, 50.0, kStaticEA_N, 25.0),
                    section(100.0, 1300.0, 1.3e9, 10.0)};
  model.joint_load_N = {2.0e4, 0.0};
  for (FeLineSection& s : model.sections) {
    s.hydro_diameter_m = 0.2;
    s.drag_normal = 1.2;  // damps the transverse modes the ramp rings
    s.displaced_area_m2 = 0.25 * 3.14159 * 0.2 * 0.2;
    s.added_mass_normal = 1.0;
  }
  model.sections[1].EA_dynamic_N = polyester_dynamic_EA_N;
  return model;
}

const FeLineEnds kTautLegEnds{{0.0, 0.0, -1802.0}, {2118.0, 0.0, -1802.0 + 1772.0}};

// Deep-water taut leg (chain, polyester, chain; a 20 kN clump at the lower
// joint), fully suspended: the catenary's closed form and the FE line solve
// the same state independently.
CatenaryLine taut_leg_catenary(double polyester_EA_N) {
  return {{{150.0, 1300.0, 1.3e9}, {2490.0, 50.0, polyester_EA_N}, {100.0, 1300.0, 1.3e9}}, {2.0e4, 0.0}, 0.0};
}

TEST(TwoStiffnessTangent, CatenaryAtTheStaticEAIsItsOwnTangent) {
  const CatenaryLine line = taut_leg_catenary(kStaticEA_N);
  const CatenaryGeometry g{2118.0, 1772.0, 30.0};
  const CatenarySolution s = solve_catenary(line, g);
  const Eigen::Matrix2d k = catenary_incremental_tangent(line, g, s, {1.3e9, kStaticEA_N, 1.3e9});
  EXPECT_LE((k - s.tangent_stiffness).norm(), 1e-12 * s.tangent_stiffness.norm());
}

TEST(TwoStiffnessTangent, CatenaryAndFeLineAgreeOnTheDynamicTangentOfATautLeg) {
  const CatenaryLine line = taut_leg_catenary(kStaticEA_N);
  const CatenaryGeometry g{2118.0, 1772.0, 30.0};
  const CatenarySolution s = solve_catenary(line, g);
  const std::vector<double> incremental{1.3e9, kDynamicEA_N, 1.3e9};
  const Eigen::Matrix2d k_catenary = catenary_incremental_tangent(line, g, s, incremental);

  const FeLineModel model = taut_leg_fe(0.0);
  const FeStaticsResult r = solve_fe_line_statics(model, FeEnvironment{}, kTautLegEnds);
  // Same state first: the FE fairlead force is the catenary's (cubic
  // elements of 10–25 m on a taut line: 1e-6).
  EXPECT_NEAR(-r.end_B_force_N.x(), s.fairlead_horizontal_N, 1e-6 * s.fairlead_tension_N);
  EXPECT_NEAR(-r.end_B_force_N.z(), s.fairlead_vertical_N, 1e-6 * s.fairlead_tension_N);
  const Eigen::Matrix3d k_fe = fe_line_incremental_end_B_stiffness(model, FeEnvironment{}, r, incremental);
  // In-plane block: d(H, V)/d(XF, ZF) = −d(F_x, F_z)/d(x, z) of the FE end force.
  const Eigen::Matrix2d k_fe_plane{{-k_fe(0, 0), -k_fe(0, 2)}, {-k_fe(2, 0), -k_fe(2, 2)}};
  // At the static EA the two agree to round-off (the FE tangent is exact,
  // cubic elements on a taut line)...
  const Eigen::Matrix3d& k0 = r.end_B_stiffness_N_per_m;
  const Eigen::Matrix2d k0_plane{{-k0(0, 0), -k0(0, 2)}, {-k0(2, 0), -k0(2, 2)}};
  EXPECT_LE((k0_plane - s.tangent_stiffness).norm(), 1e-8 * s.tangent_stiffness.norm());
  // ...and at the dynamic EA within the catenary's stated approximation:
  // the term it leaves out is ε_s (1 − EA_s/EA_inc) of the geometric part.
  const double static_strain = s.fairlead_tension_N / kStaticEA_N;
  const double bound = static_strain * (1.0 - kStaticEA_N / kDynamicEA_N);
  std::printf("dynamic tangent: catenary vs FE %.2e of K (bound %.2e)\n",
              (k_fe_plane - k_catenary).norm() / k_catenary.norm(), bound);
  EXPECT_LE((k_fe_plane - k_catenary).norm(), bound * k_catenary.norm()) << "catenary\n"
                                                                         << k_catenary << "\nFE\n"
                                                                         << k_fe_plane;
  // And the dynamic EA stiffens the leg: a taut leg's axial stiffness is
  // mostly elastic, so its largest eigenvalue grows by a good part of the
  // EA ratio.
  const double stiffening = k_catenary.norm() / s.tangent_stiffness.norm();
  EXPECT_GT(stiffening, 1.3);
  EXPECT_LT(stiffening, kDynamicEA_N / kStaticEA_N);
}

// The fairlead moved by δ = (0.3, 0.1, 0.15) m along a quintic ramp over
// 100 s (no velocity or acceleration at its ends: nothing rings), then held
// 40 s: the end force change is the incremental tangent's K δ. What is left
// beyond it: the second-order change of the tangent over δ (≈ |δ| / the
// metres over which a taut leg's K changes: < 0.1 %) and the drag-damped
// transverse ringing; 1 % covers both. The static EA's tangent predicts a
// change ≥ 30 % smaller along the leg: the test tells them apart.
TEST(TwoStiffnessTangent, FeLineDynamicsCarriesASlowDisplacementOnTheDynamicEA) {
  const FeLineModel model = taut_leg_fe(kDynamicEA_N);
  FeDynamicEnvironment environment;
  const FeStaticsResult st = solve_fe_line_statics(model, environment.statics, kTautLegEnds);
  const Eigen::Vector3d delta(0.3, 0.1, 0.15);
  constexpr double kRamp_s = 100.0;
  FeDynamicsOptions options;
  const Eigen::Vector3d rest = st.node_position_m.back();
  options.end_B_motion = [&](double t) {
    const RampValue r = smooth_ramp(t, kRamp_s);
    return EndKinematics{rest + r.value * delta, r.rate_per_s * delta, r.rate2_per_s2 * delta};
  };
  FeLineDynamics dynamics(model, environment, st, options);
  Eigen::Vector3d mean_force = Eigen::Vector3d::Zero();
  int samples = 0;
  for (int k = 1; k <= 140; ++k) {
    dynamics.advance_to(static_cast<double>(k));
    if (k > 120) mean_force += dynamics.end_B_force_N(), ++samples;
  }
  const Eigen::Vector3d change = mean_force / samples - st.end_B_force_N;
  const Eigen::Vector3d predicted =
      fe_line_incremental_end_B_stiffness(model, environment.statics, st, {1.3e9, kDynamicEA_N, 1.3e9}) * delta;
  const Eigen::Vector3d static_ea = st.end_B_stiffness_N_per_m * delta;
  std::printf("end force change %.0f %.0f %.0f N; dynamic-EA tangent %.0f %.0f %.0f N; static-EA %.0f %.0f %.0f N\n",
              change.x(), change.y(), change.z(), predicted.x(), predicted.y(), predicted.z(), static_ea.x(),
              static_ea.y(), static_ea.z());
  EXPECT_LE((change - predicted).norm(), 0.01 * predicted.norm());
  EXPECT_GT((change - static_ea).norm(), 0.3 * static_ea.norm());
}

TEST(TwoStiffnessTangent, AWrongNumberOfStiffnessesIsRefused) {
  const CatenaryLine line = taut_leg_catenary(kStaticEA_N);
  const CatenaryGeometry g{2118.0, 1772.0, 30.0};
  const CatenarySolution s = solve_catenary(line, g);
  EXPECT_THROW(catenary_incremental_tangent(line, g, s, {kDynamicEA_N}), std::invalid_argument);
  EXPECT_THROW(catenary_incremental_tangent(line, g, s, {1.3e9, 0.0, 1.3e9}), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
