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

#include <algorithm>
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
  double damping_N_s_per_m2 = 0.0;          ///< per m of line per m/s of vertical velocity, in contact
  double axial_friction = 0.0;              ///< μ along the line
  double lateral_friction = 0.0;            ///< μ across the line
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
  ElementMatrix K{};  ///< ∂f/∂q: add_dynamic_element_forces: of its terms (force offset only);
                      ///< element_newton_matrices: in full (with the static tangent), N/m
};

namespace detail {
inline void add_outer(ElementMatrix& m, const std::array<double, 4>& su, const std::array<double, 4>& sv,
                      const double (*p)[3], double scale) {
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

/// The dynamic loads at Gauss point gp, per unstretched length, from r' = a
/// (|a| = na), ṙ' = ad, ṙ = rd, r̈ = rdd and the fluid (nullptr: still water).
struct PointLoad {
  double t[3];     ///< unit tangent a/|a|
  double p[3];     ///< inertia, fluid inertia and drag, N/m
  double n_axial;  ///< axial damping minus force offset, along t, N
  // Drag pieces for ∂p/∂ṙ: normal relative velocity, its norm, the tangential
  // one and the coefficients on the stretched length.
  double un[3] = {0, 0, 0}, nun = 0.0, ut = 0.0, cn = 0.0, ct = 0.0;
};
inline PointLoad point_load(const ElementProperties& e, const DynamicElementProperties& d, std::size_t gp,
                            const double* a, double na, const double* ad, const double* rd, const double* rdd,
                            const ElementFluid* fluid) {
  PointLoad pl;
  double* t = pl.t;
  const double inv_na = 1.0 / na;
  for (int x = 0; x < 3; ++x) t[x] = a[x] * inv_na;
  // Inertia and fluid inertia, in vector form: [m I + m_an P_n + m_at t tᵀ] x
  // = (m + m_an) x + (m_at − m_an)(t·x) t (p: distributed load per unstretched length).
  const double mn = d.added_mass_normal_kg_per_m, mt = d.added_mass_tangential_kg_per_m;
  const double t_rdd = t[0] * rdd[0] + t[1] * rdd[1] + t[2] * rdd[2];
  for (int x = 0; x < 3; ++x) pl.p[x] = -((d.mass_kg_per_m + mn) * rdd[x] + (mt - mn) * t_rdd * t[x]);
  if (fluid != nullptr) {
    const auto& af = fluid->acceleration[gp];
    if (af[0] != 0.0 || af[1] != 0.0 || af[2] != 0.0) {
      const double t_af = t[0] * af[0] + t[1] * af[1] + t[2] * af[2];
      for (int x = 0; x < 3; ++x) pl.p[x] += (d.displaced_mass_kg_per_m + mn) * af[x] + (mt - mn) * t_af * t[x];
    }
  }
  // Drag on the relative velocity.
  if (e.normal_drag_N_s2_per_m3 > 0.0 || e.tangential_drag_N_s2_per_m3 > 0.0) {
    double u[3] = {-rd[0], -rd[1], -rd[2]};
    if (fluid != nullptr) {
      for (int x = 0; x < 3; ++x) u[x] += fluid->velocity[gp][static_cast<std::size_t>(x)];
    }
    pl.ut = u[0] * t[0] + u[1] * t[1] + u[2] * t[2];
    for (int x = 0; x < 3; ++x) pl.un[x] = u[x] - pl.ut * t[x];
    pl.nun = std::sqrt(pl.un[0] * pl.un[0] + pl.un[1] * pl.un[1] + pl.un[2] * pl.un[2]);
    pl.cn = e.normal_drag_N_s2_per_m3 * na;
    pl.ct = e.tangential_drag_N_s2_per_m3 * na;
    for (int x = 0; x < 3; ++x) pl.p[x] += pl.cn * pl.nun * pl.un[x] + pl.ct * std::abs(pl.ut) * pl.ut * t[x];
  }
  // Axial damping and force offset act on r' like the tension: −dS_k (N a/|a|).
  const double strain_rate = (a[0] * ad[0] + a[1] * ad[1] + a[2] * ad[2]) * inv_na;
  pl.n_axial = d.axial_damping_Ns * strain_rate - d.axial_force_offset_N[gp];
  return pl;
}

/// Seabed damping and regularised friction at a contact point with contact
/// force normal_N_per_m, r' = a, ṙ = rd: adds the load to p and, if Cb is
/// given, writes ∂p/∂ṙ.
inline void add_seabed_point_load(const SeabedDynamics& bed, double normal_N_per_m, const double* a, const double* rd,
                                  double* p, double (*Cb)[3]) {
  p[2] -= bed.damping_N_s_per_m2 * rd[2];
  if (Cb != nullptr) {
    for (int x = 0; x < 3; ++x) {
      for (int y = 0; y < 3; ++y) Cb[x][y] = 0.0;
    }
    Cb[2][2] = -bed.damping_N_s_per_m2;
  }
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
      if (Cb != nullptr) {
        for (int y = 0; y < 2; ++y) Cb[x][y] -= slope * dir[m][x] * dir[m][y];
      }
    }
  }
}

