// Unit test of the analytic ANCF element tangent: it must equal the
// forward-mode AD Jacobian of the same element forces (element_forces<Dual<12>>)
// for axial, bending, drag (depth-varying current) and seabed contact terms.
// The AD Jacobian differentiates drag_load itself, so it is an independent
// check of drag_load_and_tangent's hand-derived derivatives. And the
// residual kernel the statics assemble with (element_forces_side_by_side)
// must equal the reference element_forces<double> bit for bit.

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/lines/ancf_cable_element.hpp"

namespace spiral::engine::ancf {
namespace {

// Both are exact derivatives of one function evaluated in different orders:
// they agree to round-off, relative to the largest entry of the tangent.
constexpr double kRoundOffAgreement = 1e-11;

using D = Dual<12>;

struct Case {
  ElementProperties e;
  LoadContext ctx;
  std::array<double, 12> q;
};

// A curved, stretched SCR-like element crossing the seabed (contact), in a
// sheared current oblique to its plane.
Case make_case(double EI, bool drag_jacobian, const std::vector<CurrentProfilePoint>* current) {
  Case c;
  c.e.length_m = 2.0;
  c.e.EA_N = 6.2e9;
  c.e.EI_Nm2 = EI;
  c.e.weight_N_per_m = 1150.0;
  c.e.normal_drag_N_s2_per_m3 = 0.5 * 1025.0 * 1.0 * 0.2731;
  c.e.tangential_drag_N_s2_per_m3 = 0.5 * 1025.0 * 0.1 * M_PI * 0.2731;
  c.ctx.current = current;
  c.ctx.current_factor = 0.8;
  c.ctx.seabed_z_m = -1800.0;
  c.ctx.seabed_stiffness_N_per_m2 = 1e7;
  c.ctx.drag_jacobian = drag_jacobian;
  // r_a, r'_a, r_b, r'_b: the element dips 2 mm below the seabed at A.
  c.q = {-10.0, 0.3, -1800.002, 0.9995, 0.01, 0.035, -8.0, 0.32, -1799.93, 0.9980, 0.02, 0.072};
  return c;
}

void expect_tangent_matches_ad(const Case& c) {
  std::array<D, 12> qd, gd;
  for (int k = 0; k < 12; ++k) qd[static_cast<std::size_t>(k)] = D::seed(c.q[static_cast<std::size_t>(k)], k);
  element_forces<D>(c.e, c.ctx, qd.data(), gd.data());
  std::array<double, 12> g;
  ElementTangent K;
  element_forces_and_tangent(c.e, c.ctx, c.q.data(), g.data(), K);
  double k_max = 0.0, g_max = 0.0;
  for (std::size_t i = 0; i < 12; ++i) {
    g_max = std::max(g_max, std::abs(gd[i].v));
    for (std::size_t j = 0; j < 12; ++j) k_max = std::max(k_max, std::abs(gd[i].d[j]));
  }
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_NEAR(g[i], gd[i].v, kRoundOffAgreement * g_max) << "g_" << i;
    for (std::size_t j = 0; j < 12; ++j) {
      EXPECT_NEAR(K[12 * i + j], gd[i].d[j], kRoundOffAgreement * k_max) << "K_" << i << "," << j;
    }
  }
}

std::vector<CurrentProfilePoint> sheared_current() {
  return {{-1800.0, {0.2, 0.1, 0.0}}, {-1799.0, {0.5, 0.4, 0.0}}, {0.0, {1.5, 0.9, 0.0}}};
}

TEST(AncfTangent, CableMatchesAutomaticDifferentiation) {
  const auto current = sheared_current();
  expect_tangent_matches_ad(make_case(0.0, true, &current));
}

TEST(AncfTangent, BeamMatchesAutomaticDifferentiation) {
  const auto current = sheared_current();
  expect_tangent_matches_ad(make_case(1.7e7, true, &current));
}

TEST(AncfTangent, DeadLoadDragMatchesAutomaticDifferentiation) {
  const auto current = sheared_current();
  expect_tangent_matches_ad(make_case(1.7e7, false, &current));
}

// The drag's derivatives are tiny beside EA/L: with a soft element the
// comparison is dominated by them, so an error in the analytic drag tangent
// (drag_load_and_tangent) cannot hide under the axial stiffness. In the
// current's sheared segment (its ∂/∂z) and above the table's top (none).
TEST(AncfTangent, DragDominatedTangentMatchesAutomaticDifferentiation) {
  const auto current = sheared_current();
  for (const double z_shift : {0.0, 1500.0, 1900.0}) {
    Case c = make_case(0.0, true, &current);
    c.e.EA_N = 50.0;
    c.e.weight_N_per_m = 0.0;
    c.ctx.seabed_stiffness_N_per_m2 = 0.0;
    c.q[2] += z_shift;
    c.q[8] += z_shift;
    expect_tangent_matches_ad(c);
  }
}

TEST(AncfTangent, NoCurrentMatchesAutomaticDifferentiation) {
  const std::vector<CurrentProfilePoint> none;
  expect_tangent_matches_ad(make_case(1.7e7, true, &none));
  expect_tangent_matches_ad(make_case(1.7e7, true, nullptr));
}

// The same operations in the same order: equal, not close. Cable and beam,
// with and without current, the element across the profile's breakpoint at
// −1799 m, above its top and below its bottom, on and off the seabed.
TEST(AncfSideBySide, ForcesEqualTheReferenceBitForBit) {
  const auto sheared = sheared_current();
  const std::vector<CurrentProfilePoint> none;
  for (const double EI : {0.0, 1.7e7}) {
    for (const std::vector<CurrentProfilePoint>* current :
         {&sheared, &none, static_cast<const std::vector<CurrentProfilePoint>*>(nullptr)}) {
      for (const double z_shift : {0.0, 0.5, 1.02, 1500.0, 1900.0, -3.0}) {
        Case c = make_case(EI, true, current);
        c.q[2] += z_shift;
        c.q[8] += z_shift;
        GaussPointRows rows;
        rows.set(c.e.length_m);
        std::array<double, 12> reference, side_by_side;
        element_forces<double>(c.e, c.ctx, c.q.data(), reference.data());
        element_forces_side_by_side(c.e, c.ctx, rows, c.q.data(), side_by_side.data());
        for (std::size_t i = 0; i < 12; ++i)
          EXPECT_EQ(side_by_side[i], reference[i]) << "EI " << EI << ", z shift " << z_shift << ", g_" << i;
      }
    }
  }
}

// The lookup's segment holds where current_segment would pick the same one:
// at the breakpoints themselves (a table row belongs to the segment below
// it; the top row to the constant part above), beside them and beyond the
// table, visited in an order that leaves and re-enters segments.
TEST(AncfSideBySide, CurrentLookupGivesCurrentSegmentsVelocity) {
  const auto current = sheared_current();
  LoadContext ctx;
  ctx.current = &current;
  ctx.current_factor = 0.8;
  CurrentLookup lookup(ctx);
  const double below = std::nextafter(-1799.0, -INFINITY), above = std::nextafter(-1799.0, INFINITY);
  for (const double z : {-1799.5, -1799.0, below, above, -1800.0, -1850.0, -1799.2, 0.0, std::nextafter(0.0, -1.0),
                         -900.0, 5.0, -1799.0, -1800.0, std::nextafter(-1800.0, 0.0)}) {
    const V3<double> expected = current_segment(ctx, z).at(z);
    const V3<double> got = lookup.at(z).at(z);
    EXPECT_EQ(got.x, expected.x) << z;
    EXPECT_EQ(got.y, expected.y) << z;
    EXPECT_EQ(got.z, expected.z) << z;
    // The heights the segment claims, at both ends: current_segment gives
    // the same velocity there.
    const CurrentSegment segment = current_segment(ctx, z);
    for (const double probe : {std::nextafter(segment.above_m, INFINITY), segment.up_to_m}) {
      if (!std::isfinite(probe)) continue;
      const V3<double> own = current_segment(ctx, probe).at(probe), claimed = segment.at(probe);
      EXPECT_EQ(claimed.x, own.x) << z << " at " << probe;
      EXPECT_EQ(claimed.y, own.y) << z << " at " << probe;
    }
  }
}

}  // namespace
}  // namespace spiral::engine::ancf
