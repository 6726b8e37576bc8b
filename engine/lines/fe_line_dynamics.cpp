// FE line dynamics: the DAE of fe_line_dynamics.hpp, its reduced Newton
// matrix, consistent initial values and the outputs. Past 600 lines because
// the two small band-matrix classes of the Newton solve (symmetric storage,
// banded Cholesky) live here, private to this integrator, rather than in a
// shared header of their own.

#include "engine/lines/fe_line_dynamics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/lines/ancf_dynamic_loads.hpp"
#include "engine/lines/fe_line_problem.hpp"

namespace spiral::engine {

using fe_detail::kElementDofs;
using fe_detail::Problem;

namespace {

// A change of an element's seabed contact by this fraction of its length
// since the Newton matrix was factored refreshes the matrix (see
// newton_matrix_stale). Measured on the OC4 benchmark (80 elements, rtol
// 1e-6): never 14.2k steps, 269 Newton convergence failures; 0.2 12.7k,
// 183; 0.1 11.4k, 65; 0.05 11.1k, none, but 4.7k refreshes (2.8k at 0.1).
constexpr double kContactChangeForRefresh = 0.1;

[[noreturn]] void invalid_dynamics(const std::string& what) {
  throw SolverError("FE line dynamics: invalid input: " + what);
}

/// Σ a[r] b[r] for r in [1, len], in four partial sums: the band solves are
/// otherwise bound by the latency of one long chain of additions.
inline double band_dot(const double* a, const double* b, int len) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  int r = 1;
  for (; r + 3 <= len; r += 4) {
    s0 += a[r] * b[r];
    s1 += a[r + 1] * b[r + 1];
    s2 += a[r + 2] * b[r + 2];
    s3 += a[r + 3] * b[r + 3];
  }
  for (; r <= len; ++r) s0 += a[r] * b[r];
  return (s0 + s1) + (s2 + s3);
}

/// A symmetric band matrix by its lower band (column-major, b + 1 entries
/// per column), for a matrix whose products the Newton solves need but
/// never its factors.
struct SymmetricBand {
  int n = 0, b = 0;
  std::vector<double> a;
  void reset(int size, int half_band) {
    n = size;
    b = half_band;
    a.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(b + 1), 0.0);
  }
  /// Where entry (i, j), i ≥ j, i − j ≤ half_band, sits in the lower band.
  static std::size_t offset(int i, int j, int half_band) {
    return static_cast<std::size_t>(j * (half_band + 1) + i - j);
  }
  double& lower(int i, int j) { return a[offset(i, j, b)]; }
  double* lower_data() { return a.data(); }
  /// y += A x.
  void multiply_add(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    const double* xp = x.data();
    double* yp = y.data();
    for (int j = 0; j < n; ++j) {
      const double* col = &a[static_cast<std::size_t>(j * (b + 1))];
      const int km = std::min(b, n - 1 - j);
      const double xj = xp[j];
      for (int r = 1; r <= km; ++r) yp[j + r] += col[r] * xj;
      yp[j] += col[0] * xj + band_dot(col, xp + j, km);
    }
  }
};

/// The reduced Newton matrix S = c² M − c C − K, symmetric (M, the drag,
/// damping and friction Jacobians and the elastic and contact tangents all
/// are; the drag's direction derivatives, which are not, are left out) and
/// positive definite for a line in tension: factored by banded Cholesky
/// (dpbtf2 / dpbtrs, LAPACK Users' Guide §5.3.2) on its lower band — a
/// third of the operations of the pivoted band LU and no fill-in — with the
/// band LU (BandMatrix) as the fallback when a pivot is not positive (slack
/// or compressed elements at long steps). Prescribed DOFs get identity
/// rows and zero columns (their corrections are the right-hand side's).
class NewtonMatrix {
 public:
  void reset(int size, int half_band) {
    n_ = size;
    b_ = half_band;
    band_.reset(size, half_band);
  }
  /// Entry (i, j), i ≥ j, i − j ≤ half band.
  double& lower(int i, int j) { return band_.lower(i, j); }
  /// The lower band, column-major (SymmetricBand::offset).
  double* lower_data() { return band_.lower_data(); }

  /// Factors; false if singular (both factorisations failed).
  bool factorize() {
    copy_ = band_.a;
    cholesky_ = cholesky();
    if (cholesky_) return true;
    lu_.reset(n_, b_, b_);
    for (int j = 0; j < n_; ++j) {
      for (int i = j; i <= std::min(n_ - 1, j + b_); ++i) {
        const double v = copy_[SymmetricBand::offset(i, j, b_)];
        lu_.at(i, j) = v;
        lu_.at(j, i) = v;
      }
    }
    return lu_.factorize();
  }