inline bool has_bed_dynamics(const LoadContext& ctx, const SeabedDynamics& bed) {
  return ctx.seabed_stiffness_N_per_m2 > 0.0 &&
         (bed.damping_N_s_per_m2 > 0.0 || bed.axial_friction > 0.0 || bed.lateral_friction > 0.0);
}

/// r, r' and ṙ at a point of the element.
inline void point_kinematics(const ShapeAt& sh, const double* q, const double* v, double* r, double* a, double* rd) {
  for (int x = 0; x < 3; ++x) r[x] = a[x] = rd[x] = 0.0;
  for (int k = 0; k < 4; ++k) {
    for (int x = 0; x < 3; ++x) {
      r[x] += sh.S[k] * q[3 * k + x];
      a[x] += sh.dS[k] * q[3 * k + x];
      rd[x] += sh.S[k] * v[3 * k + x];
    }
  }
}
/// r', ṙ, ṙ' and r̈ at a point of the element.
inline void motion_at(const ShapeAt& sh, const double* q, const double* v, const double* acc, double* a, double* rd,
                      double* ad, double* rdd) {
  for (int x = 0; x < 3; ++x) a[x] = rd[x] = ad[x] = rdd[x] = 0.0;
  for (int k = 0; k < 4; ++k) {
    for (int x = 0; x < 3; ++x) {
      const int i = 3 * k + x;
      a[x] += sh.dS[k] * q[i];
      rd[x] += sh.S[k] * v[i];
      ad[x] += sh.dS[k] * v[i];
      rdd[x] += sh.S[k] * acc[i];
    }
  }
}

/// Calls f(sh, w, pen, a, rd) at each point of the 4-point rules on the
/// element's exact contact pieces (seabed_contact_pieces) where it
/// penetrates the seabed: shape functions, quadrature weight (m), penetration
/// (m), r' and ṙ there. Returns the fraction of the element in contact.
template <typename F>
double for_each_contact_point(const ElementProperties& e, const LoadContext& ctx, const double* q, const double* v,
                              F&& f) {
  if (ctx.seabed_stiffness_N_per_m2 <= 0.0) return 0.0;
  const double L = e.length_m;
  std::array<std::array<double, 2>, 4> pieces;
  const int n_pieces = seabed_contact_pieces(e, ctx.seabed_z_m, {q[2], q[5], q[8], q[11]}, pieces);
  double contact = 0.0;
  for (int c = 0; c < n_pieces; ++c) {
    const double pa = pieces[static_cast<std::size_t>(c)][0], pb = pieces[static_cast<std::size_t>(c)][1];
    contact += pb - pa;
    for (int gp = 0; gp < 4; ++gp) {
      const double xi = pa + (pb - pa) * kContactGaussXi[gp];
      const ShapeAt sh = shape_at(xi, L);
      double r[3], a[3], rd[3];
      point_kinematics(sh, q, v, r, a, rd);
      const double pen = ctx.seabed_z_m - r[2];
      if (pen > 0.0) f(sh, kContactGaussW[gp] * (pb - pa) * L, pen, a, rd);
    }
  }
  return contact;
}
}  // namespace detail

