// Unit tests of the FE line statics: loads (drag conventions, current, point
// loads), seabed penalty contact, warm starts, and the error channel.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "engine/lines/fe_line_statics.hpp"

namespace spiral::engine {
namespace {

constexpr double kOc4Length_m = 835.35;
constexpr double kOc4EA_N = 7.536e8;
const double kOc4Weight_N_per_m = (113.35 - 1025.0 * M_PI / 4.0 * 0.0766 * 0.0766) * 9.80665;
const FeLineEnds kOc4Ends{{-837.6, 0.0, -200.0}, {-40.868, 0.0, -14.0}};
// Newton stops at 1e-10 of the force scale; global balances hold to that, with
// round-off: 1e-8 relative.
constexpr double kBalanceTolerance = 1e-8;

FeLineSection oc4_section(int elements) {
  FeLineSection s;
  s.length_m = kOc4Length_m;
  s.EA_N = kOc4EA_N;
  s.mass_kg_per_m = 113.35;
  s.weight_N_per_m = kOc4Weight_N_per_m;
  s.hydro_diameter_m = 0.0766 * 1.8;  // studless chain volume-equivalent diameter
  s.drag_normal = 1.1;
  s.drag_tangential = 0.2;
  s.element_length_m = kOc4Length_m / elements;
  return s;
}

FeLineModel oc4_model(int elements = 20) {
  FeLineModel m;
  m.sections = {oc4_section(elements)};
  return m;
}

FeEnvironment seabed(double stiffness_N_per_m2) {
  FeEnvironment env;
  env.seabed_z_m = -200.0;
  env.seabed_stiffness_N_per_m2 = stiffness_N_per_m2;
  return env;
}

TEST(FeStatics, CurrentPushesTheLineDownstream) {
  FeEnvironment env = seabed(1e6);
  env.current = {{-200.0, {0.0, 0.5, 0.0}}, {0.0, {0.0, 1.0, 0.0}}};  // +y, sheared
  const auto r = solve_fe_line_statics(oc4_model(), env, kOc4Ends);
  double y_max = 0.0;
  for (std::size_t i = 1; i + 1 < r.node_position_m.size(); ++i) {
    EXPECT_GE(r.node_position_m[i].y(), 0.0) << "node " << i;
    y_max = std::max(y_max, r.node_position_m[i].y());
  }
  EXPECT_GT(y_max, 1.0);  // a visible offset, m
  // The line drags both ends downstream.
  EXPECT_GT(r.end_A_force_N.y(), 0.0);
  EXPECT_GT(r.end_B_force_N.y(), 0.0);
  for (const auto& p : r.node_position_m) EXPECT_TRUE(p.allFinite());
}

// A weightless straight line, pre-stretched between two points at the same
// depth, in a current along it: only tangential drag acts, and the two ends
// together carry ½ ρ Cdt π D U² × stretched length (OrcaFlex/MoorDyn axial
// convention on π D).
TEST(FeStatics, TangentialDragUsesPiD) {
  constexpr double rho = 1025.0, U = 1.2, D = 0.15, Cdt = 0.5, L = 100.0, EA = 1e8, pre_strain = 0.01;
  FeLineSection s;
  s.length_m = L;
  s.EA_N = EA;
  s.hydro_diameter_m = D;
  s.drag_tangential = Cdt;
  s.element_length_m = 10.0;
  FeLineModel m;
  m.sections = {s};
  FeEnvironment env;
  env.current = {{0.0, {U, 0.0, 0.0}}};
  const auto r = solve_fe_line_statics(m, env, FeLineEnds{{0, 0, -50}, {L * (1 + pre_strain), 0, -50}});
  const double stretched_length = r.node_position_m.back().x() - r.node_position_m.front().x();
  const double expected = 0.5 * rho * Cdt * M_PI * D * U * U * stretched_length;
  EXPECT_NEAR((r.end_A_force_N + r.end_B_force_N).x() / expected, 1.0, kBalanceTolerance);
}

// Same line across the current: normal drag ½ ρ Cdn D U² per stretched length;
// the line bows by 17 cm, so the normal velocity is U cos θ with θ up to 7e-3:
// θ² ≈ 5e-5, bounded by 1e-4.
TEST(FeStatics, NormalDragUsesD) {
  constexpr double kSmallAngleTolerance = 1e-4;
  constexpr double rho = 1025.0, U = 1.2, D = 0.15, Cdn = 1.2, L = 100.0, EA = 1e8, pre_strain = 0.01;
  FeLineSection s;
  s.length_m = L;
  s.EA_N = EA;
  s.hydro_diameter_m = D;
  s.drag_normal = Cdn;
  s.element_length_m = 10.0;
  FeLineModel m;
  m.sections = {s};
  FeEnvironment env;
  env.current = {{0.0, {0.0, U, 0.0}}};
  const auto r = solve_fe_line_statics(m, env, FeLineEnds{{0, 0, -50}, {L * (1 + pre_strain), 0, -50}});
  double length = 0.0;
  for (std::size_t i = 1; i < r.node_position_m.size(); ++i) {
    length += (r.node_position_m[i] - r.node_position_m[i - 1]).norm();
  }
  const double expected = 0.5 * rho * Cdn * D * U * U * length;
  EXPECT_NEAR((r.end_A_force_N + r.end_B_force_N).y() / expected, 1.0, kSmallAngleTolerance);
}

TEST(FeStatics, SeabedHoldsTheLaidPartWithinItsPenaltyPenetration) {
  constexpr double k = 1e5;  // soft (clay), so the penetration w/k ≈ 1 cm is visible
  const double pen_max = kOc4Weight_N_per_m / k;
  // Laid nodes sit at w/k: exactly so on a mesh that resolves the penalty
  // layers √(H/k) ≈ 3 m at the anchor and the touchdown point; on this 21 m
  // mesh their trace oscillates, decays element by element and stays within
  // 2 % of w/k (both for the deepest node and for the laid ones).
  constexpr double kLaidPenetrationTolerance = 0.02;  // relative to w/k
  const auto r = solve_fe_line_statics(oc4_model(40), seabed(k), kOc4Ends);
  ASSERT_TRUE(r.touchdown.has_value());
  const double layer = std::sqrt(9.1e5 / k);
  int laid = 0;
  for (std::size_t i = 0; i < r.node_position_m.size(); ++i) {
    const double pen = -200.0 - r.node_position_m[i].z();
    EXPECT_LE(pen, pen_max * (1.0 + kLaidPenetrationTolerance)) << "node " << i;
    const double s = r.node_arc_length_m[i];
    if (s > 10.0 * layer && s < r.touchdown->arc_length_m - 10.0 * layer) {
      EXPECT_NEAR(pen / pen_max, 1.0, kLaidPenetrationTolerance) << "node " << i;
      ++laid;
    }
  }
  EXPECT_GT(laid, 5);
  EXPECT_NEAR(r.touchdown->position_m.z(), -200.0, 1e-9);
}

TEST(FeStatics, ClumpWeightAtAJointIsCarriedByTheEnds) {
  // Two sections, a 50 kN clump at the joint, no seabed: the ends carry the
  // whole weight; the joint is a node.
  FeLineModel m;
  auto a = oc4_section(10), b = oc4_section(10);
  a.length_m = b.length_m = kOc4Length_m / 2.0;
  m.sections = {a, b};
  m.joint_load_N = {5e4};
  const auto r = solve_fe_line_statics(m, FeEnvironment{}, FeLineEnds{{0, 0, 0}, {796.732, 0, 186.0}});
  const double total = kOc4Weight_N_per_m * kOc4Length_m + 5e4;
  EXPECT_NEAR(-(r.end_A_force_N + r.end_B_force_N).z() / total, 1.0, kBalanceTolerance);
  bool joint_node = false;
  for (double s : r.node_arc_length_m) joint_node = joint_node || s == kOc4Length_m / 2.0;
  EXPECT_TRUE(joint_node);
}

TEST(FeStatics, WarmStartReturnsTheSameEquilibriumAtOnce) {
  constexpr int kMaxWarmIterations = 2;
  const auto env = seabed(1e7);
  const auto first = solve_fe_line_statics(oc4_model(), env, kOc4Ends);
  FeStaticsOptions o;
  o.warm_start_state = first.state;
  o.warm_start_node_arc_length_m = first.node_arc_length_m;
  const auto again = solve_fe_line_statics(oc4_model(), env, kOc4Ends, o);
  EXPECT_LE(again.iterations, kMaxWarmIterations);
  EXPECT_LT((again.end_B_force_N - first.end_B_force_N).norm(), kBalanceTolerance * first.end_B_force_N.norm());
}

// A caller that needs the force first and the end-B stiffness later at the
// same ends (the hull's line search, then its Newton step) completes the
// force-only solution instead of solving again: the same numbers, bit for bit,
// as one solve with the stiffness, and the same warm start for the next solve.
TEST(FeStatics, StiffnessCompletedAfterAForceOnlySolveIsTheSolveWithIt) {
  FeEnvironment env = seabed(1e7);
  env.current = {{-200.0, {0.0, 0.5, 0.0}}, {0.0, {0.0, 1.0, 0.0}}};
  FeStaticsOptions force_only;
  force_only.compute_end_B_stiffness = false;
  const auto forces = solve_fe_line_statics(oc4_model(), env, kOc4Ends, force_only);
  ASSERT_FALSE(forces.has_end_B_stiffness);
  const auto completed = with_end_B_stiffness(oc4_model(), env, forces);
  const auto both = solve_fe_line_statics(oc4_model(), env, kOc4Ends);
  ASSERT_TRUE(both.has_end_B_stiffness);
  EXPECT_TRUE(completed.has_end_B_stiffness);
  EXPECT_EQ(completed.state, both.state);
  EXPECT_EQ(completed.end_B_force_N, both.end_B_force_N);
  EXPECT_EQ(completed.end_B_stiffness_N_per_m, both.end_B_stiffness_N_per_m);
  EXPECT_EQ(completed.jacobian_evaluations, both.jacobian_evaluations);

  const FeLineEnds moved{kOc4Ends.end_A_m, kOc4Ends.end_B_m + Eigen::Vector3d(3.0, 1.0, 0.0)};
  FeStaticsOptions from_completed, from_both;
  warm_start_from(from_completed, completed);
  warm_start_from(from_both, both);
  const auto next_completed = solve_fe_line_statics(oc4_model(), env, moved, from_completed);
  const auto next_both = solve_fe_line_statics(oc4_model(), env, moved, from_both);
  EXPECT_EQ(next_completed.end_B_force_N, next_both.end_B_force_N);
  EXPECT_EQ(next_completed.iterations, next_both.iterations);
}

template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const SolverError& e) {
    return e.what();
  }
  return "(no SolverError thrown)";
}