  void solve_in_place(Eigen::VectorXd& x) const {
    if (!cholesky_) {
      lu_.solve_in_place(x);
    } else if (b_ == 11) {
      solve_kd<11>(x.data());
    } else if (b_ == 14) {
      solve_kd<14>(x.data());
    } else {
      solve_kd<0>(x.data());
    }
  }

 private:
  // The band kernels with the half bandwidth a compile-time constant for the
  // two bandwidths of FE lines (11; 14 with a hinge joint): the interior
  // columns' loops then have fixed lengths and unroll (KD = 0: run time).
  template <int KD>
  int kd() const {
    return KD > 0 ? KD : b_;
  }

  template <int KD>
  void solve_kd(double* x) const {
    const int b = kd<KD>(), ld = b + 1;
    const double* l = band_.a.data();
    const double* inv = inv_diagonal_.data();
    for (int j = 0; j < n_; ++j) {  // L y = x
      const double* col = l + static_cast<std::ptrdiff_t>(j) * ld;
      const double xj = x[j] * inv[j];
      x[j] = xj;
      double* xr = x + j;
      if (j + b < n_) {
        for (int r = 1; r <= b; ++r) xr[r] -= col[r] * xj;
      } else {
        for (int r = 1; r < n_ - j; ++r) xr[r] -= col[r] * xj;
      }
    }
    for (int j = n_ - 1; j >= 0; --j) {  // Lᵀ x = y
      const double* col = l + static_cast<std::ptrdiff_t>(j) * ld;
      const double* xr = x + j;
      const double sum = j + b < n_ ? band_dot(col, xr, b) : band_dot(col, xr, n_ - 1 - j);
      x[j] = (x[j] - sum) * inv[j];
    }
  }

  bool cholesky() {
    inv_diagonal_.resize(static_cast<std::size_t>(n_));
    if (b_ == 11) return cholesky_kd<11>();
    if (b_ == 14) return cholesky_kd<14>();
    return cholesky_kd<0>();
  }

  template <int KD>
  bool cholesky_kd() {
    const int b = kd<KD>(), ld = b + 1;
    double* l = band_.a.data();
    for (int j = 0; j < n_; ++j) {
      double* col = l + static_cast<std::ptrdiff_t>(j) * ld;
      if (!(col[0] > 0.0)) return false;
      const double d = std::sqrt(col[0]);
      col[0] = d;
      const double inv = 1.0 / d;
      inv_diagonal_[static_cast<std::size_t>(j)] = inv;
      const int km = std::min(b, n_ - 1 - j);
      for (int r = 1; r <= km; ++r) col[r] *= inv;
      // Trailing update of columns j + c: L(j+r, j+c) −= L(j+r, j) L(j+c, j).
      if (km == b) {
        for (int c = 1; c <= b; ++c) {
          double* target = col + c * ld - c;
          const double f = col[c];
          for (int r = c; r <= b; ++r) target[r] -= col[r] * f;
        }
      } else {
        for (int c = 1; c <= km; ++c) {
          double* target = col + c * ld - c;
          const double f = col[c];
          for (int r = c; r <= km; ++r) target[r] -= col[r] * f;
        }
      }
    }
    return true;
  }

  int n_ = 0, b_ = 0;
  SymmetricBand band_;  // the lower band; Cholesky factors in place
  std::vector<double> copy_, inv_diagonal_;
  BandMatrix lu_;
  bool cholesky_ = true;
};

}  // namespace

struct FeLineDynamics::Impl final : ImplicitSystem {
  Problem p;
  std::vector<ancf::DynamicElementProperties> dyn;
  std::vector<std::array<int, kElementDofs>> element_dofs;  // global DOF of each element DOF
  std::vector<ancf::GaussShapes> shapes;                    // element lengths are fixed
  std::vector<std::array<double, 2>>
      end_force_offset_N;         // N_0 at ξ = 0, 1 per element (node tensions)
  ancf::LoadContext static_ctx;   // no current: the drag is dynamic
  ancf::LoadContext current_ctx;  // for current_at
  std::vector<CurrentProfilePoint> current;
  ancf::SeabedDynamics bed;
  WaveKinematicsFn waves;
  bool still_water = true;  // no current, no waves: the fluid kinematics are zero
  FeDynamicsOptions options;
  Eigen::Vector3d end_A_rest_m = Eigen::Vector3d::Zero(), end_B_rest_m = Eigen::Vector3d::Zero();
  int n = 0;

