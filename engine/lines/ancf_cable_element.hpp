#pragma once
// Generalised nodal forces of one ANCF cable/beam element (internal to the FE
// line statics; see fe_line_statics.hpp for the formulation and conventions).
//
// DOFs, 12: [r_a, r'_a, r_b, r'_b] (positions in m, slopes dimensionless, the
// derivative with respect to unstretched arc length). The kernel is a template
// on the scalar type: `double` for residuals, `Dual<12>` for exact Jacobians.
//
// Shape functions (cubic Hermite on ξ = s/L ∈ [0, 1]; Gerstmayr & Shabana 2006,
// eq. 4 in arc-length form):
//   S1 = 1 − 3ξ² + 2ξ³, S2 = L(ξ − 2ξ² + ξ³), S3 = 3ξ² − 2ξ³, S4 = L(ξ³ − ξ²).

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

#include "engine/common/forward_dual.hpp"
#include "engine/lines/fe_line_statics.hpp"

namespace spiral::engine::ancf {

/// Properties of one element (copied from its section).
struct ElementProperties {
  double length_m = 0.0;
  double EA_N = 0.0;
  double EI_Nm2 = 0.0;
  double weight_N_per_m = 0.0;
  double normal_drag_N_s2_per_m3 = 0.0;      ///< ½ ρ Cdn D, force per length per (m/s)²
  double tangential_drag_N_s2_per_m3 = 0.0;  ///< ½ ρ Cdt π D
};

/// What the distributed loads depend on besides the element DOFs.
struct LoadContext {
  const std::vector<CurrentProfilePoint>* current = nullptr;  ///< may be empty
  double current_factor = 1.0;                                ///< continuation factor on the current velocity
  double seabed_z_m = -1.0e30;
  double seabed_stiffness_N_per_m2 = 0.0;
  bool drag_jacobian = true;  ///< include the drag's derivatives in Dual evaluations
};

template <typename T>
struct V3 {
  T x, y, z;
};
template <typename T>
inline V3<T> operator+(const V3<T>& a, const V3<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename T>
inline V3<T> operator-(const V3<T>& a, const V3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename T, typename S>
inline V3<T> operator*(const S& s, const V3<T>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <typename T>
inline T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// |v| with a zero derivative at v = 0 (where |v|·v, the only use here, has
/// derivative 0): the quadratic drag law is C¹ there.
template <typename T>
inline T norm_c1(const V3<T>& v) {
  const T s = dot(v, v);
  if (value_of(s) <= 0.0) return T(0.0);
  using std::sqrt;
  return sqrt(s);
}

/// The current profile about height z: u(z') = velocity + shear (z' − z_ref)
/// on the table's segment that holds z; constant (zero shear) beyond the
/// table (times the continuation factor). current_segment gives this same
/// segment for every height in (above_m, up_to_m].
struct CurrentSegment {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d shear = Eigen::Vector3d::Zero();  ///< du/dz, 1/s
  double z_ref_m = 0.0;
  double above_m = -INFINITY, up_to_m = INFINITY;
  template <typename T>
  V3<T> at(const T& z) const {
    const T dz = z - z_ref_m;
    return {velocity.x() + shear.x() * dz, velocity.y() + shear.y() * dz, velocity.z() + shear.z() * dz};
  }
};
inline CurrentSegment current_segment(const LoadContext& ctx, double z) {
  const auto& c = *ctx.current;
  const double f = ctx.current_factor;
  CurrentSegment s;
  s.z_ref_m = z;
  if (c.empty()) return s;
  if (z <= c.front().z_m) {
    s.velocity = f * c.front().velocity_m_per_s;
    s.up_to_m = c.front().z_m;
    return s;
  }
  // The top row's height belongs to the constant part above the table.
  // (Taken only where used: nextafter is a libm call, and this runs at
  // Gauss points of every line at every residual.)
  const auto below_top = [&c] { return std::nextafter(c.back().z_m, -INFINITY); };
  if (z >= c.back().z_m) {
    s.velocity = f * c.back().velocity_m_per_s;
    s.above_m = below_top();
    return s;
  }
  std::size_t i = 1;
  while (c[i].z_m < z) ++i;
  const auto& p0 = c[i - 1];
  const auto& p1 = c[i];
  s.velocity = f * p0.velocity_m_per_s;
  s.shear = f * (p1.velocity_m_per_s - p0.velocity_m_per_s) / (p1.z_m - p0.z_m);
  s.z_ref_m = p0.z_m;
  s.above_m = p0.z_m;
  s.up_to_m = i + 1 == c.size() ? below_top() : p1.z_m;
  return s;
}

/// current_segment for the Gauss points of one element, which mostly lie in
/// one segment of the profile: the segment is looked up again only when z
/// leaves the heights it holds for (the same segment, the same numbers).
class CurrentLookup {
 public:
  explicit CurrentLookup(const LoadContext& ctx) : ctx_(ctx) {}
  const CurrentSegment& at(double z) {
    if (!looked_up_ || !(z > segment_.above_m && z <= segment_.up_to_m)) {
      segment_ = current_segment(ctx_, z);
      looked_up_ = true;
    }
    return segment_;
  }

 private:
  const LoadContext& ctx_;
  CurrentSegment segment_;
  bool looked_up_ = false;
};

/// Current velocity at height z: linear in z, constant beyond the table.
template <typename T>
inline V3<T> current_at(const LoadContext& ctx, const T& z) {
  return current_segment(ctx, value_of(z)).at(z);
}

/// 5-point Gauss–Legendre rule on [0, 1] (exact to degree 9: the weight load,
/// the bending terms of a straight element and the shape-function products).
inline constexpr std::array<double, 5> kGaussXi = {0.5 - 0.5 * 0.9061798459386640, 0.5 - 0.5 * 0.5384693101056831, 0.5,
                                                   0.5 + 0.5 * 0.5384693101056831, 0.5 + 0.5 * 0.9061798459386640};
inline constexpr std::array<double, 5> kGaussW = {0.5 * 0.2369268850561891, 0.5 * 0.4786286704993665,
                                                  0.5 * 0.5688888888888889, 0.5 * 0.4786286704993665,
                                                  0.5 * 0.2369268850561891};

struct ShapeAt {
  std::array<double, 4> S, dS, ddS;  ///< S_k, dS_k/ds, d²S_k/ds² (slope DOFs carry the L factor)
};
/// The shapes at ξ of an element of length L, given 1/L: the kernels call
/// this at every Gauss point, where a division per derivative would cost as
/// much as the rest of the interpolation.
inline ShapeAt shape_at(double xi, double L, double inv_L) {
  const double x2 = xi * xi, x3 = x2 * xi;
  const double inv_L2 = inv_L * inv_L;
  ShapeAt s;
  s.S = {1.0 - 3.0 * x2 + 2.0 * x3, L * (xi - 2.0 * x2 + x3), 3.0 * x2 - 2.0 * x3, L * (x3 - x2)};
  s.dS = {(-6.0 * xi + 6.0 * x2) * inv_L, 1.0 - 4.0 * xi + 3.0 * x2, (6.0 * xi - 6.0 * x2) * inv_L,
          3.0 * x2 - 2.0 * xi};
  s.ddS = {(-6.0 + 12.0 * xi) * inv_L2, (-4.0 + 6.0 * xi) * inv_L, (6.0 - 12.0 * xi) * inv_L2,
           (6.0 * xi - 2.0) * inv_L};
  return s;
}
inline ShapeAt shape_at(double xi, double L) { return shape_at(xi, L, 1.0 / L); }

/// Shape functions at the Gauss points kGaussXi of an element of length L.
using GaussShapes = std::array<ShapeAt, kGaussXi.size()>;
inline GaussShapes gauss_shapes(double L) {
  const double inv_L = 1.0 / L;
  GaussShapes s;
  for (std::size_t gp = 0; gp < kGaussXi.size(); ++gp) s[gp] = shape_at(kGaussXi[gp], L, inv_L);
  return s;
}

/// Seabed penalty load k·max(0, z_seabed − z) integrated exactly: the element
/// is split at the roots of z(ξ) = z_seabed and each penetrating piece gets a
/// 4-point Gauss rule (exact for the degree-6 integrand). Integrating the kink
/// of max(0, ·) with a fixed rule instead makes the contact force jump with
/// the DOFs (Newton stalls) and pins the touchdown point to element ends
/// (first-order error). The piece ends depend on the DOFs but the integrand
/// vanishes there, so holding them fixed gives the exact derivative (Leibniz).
/// Element tangent, 12×12 row-major: K[12 i + j] = ∂g_i/∂q_j.
using ElementTangent = std::array<double, 144>;

/// The pieces [ξ_a, ξ_b] of the element below the seabed (at most 4; the
/// penetration of a cubic changes sign at most 3 times), found on 16 samples
/// refined by bisection. node_z: the z components of [r_a, r'_a, r_b, r'_b].
/// Returns the number of pieces.
inline int seabed_contact_pieces(const ElementProperties& e, double seabed_z_m, const std::array<double, 4>& node_z,
                                 std::array<std::array<double, 2>, 4>& pieces) {
  const double L = e.length_m;
  // Bounds of the cubic: S1 + S3 = 1 with S1, S3 in [0, 1], and |S2|, |S4| <=
  // 4L/27 (the maximum of ξ(1 − ξ)²), so z lies within the end values ± the
  // slope terms. Most elements of a line are clear of the seabed or wholly on it.
  const double reach = 4.0 / 27.0 * L * (std::abs(node_z[1]) + std::abs(node_z[3]));
  if (std::min(node_z[0], node_z[2]) - reach >= seabed_z_m) return 0;
  if (std::max(node_z[0], node_z[2]) + reach < seabed_z_m) {
    pieces[0] = {0.0, 1.0};
    return 1;
  }
  auto z_at = [&](double xi) {
    const double x2 = xi * xi, x3 = x2 * xi;
    return (1.0 - 3.0 * x2 + 2.0 * x3) * node_z[0] + L * (xi - 2.0 * x2 + x3) * node_z[1] +
           (3.0 * x2 - 2.0 * x3) * node_z[2] + L * (x3 - x2) * node_z[3] - seabed_z_m;
  };
  constexpr int kSamples = 16;
  std::array<double, kSamples + 1> zv;
  bool any = false;
  for (int j = 0; j <= kSamples; ++j) {
    zv[j] = z_at(static_cast<double>(j) / kSamples);
    any = any || zv[j] < 0.0;
  }
  if (!any) return 0;
  std::array<double, 8> cuts{};
  int nc = 0;
  cuts[nc++] = 0.0;
  for (int j = 0; j < kSamples; ++j) {
    if ((zv[j] < 0.0) != (zv[j + 1] < 0.0)) {
      double lo = static_cast<double>(j) / kSamples, hi = static_cast<double>(j + 1) / kSamples;
      const bool lo_in = zv[j] < 0.0;
      for (int it = 0; it < 48; ++it) {  // 1/16 · 2⁻⁴⁸ ≈ 2e-16: the root to round-off
        const double mid = 0.5 * (lo + hi);
        ((z_at(mid) < 0.0) == lo_in ? lo : hi) = mid;
      }
      if (nc < 7) cuts[nc++] = 0.5 * (lo + hi);
    }
  }
  cuts[nc++] = 1.0;
  int n = 0;
  for (int c = 0; c + 1 < nc && n < 4; ++c) {
    const double a = cuts[c], b = cuts[c + 1];
    if (b - a <= 0.0 || z_at(0.5 * (a + b)) >= 0.0) continue;
    pieces[static_cast<std::size_t>(n++)] = {a, b};
  }
  return n;
}

/// 4-point Gauss–Legendre rule on [0, 1] for the contact pieces.
inline constexpr std::array<double, 4> kContactGaussXi = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                                                          0.9305681557970263};
inline constexpr std::array<double, 4> kContactGaussW = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                                         0.1739274225687269};

template <typename T>
void add_seabed_contact(const ElementProperties& e, const LoadContext& ctx, const V3<T>* node, V3<T>* force,
                        ElementTangent* K = nullptr) {
  const double L = e.length_m, inv_L = 1.0 / L;
  const double zs = ctx.seabed_z_m;
  std::array<std::array<double, 2>, 4> pieces;
  const int n_pieces = seabed_contact_pieces(
      e, zs, {value_of(node[0].z), value_of(node[1].z), value_of(node[2].z), value_of(node[3].z)}, pieces);
  for (int c = 0; c < n_pieces; ++c) {
    const double a = pieces[static_cast<std::size_t>(c)][0], b = pieces[static_cast<std::size_t>(c)][1];
    for (int gp = 0; gp < 4; ++gp) {
      const double xi = a + (b - a) * kContactGaussXi[gp];
      const ShapeAt sh = shape_at(xi, L, inv_L);
      T z = T(0.0);
      for (int k = 0; k < 4; ++k) z = z + sh.S[k] * node[k].z;
      const T pen = zs - z;
      if (value_of(pen) <= 0.0) continue;
      const double c_w = ctx.seabed_stiffness_N_per_m2 * kContactGaussW[gp] * (b - a) * L;
      const T fz = c_w * pen;
      for (int k = 0; k < 4; ++k) force[k].z = force[k].z + sh.S[k] * fz;
      if (K != nullptr) {
        for (int k = 0; k < 4; ++k) {
          for (int j = 0; j < 4; ++j) (*K)[12 * (3 * k + 2) + 3 * j + 2] -= c_w * sh.S[k] * sh.S[j];
        }
      }
    }
  }
}

/// Morison drag of the current on the line at rest, per unstretched length,
/// on the stretched length |r'| ds (OrcaFlex / MoorDyn v2 convention, see
/// fe_line_statics.hpp). na = |r'|, inv_na = 1/|r'|. With ctx.drag_jacobian
/// false, a Dual evaluation returns the drag as a dead load (values only,
/// zero derivatives).
template <typename T>
V3<T> drag_load(const ElementProperties& e, const LoadContext& ctx, const V3<T>& r, const V3<T>& a, const T& na,
                const T& inv_na) {
  if (!ctx.drag_jacobian && !std::is_same_v<T, double>) {
    const V3<double> rv{value_of(r.x), value_of(r.y), value_of(r.z)};
    const V3<double> av{value_of(a.x), value_of(a.y), value_of(a.z)};
    const V3<double> p = drag_load<double>(e, ctx, rv, av, value_of(na), value_of(inv_na));
    return {T(p.x), T(p.y), T(p.z)};
  }
  const V3<T> u = current_at<T>(ctx, r.z);
  const V3<T> t = inv_na * a;
  const T ut = dot(u, t);
  const V3<T> un = u - ut * t;
  const T abs_ut = value_of(ut) < 0.0 ? T(-ut) : ut;
  return (e.normal_drag_N_s2_per_m3 * norm_c1(un) * na) * un + (e.tangential_drag_N_s2_per_m3 * abs_ut * ut * na) * t;
}

using M3 = std::array<std::array<double, 3>, 3>;

/// drag_load<double> and its derivatives ∂p/∂r' (d_da) and ∂p/∂z (d_dz),
/// analytic. With t = a/|a|, u_t = u·t, u_n = u − u_t t, P = I − t tᵀ and
/// p = |a| [c_n |u_n| u_n + c_t |u_t| u_t t] (drag_load):
///   ∂t/∂a = P/|a|, ∂u_t/∂a = u_nᵀ/|a|, ∂u_n/∂a = −(t u_nᵀ + u_t P)/|a|,
///   ∂|u_n|/∂a = −u_t u_nᵀ/(|a| |u_n|), ∂|a|/∂a = tᵀ, so
///   ∂p/∂a = c_n [|u_n| u_n tᵀ − (u_t/|u_n|) u_n u_nᵀ − |u_n| (t u_nᵀ + u_t P)]
///         + c_t |u_t| [u_t t tᵀ + 2 t u_nᵀ + u_t P];
///   ∂p/∂u = |a| [c_n (|u_n| P + u_n u_nᵀ/|u_n|) + 2 c_t |u_t| t tᵀ],
///   ∂p/∂z = ∂p/∂u du/dz (the profile's shear).
/// The u_n u_nᵀ/|u_n| terms vanish with u_n, as norm_c1's derivative does.
/// Collected on the dyads of t and u_n (P = I − t tᵀ):
///   ∂p/∂a = α I + c_n |u_n| u_n tᵀ − c_n (u_t/|u_n|) u_n u_nᵀ
///           + (2 c_t |u_t| − c_n |u_n|) t u_nᵀ + c_n |u_n| u_t t tᵀ,
///   α = u_t (c_t |u_t| − c_n |u_n|);
///   ∂p/∂z = |a| [c_n |u_n| s + (2 c_t |u_t| − c_n |u_n|) (t·s) t + c_n (u_n·s)/|u_n| u_n],
///   s = du/dz.
/// Equal to the forward-mode derivatives of drag_load to round-off
/// (tests/unit/engine/lines/ancf_tangent_test.cpp).
struct DragTangent {
  V3<double> load;
  M3 d_da;
  std::array<double, 3> d_dz;
};
inline DragTangent drag_load_and_tangent(const ElementProperties& e, const CurrentSegment& current, const V3<double>& r,
                                         const V3<double>& a, double na, double inv_na) {
  const V3<double> u = current.at(r.z);
  const V3<double> t = inv_na * a;
  const double ut = dot(u, t);
  const V3<double> un = u - ut * t;
  const double nun = norm_c1(un);
  const double abs_ut = std::abs(ut);
  const double cn = e.normal_drag_N_s2_per_m3, ct = e.tangential_drag_N_s2_per_m3;
  DragTangent out;
  out.load = (cn * nun * na) * un + (ct * abs_ut * ut * na) * t;
  const double inv_nun = nun > 0.0 ? 1.0 / nun : 0.0;
  const double cn_nun = cn * nun, tn = 2.0 * ct * abs_ut - cn_nun;
  const double alpha = ut * (ct * abs_ut - cn_nun), c_nn = -cn * ut * inv_nun, c_tt = cn_nun * ut;
  const double tv[3] = {t.x, t.y, t.z}, nv[3] = {un.x, un.y, un.z};
  for (int x = 0; x < 3; ++x) {
    const double n_x = cn_nun * nv[x] + c_tt * tv[x], nn_x = c_nn * nv[x], t_x = tn * tv[x];
    for (int y = 0; y < 3; ++y) out.d_da[x][y] = n_x * tv[y] + (nn_x + t_x) * nv[y];
    out.d_da[x][x] += alpha;
  }
  const V3<double> shear{current.shear.x(), current.shear.y(), current.shear.z()};
  const V3<double> d_dz = na * (cn_nun * shear + (tn * dot(t, shear)) * t + (cn * inv_nun * dot(un, shear)) * un);
  out.d_dz = {d_dz.x, d_dz.y, d_dz.z};
  return out;
}

/// Gradient of the strain-energy density per unstretched length at a point
/// with r' = a, r'' = b (aa = a·a, na = |a|, inv_na = 1/|a|): fa = ∂W/∂r',
/// fb = ∂W/∂r''.
template <typename T>
inline void strain_energy_gradient(const ElementProperties& e, const V3<T>& a, const V3<T>& b, const T& aa, const T& na,
                                   const T& inv_na, V3<T>& fa, V3<T>& fb) {
  // Axial: N δ|r'| with N = EA (|r'| − 1) (engineering strain, Irvine 1981).
  const T axial = e.EA_N * (na - 1.0) * inv_na;  // N / |r'|
  fa = axial * a;
  fb = {T(0.0), T(0.0), T(0.0)};
  if (e.EI_Nm2 > 0.0) {
    // U_b = EI/2 κ², κ² = (|a|²|b|² − (a·b)²) / |a|⁶ (Gerstmayr & Shabana 2006, eq. 17).
    const T bb = dot(b, b);
    const T ab = dot(a, b);
    const T inv_aa = inv_na * inv_na;
    const T ei_a6 = e.EI_Nm2 * (inv_aa * inv_aa * inv_aa);  // EI / |a|⁶
    const T gk = aa * bb - ab * ab;
    fa = fa + ei_a6 * ((bb * a - ab * b) - (3.0 * gk * inv_aa) * a);
    fb = ei_a6 * (aa * b - ab * a);
  }
}

/// Generalised forces on the 12 DOFs: external minus internal (the net force
/// the element and its loads apply to its nodes). q, g: 12 entries each.
template <typename T>
void element_forces(const ElementProperties& e, const LoadContext& ctx, const T* q, T* g) {
  using std::sqrt;
  const double L = e.length_m;
  V3<T> node[4];
  for (int k = 0; k < 4; ++k) node[k] = {q[3 * k], q[3 * k + 1], q[3 * k + 2]};
  V3<T> force[4];
  for (int k = 0; k < 4; ++k) force[k] = {T(0.0), T(0.0), T(0.0)};

  const GaussShapes shapes = gauss_shapes(L);
  for (std::size_t gp = 0; gp < kGaussXi.size(); ++gp) {
    const ShapeAt& sh = shapes[gp];
    const double wds = kGaussW[gp] * L;  // quadrature weight times ds/dξ
    V3<T> r{T(0.0), T(0.0), T(0.0)}, a = r, b = r;
    for (int k = 0; k < 4; ++k) {
      r = r + sh.S[k] * node[k];
      a = a + sh.dS[k] * node[k];
      b = b + sh.ddS[k] * node[k];
    }
    const T aa = dot(a, a);
    const T na = sqrt(aa);
    const T inv_na = 1.0 / na;
    V3<T> fa, fb;  // ∂U/∂r', ∂U/∂r'' per length
    strain_energy_gradient(e, a, b, aa, na, inv_na, fa, fb);
    // Distributed external load per unstretched length.
    V3<T> p{T(0.0), T(0.0), T(-e.weight_N_per_m)};
    if (ctx.current != nullptr && !ctx.current->empty() &&
        (e.normal_drag_N_s2_per_m3 > 0.0 || e.tangential_drag_N_s2_per_m3 > 0.0)) {
      // Morison drag of the current on the line at rest, on the stretched
      // length |r'| ds (OrcaFlex / MoorDyn v2 convention, see header).
      p = p + drag_load<T>(e, ctx, r, a, na, inv_na);
    }
    for (int k = 0; k < 4; ++k) {
      force[k] = force[k] + wds * (sh.S[k] * p - sh.dS[k] * fa - sh.ddS[k] * fb);
    }
  }
  if (ctx.seabed_stiffness_N_per_m2 > 0.0) add_seabed_contact(e, ctx, node, force);
  for (int k = 0; k < 4; ++k) {
    g[3 * k] = force[k].x;
    g[3 * k + 1] = force[k].y;
    g[3 * k + 2] = force[k].z;
  }
}

/// The Gauss shapes of an element length laid out point by point (arrays
/// over the points) for element_forces_side_by_side, with a sixth point
/// that repeats the fifth: an even count fills 2-wide vector registers.
struct GaussPointRows {
  static constexpr int kPoints = 6;
  double length_m = -1.0;
  alignas(16) double S[4][kPoints], dS[4][kPoints], ddS[4][kPoints], wds[kPoints];
  void set(double L) {
    length_m = L;
    const GaussShapes shapes = gauss_shapes(L);
    for (int gp = 0; gp < kPoints; ++gp) {
      const auto g = static_cast<std::size_t>(std::min(gp, static_cast<int>(kGaussXi.size()) - 1));
      for (std::size_t k = 0; k < 4; ++k) {
        S[k][gp] = shapes[g].S[k];
        dS[k][gp] = shapes[g].dS[k];
        ddS[k][gp] = shapes[g].ddS[k];
      }
      wds[gp] = kGaussW[g] * L;
    }
  }
};

/// element_forces<double> with the Gauss points side by side: each step of
/// the point's arithmetic is done for all points at once (loops the compiler
/// turns into 2-wide vector instructions, square roots and divisions
/// included), each point with the same operations in the same order, and the
/// points summed in the same order: the same result, bit for bit
/// (tests/unit/engine/lines/ancf_tangent_test.cpp). rows: set for e.length_m.
inline void element_forces_side_by_side(const ElementProperties& e, const LoadContext& ctx, const GaussPointRows& rows,
                                        const double* q, double* g) {
  constexpr int P = GaussPointRows::kPoints;
  constexpr int used = static_cast<int>(kGaussXi.size());
  double r[3][P] = {}, a[3][P] = {}, b[3][P] = {};
  for (int k = 0; k < 4; ++k) {
    for (int x = 0; x < 3; ++x) {
      const double n = q[3 * k + x];
      for (int gp = 0; gp < P; ++gp) {
        r[x][gp] = r[x][gp] + rows.S[k][gp] * n;
        a[x][gp] = a[x][gp] + rows.dS[k][gp] * n;
        b[x][gp] = b[x][gp] + rows.ddS[k][gp] * n;
      }
    }
  }
  double aa[P], na[P], inv_na[P], fa[3][P], fb[3][P] = {}, p[3][P];
  for (int gp = 0; gp < P; ++gp) {
    aa[gp] = a[0][gp] * a[0][gp] + a[1][gp] * a[1][gp] + a[2][gp] * a[2][gp];
    na[gp] = std::sqrt(aa[gp]);
    inv_na[gp] = 1.0 / na[gp];
    const double axial = e.EA_N * (na[gp] - 1.0) * inv_na[gp];
    for (int x = 0; x < 3; ++x) fa[x][gp] = axial * a[x][gp];
  }
  if (e.EI_Nm2 > 0.0) {
    for (int gp = 0; gp < P; ++gp) {
      const double bb = b[0][gp] * b[0][gp] + b[1][gp] * b[1][gp] + b[2][gp] * b[2][gp];
      const double ab = a[0][gp] * b[0][gp] + a[1][gp] * b[1][gp] + a[2][gp] * b[2][gp];
      const double inv_aa = inv_na[gp] * inv_na[gp];
      const double ei_a6 = e.EI_Nm2 * (inv_aa * inv_aa * inv_aa);
      const double gk = aa[gp] * bb - ab * ab;
      const double c = 3.0 * gk * inv_aa;
      for (int x = 0; x < 3; ++x) {
        fa[x][gp] = fa[x][gp] + ei_a6 * ((bb * a[x][gp] - ab * b[x][gp]) - c * a[x][gp]);
        fb[x][gp] = ei_a6 * (aa[gp] * b[x][gp] - ab * a[x][gp]);
      }
    }
  }
  for (int gp = 0; gp < P; ++gp) {
    p[0][gp] = 0.0;
    p[1][gp] = 0.0;
    p[2][gp] = -e.weight_N_per_m;
  }
  if (ctx.current != nullptr && !ctx.current->empty() &&
      (e.normal_drag_N_s2_per_m3 > 0.0 || e.tangential_drag_N_s2_per_m3 > 0.0)) {
    // drag_load, point by point.
    double u[3][P];
    CurrentLookup current(ctx);
    for (int gp = 0; gp < P; ++gp) {
      const CurrentSegment& s = current.at(r[2][gp]);
      const double dz = r[2][gp] - s.z_ref_m;
      u[0][gp] = s.velocity.x() + s.shear.x() * dz;
      u[1][gp] = s.velocity.y() + s.shear.y() * dz;
      u[2][gp] = s.velocity.z() + s.shear.z() * dz;
    }
    const double cn = e.normal_drag_N_s2_per_m3, ct = e.tangential_drag_N_s2_per_m3;
    double t[3][P], un[3][P], ut[P], c_n[P], c_t[P];
    for (int x = 0; x < 3; ++x)
      for (int gp = 0; gp < P; ++gp) t[x][gp] = inv_na[gp] * a[x][gp];
    for (int gp = 0; gp < P; ++gp) ut[gp] = u[0][gp] * t[0][gp] + u[1][gp] * t[1][gp] + u[2][gp] * t[2][gp];
    for (int x = 0; x < 3; ++x)
      for (int gp = 0; gp < P; ++gp) un[x][gp] = u[x][gp] - ut[gp] * t[x][gp];
    for (int gp = 0; gp < P; ++gp) {
      // norm_c1: the square root of +0 is the 0 it returns there.
      const double nun = std::sqrt(un[0][gp] * un[0][gp] + un[1][gp] * un[1][gp] + un[2][gp] * un[2][gp]);
      c_n[gp] = cn * nun * na[gp];
      c_t[gp] = ct * std::abs(ut[gp]) * ut[gp] * na[gp];
    }
    for (int x = 0; x < 3; ++x)
      for (int gp = 0; gp < P; ++gp) p[x][gp] = p[x][gp] + (c_n[gp] * un[x][gp] + c_t[gp] * t[x][gp]);
  }
  double term[4][3][P];
  for (int k = 0; k < 4; ++k) {
    for (int x = 0; x < 3; ++x) {
      for (int gp = 0; gp < P; ++gp) {
        term[k][x][gp] =
            rows.wds[gp] * (rows.S[k][gp] * p[x][gp] - rows.dS[k][gp] * fa[x][gp] - rows.ddS[k][gp] * fb[x][gp]);
      }
    }
  }
  V3<double> force[4];
  for (int k = 0; k < 4; ++k) {
    double f[3];
    for (int x = 0; x < 3; ++x) {
      f[x] = 0.0;
      for (int gp = 0; gp < used; ++gp) f[x] = f[x] + term[k][x][gp];
    }
    force[k] = {f[0], f[1], f[2]};
  }
  if (ctx.seabed_stiffness_N_per_m2 > 0.0) {
    V3<double> node[4];
    for (int k = 0; k < 4; ++k) node[k] = {q[3 * k], q[3 * k + 1], q[3 * k + 2]};
    add_seabed_contact(e, ctx, node, force);
  }
  for (int k = 0; k < 4; ++k) {
    g[3 * k] = force[k].x;
    g[3 * k + 1] = force[k].y;
    g[3 * k + 2] = force[k].z;
  }
}

/// The strain-energy gradient (fa = ∂W/∂r', fb = ∂W/∂r'') and Hessian
/// (Haa = ∂fa/∂a, Hab = ∂fa/∂b, Hbb = ∂fb/∂b; ∂fb/∂a = Habᵀ) at a point with
/// r' = a, r'' = b (A = a·a, na = |a|); formulas at element_forces_and_tangent.
inline void strain_energy_hessian(const ElementProperties& e, const V3<double>& a, const V3<double>& b, double A,
                                  double na, V3<double>& fa, V3<double>& fb, M3& Haa, M3& Hab, M3& Hbb) {
  const double av[3] = {a.x, a.y, a.z}, bv[3] = {b.x, b.y, b.z};
  const double inv_na = 1.0 / na, inv_A = inv_na * inv_na;  // the one division
  const double axial = e.EA_N * (na - 1.0) * inv_na;
  fa = axial * a;
  fb = {0.0, 0.0, 0.0};
  Haa = {};
  Hab = {};
  Hbb = {};
  const double c_aa = e.EA_N * inv_A * inv_na;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) Haa[i][j] = c_aa * av[i] * av[j];
    Haa[i][i] += axial;
  }
  if (e.EI_Nm2 > 0.0) {
    const double B = dot(b, b), C = dot(a, b);
    const double G = A * B - C * C;
    const double EI = e.EI_Nm2;
    const double iA3 = EI * (inv_A * inv_A * inv_A), iA4 = iA3 * inv_A, iA5 = iA4 * inv_A;
    fa = fa + iA3 * ((B * a - C * b) - (3.0 * G * inv_A) * a);
    fb = iA3 * (A * b - C * a);
    double u[3], v[3];  // u = B a − C b, v = A b − C a
    for (int i = 0; i < 3; ++i) {
      u[i] = B * av[i] - C * bv[i];
      v[i] = A * bv[i] - C * av[i];
    }
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        Haa[i][j] +=
            -iA3 * bv[i] * bv[j] - 6.0 * iA4 * u[i] * av[j] - 6.0 * iA4 * av[i] * u[j] + 24.0 * G * iA5 * av[i] * av[j];
        Hab[i][j] = iA3 * (2.0 * av[i] * bv[j] - bv[i] * av[j]) - 6.0 * iA4 * av[i] * v[j];
        Hbb[i][j] = -iA3 * av[i] * av[j];
      }
      Haa[i][i] += iA3 * B - 3.0 * iA4 * G;
      Hab[i][i] -= iA3 * C;
      Hbb[i][i] += iA3 * A;
    }
  }
}

