// Validation of solve_catenary against closed-form elastic catenaries written
// out here independently of the solver: Irvine, "Cable Structures" (1981),
// eqs. 1.43-1.44 (suspended), and Jonkman, NREL/TP-500-41958 (2007), eqs. B-3,
// B-4 (seabed, no friction) and B-7 (seabed with friction, both sub-cases).
// The spans are computed from chosen fairlead forces (H, V); the solver must
// recover those forces from the spans.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/lines/catenary.hpp"
#include "engine/lines/catenary_spans.hpp"
#include "support/expect_near.hpp"

namespace spiral::engine {
namespace {

// H, V recovered from spans closed to 1e-9 m on ~1 km spans: the closure error
// maps to < 1e-10 of the forces through the line's compliance, so 1e-8 has margin.
constexpr double kRecoverRelTol = 1e-8;
// EA = 1e15 N against the inextensible formulas: the neglected stretch H L/EA is
// ~3e-7 m on ~1 km, a ~1e-9 relative change of the forces.
constexpr double kInextensibleRelTol = 1e-7;
// Equilibrium residuals are sums of a few forces of the size of the tension:
// round-off only.
constexpr double kEquilibriumRelTol = 1e-9;
// Splitting a homogeneous segment changes only round-off in the sums.
constexpr double kSplitRelTol = 1e-9;
// Central differences with a 1e-3 m step: truncation (step/curvature length)^2
// ~1e-10 and round-off (closure 1e-11 m / step) ~1e-8 of the stiffness.
constexpr double kStiffnessFdRelTol = 1e-6;
constexpr double kStiffnessFdStep_m = 1e-3;
// Slope of the profile from central differences of nearby points (step 0.05 m
// on segments of hundreds of m): truncation ~(0.05/100)^2.
constexpr double kProfileSlopeRelTol = 1e-5;

struct Spans {
  double XF_m;
  double ZF_m;
};

// Irvine (1981) eqs. 1.43-1.44, one segment, fully suspended, end A below.
Spans suspended_spans(double H, double V_F, double w, double EA, double L) {
  const double V_A = V_F - w * L;
  const double XF = H / w * (std::asinh(V_F / H) - std::asinh(V_A / H)) + H * L / EA;
  const double ZF = H / w * (std::sqrt(1.0 + std::pow(V_F / H, 2)) - std::sqrt(1.0 + std::pow(V_A / H, 2))) +
                    (V_F * L - 0.5 * w * L * L) / EA;
  return {XF, ZF};
}

// Jonkman (2007) eqs. B-3/B-4 (CB = 0) and B-7 (CB > 0): one segment, anchor on seabed.
Spans seabed_spans(double H, double V_F, double w, double EA, double L, double CB) {
  const double LB = L - V_F / w;
  double XF = LB + H / w * std::asinh(V_F / H) + H * L / EA;
  if (CB > 0.0) {
    const double d = LB - H / (CB * w);
    XF += CB * w / (2.0 * EA) * (-LB * LB + d * std::max(d, 0.0));
  }
  const double ZF = H / w * (std::sqrt(1.0 + std::pow(V_F / H, 2)) - 1.0) + V_F * V_F / (2.0 * EA * w);
  return {XF, ZF};
}

CatenaryLine single(double L, double w, double EA, double mu = 0.0) {
  CatenaryLine line;
  line.segments = {{L, w, EA}};
  line.seabed_friction = mu;
  return line;
}

// A chain of ~1 km in 300 m of water: H = 3e5 N, V_F = 5e5 N, w = 1000 N/m.
constexpr double kL = 900.0, kW = 1000.0, kEA = 5e8, kH = 3e5, kV = 5e5;

TEST(CatenaryAnalytic, FullySuspendedRecoversForces) {
  const double V = 1.2e6;  // > w L: no sag below the anchor's level; anchor above seabed
  const Spans s = suspended_spans(kH, V, kW, kEA, kL);
  const CatenarySolution sol = solve_catenary(single(kL, kW, kEA), {s.XF_m, s.ZF_m, 50.0});
  EXPECT_EQ(sol.regime, CatenaryRegime::suspended);
  EXPECT_REL_NEAR(sol.fairlead_horizontal_N, kH, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, V, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.anchor_vertical_N, V - kW * kL, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.anchor_horizontal_N, kH, kRecoverRelTol);
}

TEST(CatenaryAnalytic, SuspendedWithLowPointBelowAnchor) {
  const double V = 3e5;  // V_A < 0: the line sags below the (raised) anchor
  const Spans s = suspended_spans(kH, V, kW, kEA, kL);
  const CatenarySolution sol = solve_catenary(single(kL, kW, kEA), {s.XF_m, s.ZF_m, 100.0});
  EXPECT_REL_NEAR(sol.fairlead_horizontal_N, kH, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, V, kRecoverRelTol);
  EXPECT_LT(sol.anchor_vertical_N, 0.0);
}

TEST(CatenaryAnalytic, SeabedWithoutFriction) {
  const Spans s = seabed_spans(kH, kV, kW, kEA, kL, 0.0);
  const CatenarySolution sol = solve_catenary(single(kL, kW, kEA), {s.XF_m, s.ZF_m, 0.0});
  EXPECT_EQ(sol.regime, CatenaryRegime::touchdown);
  EXPECT_REL_NEAR(sol.fairlead_horizontal_N, kH, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, kV, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.laid_length_m, kL - kV / kW, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.anchor_horizontal_N, kH, kRecoverRelTol);  // no friction: H_A = H
  EXPECT_EQ(sol.anchor_vertical_N, 0.0);
}

TEST(CatenaryAnalytic, SeabedWithFrictionAnchorTensionPositive) {
  const double CB = 0.5;  // CB w L_B = 2e5 N < H: tension reaches the anchor
  const Spans s = seabed_spans(kH, kV, kW, kEA, kL, CB);
  const CatenarySolution sol = solve_catenary(single(kL, kW, kEA, CB), {s.XF_m, s.ZF_m, 0.0});
  EXPECT_REL_NEAR(sol.fairlead_horizontal_N, kH, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, kV, kRecoverRelTol);
  const double LB = kL - kV / kW;
  EXPECT_REL_NEAR(sol.anchor_horizontal_N, kH - CB * kW * LB, kRecoverRelTol);
}

TEST(CatenaryAnalytic, SeabedWithFrictionTensionVanishesBeforeAnchor) {
  const double CB = 1.0;  // CB w L_B = 4e5 N > H: zero tension over the last part
  const Spans s = seabed_spans(kH, kV, kW, kEA, kL, CB);
  const CatenarySolution sol = solve_catenary(single(kL, kW, kEA, CB), {s.XF_m, s.ZF_m, 0.0});
  EXPECT_REL_NEAR(sol.fairlead_horizontal_N, kH, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, kV, kRecoverRelTol);
  EXPECT_EQ(sol.anchor_horizontal_N, 0.0);
  EXPECT_EQ(sol.anchor_tension_N, 0.0);
}

TEST(CatenaryAnalytic, InextensibleLimit) {
  // Inextensible catenary (Irvine eqs. 1.43-1.44 without the 1/EA terms).
  const double V = 5e5, LB = kL - V / kW;
  const double XF = LB + kH / kW * std::asinh(V / kH);
  const double ZF = kH / kW * (std::sqrt(1.0 + std::pow(V / kH, 2)) - 1.0);
  const CatenarySolution sol = solve_catenary(single(kL, kW, 1e15), {XF, ZF, 0.0});
  EXPECT_REL_NEAR(sol.fairlead_horizontal_N, kH, kInextensibleRelTol);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, V, kInextensibleRelTol);
}

// A three-segment chain-wire-chain line with a clump, touching down in the
// bottom chain, no friction.
CatenaryLine three_segment_line(double mu) {
  CatenaryLine line;
  line.segments = {{400.0, 1200.0, 8e8}, {600.0, 300.0, 3e8}, {150.0, 1200.0, 8e8}};
  line.joint_load_N = {2e4, 0.0};
  line.seabed_friction = mu;
  return line;
}

TEST(CatenaryAnalytic, HorizontalForceConstantAndSlopeMatchesForcesWithoutFriction) {
  CatenaryOptions options;
  options.profile_points_per_segment = 4000;
  const CatenaryLine line = three_segment_line(0.0);
  const CatenarySolution sol = solve_catenary(line, {1000.0, 300.0, 0.0}, options);
  ASSERT_EQ(sol.regime, CatenaryRegime::touchdown);
  const double H = sol.fairlead_horizontal_N;
  EXPECT_REL_NEAR(sol.anchor_horizontal_N, H, kEquilibriumRelTol);
  const auto& p = sol.profile;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    // Effective tension in the line's direction: T_x = H everywhere (no friction),
    // including the laid part.
    EXPECT_REL_NEAR(p[i].horizontal_N, H, kEquilibriumRelTol);
    // Geometry against forces: slope dz/dx of the profile = V/H (suspended part).
    if (p[i - 1].on_seabed || p[i].on_seabed || p[i + 1].on_seabed) continue;
    if (p[i - 1].segment != p[i + 1].segment) continue;
    if (p[i - 1].arc_length_m == p[i].arc_length_m || p[i].arc_length_m == p[i + 1].arc_length_m) continue;
    const double slope = (p[i + 1].z_m - p[i - 1].z_m) / (p[i + 1].x_m - p[i - 1].x_m);
    EXPECT_REL_NEAR_SCALE(slope, p[i].vertical_N / H, kProfileSlopeRelTol,
                          std::max(1.0, std::abs(p[i].vertical_N / H)));
  }
  // The profile ends at the fairlead.
  EXPECT_REL_NEAR_SCALE(p.back().x_m, 1000.0, kRecoverRelTol, 1000.0);
  EXPECT_REL_NEAR_SCALE(p.back().z_m, 300.0, kRecoverRelTol, 1000.0);
}