  // Workspace.
  Eigen::VectorXd qw, vw, aw, G, rhs, w;
  NewtonMatrix S;  // the factored Newton matrix (or the mass matrix at the start)
  std::vector<int> fixed_dofs;
  SymmetricBand D;                                             // c_j M − C at the setup's c_j
  std::vector<ancf::ElementDynamicMatrices> element_matrices;  // of the last evaluation
  // Per element: (12 i + j, position in the lower bands) of each entry
  // with i, j free and global j ≤ global i.
  std::vector<std::vector<std::pair<int, int>>> lower_entries;
  std::vector<double> contact_at_setup, contact_now;  // per element, fraction in seabed contact
  std::vector<char> element_stale;                    // contact changed since its evaluation
  std::unique_ptr<IdaIntegrator> ida;

  bool fixed(int i) const { return p.fixed[static_cast<std::size_t>(i)] != 0; }

  /// Overwrites the prescribed DOFs of (q, v, a) with their values at t.
  void apply_prescribed(double t, Eigen::VectorXd& q, Eigen::VectorXd& v,
                        Eigen::VectorXd& a) const {
    const int ra = p.r_dof.front(), rb = p.r_dof.back();
    if (options.end_A == FeEndCondition::fixed) {
      q.segment<3>(ra) = end_A_rest_m;
      v.segment<3>(ra).setZero();
      a.segment<3>(ra).setZero();
    }
    if (options.end_B == FeEndCondition::fixed) {
      q.segment<3>(rb) = end_B_rest_m;
      v.segment<3>(rb).setZero();
      a.segment<3>(rb).setZero();
    } else if (options.end_B == FeEndCondition::prescribed) {
      const EndKinematics k = options.end_B_motion(t);
      q.segment<3>(rb) = k.position_m;
      v.segment<3>(rb) = k.velocity_m_per_s;
      a.segment<3>(rb) = k.acceleration_m_per_s2;
    }
  }

