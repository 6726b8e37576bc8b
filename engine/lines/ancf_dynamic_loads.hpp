#pragma once
// Velocity- and acceleration-dependent generalised forces of one ANCF cable
// element (internal to the FE line dynamics; see fe_line_dynamics.hpp for the
// formulation). The static part — internal elastic forces, weight, seabed
// penalty — is ancf::element_forces / element_forces_and_tangent with the
// drag switched off; this kernel adds, per unstretched length:
//
//  - inertia: −[m I + m_an (I − t tᵀ) + m_at t tᵀ] r̈ (structural mass m,
//    added mass m_a = ρ A C_a normal / tangential to t = r'/|r'|), consistent
//    (through the Hermite shape functions, as the loads);
//  - Morison fluid inertia: ρ A a_f + m_an a_f,n + m_at a_f,t (Froude–Krylov
//    on the whole fluid acceleration a_f plus the added-mass parts;
//    DNV-RP-C205 §6.2 for a slender member);
//  - drag on the relative velocity u = u_current + u_wave − ṙ, on the
//    stretched length |r'| ds, as in the statics (OrcaFlex / MoorDyn v2):
//    ½ ρ Cdn D |u_n| u_n + ½ ρ Cdt π D |u_t| u_t;
//  - axial (strain-rate) damping N_d = c ε̇, ε̇ = (r'·ṙ')/|r'| — the
//    Kelvin–Voigt axial damping of MoorDyn's BA coefficient (Hall & Goupee
//    2015, eq. 6), c in N·s;
//  - an axial force offset N_0 per Gauss point (polyester: the dynamic EA
//    acts on the strain change from the mean, DNV-RP-E305 / DNV-OS-E301 ch. 2
//    sec. 4; see fe_line_dynamics.cpp for how N_0 keeps the mean state);
//  - seabed contact damping −c_b ż and Coulomb friction μ N_c against the
//    horizontal velocity, axial and lateral to the line, regularised linearly
//    below v_c (MoorDyn v2's scheme: force −μ N_c v / v_c for |v| < v_c),
//    on the same exact contact pieces as the penalty spring.
//
// Matrices for the Newton iteration (12×12, row-major, ∂/∂ of the forces):
// M (inertia, from the structural + added mass), C (∂f/∂ṙ: drag, axial and
// seabed damping, friction) and K (∂f/∂q of the force offset); the drag's
// dependence on the line direction and depth is left out of K (the Newton
// matrix of an implicit step need not be exact, only good enough to
// converge — it is dominated by c_j² M − K_elastic at the step sizes used).

#include <array>
#include <cmath>

#include "engine/lines/ancf_cable_element.hpp"

namespace spiral::engine::ancf {

/// Dynamic properties of one element (from its section).
struct DynamicElementProperties {
  double mass_kg_per_m = 0.0;                    ///< structural, incl. contents
  double added_mass_normal_kg_per_m = 0.0;       ///< ρ A C_an
  double added_mass_tangential_kg_per_m = 0.0;   ///< ρ A C_at
  double displaced_mass_kg_per_m = 0.0;          ///< ρ A (Froude–Krylov)
  double axial_damping_Ns = 0.0;                 ///< c in N_d = c ε̇
  std::array<double, 5> axial_force_offset_N{};  ///< N_0 per Gauss point (kGaussXi)
};

/// Seabed parameters of the dynamics beyond the penalty stiffness.
struct SeabedDynamics {
  double damping_N_s_per_m2 = 0.0;  ///< per m of line per m/s of vertical velocity, in contact
  double axial_friction = 0.0;      ///< μ along the line
  double lateral_friction = 0.0;    ///< μ across the line
  double friction_velocity_m_per_s = 0.01;  ///< v_c of the linear regularisation, > 0
};

/// The fluid velocity and acceleration at the element's Gauss points
/// (current + waves), global frame: filled by the caller.
struct ElementFluid {
  std::array<std::array<double, 3>, 5> velocity{};
  std::array<std::array<double, 3>, 5> acceleration{};
};

using ElementMatrix = std::array<double, 144>;  // row-major, [12 i + j]

struct ElementDynamicMatrices {
  ElementMatrix M{};  ///< mass (structural + added), kg
  ElementMatrix C{};  ///< ∂f/∂ṙ, N·s/m
  ElementMatrix K{};  ///< ∂f/∂q of the terms above (force offset only), N/m
};

namespace detail {
inline void add_outer(ElementMatrix& m, const std::array<double, 4>& su,
                      const std::array<double, 4>& sv, const double (*p)[3], double scale) {
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j < 4; ++j) {
      const double c = scale * su[static_cast<std::size_t>(k)] * sv[static_cast<std::size_t>(j)];
      if (c == 0.0) continue;
      for (int x = 0; x < 3; ++x) {
        double* row = &m[static_cast<std::size_t>(12 * (3 * k + x) + 3 * j)];
        for (int y = 0; y < 3; ++y) row[y] += c * p[x][y];
      }
    }
  }
}
}  // namespace detail