TEST(FeStatics, BadInputIsRejectedWithTheFieldAndValue) {
  const auto env = seabed(1e6);
  {
    auto m = oc4_model();
    m.sections[0].EA_N = -5.0;
    const auto msg = error_of([&] { solve_fe_line_statics(m, env, kOc4Ends); });
    EXPECT_NE(msg.find("sections[0].EA_N"), std::string::npos) << msg;
    EXPECT_NE(msg.find("-5"), std::string::npos) << msg;
  }
  {
    auto m = oc4_model();
    m.sections[0].element_length_m = NAN;
    const auto msg = error_of([&] { solve_fe_line_statics(m, env, kOc4Ends); });
    EXPECT_NE(msg.find("element_length_m"), std::string::npos) << msg;
  }
  {
    auto m = oc4_model();
    m.joint_load_N = {1.0, 2.0};
    const auto msg = error_of([&] { solve_fe_line_statics(m, env, kOc4Ends); });
    EXPECT_NE(msg.find("joint_load_N"), std::string::npos) << msg;
  }
  {
    auto e = env;
    e.current = {{0.0, {1, 0, 0}}, {-10.0, {1, 0, 0}}};
    const auto msg = error_of([&] { solve_fe_line_statics(oc4_model(), e, kOc4Ends); });
    EXPECT_NE(msg.find("current[1].z_m"), std::string::npos) << msg;
  }
  {
    const auto msg = error_of([&] {
      solve_fe_line_statics(oc4_model(), env, FeLineEnds{kOc4Ends.end_A_m, kOc4Ends.end_A_m});
    });
    EXPECT_NE(msg.find("coincide"), std::string::npos) << msg;
  }
  {
    FeStaticsOptions o;
    o.warm_start_state = Eigen::VectorXd::Zero(7);
    const auto msg = error_of([&] { solve_fe_line_statics(oc4_model(), env, kOc4Ends, o); });
    EXPECT_NE(msg.find("warm_start_state"), std::string::npos) << msg;
  }
}