TEST(CatenaryAnalytic, ForceBalanceOfEachSegment) {
  for (double mu : {0.0, 0.3, 2.0}) {
    CatenaryOptions options;
    options.profile_points_per_segment = 10;
    const CatenaryLine line = three_segment_line(mu);
    const CatenarySolution sol = solve_catenary(line, {1000.0, 300.0, 0.0}, options);
    const double T = sol.fairlead_tension_N;
    // First and last profile point of each segment.
    for (int s = 0; s < 3; ++s) {
      const CatenaryProfilePoint* bottom = nullptr;
      const CatenaryProfilePoint* top = nullptr;
      double laid_m = 0.0;
      for (const auto& q : sol.profile) {
        if (q.segment != s) continue;
        if (!bottom) bottom = &q;
        top = &q;
        if (q.on_seabed) laid_m = q.arc_length_m - bottom->arc_length_m;
      }
      ASSERT_TRUE(bottom && top);
      const auto& seg = line.segments[s];
      const double suspended_m = seg.length_m - laid_m;
      // Vertical: the seabed carries the laid weight; the rest is V_top - V_bottom.
      EXPECT_REL_NEAR_SCALE(top->vertical_N - bottom->vertical_N, seg.weight_N_per_m * suspended_m, kEquilibriumRelTol,
                            T)
          << "mu " << mu << " segment " << s;
      // Horizontal: friction mu w on the laid part where tension remains, else none.
      if (bottom->horizontal_N > 0.0) {
        EXPECT_REL_NEAR_SCALE(top->horizontal_N - bottom->horizontal_N, mu * seg.weight_N_per_m * laid_m,
                              kEquilibriumRelTol, T)
            << "mu " << mu << " segment " << s;
      }
    }
    // Whole line: fairlead vertical force carries the suspended weight.
    double suspended_weight_N = 0.0, remaining_laid = sol.laid_length_m;
    for (std::size_t s = 0; s < 3; ++s) {
      const auto& seg = line.segments[s];
      const double laid = std::min(remaining_laid, seg.length_m);
      remaining_laid -= laid;
      suspended_weight_N += seg.weight_N_per_m * (seg.length_m - laid);
      if (s < 2 && remaining_laid <= 0.0) suspended_weight_N += line.joint_load_N[s];
    }
    EXPECT_REL_NEAR_SCALE(sol.fairlead_vertical_N - sol.anchor_vertical_N, suspended_weight_N, kEquilibriumRelTol, T);
  }
}

