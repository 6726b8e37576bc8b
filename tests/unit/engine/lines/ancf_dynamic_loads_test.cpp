// Unit test of the fused kernels of the FE line dynamics: the one-pass
// residual (dynamic_element_forces) must equal element_forces<double> plus
// add_dynamic_element_forces, and the one-pass Newton matrices
// (element_newton_matrices) the matrices of add_dynamic_element_forces with
// the tangent of element_forces_and_tangent in K — for a cable and a beam,
// with drag in a moving fluid, added mass, axial damping, a force offset
// and seabed contact with damping and friction.

#include "engine/lines/ancf_dynamic_loads.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace spiral::engine::ancf {
namespace {

// The fused and the separate kernels sum the same terms in other orders:
// they agree to round-off, relative to the largest entry.
constexpr double kRoundOffAgreement = 1e-12;

struct Case {
  ElementProperties e;
  DynamicElementProperties d;
  LoadContext ctx;
  SeabedDynamics bed;
  ElementFluid fluid;
  std::array<double, 12> q, v, a;
};

// A chain-like element (OC4 sizes) near its touchdown point: end A 2 mm
// into the seabed, end B above it, moving and accelerating, in a current.
Case make_case(double EI) {
  Case c;
  c.e.length_m = 10.4;
  c.e.EA_N = 7.536e8;
  c.e.EI_Nm2 = EI;
  c.e.weight_N_per_m = 1065.0;
  c.e.normal_drag_N_s2_per_m3 = 0.5 * 1025.0 * 2.0 * 0.0766;
  c.e.tangential_drag_N_s2_per_m3 = 0.5 * 1025.0 * 0.4 * M_PI * 0.0766;
  c.d.mass_kg_per_m = 113.35;
  c.d.added_mass_normal_kg_per_m = 3.8;
  c.d.added_mass_tangential_kg_per_m = 1.2;
  c.d.displaced_mass_kg_per_m = 4.7;
  c.d.axial_damping_Ns = 2.0e7;
  c.d.axial_force_offset_N = {1.0e4, 2.0e4, -5.0e3, 3.0e3, 8.0e3};
  c.ctx.seabed_z_m = -200.0;
  c.ctx.seabed_stiffness_N_per_m2 = 1e6;
  c.bed.damping_N_s_per_m2 = 7.7e3;
  c.bed.axial_friction = 0.6;
  c.bed.lateral_friction = 1.0;
  c.bed.friction_velocity_m_per_s = 0.01;
  for (std::size_t gp = 0; gp < 5; ++gp) {
    c.fluid.velocity[gp] = {0.3, 0.1 * static_cast<double>(gp), 0.0};
    c.fluid.acceleration[gp] = {0.02, -0.01, 0.005 * static_cast<double>(gp)};
  }
  c.q = {-600.0, 0.0, -200.002, 0.999, 0.002, 0.004, -589.6, 0.02, -199.95, 0.998, 0.003, 0.012};
  c.v = {0.2, 0.01, -0.03, 0.001, 0.0005, -0.002, 0.25, 0.02, 0.05, 0.0012, -0.0003, 0.003};
  c.a = {0.1, -0.02, 0.3, 0.0001, 0.0, 0.0002, -0.05, 0.01, 0.2, 0.0, 0.0001, -0.0003};
  return c;
}

double max_abs(const double* x, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = std::max(m, std::abs(x[i]));
  return m;
}

void expect_fused_forces_match(const Case& c) {
  std::array<double, 12> g_sep{}, g_fused{};
  element_forces<double>(c.e, c.ctx, c.q.data(), g_sep.data());
  add_dynamic_element_forces(c.e, c.d, c.ctx, c.bed, c.fluid, c.q.data(), c.v.data(), c.a.data(), g_sep.data(),
                             nullptr);
  const double contact = dynamic_element_forces(c.e, c.d, gauss_shapes(c.e.length_m), c.ctx, c.bed, &c.fluid,
                                                c.q.data(), c.v.data(), c.a.data(), g_fused.data());
  EXPECT_GT(contact, 0.0);
  EXPECT_LT(contact, 1.0);
  const double scale = max_abs(g_sep.data(), 12);
  for (std::size_t i = 0; i < 12; ++i)
    EXPECT_NEAR(g_fused[i], g_sep[i], kRoundOffAgreement * scale) << "g[" << i << "]";
}

void expect_fused_matrices_match(const Case& c) {
  std::array<double, 12> g;
  ElementTangent K;
  element_forces_and_tangent(c.e, c.ctx, c.q.data(), g.data(), K);
  ElementDynamicMatrices sep;
  add_dynamic_element_forces(c.e, c.d, c.ctx, c.bed, c.fluid, c.q.data(), c.v.data(), c.a.data(), g.data(), &sep);
  for (std::size_t ij = 0; ij < 144; ++ij) sep.K[ij] += K[ij];
  ElementDynamicMatrices fused;
  const double contact = element_newton_matrices(c.e, c.d, gauss_shapes(c.e.length_m), c.ctx, c.bed, &c.fluid,
                                                 c.q.data(), c.v.data(), fused);
  EXPECT_GT(contact, 0.0);
  const ElementMatrix* pairs[3][2] = {{&fused.M, &sep.M}, {&fused.C, &sep.C}, {&fused.K, &sep.K}};
  const char* names[3] = {"M", "C", "K"};
  for (int m = 0; m < 3; ++m) {
    const double scale = max_abs(pairs[m][1]->data(), 144);
    EXPECT_GT(scale, 0.0) << names[m];
    for (std::size_t ij = 0; ij < 144; ++ij) {
      EXPECT_NEAR((*pairs[m][0])[ij], (*pairs[m][1])[ij], kRoundOffAgreement * scale) << names[m] << "[" << ij << "]";
    }
  }
}

TEST(AncfDynamicLoads, FusedResidualEqualsStaticPlusDynamicForcesForACable) {
  expect_fused_forces_match(make_case(0.0));
}

TEST(AncfDynamicLoads, FusedResidualEqualsStaticPlusDynamicForcesForABeam) {
  expect_fused_forces_match(make_case(1.0e6));
}

TEST(AncfDynamicLoads, FusedNewtonMatricesEqualTheSeparateOnesForACable) {
  expect_fused_matrices_match(make_case(0.0));
}

TEST(AncfDynamicLoads, FusedNewtonMatricesEqualTheSeparateOnesForABeam) {
  expect_fused_matrices_match(make_case(1.0e6));
}

}  // namespace
}  // namespace spiral::engine::ancf