  /// Fluid velocity and acceleration at the element's Gauss points.
  void fluid_at(double t, std::size_t e, const double* qe, ancf::ElementFluid& fluid) const {
    for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp) {
      const ancf::ShapeAt& sh = shapes[e][gp];
      Eigen::Vector3d r = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k)
        r += sh.S[k] * Eigen::Vector3d(qe[3 * k], qe[3 * k + 1], qe[3 * k + 2]);
      Eigen::Vector3d u = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
      if (!current.empty()) {
        const ancf::V3<double> c = ancf::current_at<double>(current_ctx, r.z());
        u = {c.x, c.y, c.z};
      }
      if (waves) {
        Eigen::Vector3d uw, aw_;
        waves(r, t, uw, aw_);
        u += uw;
        a += aw_;
      }
      for (int x = 0; x < 3; ++x) {
        fluid.velocity[gp][static_cast<std::size_t>(x)] = u[x];
        fluid.acceleration[gp][static_cast<std::size_t>(x)] = a[x];
      }
    }
  }

  struct ElementValues {
    std::array<double, kElementDofs> q, v, a;
  };
  ElementValues gather(std::size_t e, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       const Eigen::VectorXd& a) const {
    ElementValues x;
    for (int k = 0; k < kElementDofs; ++k) {
      const int dof = element_dofs[e][static_cast<std::size_t>(k)];
      x.q[k] = q[dof];
      x.v[k] = v[dof];
      x.a[k] = a[dof];
    }
    return x;
  }

  /// Net generalised forces of element e (inertia included, d'Alembert);
  /// returns the element's fraction in seabed contact.
  double element_forces(double t, std::size_t e, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                        const Eigen::VectorXd& a, std::array<double, kElementDofs>& ge) const {
    const ElementValues x = gather(e, q, v, a);
    ancf::ElementFluid fluid;
    if (!still_water) fluid_at(t, e, x.q.data(), fluid);
    return ancf::dynamic_element_forces(p.elements[e], dyn[e], shapes[e], static_ctx, bed,
                                        still_water ? nullptr : &fluid, x.q.data(), x.v.data(),
                                        x.a.data(), ge.data());
  }

  /// Net generalised nodal forces G (inertia included, d'Alembert) at (t, q,
  /// v, a); with contact, each element's fraction in seabed contact.
  void assemble_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       const Eigen::VectorXd& a, Eigen::VectorXd& g,
                       std::vector<double>* contact = nullptr) const {
    g.setZero(n);
    std::array<double, kElementDofs> ge;
    for (std::size_t e = 0; e < p.elements.size(); ++e) {
      const double c = element_forces(t, e, q, v, a, ge);
      if (contact != nullptr) (*contact)[e] = c;
      for (int i = 0; i < kElementDofs; ++i)
        g[element_dofs[e][static_cast<std::size_t>(i)]] += ge[i];
    }
    for (const auto& [node, f] : p.mesh.point_loads)
      g[p.r_dof[static_cast<std::size_t>(node)] + 2] -= f;
  }

  /// The net force on the position DOFs of an end node (0: end A, else end
  /// B): G there, from the one element at that end.
  Eigen::Vector3d end_force(bool end_B, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                            const Eigen::VectorXd& a, double t) const {
    const std::size_t e = end_B ? p.elements.size() - 1 : 0;
    const int node = end_B ? p.n_nodes - 1 : 0;
    std::array<double, kElementDofs> ge;
    element_forces(t, e, q, v, a, ge);
    const int k0 = end_B ? 6 : 0;  // r_b or r_a in [r_a, r'_a, r_b, r'_b]
    Eigen::Vector3d f(ge[k0], ge[k0 + 1], ge[k0 + 2]);
    for (const auto& [load_node, load] : p.mesh.point_loads) {
      if (load_node == node) f.z() -= load;
    }
    return f;
  }

  /// The Newton matrices of element e (M, C = ∂G/∂v, K = ∂G/∂q) at (t, q,
  /// v), and its seabed contact there.
  void evaluate_element_matrices(double t, std::size_t e, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& v) {
    const ElementValues x = gather(e, q, v, v);  // the matrices do not depend on q̈
    ancf::ElementFluid fluid;
    if (!still_water) fluid_at(t, e, x.q.data(), fluid);
    contact_at_setup[e] = ancf::element_newton_matrices(
        p.elements[e], dyn[e], shapes[e], static_ctx, bed, still_water ? nullptr : &fluid,
        x.q.data(), x.v.data(), element_matrices[e]);
    element_stale[e] = 0;
  }

  /// S = cM M + cC C + cK K and, with D_cj, D = D_cj M − C from the element
  /// matrices (lower bands: both are symmetric); prescribed DOFs get
  /// identity rows and zero columns in S and nothing in D.
  void combine_matrices(double cM, double cC, double cK, std::optional<double> D_cj) {
    S.reset(n, p.band);
    if (D_cj) D.reset(n, p.band);
    double* s_lower = S.lower_data();
    double* d_lower = D_cj ? D.lower_data() : nullptr;
    const double cB = D_cj.value_or(0.0);
    for (std::size_t e = 0; e < p.elements.size(); ++e) {
      const ancf::ElementDynamicMatrices& em = element_matrices[e];
      for (const auto& [ij, at] : lower_entries[e]) {
        const auto k = static_cast<std::size_t>(ij);
        s_lower[at] += cM * em.M[k] + cC * em.C[k] + cK * em.K[k];
        if (d_lower != nullptr) d_lower[at] += cB * em.M[k] - em.C[k];
      }
    }
    for (int i : fixed_dofs) S.lower(i, i) = 1.0;
  }

  // The contact stiffness k ∫ S Sᵀ of an element near the touchdown point
  // (k L ≈ 1e7 N/m for the OC4 chain) dwarfs c² M at the step sizes of the
  // line's motion: a Newton matrix factored before an element's contact
  // changed makes the iteration diverge (rate > 0.9, measured) until the
  // next refresh.
  // Only those elements are re-evaluated (update_newton_matrix).
  bool newton_matrix_stale() override {
    bool any = false;
    for (std::size_t e = 0; e < contact_now.size(); ++e) {
      if (std::abs(contact_now[e] - contact_at_setup[e]) > kContactChangeForRefresh) {
        element_stale[e] = 1;
        any = true;
      }
    }
    return any;
  }

  void load_state(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    qw = y.head(n);
    vw = y.tail(n);
    aw = yp.tail(n);
    apply_prescribed(t, qw, vw, aw);
  }

  void residual(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& r) override {
    load_state(t, y, yp);
    assemble_forces(t, qw, vw, aw, G, &contact_now);
    r.resize(2 * n);
    for (int i = 0; i < n; ++i) {
      if (fixed(i)) {
        r[i] = y[i] - qw[i];
        r[n + i] = y[n + i] - vw[i];
      } else {
        r[i] = yp[i] - y[n + i];
        r[n + i] = -G[i];
      }
    }
  }

  // S = c² M − c C − K, D = c M − C (the Newton matrix of the residual, reduced).
  bool setup_newton_matrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                           double cj) override {
    load_state(t, y, yp);
    for (std::size_t e = 0; e < p.elements.size(); ++e) evaluate_element_matrices(t, e, qw, vw);
    combine_matrices(cj * cj, -cj, -1.0, cj);
    return S.factorize();
  }

  // A new c_j, and the elements whose contact changed re-evaluated; the
  // others keep the matrices of their last evaluation (as a Jacobian kept
  // over steps is everywhere).
  bool update_newton_matrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                            double cj) override {
    load_state(t, y, yp);
    for (std::size_t e = 0; e < p.elements.size(); ++e) {
      if (element_stale[e] != 0) evaluate_element_matrices(t, e, qw, vw);
    }
    combine_matrices(cj * cj, -cj, -1.0, cj);
    return S.factorize();
  }

  // Row 2 uses the setup's c_j (the matrix it factored); row 1 (δv = c δq −
  // b_q) the current one, so the kinematic rows are always solved exactly.
  void solve_newton_system(double cj, Eigen::Ref<Eigen::VectorXd> b) override {
    w = b.head(n);
    rhs = b.tail(n);
    for (int i : fixed_dofs) w[i] = 0.0;
    D.multiply_add(w, rhs);  // D has no prescribed rows
    for (int i : fixed_dofs) rhs[i] = 0.0;
    S.solve_in_place(rhs);
    // Free DOFs: δq = rhs, δv = c δq − b_q (w holds b_q there); prescribed
    // ones: δq = b_q, δv = b_v (identity rows), set after.
    for (int i : fixed_dofs) {
      rhs[i] = b[i];
      w[i] = b[n + i];
    }
    b.tail(n) = cj * rhs - w;
    b.head(n) = rhs;
    for (int i : fixed_dofs) b[n + i] = w[i];
  }
};