/// Adds the dynamic generalised forces to g (12 entries; g accumulates) at
/// element state q (positions/slopes), q̇ = v and q̈ = acc; fills mats if
/// given (they accumulate too).
inline void add_dynamic_element_forces(const ElementProperties& e, const DynamicElementProperties& d,
                                       const LoadContext& ctx, const SeabedDynamics& bed, const ElementFluid& fluid,
                                       const double* q, const double* v, const double* acc, double* g,
                                       ElementDynamicMatrices* mats) {
  const double L = e.length_m;
  const bool drag = e.normal_drag_N_s2_per_m3 > 0.0 || e.tangential_drag_N_s2_per_m3 > 0.0;
  for (std::size_t gp = 0; gp < kGaussXi.size(); ++gp) {
    const ShapeAt sh = shape_at(kGaussXi[gp], L);
    const double wds = kGaussW[gp] * L;
    double a[3], rd[3], ad[3], rdd[3];
    detail::motion_at(sh, q, v, acc, a, rd, ad, rdd);
    const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const detail::PointLoad pl = detail::point_load(e, d, gp, a, na, ad, rd, rdd, &fluid);
    const double* t = pl.t;
    for (int k = 0; k < 4; ++k) {
      const double cs = wds * sh.S[k], ca = wds * sh.dS[k] * pl.n_axial;
      for (int x = 0; x < 3; ++x) g[3 * k + x] += cs * pl.p[x] - ca * t[x];
    }
    if (mats != nullptr) {
      const double mn = d.added_mass_normal_kg_per_m, mt = d.added_mass_tangential_kg_per_m;
      double Pn[3][3], Tt[3][3], Mg[3][3], Cd[3][3];
      for (int x = 0; x < 3; ++x) {
        for (int y = 0; y < 3; ++y) {
          Tt[x][y] = t[x] * t[y];
          Pn[x][y] = (x == y ? 1.0 : 0.0) - Tt[x][y];
          Mg[x][y] = (x == y ? d.mass_kg_per_m : 0.0) + mn * Pn[x][y] + mt * Tt[x][y];
          // ∂/∂u of the drag: cn (|u_n| P + u_n u_nᵀ/|u_n|) + 2 ct |u_t| t tᵀ; ∂u/∂ṙ = −I.
          Cd[x][y] = -(pl.cn * pl.nun * Pn[x][y] + 2.0 * pl.ct * std::abs(pl.ut) * Tt[x][y] +
                       (pl.nun > 0.0 ? pl.cn * pl.un[x] * pl.un[y] / pl.nun : 0.0));
        }
      }
      const std::array<double, 4> S = sh.S, dS = sh.dS;
      detail::add_outer(mats->M, S, S, Mg, wds);
      if (drag) detail::add_outer(mats->C, S, S, Cd, wds);
      if (d.axial_damping_Ns > 0.0) detail::add_outer(mats->C, dS, dS, Tt, -wds * d.axial_damping_Ns);
      if (d.axial_force_offset_N[gp] != 0.0) {
        // ∂/∂a of (N_0 a/|a|) = N_0 P_n / |a|, entering g with + sign.
        detail::add_outer(mats->K, dS, dS, Pn, wds * d.axial_force_offset_N[gp] / na);
      }
    }
  }

  // Seabed damping and friction on the contact pieces of the penalty spring.
  if (!detail::has_bed_dynamics(ctx, bed)) return;
  detail::for_each_contact_point(e, ctx, q, v,
                                 [&](const ShapeAt& sh, double w, double pen, const double* a, const double* rd) {
                                   double p[3] = {0.0, 0.0, 0.0}, Cb[3][3];
                                   detail::add_seabed_point_load(bed, ctx.seabed_stiffness_N_per_m2 * pen, a, rd, p,
                                                                 mats != nullptr ? Cb : nullptr);
                                   for (int k = 0; k < 4; ++k) {
                                     for (int x = 0; x < 3; ++x) g[3 * k + x] += w * sh.S[k] * p[x];
                                   }
                                   if (mats != nullptr) detail::add_outer(mats->C, sh.S, sh.S, Cb, w);
                                 });
}