TEST(FeStatics, NonConvergenceReportsIterationsResidualAndHint) {
  FeStaticsOptions o;
  o.max_iterations = 1;
  try {
    solve_fe_line_statics(oc4_model(), seabed(1e6), kOc4Ends, o);
    FAIL() << "expected SolverError";
  } catch (const SolverError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("did not converge"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Try:"), std::string::npos) << msg;
    EXPECT_GE(e.diagnostics().iterations, 1);
    EXPECT_GT(e.diagnostics().residual, 0.0);
    EXPECT_TRUE(std::isfinite(e.diagnostics().residual));
    EXPECT_EQ(e.diagnostics().residual_unit, "N");
  }
}

TEST(FeStatics, SlackLineOnTheSeabedIsExplained) {
  // 835 m of chain between an anchor and a point 100 m away and 50 m up:
  // it would have to fold on the seabed.
  const auto msg = error_of([&] {
    solve_fe_line_statics(oc4_model(), seabed(1e6), FeLineEnds{{0, 0, -200}, {100, 0, -150}});
  });
  EXPECT_NE(msg.find("slack"), std::string::npos) << msg;
}

TEST(FeStatics, MeshHonoursSectionsAndRefinementZone) {
  FeLineModel m;
  FeLineSection a = oc4_section(1), b = oc4_section(1);
  a.length_m = 100.0;
  a.element_length_m = 30.0;  // 4 elements of 25 m (rounded up, equal)
  b.length_m = 200.0;
  b.element_length_m = 50.0;
  m.sections = {a, b};
  m.refinement = FeRefinementZone{150.0, 20.0, 5.0};  // 150–170 m in 5 m elements
  const auto s = fe_line_mesh(m);
  auto has = [&](double x) {
    for (double v : s) {
      if (std::abs(v - x) < 1e-9) return true;
    }
    return false;
  };
  EXPECT_TRUE(has(0.0) && has(25.0) && has(100.0) && has(150.0) && has(155.0) && has(170.0) && has(300.0));
  for (std::size_t i = 1; i < s.size(); ++i) {
    const double h = s[i] - s[i - 1];
    if (s[i - 1] >= 150.0 - 1e-9 && s[i] <= 170.0 + 1e-9) {
      EXPECT_LE(h, 5.0 + 1e-9);
    }
  }
}

// A strong cross current swings a flexible riser through a large angle: the
// solver must get there (continuations) and every node must balance.
TEST(FeStatics, StrongCrossCurrentOnAFlexibleRiserConverges) {
  constexpr double kEquilibrium = 1e-8;  // nodal residual / largest tension (Newton stops at 1e-10)
  FeLineSection s;
  s.length_m = 170.0;
  s.EA_N = 5e8;
  s.EI_Nm2 = 120.8e3;
  s.mass_kg_per_m = 165.0;
  s.weight_N_per_m = (165.0 - 1000.0 * M_PI / 4.0 * 0.396 * 0.396) * 9.807;
  s.hydro_diameter_m = 0.396;
  s.drag_normal = 1.2;
  s.element_length_m = 5.0;
  FeLineModel m;
  m.sections = {s};
  FeEnvironment env;
  env.water_density_kg_per_m3 = 1000.0;
  env.current = {{-150.0, {0.0, 2.0, 0.0}}, {0.0, {0.0, 2.0, 0.0}}};  // 2 m/s across the riser's plane
  const auto r = solve_fe_line_statics(m, env, FeLineEnds{{0, 0, -100}, {100, 0, -50}});
  double t_max = 0.0, f_max = 0.0, y_max = 0.0;
  for (double t : r.node_tension_N) t_max = std::max(t_max, std::abs(t));
  for (std::size_t i = 1; i + 1 < r.node_position_m.size(); ++i) {
    f_max = std::max(f_max, r.node_force_residual_N[i].norm());
    y_max = std::max(y_max, r.node_position_m[i].y());
  }
  EXPECT_LT(f_max / t_max, kEquilibrium);
  EXPECT_GT(y_max, 20.0);  // swung well out of its plane, m
  EXPECT_GT(r.end_A_force_N.y(), 0.0);
  EXPECT_GT(r.end_B_force_N.y(), 0.0);
}

// A steel catenary riser in 1800 m under a current at 45° to its plane
// (tests/bench BM_SteelCatenaryRiserCurrentCold).
struct CatenaryRiserCase {
  FeLineModel model;
  FeLineEnds ends;
};
CatenaryRiserCase steel_catenary_riser() {
  constexpr double od = 0.2731, wt = 0.0254, E = 207e9, g = 9.80665;
  const double id = od - 2.0 * wt;
  const double a_steel = M_PI / 4.0 * (od * od - id * id);
  FeLineSection s;
  s.weight_N_per_m = (7850.0 * a_steel + 800.0 * M_PI / 4.0 * id * id - 1025.0 * M_PI / 4.0 * od * od) * g;
  s.EA_N = E * a_steel;
  s.EI_Nm2 = E * M_PI / 64.0 * (std::pow(od, 4) - std::pow(id, 4));
  s.hydro_diameter_m = od;
  s.drag_normal = 1.0;
  s.element_length_m = 20.0;
  const double phi = 78.0 * M_PI / 180.0, a = 1780.0 / (1.0 / std::cos(phi) - 1.0);
  s.length_m = 500.0 + a * std::tan(phi);
  const double span_m = 500.0 + a * std::asinh(std::tan(phi));
  FeLineModel m;
  m.sections = {s};
  m.refinement = FeRefinementZone{400.0, 200.0, 2.0};
  return {m, FeLineEnds{{-span_m, 0.0, -1800.0}, {0.0, 0.0, -20.0}}};
}
FeEnvironment riser_environment(double surface_speed_m_per_s) {
  FeEnvironment env;
  env.seabed_z_m = -1800.0;
  env.seabed_stiffness_N_per_m2 = 1e7;
  const Eigen::Vector3d direction(std::cos(M_PI / 4), std::sin(M_PI / 4), 0.0);
  for (int i = 0; i <= 18; ++i) {
    const double z = -1800.0 + 100.0 * i;
    env.current.push_back({z, surface_speed_m_per_s * std::pow((z + 1800.0) / 1800.0, 1.0 / 7.0) * direction});
  }
  return env;
}

// A cold solve under current starts from the catenary swung rigidly into the
// current (fe_line_newton.cpp). The riser above under 1.5 m/s: before the
// swing, 283 Newton iterations through 14 current-continuation stages. It
// must land on the equilibrium reached the slow way: warm starts along a
// ramp of the drag (current speed²) in twentieths.
TEST(FeStatics, ColdSolveUnderCurrentSwingsIntoIt) {
  constexpr int kMaxColdIterations = 60;  // measured 40: 12 direct, 4 seabed stages, touchdown moves
  constexpr int kRampSteps = 20;
  const auto [m, ends] = steel_catenary_riser();
  const auto environment = riser_environment;
  const auto cold = solve_fe_line_statics(m, environment(1.5), ends);
  EXPECT_LE(cold.iterations, kMaxColdIterations);
  FeStaticsResult ramped = solve_fe_line_statics(m, environment(0.0), ends);
  for (int k = 1; k <= kRampSteps; ++k) {
    FeStaticsOptions o;
    warm_start_from(o, ramped);
    ramped = solve_fe_line_statics(m, environment(1.5 * std::sqrt(double(k) / kRampSteps)), ends, o);
  }
  // Each state balances every free node to its residual_N; by the global
  // balance their end reactions can differ by at most the sum over the nodes
  // (on the laid part the round-off floor, ≈ 1e-3 N a node, sets it: the
  // anchor reaction agrees to 2e-7 relative, the hang-off one to 1e-10).
  const double balance_N = static_cast<double>(cold.node_position_m.size()) * (cold.residual_N + ramped.residual_N);
  EXPECT_LT((cold.end_B_force_N - ramped.end_B_force_N).norm(), balance_N);
  EXPECT_LT((cold.end_A_force_N - ramped.end_A_force_N).norm(), balance_N);
  EXPECT_GT(cold.node_position_m[cold.node_position_m.size() / 2].y(),
            10.0);  // swung downstream, m
}

// A static case keeps its risers' FE node profiles (positions and arc
// lengths); the enhanced S-C's line reduction solves the same riser at the
// same ends again, from that profile (initial_shape_is_equilibrium): Newton
// from there, without the cold start's swing and seabed continuation, lands
// on the same equilibrium.
TEST(FeStatics, AStoredEquilibriumProfileIsNewtonsStart) {
  constexpr int kMaxIterations = 5;  // measured 3; the cold solve takes 40
  const auto [m, ends] = steel_catenary_riser();
  const FeEnvironment env = riser_environment(1.5);
  const auto cold = solve_fe_line_statics(m, env, ends);
  FeStaticsOptions o;
  o.initial_shape = [&cold](double s_m) {
    const auto& s = cold.node_arc_length_m;
    const auto it = std::upper_bound(s.begin(), s.end(), s_m);
    if (it == s.begin()) return cold.node_position_m.front();
    if (it == s.end()) return cold.node_position_m.back();
    const auto i = static_cast<std::size_t>(it - s.begin());
    const double t = (s_m - s[i - 1]) / (s[i] - s[i - 1]);
    return Eigen::Vector3d(cold.node_position_m[i - 1] + t * (cold.node_position_m[i] - cold.node_position_m[i - 1]));
  };
  o.initial_shape_is_equilibrium = true;
  o.warm_start_node_arc_length_m = cold.node_arc_length_m;
  const auto again = solve_fe_line_statics(m, env, ends, o);
  EXPECT_LE(again.iterations, kMaxIterations);
  const double balance_N = static_cast<double>(cold.node_position_m.size()) * (cold.residual_N + again.residual_N);
  EXPECT_LT((again.end_B_force_N - cold.end_B_force_N).norm(), balance_N);
  EXPECT_LT((again.end_A_force_N - cold.end_A_force_N).norm(), balance_N);
  ASSERT_EQ(again.node_arc_length_m.size(), cold.node_arc_length_m.size());
  for (std::size_t i = 0; i < cold.node_position_m.size(); ++i)
    EXPECT_LT((again.node_position_m[i] - cold.node_position_m[i]).norm(), 1e-6) << "node " << i;  // m
}

// Lazy-wave riser: riser – 400 m buoyancy section (net uplift) – riser. The
// buoyancy section arches up (hog bend) above the sag bend that follows it
// towards the vessel; the joints are
// bending joints (one shared slope).
TEST(FeStatics, LazyWaveRiserFormsItsHogBend) {
  constexpr double od = 0.2731, E = 207e9, id = od - 2 * 0.0254, g = 9.80665;
  const double a_steel = M_PI / 4.0 * (od * od - id * id);
  const double w = (7850.0 * a_steel + 800.0 * M_PI / 4.0 * id * id - 1025.0 * M_PI / 4.0 * od * od) * g;
  const double EI = E * M_PI / 64.0 * (std::pow(od, 4) - std::pow(id, 4));
  auto section = [&](double length_m, double weight_N_per_m, double d_m, double h_m) {
    FeLineSection s;
    s.length_m = length_m;
    s.EA_N = E * a_steel;
    s.EI_Nm2 = EI;
    s.mass_kg_per_m = 200.0;
    s.weight_N_per_m = weight_N_per_m;
    s.hydro_diameter_m = d_m;
    s.drag_normal = 1.0;
    s.element_length_m = h_m;
    return s;
  };
  FeLineModel m;
  m.sections = {section(1500.0, w, od, 20.0), section(400.0, -1500.0, 0.8, 10.0), section(1400.0, w, od, 20.0)};
  FeEnvironment env;
  env.seabed_z_m = -1800.0;
  env.seabed_stiffness_N_per_m2 = 1e7;
  const auto r = solve_fe_line_statics(m, env, FeLineEnds{{-1900, 0, -1800}, {0, 0, -20}});
  // Highest point of the buoyancy section and lowest point of the riser
  // section above it (the sag bend) — the hump stands above the sag.
  double z_hog = -INFINITY, z_sag = INFINITY;
  for (std::size_t i = 0; i < r.node_position_m.size(); ++i) {
    const double s = r.node_arc_length_m[i];
    if (s > 1500.0 && s < 1900.0) z_hog = std::max(z_hog, r.node_position_m[i].z());
    if (s > 1900.0 && s < 2300.0) z_sag = std::min(z_sag, r.node_position_m[i].z());
  }
  EXPECT_GT(z_hog, z_sag + 10.0);
  ASSERT_TRUE(r.touchdown.has_value());
  EXPECT_LT(r.touchdown->arc_length_m, 1500.0);
  for (double t : r.node_tension_N) EXPECT_TRUE(std::isfinite(t));
}

}  // namespace
}  // namespace spiral::engine