TEST(CatenaryAnalytic, SplitSegmentsEqualSingleSegment) {
  for (double mu : {0.0, 0.5}) {
    for (double anchor_height : {0.0, 30.0}) {
      const CatenaryGeometry g{800.0, 250.0, anchor_height};
      const CatenarySolution one = solve_catenary(single(kL, kW, kEA, mu), g);
      CatenaryLine split;
      split.segments = {{200.0, kW, kEA}, {450.0, kW, kEA}, {250.0, kW, kEA}};
      split.seabed_friction = mu;
      const CatenarySolution three = solve_catenary(split, g);
      EXPECT_REL_NEAR(three.fairlead_horizontal_N, one.fairlead_horizontal_N, kSplitRelTol);
      EXPECT_REL_NEAR(three.fairlead_vertical_N, one.fairlead_vertical_N, kSplitRelTol);
      EXPECT_REL_NEAR_SCALE(three.anchor_horizontal_N, one.anchor_horizontal_N, kSplitRelTol, one.fairlead_tension_N);
      EXPECT_REL_NEAR_SCALE(three.laid_length_m, one.laid_length_m, kSplitRelTol, kL);
      EXPECT_EIGEN_REL_NEAR(three.tangent_stiffness, one.tangent_stiffness, kSplitRelTol);
    }
  }
}