/// Generalised forces g (as element_forces<double>) and their exact tangent
/// K = ∂g/∂q, analytic: per Gauss point the 6×6 Hessian of the strain-energy
/// density in (a, b) = (r', r''), mapped through the shape functions (the
/// blocks of one triangle: the elastic tangent is symmetric); the drag's
/// derivatives in (z, r') from drag_load_and_tangent; the contact's from its
/// linear integrand. Same result as element_forces<Dual<12>> to round-off
/// (tests/unit), at a fraction of its cost (docs/decisions/fe-line-statics.md).
/// With ctx.drag_jacobian false the drag is a dead load in K.
///
/// Hessian of W = EA/2 (|a| − 1)² + EI/2 (|a|²|b|² − (a·b)²)/|a|⁶ (the
/// energy whose gradient element_forces uses), with A = a·a, B = b·b,
/// C = a·b, G = AB − C², f_a = ∂W/∂a, f_b = ∂W/∂b:
///   ∂f_a/∂a = EA[(1 − 1/|a|) I + a aᵀ/|a|³]
///           + EI[A⁻³(B I − b bᵀ) − 6A⁻⁴(B a − C b) aᵀ
///                − 3A⁻⁴(G I + a (2B a − 2C b)ᵀ) + 24 G A⁻⁵ a aᵀ],
///   ∂f_a/∂b = EI[A⁻³(2 a bᵀ − b aᵀ − C I) − 6A⁻⁴ a (A b − C a)ᵀ],
///   ∂f_b/∂b = EI A⁻³ (A I − a aᵀ),  ∂f_b/∂a = (∂f_a/∂b)ᵀ.
inline void element_forces_and_tangent(const ElementProperties& e, const LoadContext& ctx, const double* q, double* g,
                                       ElementTangent& K) {
  const double L = e.length_m;
  V3<double> node[4];
  for (int k = 0; k < 4; ++k) node[k] = {q[3 * k], q[3 * k + 1], q[3 * k + 2]};
  V3<double> force[4];
  for (int k = 0; k < 4; ++k) force[k] = {0.0, 0.0, 0.0};
  K.fill(0.0);
  const bool drag = ctx.current != nullptr && !ctx.current->empty() &&
                    (e.normal_drag_N_s2_per_m3 > 0.0 || e.tangential_drag_N_s2_per_m3 > 0.0);
  const bool drag_tangent = drag && ctx.drag_jacobian;
  // The drag's tangent per Gauss point, added once the elastic part is
  // mirrored: D[gp][x][3 j + y] = ∂p_x/∂a_y dS_j + ∂p_x/∂z S_j δ_y2.
  double D[kGaussXi.size()][3][12];

  const GaussShapes shapes = gauss_shapes(L);
  CurrentLookup current(ctx);
  for (std::size_t gp = 0; gp < kGaussXi.size(); ++gp) {
    const ShapeAt& sh = shapes[gp];
    const double wds = kGaussW[gp] * L;
    V3<double> r{0.0, 0.0, 0.0}, a = r, b = r;
    for (int k = 0; k < 4; ++k) {
      r = r + sh.S[k] * node[k];
      a = a + sh.dS[k] * node[k];
      b = b + sh.ddS[k] * node[k];
    }
    const double A = dot(a, a);
    const double na = std::sqrt(A);
    V3<double> fa, fb;
    M3 Haa, Hab, Hbb;  // ∂f_a/∂a, ∂f_a/∂b, ∂f_b/∂b
    strain_energy_hessian(e, a, b, A, na, fa, fb, Haa, Hab, Hbb);
    V3<double> p{0.0, 0.0, -e.weight_N_per_m};
    if (drag_tangent) {
      const DragTangent d = drag_load_and_tangent(e, current.at(r.z), r, a, na, 1.0 / na);
      p = p + d.load;
      for (int j = 0; j < 4; ++j) {
        for (int x = 0; x < 3; ++x) {
          for (int y = 0; y < 3; ++y) D[gp][x][3 * j + y] = sh.dS[j] * d.d_da[x][y];
          D[gp][x][3 * j + 2] += sh.S[j] * d.d_dz[static_cast<std::size_t>(x)];
        }
      }
    } else if (drag) {
      p = p + drag_load<double>(e, ctx, r, a, na, 1.0 / na);
    }
    for (int k = 0; k < 4; ++k) {
      force[k] = force[k] + wds * (sh.S[k] * p - sh.dS[k] * fa - sh.ddS[k] * fb);
    }
    // Elastic: K_kj −= wds (dS_k Ma_j + ddS_k Mb_j) with Ma_j = Haa dS_j +
    // Hab ddS_j and Mb_j = Habᵀ dS_j + Hbb ddS_j, held for every j as rows of
    // 12 so that each row of K takes one contiguous update (half the
    // multiplications of the four products per block). Symmetric (the
    // Hessian of an energy): the blocks k ≤ j here, k > j mirrored below.
    double Ma[3][12], Mb[3][12];
    for (int j = 0; j < 4; ++j) {
      for (int x = 0; x < 3; ++x) {
        for (int y = 0; y < 3; ++y) {
          Ma[x][3 * j + y] = sh.dS[j] * Haa[x][y] + sh.ddS[j] * Hab[x][y];
          Mb[x][3 * j + y] = sh.dS[j] * Hab[y][x] + sh.ddS[j] * Hbb[x][y];
        }
      }
    }
    for (int k = 0; k < 4; ++k) {
      const double ca = wds * sh.dS[k], cb = wds * sh.ddS[k];
      for (int x = 0; x < 3; ++x) {
        double* row = &K[static_cast<std::size_t>(12 * (3 * k + x))];
        for (int c = 3 * k; c < 12; ++c) row[c] -= ca * Ma[x][c] + cb * Mb[x][c];
      }
    }
  }
  for (int k = 1; k < 4; ++k) {
    for (int j = 0; j < k; ++j) {
      for (int x = 0; x < 3; ++x) {
        for (int y = 0; y < 3; ++y) {
          K[static_cast<std::size_t>(12 * (3 * k + x) + 3 * j + y)] =
              K[static_cast<std::size_t>(12 * (3 * j + y) + 3 * k + x)];
        }
      }
    }
  }
  if (drag_tangent) {
    // K_kj += Σ wds S_k (∂p/∂a dS_j + ∂p/∂z e_zᵀ S_j): the one unsymmetric term.
    for (std::size_t gp = 0; gp < kGaussXi.size(); ++gp) {
      const double wds = kGaussW[gp] * L;
      for (int k = 0; k < 4; ++k) {
        const double cs = wds * shapes[gp].S[k];
        for (int x = 0; x < 3; ++x) {
          double* row = &K[static_cast<std::size_t>(12 * (3 * k + x))];
          for (int c = 0; c < 12; ++c) row[c] += cs * D[gp][x][c];
        }
      }
    }
  }
  if (ctx.seabed_stiffness_N_per_m2 > 0.0) add_seabed_contact<double>(e, ctx, node, force, &K);
  for (int k = 0; k < 4; ++k) {
    g[3 * k] = force[k].x;
    g[3 * k + 1] = force[k].y;
    g[3 * k + 2] = force[k].z;
  }
}

}  // namespace spiral::engine::ancf