namespace {

void validate_dynamics(const FeLineModel& model, const FeDynamicEnvironment& env,
                       const FeDynamicsOptions& o) {
  for (std::size_t i = 0; i < model.sections.size(); ++i) {
    const auto& s = model.sections[i];
    auto check = [&](const char* field, double v, const char* unit) {
      if (!std::isfinite(v) || v < 0.0)
        invalid_dynamics(
            fmt::format("sections[{}].{}: must be >= 0 {}, got {}", i, field, unit, v));
    };
    check("displaced_area_m2", s.displaced_area_m2, "m2");
    check("added_mass_normal", s.added_mass_normal, "");
    check("added_mass_tangential", s.added_mass_tangential, "");
    check("axial_damping_Ns", s.axial_damping_Ns, "N s");
    check("EA_dynamic_N", s.EA_dynamic_N, "N");
    if (!(s.mass_kg_per_m > 0.0) && !(s.added_mass_normal * s.displaced_area_m2 > 0.0)) {
      invalid_dynamics(fmt::format(
          "sections[{}].mass_kg_per_m: must be > 0 kg/m for dynamics, got {}", i, s.mass_kg_per_m));
    }
  }
  auto check_env = [](const char* field, double v, bool ok, const char* rule) {
    if (!std::isfinite(v) || !ok)
      invalid_dynamics(fmt::format("{}: must be {}, got {}", field, rule, v));
  };
  check_env("seabed_lateral_friction", env.seabed_lateral_friction,
            env.seabed_lateral_friction >= 0.0, ">= 0");
  check_env("seabed_axial_friction", env.statics.seabed_axial_friction,
            env.statics.seabed_axial_friction >= 0.0, ">= 0");
  check_env("seabed_damping_N_s_per_m2", env.seabed_damping_N_s_per_m2,
            env.seabed_damping_N_s_per_m2 >= 0.0, ">= 0 N s/m2");
  check_env("friction_velocity_m_per_s", env.friction_velocity_m_per_s,
            env.friction_velocity_m_per_s > 0.0, "> 0 m/s");
  if (o.end_B == FeEndCondition::prescribed && !o.end_B_motion)
    invalid_dynamics("end_B_motion: required when end B is prescribed");
  if (o.end_A == FeEndCondition::prescribed)
    invalid_dynamics("end_A: may be fixed or free (prescribe end B)");
  if (o.end_A == FeEndCondition::free && o.end_B == FeEndCondition::free)
    invalid_dynamics("end_A, end_B: at least one end must be held");
  check_env("relative_tolerance", o.relative_tolerance, o.relative_tolerance > 0.0, "> 0");
  check_env("position_tolerance_m", o.position_tolerance_m, o.position_tolerance_m > 0.0, "> 0 m");
  check_env("slope_tolerance", o.slope_tolerance, o.slope_tolerance > 0.0, "> 0");
  check_env("velocity_tolerance_m_per_s", o.velocity_tolerance_m_per_s,
            o.velocity_tolerance_m_per_s > 0.0, "> 0 m/s");
}

}  // namespace