struct StiffnessCase {
  const char* name;
  CatenaryLine line;
  CatenaryGeometry geometry;
};

TEST(CatenaryAnalytic, TangentStiffnessEqualsCentralDifferences) {
  std::vector<StiffnessCase> cases = {
      {"suspended", single(kL, kW, kEA), {700.0, 300.0, 40.0}},
      {"touchdown, no friction", single(kL, kW, kEA), {780.0, 250.0, 0.0}},
      {"touchdown, friction, T_A > 0", single(kL, kW, kEA, 0.3), {780.0, 250.0, 0.0}},
      {"touchdown, friction, T_A = 0", single(kL, kW, kEA, 3.0), {780.0, 250.0, 0.0}},
      {"three segments + clump", three_segment_line(0.4), {1000.0, 300.0, 0.0}},
      {"taut", single(500.0, 50.0, 1e8), {400.0, 300.5, 0.0}},
  };
  for (const auto& c : cases) {
    const CatenarySolution base = solve_catenary(c.line, c.geometry);
    Eigen::Matrix2d fd;
    for (int j = 0; j < 2; ++j) {
      CatenaryGeometry plus = c.geometry, minus = c.geometry;
      (j == 0 ? plus.horizontal_span_m : plus.vertical_span_m) += kStiffnessFdStep_m;
      (j == 0 ? minus.horizontal_span_m : minus.vertical_span_m) -= kStiffnessFdStep_m;
      const CatenarySolution a = solve_catenary(c.line, plus);
      const CatenarySolution b = solve_catenary(c.line, minus);
      fd(0, j) = (a.fairlead_horizontal_N - b.fairlead_horizontal_N) / (2 * kStiffnessFdStep_m);
      fd(1, j) = (a.fairlead_vertical_N - b.fairlead_vertical_N) / (2 * kStiffnessFdStep_m);
    }
    EXPECT_EIGEN_REL_NEAR(base.tangent_stiffness, fd, kStiffnessFdRelTol) << c.name;
  }
}

// Chain on the seabed up to a clump that the seabed partly carries: the
// touchdown sits at the joint. Spans from the forward span evaluation at
// chosen forces (V_F between w2 L2 and w2 L2 + clump).
TEST(CatenaryAnalytic, TouchdownAtClumpJoint) {
  CatenaryLine line;
  line.segments = {{200.0, 1000.0, 8e8}, {600.0, 300.0, 3e8}};
  line.joint_load_N = {2e5};
  line.seabed_friction = 0.6;
  const double H = 5e4, V = 2.8e5;
  catenary_detail::LineView view{&line, true, 1000.0 * 200.0 + 300.0 * 600.0 + 2e5, 800.0};
  const auto e = catenary_detail::evaluate_spans(view, H, V);
  ASSERT_TRUE(e.touchdown_at_joint);
  const CatenaryGeometry g{e.x_m, e.z_m, 0.0};
  const CatenarySolution sol = solve_catenary(line, g);
  EXPECT_REL_NEAR(sol.fairlead_horizontal_N, H, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, V, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.laid_length_m, 200.0, kRecoverRelTol);
  // Friction: mu times the clump's resting part (W_total - V_F - laid chain), then mu w L.
  const double rest = 2e5 - (V - 300.0 * 600.0);
  EXPECT_REL_NEAR(sol.anchor_horizontal_N, std::max(H - 0.6 * rest - 0.6 * 1000.0 * 200.0, 0.0), kRecoverRelTol);
  // Tangent stiffness against central differences.
  Eigen::Matrix2d fd;
  for (int j = 0; j < 2; ++j) {
    CatenaryGeometry plus = g, minus = g;
    (j == 0 ? plus.horizontal_span_m : plus.vertical_span_m) += kStiffnessFdStep_m;
    (j == 0 ? minus.horizontal_span_m : minus.vertical_span_m) -= kStiffnessFdStep_m;
    const CatenarySolution a = solve_catenary(line, plus), b = solve_catenary(line, minus);
    fd(0, j) = (a.fairlead_horizontal_N - b.fairlead_horizontal_N) / (2 * kStiffnessFdStep_m);
    fd(1, j) = (a.fairlead_vertical_N - b.fairlead_vertical_N) / (2 * kStiffnessFdStep_m);
  }
  EXPECT_EIGEN_REL_NEAR(sol.tangent_stiffness, fd, kStiffnessFdRelTol);
}