/// Every generalised force of the dynamics on the 12 DOFs in one pass — the
/// static ones of element_forces<double> (elastic forces, weight, seabed
/// penalty) plus those of add_dynamic_element_forces — without matrices: the
/// residual of the equations of motion. r, r', r'', ṙ, ṙ' and r̈ are formed
/// once per Gauss point (shapes: gauss_shapes(e.length_m)), the contact
/// pieces once per element. The current enters through fluid (nullptr: still
/// water), not ctx, whose current is ignored. g is overwritten. Returns the
/// fraction of the element in contact with the seabed.
inline double dynamic_element_forces(const ElementProperties& e, const DynamicElementProperties& d,
                                     const GaussShapes& shapes, const LoadContext& ctx, const SeabedDynamics& bed,
                                     const ElementFluid* fluid, const double* q, const double* v, const double* acc,
                                     double* g) {
  const double L = e.length_m;
  const bool bending = e.EI_Nm2 > 0.0;
  for (int i = 0; i < 12; ++i) g[i] = 0.0;
  for (std::size_t gp = 0; gp < kGaussXi.size(); ++gp) {
    const ShapeAt& sh = shapes[gp];
    const double wds = kGaussW[gp] * L;
    double a[3], b[3] = {0, 0, 0}, rd[3], ad[3], rdd[3];
    detail::motion_at(sh, q, v, acc, a, rd, ad, rdd);
    if (bending) {
      for (int k = 0; k < 4; ++k) {
        for (int x = 0; x < 3; ++x) b[x] += sh.ddS[k] * q[3 * k + x];
      }
    }
    const V3<double> av{a[0], a[1], a[2]}, bv{b[0], b[1], b[2]};
    const double aa = dot(av, av), na = std::sqrt(aa);
    V3<double> fa, fb;
    strain_energy_gradient(e, av, bv, aa, na, 1.0 / na, fa, fb);
    const detail::PointLoad pl = detail::point_load(e, d, gp, a, na, ad, rd, rdd, fluid);
    const double fat[3] = {fa.x + pl.n_axial * pl.t[0], fa.y + pl.n_axial * pl.t[1], fa.z + pl.n_axial * pl.t[2]};
    const double fbt[3] = {fb.x, fb.y, fb.z};
    const double p[3] = {pl.p[0], pl.p[1], pl.p[2] - e.weight_N_per_m};
    for (int k = 0; k < 4; ++k) {
      const double cs = wds * sh.S[k], ca = wds * sh.dS[k], cb = wds * sh.ddS[k];
      for (int x = 0; x < 3; ++x) g[3 * k + x] += cs * p[x] - ca * fat[x] - cb * fbt[x];
    }
  }

  // Seabed penalty (as add_seabed_contact), damping and friction.
  const bool bed_dynamics = detail::has_bed_dynamics(ctx, bed);
  return detail::for_each_contact_point(
      e, ctx, q, v, [&](const ShapeAt& sh, double w, double pen, const double* a, const double* rd) {
        const double normal_N_per_m = ctx.seabed_stiffness_N_per_m2 * pen;
        double p[3] = {0.0, 0.0, normal_N_per_m};
        if (bed_dynamics) detail::add_seabed_point_load(bed, normal_N_per_m, a, rd, p, nullptr);
        for (int k = 0; k < 4; ++k) {
          for (int x = 0; x < 3; ++x) g[3 * k + x] += w * sh.S[k] * p[x];
        }
      });
}