FeLineDynamics::FeLineDynamics(const FeLineModel& model, const FeDynamicEnvironment& environment,
                               const FeStaticsResult& initial, const FeDynamicsOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  validate_dynamics(model, environment, options);
  if (initial.node_position_m.size() < 2)
    invalid_dynamics("initial: not a static solution (no nodes)");
  const FeLineEnds ends{initial.node_position_m.front(), initial.node_position_m.back()};
  fe_detail::validate(model, environment.statics, ends, FeStaticsOptions{});
  m.options = options;
  m.p = fe_detail::make_problem(model, environment.statics, ends);
  m.n = m.p.n_dofs;
  if (initial.state.size() != m.n || !initial.state.allFinite()) {
    invalid_dynamics(fmt::format(
        "initial.state: needs {} finite entries (a static solution of this model), got {}", m.n,
        initial.state.size()));
  }
  fe_detail::set_node_arc_lengths(m.p, initial.node_arc_length_m);
  m.end_A_rest_m = ends.end_A_m;
  m.end_B_rest_m = ends.end_B_m;
  for (int k = 0; k < 3; ++k) {
    if (options.end_A == FeEndCondition::free)
      m.p.fixed[static_cast<std::size_t>(m.p.r_dof.front() + k)] = 0;
    if (options.end_B == FeEndCondition::free)
      m.p.fixed[static_cast<std::size_t>(m.p.r_dof.back() + k)] = 0;
  }
  m.current = environment.statics.current;
  m.current_ctx.current = &m.current;
  m.static_ctx = m.p.load;
  m.static_ctx.current = nullptr;
  m.bed.damping_N_s_per_m2 = environment.seabed_damping_N_s_per_m2;
  m.bed.axial_friction = environment.statics.seabed_axial_friction;
  m.bed.lateral_friction = environment.seabed_lateral_friction;
  m.bed.friction_velocity_m_per_s = environment.friction_velocity_m_per_s;
  m.waves = environment.waves;
  m.still_water = m.current.empty() && !m.waves;

  // Element dynamic properties; a dynamic EA takes over from the static one
  // with the force offset that keeps the static state in equilibrium.
  const Eigen::VectorXd& q0 = initial.state;
  const double rho = environment.statics.water_density_kg_per_m3;
  m.dyn.resize(m.p.elements.size());
  m.end_force_offset_N.assign(m.p.elements.size(), {0.0, 0.0});
  for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
    const FeLineSection& s = model.sections[static_cast<std::size_t>(m.p.mesh.section[e])];
    ancf::DynamicElementProperties& d = m.dyn[e];
    d.mass_kg_per_m = s.mass_kg_per_m;
    d.displaced_mass_kg_per_m = rho * s.displaced_area_m2;
    d.added_mass_normal_kg_per_m = rho * s.displaced_area_m2 * s.added_mass_normal;
    d.added_mass_tangential_kg_per_m = rho * s.displaced_area_m2 * s.added_mass_tangential;
    d.axial_damping_Ns = s.axial_damping_Ns;
    if (s.EA_dynamic_N > 0.0 && s.EA_dynamic_N != s.EA_N) {
      const fe_detail::ElementState qe = fe_detail::gather(m.p, q0, e);
      const double L = m.p.elements[e].length_m;
      auto offset_at = [&](double xi) {
        const double strain = fe_detail::slope(ancf::shape_at(xi, L), qe).norm() - 1.0;
        return (s.EA_dynamic_N - s.EA_N) * strain;
      };
      for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp)
        d.axial_force_offset_N[gp] = offset_at(ancf::kGaussXi[gp]);
      m.end_force_offset_N[e] = {offset_at(0.0), offset_at(1.0)};
      m.p.elements[e].EA_N = s.EA_dynamic_N;
    }
  }

  m.element_dofs.resize(m.p.elements.size());
  m.shapes.resize(m.p.elements.size());
  for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
    const auto blocks = fe_detail::element_blocks(m.p, e);
    for (int k = 0; k < kElementDofs; ++k)
      m.element_dofs[e][static_cast<std::size_t>(k)] =
          blocks[static_cast<std::size_t>(k / 3)] + k % 3;
    m.shapes[e] = ancf::gauss_shapes(m.p.elements[e].length_m);
  }
  for (int i = 0; i < m.n; ++i) {
    if (m.fixed(i)) m.fixed_dofs.push_back(i);
  }
  m.element_matrices.resize(m.p.elements.size());
  m.lower_entries.resize(m.p.elements.size());
  for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
    const auto& dof = m.element_dofs[e];
    for (int i = 0; i < kElementDofs; ++i) {
      for (int j = 0; j < kElementDofs; ++j) {
        const int gi = dof[static_cast<std::size_t>(i)], gj = dof[static_cast<std::size_t>(j)];
        if (gj > gi || m.fixed(gi) || m.fixed(gj)) continue;
        m.lower_entries[e].emplace_back(kElementDofs * i + j,
                                        static_cast<int>(SymmetricBand::offset(gi, gj, m.p.band)));
      }
    }
  }
  m.element_stale.assign(m.p.elements.size(), 0);
  m.contact_at_setup.assign(m.p.elements.size(), 0.0);
  m.contact_now.assign(m.p.elements.size(), 0.0);

  // Initial state, velocity and a consistent acceleration: M a0 = G(q0, v0, a = 0).
  Eigen::VectorXd v0 = Eigen::VectorXd::Zero(m.n), a0 = Eigen::VectorXd::Zero(m.n);
  if (options.initial_velocity) {
    const double delta = 1e-6 * m.p.line_length_m;
    for (std::size_t i = 0; i < static_cast<std::size_t>(m.p.n_nodes); ++i) {
      const double s = m.p.mesh.s[i];
      v0.segment<3>(m.p.r_dof[i]) = options.initial_velocity(s);
      const double s0 = std::max(0.0, s - delta), s1 = std::min(m.p.line_length_m, s + delta);
      const Eigen::Vector3d rate =
          (options.initial_velocity(s1) - options.initial_velocity(s0)) / (s1 - s0);
      v0.segment<3>(m.p.t_in[i]) = rate;
      v0.segment<3>(m.p.t_out[i]) = rate;
    }
    if (!v0.allFinite()) invalid_dynamics("initial_velocity: returned non-finite values");
  }
  Eigen::VectorXd q_start = q0;
  {
    Eigen::VectorXd q_check = q0, v_check = v0, a_check = a0;
    m.apply_prescribed(options.start_time_s, q_check, v_check, a_check);
    const double mismatch = (q_check - q0).cwiseAbs().maxCoeff();
    if (mismatch > 1e-6 * std::max(1.0, m.p.line_length_m)) {
      invalid_dynamics(
          fmt::format("end_B_motion: at the start time {} s the end is {:.6g} m from the static "
                      "solution's end; start the motion from the static position",
                      options.start_time_s, mismatch));
    }
    q_start = q_check;
    v0 = v_check;
    a0 = a_check;
  }
  m.assemble_forces(options.start_time_s, q_start, v0, a0, m.G);
  for (std::size_t e = 0; e < m.p.elements.size(); ++e)
    m.evaluate_element_matrices(options.start_time_s, e, q_start, v0);
  m.combine_matrices(1.0, 0.0, 0.0, std::nullopt);
  m.rhs = m.G;
  for (int i = 0; i < m.n; ++i) {
    if (m.fixed(i)) m.rhs[i] = 0.0;
  }
  if (!m.S.factorize()) invalid_dynamics("mass matrix: singular (a section without mass?)");
  m.S.solve_in_place(m.rhs);
  for (int i = 0; i < m.n; ++i) {
    if (!m.fixed(i)) a0[i] = m.rhs[i];
  }

  Eigen::VectorXd y0(2 * m.n), yp0(2 * m.n), atol(2 * m.n), id = Eigen::VectorXd::Ones(2 * m.n);
  y0 << q_start, v0;
  yp0 << v0, a0;
  std::vector<char> is_position(static_cast<std::size_t>(m.n), 0);
  for (int r : m.p.r_dof) {
    for (int k = 0; k < 3; ++k) is_position[static_cast<std::size_t>(r + k)] = 1;
  }
  const double slope_rate_tolerance =
      options.slope_tolerance * options.velocity_tolerance_m_per_s / options.position_tolerance_m;
  for (int i = 0; i < m.n; ++i) {
    const bool pos = is_position[static_cast<std::size_t>(i)] != 0;
    atol[i] = pos ? options.position_tolerance_m : options.slope_tolerance;
    atol[m.n + i] = pos ? options.velocity_tolerance_m_per_s : slope_rate_tolerance;
    if (m.fixed(i)) id[i] = id[m.n + i] = 0.0;
  }
  IdaOptions io;
  io.relative_tolerance = options.relative_tolerance;
  io.absolute_tolerances = atol;
  io.differential_id = id;
  io.max_order = options.max_order;
  io.max_step_s = options.max_step_s;
  io.initial_step_s = options.initial_step_s;
  io.max_steps_between_outputs = options.max_steps_between_outputs;
  m.ida = std::make_unique<IdaIntegrator>(m, options.start_time_s, y0, yp0, io);
}