TEST(CatenaryAnalytic, VerticalTautTendon) {
  // XF = 0: straight vertical line, ZF = L + (V_F + V_A) L/(2 EA), V_A = V_F - w L.
  const double L = 500.0, w = 400.0, EA = 2e9, ZF = 500.4;
  const double V_F = (ZF - L) * EA / L + 0.5 * w * L;
  const CatenarySolution sol = solve_catenary(single(L, w, EA), {0.0, ZF, 0.0});
  EXPECT_EQ(sol.fairlead_horizontal_N, 0.0);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, V_F, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.anchor_vertical_N, V_F - w * L, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.tangent_stiffness(1, 1), EA / L, kRecoverRelTol);
  // Pendulum stiffness dH/dXF = 1 / integral (1/T + 1/EA) ds, with integral ds/T = ln(V_F/V_A)/w.
  EXPECT_REL_NEAR(sol.tangent_stiffness(0, 0), 1.0 / (std::log(V_F / (V_F - w * L)) / w + L / EA), kRecoverRelTol);
}

TEST(CatenaryAnalytic, SlackVerticalHangingLine) {
  // Long chain, fairlead almost above the anchor: H = 0, a vertical hanging part
  // stretched to ZF, the rest on the seabed. Vertical: ZF = l + w l^2/(2 EA).
  const double ZF = 200.0;
  const CatenarySolution sol = solve_catenary(single(kL, kW, kEA, 0.5), {100.0, ZF, 0.0});
  ASSERT_EQ(sol.regime, CatenaryRegime::slack_vertical);
  const double l = (-1.0 + std::sqrt(1.0 + 2.0 * kW * ZF / kEA)) / (kW / kEA);
  EXPECT_EQ(sol.fairlead_horizontal_N, 0.0);
  EXPECT_REL_NEAR(sol.fairlead_vertical_N, kW * l, kRecoverRelTol);
  EXPECT_REL_NEAR(sol.laid_length_m, kL - l, kRecoverRelTol);
  EXPECT_EQ(sol.tangent_stiffness(0, 0), 0.0);
  EXPECT_EQ(sol.tangent_stiffness(0, 1), 0.0);
  EXPECT_EQ(sol.tangent_stiffness(1, 0), 0.0);
  EXPECT_REL_NEAR(sol.tangent_stiffness(1, 1), kW / (1.0 + kW * l / kEA), kRecoverRelTol);
}

TEST(CatenaryAnalytic, WarmStartTakesFewIterations) {
  constexpr int kMaxWarmIterations = 3;  // the brief's target for small geometry changes
  const CatenaryLine line = three_segment_line(0.5);
  const CatenarySolution cold = solve_catenary(line, {1000.0, 300.0, 0.0});
  const CatenarySolution warm = solve_catenary(line, {1000.1, 300.0, 0.0}, {},
                                               CatenaryGuess{cold.fairlead_horizontal_N, cold.fairlead_vertical_N});
  EXPECT_LE(warm.iterations, kMaxWarmIterations);
}

}  // namespace
}  // namespace spiral::engine
