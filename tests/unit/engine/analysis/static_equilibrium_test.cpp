// Coupled static equilibrium of the OC4 hull and mooring: balance at the
// solution, linear response to small loads, damaged-line behaviour.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "engine/analysis/static_equilibrium.hpp"
#include "engine/common/table_range_error.hpp"
#include "support/oc4_mooring.hpp"

namespace spiral::engine {
namespace {

// Newton converges to the default relative tolerance 1e-9 of the force scale.
constexpr double kBalance = 1e-8;

TEST(StaticEquilibrium, StillWaterBalancesAndStaysCentred) {
  const auto lines = test::oc4_static_lines();
  const auto result = solve_static_equilibrium(test::oc4_hull_statics(), lines, nullptr);
  EXPECT_LT(result.residual.head<3>().norm(), kBalance * result.force_reference_N);
  EXPECT_NEAR(result.offset(0), 0.0, 1e-6);
  EXPECT_NEAR(result.offset(1), 0.0, 1e-6);
  // Buoyancy excess 1.8615e6 N against 1.895e6 N of mooring load: the hull
  // sinks by (1.895e6 − 1.8615e6) / (C33 + K33) ≈ 9 mm.
  EXPECT_LT(result.offset(2), 0.0);
  EXPECT_GT(result.offset(2), -0.02);
}

TEST(StaticEquilibrium, SmallLoadGivesTheOffsetTheStiffnessPredicts) {
  const auto lines = test::oc4_static_lines();
  const auto hull = test::oc4_hull_statics();
  const auto base = solve_static_equilibrium(hull, lines, nullptr);
  const Matrix6d k_total = hull.hydrostatic_stiffness + base.lines.stiffness;
  Vector6d load = Vector6d::Zero();
  load(0) = 2.0e4;  // N: 0.3 m of surge, well inside the linear range
  const auto loaded = solve_static_equilibrium(hull, lines, [&](const Vector6d&) { return load; });
  const Vector6d predicted = k_total.fullPivLu().solve(load);
  const Vector6d actual = loaded.offset - base.offset;
  // Second-order terms over 0.3 m of a stiffness that changes ~1 % per 7 m.
  EXPECT_NEAR(actual(0), predicted(0), 0.01 * predicted(0));
  EXPECT_NEAR(actual(4), predicted(4), 0.02 * std::abs(predicted(4)) + 1e-7);
}

TEST(StaticEquilibrium, OffsetGrowsWithLoad) {
  const auto lines = test::oc4_static_lines();
  const auto hull = test::oc4_hull_statics();
  double previous = 0.0;
  for (double force : {2e5, 5e5, 1e6}) {
    Vector6d load = Vector6d::Zero();
    load(1) = force;
    const auto r = solve_static_equilibrium(hull, lines, [&](const Vector6d&) { return load; });
    EXPECT_GT(r.offset(1), previous);
    EXPECT_LT(r.residual.head<3>().norm(), kBalance * r.force_reference_N);
    previous = r.offset(1);
  }
}

/// Six OC4 lines in three clusters of two (cluster centres 60°, 180°, 300°, ±5°).
std::vector<std::unique_ptr<StaticLine>> clustered_lines(int skipped = -1) {
  const auto base = test::oc4_lines().front();
  std::vector<std::unique_ptr<StaticLine>> lines;
  int index = 0;
  for (double centre : {60.0, 180.0, 300.0}) {
    for (double delta : {-5.0, 5.0}) {
      const double a = (centre + delta) * std::numbers::pi / 180.0;
      const Eigen::Vector3d anchor(837.6 * std::cos(a), 837.6 * std::sin(a), -200.0);
      const Eigen::Vector3d fairlead(40.868 * std::cos(a), 40.868 * std::sin(a), -14.0);
      if (index++ == skipped) continue;
      lines.push_back(
          std::make_unique<CatenaryStaticLine>(fmt::format("L{}", index), anchor, fairlead, 0.0, base.line));
    }
  }
  return lines;
}

TEST(StaticEquilibrium, DamagedLineMovesTheHullAwayAndLoadsTheNeighbour) {
  // A steady load towards −x is held by the windward clusters at 60° and 300°.
  // Removing the line at 55° lets the hull drift further from its anchor and
  // throws its load onto its cluster neighbour at 65°.
  auto hull = test::oc4_hull_statics();
  hull.rest_force(2) *= 2.0;  // six lines hang twice the OC4 mooring load
  Vector6d load = Vector6d::Zero();
  load(0) = -4.0e5;
  const auto with_load = [&](const Vector6d&) { return load; };
  const auto intact_lines = clustered_lines();
  const auto intact = solve_static_equilibrium(hull, intact_lines, with_load);
  const auto damaged_lines = clustered_lines(0);
  const auto damaged = solve_static_equilibrium(hull, damaged_lines, with_load);

  const double a = 55.0 * std::numbers::pi / 180.0;
  const Eigen::Vector2d away_from_anchor(-std::cos(a), -std::sin(a));
  EXPECT_GT(damaged.offset.head<2>().dot(away_from_anchor), intact.offset.head<2>().dot(away_from_anchor) + 0.5);
  const double neighbour_intact = intact.lines.lines[1].end.top_tension_N;
  const double neighbour_damaged = damaged.lines.lines[0].end.top_tension_N;
  EXPECT_GT(neighbour_damaged, 1.1 * neighbour_intact);
  EXPECT_LT(damaged.residual.head<3>().norm(), kBalance * damaged.force_reference_N);
}

// A mean environmental load that turns with the hull (wind, current and drift
// coefficients are tables in the relative heading): its stiffness belongs in
// the Newton tangent, or the yaw converges only linearly, at the ratio of the
// load's yaw stiffness to the mooring's. Here a weathervaning moment
// M_z = M0 sin 2(β − ψ) with 2 M0 of the order of the 6 lines' yaw stiffness.
TEST(StaticEquilibrium, LoadThatTurnsWithTheHullConvergesQuadratically) {
  auto hull = test::oc4_hull_statics();
  hull.rest_force(2) *= 2.0;  // six lines hang twice the OC4 mooring load
  const auto lines = clustered_lines();
  const double beta = 30.0 * std::numbers::pi / 180.0;
  const double yaw_stiffness_Nm_per_rad = solve_static_equilibrium(hull, lines, nullptr).lines.stiffness(5, 5);
  const double m0_Nm = 0.4 * yaw_stiffness_Nm_per_rad;
  const ExternalLoad weathervaning = [&](const Vector6d& offset) {
    Vector6d load = Vector6d::Zero();
    load(0) = -2.0e5;
    load(5) = m0_Nm * std::sin(2.0 * (beta - offset(5)));
    return load;
  };
  // The central differences against the analytic dM_z/dψ = −2 M0 cos 2(β − ψ):
  // truncation (1e-4 rad)² / 6 × 4 relative.
  Vector6d at = Vector6d::Zero();
  at(5) = 0.1;
  EXPECT_NEAR(external_load_stiffness(weathervaning, at)(5, 5), 2.0 * m0_Nm * std::cos(2.0 * (beta - 0.1)),
              1e-7 * m0_Nm);
  const auto result = solve_static_equilibrium(hull, lines, weathervaning);
  EXPECT_LT(result.residual.norm(), kBalance * result.force_reference_N * 40.868);
  EXPECT_GT(result.offset(5), 0.15);  // turned 12.5° towards β
  // From 1 m and 1° off the solution (inside the step caps), Newton's
  // quadratic rate: 3 iterations measured (8 while the tangent left out the
  // Euler-angle map T of the turned hull, a roll/pitch ratio of 0.2 per
  // iteration). A tangent without the load's stiffness would contract the
  // yaw error by 1 − (K + K_env)/K ≈ −0.66 per iteration: 40 iterations.
  Vector6d start = result.offset;
  start(0) += 1.0;
  start(5) += std::numbers::pi / 180.0;
  const auto again = solve_static_equilibrium(hull, lines, weathervaning, start);
  EXPECT_LE(again.iterations, 4);
  EXPECT_NEAR(again.offset(5), result.offset(5), 1e-8);
}

/// A line that counts the solves asked for its stiffness (an FE line's
/// Jacobian factorisation each) and forwards everything to `inner`.
class StiffnessCountingLine final : public StaticLine {
 public:
  StiffnessCountingLine(std::unique_ptr<StaticLine> inner, int& stiffness_solves)
      : inner_(std::move(inner)), stiffness_solves_(stiffness_solves) {}
  const std::string& name() const override { return inner_->name(); }
  const Eigen::Vector3d& attachment_b() const override { return inner_->attachment_b(); }
  LineEndResponse solve(const Eigen::Vector3d& attachment_g) override {
    ++stiffness_solves_;
    return inner_->solve(attachment_g);
  }
  Eigen::Vector3d solve_force(const Eigen::Vector3d& attachment_g) override {
    return inner_->solve_force(attachment_g);
  }
  LineState state(const Eigen::Vector3d& attachment_g, int points_per_segment) override {
    return inner_->state(attachment_g, points_per_segment);
  }
  void reset() override { inner_->reset(); }