FeLineDynamics::~FeLineDynamics() = default;
FeLineDynamics::FeLineDynamics(FeLineDynamics&&) noexcept = default;
FeLineDynamics& FeLineDynamics::operator=(FeLineDynamics&&) noexcept = default;

void FeLineDynamics::advance_to(double t_s) {
  impl_->ida->advance_to(t_s);
}
double FeLineDynamics::time_s() const {
  return impl_->ida->time_s();
}
IdaStatistics FeLineDynamics::statistics() const {
  return impl_->ida->statistics();
}
int FeLineDynamics::node_count() const {
  return impl_->p.n_nodes;
}
int FeLineDynamics::dof_count() const {
  return impl_->n;
}

Eigen::Vector3d FeLineDynamics::end_B_force_N() const {
  Impl& m = *impl_;
  if (m.options.end_B == FeEndCondition::free) return Eigen::Vector3d::Zero();
  m.load_state(m.ida->time_s(), m.ida->state(), m.ida->state_derivative());
  return m.end_force(true, m.qw, m.vw, m.aw, m.ida->time_s());
}

FeLineDynamicSnapshot FeLineDynamics::snapshot() const {
  Impl& m = *impl_;
  const double t = m.ida->time_s();
  m.load_state(t, m.ida->state(), m.ida->state_derivative());
  FeLineDynamicSnapshot snap;
  snap.time_s = t;
  const auto nn = static_cast<std::size_t>(m.p.n_nodes);
  for (std::size_t i = 0; i < nn; ++i) {
    snap.node_position_m.push_back(m.qw.segment<3>(m.p.r_dof[i]));
    snap.node_velocity_m_per_s.push_back(m.vw.segment<3>(m.p.r_dof[i]));
    double sum = 0.0;
    int count = 0;
    if (i > 0) {
      sum += m.p.elements[i - 1].EA_N * (m.qw.segment<3>(m.p.t_in[i]).norm() - 1.0) -
             m.end_force_offset_N[i - 1][1];
      ++count;
    }
    if (i + 1 < nn) {
      sum += m.p.elements[i].EA_N * (m.qw.segment<3>(m.p.t_out[i]).norm() - 1.0) -
             m.end_force_offset_N[i][0];
      ++count;
    }
    snap.node_tension_N.push_back(sum / count);
  }
  if (m.options.end_A != FeEndCondition::free)
    snap.end_A_force_N = m.end_force(false, m.qw, m.vw, m.aw, t);
  if (m.options.end_B != FeEndCondition::free)
    snap.end_B_force_N = m.end_force(true, m.qw, m.vw, m.aw, t);
  return snap;
}