/// Adds the dynamic generalised forces to g (12 entries; g accumulates) at
/// element state q (positions/slopes), q̇ = v and q̈ = acc; fills mats if
/// given (they accumulate too).
inline void add_dynamic_element_forces(const ElementProperties& e,
                                       const DynamicElementProperties& d, const LoadContext& ctx,
                                       const SeabedDynamics& bed, const ElementFluid& fluid,
                                       const double* q, const double* v, const double* acc,
                                       double* g, ElementDynamicMatrices* mats) {
  const double L = e.length_m;
  const bool drag = e.normal_drag_N_s2_per_m3 > 0.0 || e.tangential_drag_N_s2_per_m3 > 0.0;
  for (std::size_t gp = 0; gp < kGaussXi.size(); ++gp) {
    const ShapeAt sh = shape_at(kGaussXi[gp], L);
    const double wds = kGaussW[gp] * L;
    double a[3] = {0, 0, 0}, rd[3] = {0, 0, 0}, ad[3] = {0, 0, 0}, rdd[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      for (int x = 0; x < 3; ++x) {
        const int i = 3 * k + x;
        a[x] += sh.dS[k] * q[i];
        rd[x] += sh.S[k] * v[i];
        ad[x] += sh.dS[k] * v[i];
        rdd[x] += sh.S[k] * acc[i];
      }
    }
    const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double t[3] = {a[0] / na, a[1] / na, a[2] / na};
    // Inertia and fluid inertia, in vector form: [m I + m_an P_n + m_at t tᵀ] x
    // = (m + m_an) x + (m_at − m_an)(t·x) t (p: distributed load per unstretched length).
    const double mn = d.added_mass_normal_kg_per_m, mt = d.added_mass_tangential_kg_per_m;
    const auto& af = fluid.acceleration[gp];
    const double t_rdd = t[0] * rdd[0] + t[1] * rdd[1] + t[2] * rdd[2];
    const double t_af = t[0] * af[0] + t[1] * af[1] + t[2] * af[2];
    const bool fluid_accelerates = af[0] != 0.0 || af[1] != 0.0 || af[2] != 0.0;
    double p[3];
    for (int x = 0; x < 3; ++x) {
      p[x] = -((d.mass_kg_per_m + mn) * rdd[x] + (mt - mn) * t_rdd * t[x]);
      if (fluid_accelerates)
        p[x] += (d.displaced_mass_kg_per_m + mn) * af[x] + (mt - mn) * t_af * t[x];
    }
    // Drag on the relative velocity.
    double un[3] = {0, 0, 0}, ut = 0.0, nun = 0.0, cn = 0.0, ct = 0.0;
    if (drag) {
      const auto& uf = fluid.velocity[gp];
      const double u[3] = {uf[0] - rd[0], uf[1] - rd[1], uf[2] - rd[2]};
      ut = u[0] * t[0] + u[1] * t[1] + u[2] * t[2];
      for (int x = 0; x < 3; ++x) un[x] = u[x] - ut * t[x];
      nun = std::sqrt(un[0] * un[0] + un[1] * un[1] + un[2] * un[2]);
      cn = e.normal_drag_N_s2_per_m3 * na;
      ct = e.tangential_drag_N_s2_per_m3 * na;
      for (int x = 0; x < 3; ++x) p[x] += cn * nun * un[x] + ct * std::abs(ut) * ut * t[x];
    }
    // Axial damping and force offset act on r' like the tension: −dS_k (N a/|a|).
    const double strain_rate = (a[0] * ad[0] + a[1] * ad[1] + a[2] * ad[2]) / na;
    const double n_axial = d.axial_damping_Ns * strain_rate - d.axial_force_offset_N[gp];
    for (int k = 0; k < 4; ++k) {
      const double cs = wds * sh.S[k], ca = wds * sh.dS[k] * n_axial;
      for (int x = 0; x < 3; ++x) g[3 * k + x] += cs * p[x] - ca * t[x];
    }
    if (mats != nullptr) {
      double Pn[3][3], Tt[3][3], Mg[3][3], Cd[3][3];
      for (int x = 0; x < 3; ++x) {
        for (int y = 0; y < 3; ++y) {
          Tt[x][y] = t[x] * t[y];
          Pn[x][y] = (x == y ? 1.0 : 0.0) - Tt[x][y];
          Mg[x][y] = (x == y ? d.mass_kg_per_m : 0.0) + mn * Pn[x][y] + mt * Tt[x][y];
          // ∂/∂u of the drag: cn (|u_n| P + u_n u_nᵀ/|u_n|) + 2 ct |u_t| t tᵀ; ∂u/∂ṙ = −I.
          Cd[x][y] = -(cn * nun * Pn[x][y] + 2.0 * ct * std::abs(ut) * Tt[x][y] +
                       (nun > 0.0 ? cn * un[x] * un[y] / nun : 0.0));
        }
      }
      const std::array<double, 4> S = sh.S, dS = sh.dS;
      detail::add_outer(mats->M, S, S, Mg, wds);
      if (drag) detail::add_outer(mats->C, S, S, Cd, wds);
      if (d.axial_damping_Ns > 0.0)
        detail::add_outer(mats->C, dS, dS, Tt, -wds * d.axial_damping_Ns);
      if (d.axial_force_offset_N[gp] != 0.0) {
        // ∂/∂a of (N_0 a/|a|) = N_0 P_n / |a|, entering g with + sign.
        detail::add_outer(mats->K, dS, dS, Pn, wds * d.axial_force_offset_N[gp] / na);
      }
    }
  }

  // Seabed damping and friction on the contact pieces of the penalty spring.
  const bool bed_dynamics =
      ctx.seabed_stiffness_N_per_m2 > 0.0 &&
      (bed.damping_N_s_per_m2 > 0.0 || bed.axial_friction > 0.0 || bed.lateral_friction > 0.0);
  if (!bed_dynamics) return;
  std::array<std::array<double, 2>, 4> pieces;
  const int n_pieces = seabed_contact_pieces(e, ctx.seabed_z_m, {q[2], q[5], q[8], q[11]}, pieces);
  for (int c = 0; c < n_pieces; ++c) {
    const double pa = pieces[static_cast<std::size_t>(c)][0],
                 pb = pieces[static_cast<std::size_t>(c)][1];
    for (int gp = 0; gp < 4; ++gp) {
      const double xi = pa + (pb - pa) * kContactGaussXi[gp];
      const ShapeAt sh = shape_at(xi, L);
      const double w = kContactGaussW[gp] * (pb - pa) * L;
      double r[3] = {0, 0, 0}, a[3] = {0, 0, 0}, rd[3] = {0, 0, 0};
      for (int k = 0; k < 4; ++k) {
        for (int x = 0; x < 3; ++x) {
          r[x] += sh.S[k] * q[3 * k + x];
          a[x] += sh.dS[k] * q[3 * k + x];
          rd[x] += sh.S[k] * v[3 * k + x];
        }
      }
      const double pen = ctx.seabed_z_m - r[2];
      if (pen <= 0.0) continue;
      const double normal_N_per_m = ctx.seabed_stiffness_N_per_m2 * pen;
      double p[3] = {0.0, 0.0, -bed.damping_N_s_per_m2 * rd[2]};
      double Cb[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, -bed.damping_N_s_per_m2}};
      // Horizontal line direction (axial friction) and its normal (lateral).
      const double nh = std::hypot(a[0], a[1]);
      const double th[2] = {nh > 0.0 ? a[0] / nh : 1.0, nh > 0.0 ? a[1] / nh : 0.0};
      const double lat[2] = {-th[1], th[0]};
      const double vc = bed.friction_velocity_m_per_s;
      const double mu[2] = {bed.axial_friction, bed.lateral_friction};
      const double* dir[2] = {th, lat};
      for (int m = 0; m < 2; ++m) {
        if (mu[m] <= 0.0) continue;
        const double vel = rd[0] * dir[m][0] + rd[1] * dir[m][1];
        const double slope = mu[m] * normal_N_per_m / std::max(std::abs(vel), vc);  // −f/v
        for (int x = 0; x < 2; ++x) {
          p[x] -= slope * vel * dir[m][x];
          for (int y = 0; y < 2; ++y) Cb[x][y] -= slope * dir[m][x] * dir[m][y];
        }
      }
      for (int k = 0; k < 4; ++k) {
        for (int x = 0; x < 3; ++x) g[3 * k + x] += w * sh.S[k] * p[x];
      }
      if (mats != nullptr) {
        const std::array<double, 4> S = sh.S;
        detail::add_outer(mats->C, S, S, Cb, w);
      }
    }
  }
}

}  // namespace spiral::engine::ancf