 private:
  std::unique_ptr<StaticLine> inner_;
  int& stiffness_solves_;
};

// EquilibriumOptions::stiffness_reuse_distance_m: started 5 cm and 0.01°
// from its solution under a load that turns with the hull, the solve keeps
// the lines' stiffness of its first Newton pose for the closing steps (the
// catenaries' stiffness changes by ~1 % over metres: each step contracts the
// residual by about 1e-3, so it converges in about as many iterations). It
// reaches the same equilibrium to the tolerance, and its stiffness at the
// solution is the exact one there.
TEST(StaticEquilibrium, NearbyLineStiffnessServesTheClosingNewtonSteps) {
  auto hull = test::oc4_hull_statics();
  hull.rest_force(2) *= 2.0;  // six lines hang twice the OC4 mooring load
  const ExternalLoad load = [](const Vector6d& offset) {
    Vector6d f = Vector6d::Zero();
    f(0) = -3.0e5;
    f(1) = 1.0e5;
    f(5) = 2.0e6 * std::sin(0.5 - offset(5));
    return f;
  };
  const auto reference_lines = clustered_lines();
  const EquilibriumResult reference = solve_static_equilibrium(hull, reference_lines, load);
  Vector6d start = reference.offset;
  start(0) += 0.04;
  start(1) -= 0.03;
  start(5) += 1e-4;

  const auto counted = [&](int& stiffness_solves) {
    std::vector<std::unique_ptr<StaticLine>> lines;
    for (auto& line : clustered_lines())
      lines.push_back(std::make_unique<StiffnessCountingLine>(std::move(line), stiffness_solves));
    return lines;
  };
  int exact_solves = 0, reused_solves = 0;
  const auto exact_lines = counted(exact_solves);
  const auto reused_lines = counted(reused_solves);
  const EquilibriumResult exact = solve_static_equilibrium(hull, exact_lines, load, start);
  const EquilibriumResult reused =
      solve_static_equilibrium(hull, reused_lines, load, start, {.stiffness_reuse_distance_m = 0.1});
  ASSERT_GE(exact.iterations, 2);
  // Six lines: a stiffness at every Newton pose and at the solution, against
  // one at the first pose and one at the solution.
  EXPECT_EQ(exact_solves, 6 * (exact.iterations + 1));
  EXPECT_EQ(reused_solves, 6 * 2);
  EXPECT_LE(reused.iterations, exact.iterations + 1);
  EXPECT_LT(reused.residual.head<3>().norm(), kBalance * reused.force_reference_N);
  // The offsets agree to the tolerance's force over the stiffness (≈ 1e-9 ×
  // 4e6 N over 1e5 N/m).
  EXPECT_LT((reused.offset - reference.offset).head<3>().norm(), 1e-6);
  EXPECT_NEAR(reused.offset(5), reference.offset(5), 1e-8);
  const LineArrayResponse at_solution = evaluate_line_array(reused_lines, reused.pose);
  EXPECT_TRUE(reused.lines.stiffness.isApprox(at_solution.stiffness, 1e-12));
}

// A coefficient table ends at some relative heading: at a hull yaw just
// inside its edge the tangent's central difference would step off it; the
// one-sided difference on the inside stands in (first order: h/2 of the
// second derivative).
TEST(StaticEquilibrium, LoadStiffnessAtTheEdgeOfItsTableIsOneSided) {
  constexpr double kEdge_rad = 0.2, kM0_Nm = 1e7;
  const ExternalLoad table = [&](const Vector6d& offset) {
    if (offset(5) > kEdge_rad) throw TableRangeError("relative heading outside the table");
    Vector6d load = Vector6d::Zero();
    load(5) = kM0_Nm * std::sin(2.0 * offset(5));
    return load;
  };
  Vector6d at = Vector6d::Zero();
  at(5) = kEdge_rad - 5e-5;  // the +1e-4 rad step leaves the table
  const double analytic = -2.0 * kM0_Nm * std::cos(2.0 * at(5));
  const double second = 4.0 * kM0_Nm * std::sin(2.0 * at(5));  // |d²M/dψ²|
  EXPECT_NEAR(external_load_stiffness(table, at)(5, 5), analytic, 0.5e-4 * second + 1e-9 * kM0_Nm);
  EXPECT_THROW(table(at + Vector6d::Unit(5) * 1e-4), TableRangeError);
  at(5) = 0.1;  // inside: central
  EXPECT_NEAR(external_load_stiffness(table, at)(5, 5), -2.0 * kM0_Nm * std::cos(0.2), 1e-7 * kM0_Nm);
}

TEST(StaticEquilibrium, NoYawStiffnessIsReported) {
  std::vector<std::unique_ptr<StaticLine>> none;
  auto hull = test::oc4_hull_statics();
  hull.hydrostatic_stiffness(0, 0) = hull.hydrostatic_stiffness(1, 1) = 1e5;
  hull.rest_force(2) = 0.0;
  Vector6d load = Vector6d::Zero();
  load(0) = 1e4;
  try {
    solve_static_equilibrium(hull, none, [&](const Vector6d&) { return load; });
    FAIL();
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("no stiffness"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spiral::engine