FeLineEnergy FeLineDynamics::energy() const {
  Impl& m = *impl_;
  m.load_state(m.ida->time_s(), m.ida->state(), m.ida->state_derivative());
  FeLineEnergy en;
  for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
    const ancf::ElementProperties& ep = m.p.elements[e];
    const fe_detail::ElementState qe = fe_detail::gather(m.p, m.qw, e);
    const fe_detail::ElementState ve = fe_detail::gather(m.p, m.vw, e);
    for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp) {
      const ancf::ShapeAt& sh = m.shapes[e][gp];
      const double wds = ancf::kGaussW[gp] * ep.length_m;
      const Eigen::Vector3d r = fe_detail::position(sh, qe), a = fe_detail::slope(sh, qe);
      const Eigen::Vector3d rd = fe_detail::position(sh, ve);
      const double strain = a.norm() - 1.0;
      en.kinetic_J += 0.5 * m.dyn[e].mass_kg_per_m * rd.squaredNorm() * wds;
      double density = 0.5 * ep.EA_N * strain * strain - m.dyn[e].axial_force_offset_N[gp] * strain;
      if (ep.EI_Nm2 > 0.0) {
        const double kappa = fe_detail::curvature(sh, qe);
        density += 0.5 * ep.EI_Nm2 * kappa * kappa;
      }
      en.strain_J += density * wds;
      en.gravity_J += ep.weight_N_per_m * r.z() * wds;
    }
    ancf::detail::for_each_contact_point(
        ep, m.static_ctx, qe.data(), ve.data(),
        [&](const ancf::ShapeAt&, double w, double pen, const double*, const double*) {
          en.seabed_J += 0.5 * m.static_ctx.seabed_stiffness_N_per_m2 * pen * pen * w;
        });
  }
  for (const auto& [node, f] : m.p.mesh.point_loads)
    en.gravity_J += f * m.qw[m.p.r_dof[static_cast<std::size_t>(node)] + 2];
  return en;
}

}  // namespace spiral::engine