/// The element's Newton matrices of the dynamics, overwritten: the mass M,
/// C = ∂g/∂q̇ (drag, axial damping, seabed damping and friction) and the
/// full K = ∂g/∂q — the static tangent of element_forces_and_tangent
/// (elastic forces and seabed penalty; ctx's current is ignored, as in
/// dynamic_element_forces) plus the force-offset term. One pass over the
/// Gauss points builds each term's 3×3 block per pair of shape functions
/// once; equal to element_forces_and_tangent + add_dynamic_element_forces to
/// round-off (tests/unit/engine/lines/ancf_dynamic_loads_test.cpp). All three are
/// symmetric. Returns the fraction of the element in seabed contact, as
/// dynamic_element_forces.
inline double element_newton_matrices(const ElementProperties& e, const DynamicElementProperties& d,
                                      const GaussShapes& shapes, const LoadContext& ctx, const SeabedDynamics& bed,
                                      const ElementFluid* fluid, const double* q, const double* v,
                                      ElementDynamicMatrices& m) {
  const double L = e.length_m;
  const bool bending = e.EI_Nm2 > 0.0;
  const bool drag = e.normal_drag_N_s2_per_m3 > 0.0 || e.tangential_drag_N_s2_per_m3 > 0.0;
  const double mn = d.added_mass_normal_kg_per_m, mt = d.added_mass_tangential_kg_per_m;
  const double c_ax = d.axial_damping_Ns;
  m.M.fill(0.0);
  m.C.fill(0.0);
  m.K.fill(0.0);
  // m(k, j) += c su_k sv_j P for the 3×3 blocks (k, j).
  auto add_pair = [](ElementMatrix& mat, const std::array<double, 4>& su, const std::array<double, 4>& sv, const M3& P,
                     double c) {
    for (std::size_t k = 0; k < 4; ++k) {
      for (std::size_t j = 0; j < 4; ++j) {
        const double ckj = c * su[k] * sv[j];
        for (std::size_t x = 0; x < 3; ++x) {
          double* row = &mat[12 * (3 * k + x) + 3 * j];
          for (std::size_t y = 0; y < 3; ++y) row[y] += ckj * P[x][y];
        }
      }
    }
  };
  for (std::size_t gp = 0; gp < kGaussXi.size(); ++gp) {
    const ShapeAt& sh = shapes[gp];
    const double wds = kGaussW[gp] * L;
    double av[3] = {0, 0, 0}, bv[3] = {0, 0, 0}, rd[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      for (int x = 0; x < 3; ++x) {
        av[x] += sh.dS[k] * q[3 * k + x];
        rd[x] += sh.S[k] * v[3 * k + x];
        if (bending) bv[x] += sh.ddS[k] * q[3 * k + x];
      }
    }
    const V3<double> a{av[0], av[1], av[2]}, b{bv[0], bv[1], bv[2]};
    const double aa = dot(a, a), na = std::sqrt(aa);
    V3<double> fa, fb;
    M3 Haa, Hab, Hbb;
    strain_energy_hessian(e, a, b, aa, na, fa, fb, Haa, Hab, Hbb);
    const double zero[3] = {0.0, 0.0, 0.0};
    const detail::PointLoad pl = detail::point_load(e, d, gp, av, na, zero, rd, zero, fluid);
    const double* t = pl.t;
    const double offset = d.axial_force_offset_N[gp] / na;
    M3 Mg, Cd, Ct, Kdd;  // mass and drag on (S, S); axial damping and stiffness on (dS, dS)
    for (std::size_t x = 0; x < 3; ++x) {
      for (std::size_t y = 0; y < 3; ++y) {
        const double Tt = t[x] * t[y], Pn = (x == y ? 1.0 : 0.0) - Tt;
        Mg[x][y] = (x == y ? d.mass_kg_per_m : 0.0) + mn * Pn + mt * Tt;
        // ∂/∂u of the drag: cn (|u_n| P + u_n u_nᵀ/|u_n|) + 2 ct |u_t| t tᵀ; ∂u/∂ṙ = −I.
        Cd[x][y] = -(pl.cn * pl.nun * Pn + 2.0 * pl.ct * std::abs(pl.ut) * Tt +
                     (pl.nun > 0.0 ? pl.cn * pl.un[x] * pl.un[y] / pl.nun : 0.0));
        Ct[x][y] = -c_ax * Tt;
        // Elastic: −∂f_a/∂a; force offset: ∂/∂a of N_0 a/|a| = N_0 P_n/|a|.
        Kdd[x][y] = offset * Pn - Haa[x][y];
        Hab[x][y] = -Hab[x][y];
        Hbb[x][y] = -Hbb[x][y];
      }
    }
    add_pair(m.M, sh.S, sh.S, Mg, wds);
    if (drag) add_pair(m.C, sh.S, sh.S, Cd, wds);
    if (c_ax > 0.0) add_pair(m.C, sh.dS, sh.dS, Ct, wds);
    add_pair(m.K, sh.dS, sh.dS, Kdd, wds);
    if (bending) {
      M3 Hba;
      for (std::size_t x = 0; x < 3; ++x) {
        for (std::size_t y = 0; y < 3; ++y) Hba[x][y] = Hab[y][x];
      }
      add_pair(m.K, sh.dS, sh.ddS, Hab, wds);
      add_pair(m.K, sh.ddS, sh.dS, Hba, wds);
      add_pair(m.K, sh.ddS, sh.ddS, Hbb, wds);
    }
  }

  // Seabed penalty (K), damping and friction (C) at the contact points.
  return detail::for_each_contact_point(
      e, ctx, q, v, [&](const ShapeAt& sh, double w, double pen, const double* a, const double* rd) {
        double p[3] = {0.0, 0.0, 0.0}, cb[3][3];
        detail::add_seabed_point_load(bed, ctx.seabed_stiffness_N_per_m2 * pen, a, rd, p, cb);
        M3 Cb, Kb{};
        for (std::size_t x = 0; x < 3; ++x) {
          for (std::size_t y = 0; y < 3; ++y) Cb[x][y] = cb[x][y];
        }
        Kb[2][2] = -ctx.seabed_stiffness_N_per_m2;
        add_pair(m.C, sh.S, sh.S, Cb, w);
        add_pair(m.K, sh.S, sh.S, Kb, w);
      });
}

}  // namespace spiral::engine::ancf
