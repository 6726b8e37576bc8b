#pragma once
// One FE line's dynamic equations as an implicit system (the DAE, reduced
// Newton matrix and outputs of fe_line_dynamics.hpp): integrated on its own
// by FeLineDynamics, or as one block of the coupled hull + lines system
// (engine/analysis/coupled_dynamics.hpp), whose end B then follows the hull
// (FeEndCondition::attached) and whose Newton solve is split so that the
// hull rows can take the line's Schur complement at its end B.
// Private to engine: callers use FeLineDynamics or the coupled system.

#include <Eigen/Core>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/numerics/sampled_trajectory.hpp"
#include "engine/numerics/sundials_ida.hpp"
#include "engine/environment/fixed_point_wave_kinematics.hpp"
#include "engine/lines/ancf_dynamic_loads.hpp"
#include "engine/lines/fe_band_matrices.hpp"
#include "engine/lines/fe_line_dynamics.hpp"
#include "engine/lines/fe_line_problem.hpp"

namespace spiral::engine::fe_detail {

// A change of an element's seabed contact by this fraction of its length
// since the Newton matrix was factored refreshes the matrix (see
// newton_matrix_stale). 0.1: fewer steps and Newton convergence failures
// than a coarser threshold, fewer refreshes than a finer one
// (docs/decisions/fe-line-dynamics-integrator.md).
constexpr double kContactChangeForRefresh = 0.1;
[[noreturn]] inline void invalid_dynamics(const std::string& what) {
  throw SolverError("FE line dynamics: invalid input: " + what);
}

struct DynamicLine final : ImplicitSystem {
  Problem p;
  std::vector<ancf::DynamicElementProperties> dyn;
  std::vector<std::array<int, kElementDofs>> element_dofs;  // global DOF of each element DOF
  std::vector<ancf::GaussShapes> shapes;                    // element lengths are fixed
  std::vector<std::array<double, 2>> end_force_offset_N;    // N_0 at ξ = 0, 1 per element (node tensions)
  ancf::LoadContext static_ctx;                             // no current: the drag is dynamic
  ancf::LoadContext current_ctx;                            // for CurrentLookup
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
  // Per element: each entry with i, j free and global j ≤ global i.
  struct LowerEntry {
    int ij;      // 12 i + j in the element's matrices
    int at;      // position in the lower bands
    int column;  // global j, the band column it sits in
  };
  std::vector<std::vector<LowerEntry>> lower_entries;
  std::vector<double> contact_at_setup, contact_now;  // per element, fraction in seabed contact
  std::vector<char> element_stale;                    // contact changed since its evaluation
  // The combination S and D hold (combine_matrices): its coefficients, the
  // elements evaluated since, and the first column changed since S was last
  // factored.
  struct Combined {
    double cM = std::numeric_limits<double>::quiet_NaN(), cC = 0.0, cK = 0.0;
    std::optional<double> D_cj;
    bool same(double m, double c, double k, std::optional<double> d) const {
      return m == cM && c == cC && k == cK && d == D_cj;
    }
  } combined;
  std::vector<char> element_changed;
  int first_changed_column = 0;
  std::vector<char> dirty_column, element_touched;  // workspace of the combination, per column and element
  std::vector<std::vector<int>> column_elements;    // per column, the elements with entries in it (ascending)

  bool fixed(int i) const { return p.fixed[static_cast<std::size_t>(i)] != 0; }

  // End B attached (coupled system): its kinematics, set by the system
  // before each residual and setup, and its Schur complement (below).
  EndKinematics end_B_attached;
  std::array<double, kElementDofs * kElementDofs> end_S{}, end_D{};  // last element, setup c_j
  Eigen::Matrix<double, Eigen::Dynamic, 3> end_B_influence;          // X = S_ff⁻¹ S_fB
  Eigen::Matrix3d end_B_schur = Eigen::Matrix3d::Zero();             // S_BB − S_Bf X
  static constexpr int kEndBLocal = 6;                               // r_b in the element's [r_a, r'_a, r_b, r'_b]

  /// Overwrites the prescribed DOFs of (q, v, a) with their values at t.
  void apply_prescribed(double t, Eigen::VectorXd& q, Eigen::VectorXd& v, Eigen::VectorXd& a) const {
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
    } else if (options.end_B != FeEndCondition::free) {
      const EndKinematics k = options.end_B == FeEndCondition::prescribed ? options.end_B_motion(t) : end_B_attached;
      q.segment<3>(rb) = k.position_m;
      v.segment<3>(rb) = k.velocity_m_per_s;
      a.segment<3>(rb) = k.acceleration_m_per_s2;
    }
  }

  // The sea's kinematics at the elements' midpoints, evaluated once per
  // time (the Newton iterations of a step share it), with their gradients:
  // each Gauss point takes them carried to where it is (fluid_at), and a
  // point moves when it has drifted kLinePointDrift_m. An element in the
  // wave zone, over which one point's value would err by more than
  // kWaveZoneMidpointError (both FixedPointWaveKinematics'), has a point at
  // each Gauss point instead: its points are wave_point_start[e] …
  // wave_point_start[e + 1] − 1.
  std::unique_ptr<FixedPointWaveKinematics> element_waves;
  std::vector<std::size_t> wave_point_start;
  std::size_t wave_point_count(std::size_t e) const { return wave_point_start[e + 1] - wave_point_start[e]; }
  /// The point at the element's midpoint (the middle Gauss point, ξ = ½).
  std::size_t wave_midpoint(std::size_t e) const {
    return wave_point_start[e] + (wave_point_count(e) == 1 ? 0 : ancf::kGaussXi.size() / 2);
  }
  /// Where point k of element e lies along it (ξ).
  double wave_point_xi(std::size_t e, std::size_t k) const {
    return wave_point_count(e) == 1 ? 0.5 : ancf::kGaussXi[k];
  }
  double sea_ramp_s = 0.0;
  mutable double element_waves_time = std::numeric_limits<double>::quiet_NaN();
  mutable std::vector<Eigen::Vector3d> element_wave_velocity, element_wave_acceleration;
  mutable std::vector<FixedPointWaveKinematics::Gradients> element_wave_gradients;
  // One element's points at a time the line is not otherwise evaluated at (fluid_at's `alone`).
  mutable std::array<Eigen::Vector3d, ancf::kGaussXi.size()> alone_wave_u, alone_wave_a;
  mutable std::array<FixedPointWaveKinematics::Gradients, ancf::kGaussXi.size()> alone_wave_g;

  /// Moves every wave-kinematics point whose place on its element (the
  /// midpoint or a Gauss point) in the state q (the line's position DOFs, as
  /// y.head(n)) is more than FixedPointWaveKinematics::kLinePointDrift_m
  /// from it; between output times only (the kinematics must not change
  /// inside a step's Newton iteration). Returns how many moved.
  int follow_elements(const Eigen::VectorXd& q) {
    if (!element_waves) return 0;
    int moved = 0;
    for (std::size_t e = 0; e < p.elements.size(); ++e) {
      const fe_detail::ElementState qe = fe_detail::gather(p, q, e);
      for (std::size_t k = 0; k < wave_point_count(e); ++k) {
        const std::size_t point = wave_point_start[e] + k;
        const Eigen::Vector3d at = fe_detail::position(ancf::shape_at(wave_point_xi(e, k), p.elements[e].length_m), qe);
        if ((at - element_waves->position(point)).norm() > FixedPointWaveKinematics::kLinePointDrift_m) {
          element_waves->move_point(point, at);
          ++moved;
        }
      }
    }
    if (moved > 0) element_waves_time = std::numeric_limits<double>::quiet_NaN();
    return moved;
  }

  /// Fluid velocity and acceleration at the element's Gauss points.
  /// `alone`: this element's forces only are wanted at t (an output's end
  /// force): its own wave kinematics, not the whole line's.
  void fluid_at(double t, std::size_t e, const double* qe, ancf::ElementFluid& fluid, bool alone = false) const {
    // The sea at each Gauss point: at the element's one point or the Gauss
    // point's own, carried to where the Gauss point now is to first order,
    // u(r) = u(p) + G_u (r − p) (FixedPointWaveKinematics::Gradients): the
    // kinematics follow the line continuously, and a point moves only when
    // the second-order term would matter (FixedPointWaveKinematics::kLinePointDrift_m).
    constexpr std::size_t kPoints = ancf::kGaussXi.size();
    std::array<std::size_t, kPoints> wave_point{};
    std::array<const Eigen::Vector3d*, kPoints> wave_u{}, wave_a{};
    std::array<const FixedPointWaveKinematics::Gradients*, kPoints> wave_g{};
    const bool own = element_waves && wave_point_count(e) > 1;  // a point per Gauss point
    if (element_waves) {
      for (std::size_t gp = 0; gp < kPoints; ++gp) wave_point[gp] = wave_point_start[e] + (own ? gp : 0);
    }
    if (element_waves && alone && t != element_waves_time) {
      for (std::size_t k = 0; k < wave_point_count(e); ++k) {
        element_waves->evaluate_point(t, wave_point_start[e] + k, alone_wave_u[k], alone_wave_a[k], &alone_wave_g[k]);
      }
      for (std::size_t gp = 0; gp < kPoints; ++gp) {
        const std::size_t k = own ? gp : 0;
        wave_u[gp] = &alone_wave_u[k], wave_a[gp] = &alone_wave_a[k], wave_g[gp] = &alone_wave_g[k];
      }
    } else if (element_waves) {
      if (t != element_waves_time) {
        element_waves->evaluate(t, element_wave_velocity, element_wave_acceleration, &element_wave_gradients);
        element_waves_time = t;
      }
      for (std::size_t gp = 0; gp < kPoints; ++gp) {
        const std::size_t point = wave_point[gp];
        wave_u[gp] = &element_wave_velocity[point];
        wave_a[gp] = &element_wave_acceleration[point];
        wave_g[gp] = &element_wave_gradients[point];
      }
    }
    const RampValue ramp = element_waves ? smooth_ramp(t - options.start_time_s, sea_ramp_s) : RampValue{};
    ancf::CurrentLookup current_lookup(current_ctx);
    for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp) {
      const ancf::ShapeAt& sh = shapes[e][gp];
      Eigen::Vector3d r = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k) r += sh.S[k] * Eigen::Vector3d(qe[3 * k], qe[3 * k + 1], qe[3 * k + 2]);
      Eigen::Vector3d u = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
      if (!current.empty()) {
        const ancf::V3<double> c = current_lookup.at(r.z()).at(r.z());
        u = {c.x, c.y, c.z};
      }
      if (waves) {
        Eigen::Vector3d uw, aw_;
        waves(r, t, uw, aw_);
        u += uw;
        a += aw_;
      }
      if (element_waves) {
        const Eigen::Vector3d d = r - element_waves->position(wave_point[gp]);
        const Eigen::Vector3d uw = *wave_u[gp] + wave_g[gp]->velocity_per_s * d;
        const Eigen::Vector3d aw = *wave_a[gp] + wave_g[gp]->acceleration_per_s2 * d;
        u += ramp.value * uw;
        a += ramp.value * aw + ramp.rate_per_s * uw;
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
                        const Eigen::VectorXd& a, std::array<double, kElementDofs>& ge, bool alone = false) const {
    const ElementValues x = gather(e, q, v, a);
    ancf::ElementFluid fluid;
    if (!still_water) fluid_at(t, e, x.q.data(), fluid, alone);
    return ancf::dynamic_element_forces(p.elements[e], dyn[e], shapes[e], static_ctx, bed,
                                        still_water ? nullptr : &fluid, x.q.data(), x.v.data(), x.a.data(), ge.data());
  }

  /// Net generalised nodal forces G (inertia included, d'Alembert) at (t, q,
  /// v, a); with contact, each element's fraction in seabed contact.
  void assemble_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& a,
                       Eigen::VectorXd& g, std::vector<double>* contact = nullptr) const {
    g.setZero(n);
    std::array<double, kElementDofs> ge;
    for (std::size_t e = 0; e < p.elements.size(); ++e) {
      const double c = element_forces(t, e, q, v, a, ge);
      if (contact != nullptr) (*contact)[e] = c;
      for (int i = 0; i < kElementDofs; ++i) g[element_dofs[e][static_cast<std::size_t>(i)]] += ge[i];
    }
    for (const auto& [node, f] : p.mesh.point_loads) g[p.r_dof[static_cast<std::size_t>(node)] + 2] -= f;
  }

  /// The net force on the position DOFs of an end node (0: end A, else end
  /// B): G there, from the one element at that end.
  Eigen::Vector3d end_force(bool end_B, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& a,
                            double t) const {
    const std::size_t e = end_B ? p.elements.size() - 1 : 0;
    const int node = end_B ? p.n_nodes - 1 : 0;
    std::array<double, kElementDofs> ge;
    element_forces(t, e, q, v, a, ge, /*alone=*/true);
    const int k0 = end_B ? 6 : 0;  // r_b or r_a in [r_a, r'_a, r_b, r'_b]
    Eigen::Vector3d f(ge[k0], ge[k0 + 1], ge[k0 + 2]);
    for (const auto& [load_node, load] : p.mesh.point_loads) {
      if (load_node == node) f.z() -= load;
    }
    return f;
  }

  /// The Newton matrices of element e (M, C = ∂G/∂v, K = ∂G/∂q) at (t, q,
  /// v), and its seabed contact there.
  void evaluate_element_matrices(double t, std::size_t e, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    const ElementValues x = gather(e, q, v, v);  // the matrices do not depend on q̈
    ancf::ElementFluid fluid;
    if (!still_water) fluid_at(t, e, x.q.data(), fluid);
    contact_at_setup[e] =
        ancf::element_newton_matrices(p.elements[e], dyn[e], shapes[e], static_ctx, bed, still_water ? nullptr : &fluid,
                                      x.q.data(), x.v.data(), element_matrices[e]);
    element_stale[e] = 0;
    element_changed[e] = 1;
    if (e < evaluated_at.size()) evaluated_at[e] = refresh_key(t, e, x);
    ++element_evaluations;
  }

  // --- Selective refresh of a full setup (the coupled system's) ---
  //
  // An element whose slopes (r': direction and strain), node velocities and
  // sea velocity have each moved less than these since its matrices were
  // evaluated keeps them at a full setup; a change of its seabed contact
  // re-evaluates it as before (newton_matrix_stale). 0: every element at
  // every full setup; so too with a `waves` function, whose sea velocity the
  // key below does not see. CoupledOptions documents the values and why
  // they do not change the solution.
  double refresh_slope_tolerance = 0.0;
  double refresh_velocity_tolerance_m_per_s = 0.0;
  long element_evaluations = 0;    // element matrices evaluated, at setups and updates
  long element_matrices_kept = 0;  // of the elements a full setup visited, those it kept

  bool selective_refresh() const {
    return (refresh_slope_tolerance > 0.0 || refresh_velocity_tolerance_m_per_s > 0.0) && !waves;
  }

  // The element's slopes (6), node velocities (6) and the sea's velocity at
  // its kinematics point (3, ramped as fluid_at applies it) at time t.
  using RefreshKey = std::array<double, 15>;
  std::vector<RefreshKey> evaluated_at;  // per element, at its last evaluation
  RefreshKey refresh_key(double t, std::size_t e, const ElementValues& x) const {
    RefreshKey k{};
    std::size_t i = 0;
    for (int slope : {3, 4, 5, 9, 10, 11}) k[i++] = x.q[slope];
    for (int r : {0, 1, 2, 6, 7, 8}) k[i++] = x.v[r];
    if (element_waves) {
      const double ramp = smooth_ramp(t - options.start_time_s, sea_ramp_s).value;
      for (int d = 0; d < 3; ++d) k[i++] = ramp * element_wave_velocity[wave_midpoint(e)][d];
    }
    return k;
  }
  bool element_moved(double t, std::size_t e, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
    const RefreshKey now = refresh_key(t, e, gather(e, q, v, v));
    const RefreshKey& then = evaluated_at[e];
    for (std::size_t i = 0; i < now.size(); ++i) {
      const double tolerance = i < 6 ? refresh_slope_tolerance : refresh_velocity_tolerance_m_per_s;
      if (std::abs(now[i] - then[i]) > tolerance) return true;
    }
    return false;
  }

  /// S = cM M + cC C + cK K and, with D_cj, D = D_cj M − C from the element
  /// matrices (lower bands: both are symmetric); prescribed DOFs get
  /// identity rows and zero columns in S and nothing in D.
  ///
  /// With the coefficients of the last combination, only the columns of the
  /// elements evaluated since are combined again (a full setup under
  /// wave-frequency motion keeps most elements' matrices, and c_j rarely
  /// changes between setups: with a setup at every step, as the coupled
  /// level then had, the combination was 12 % of a coupled run, bound by
  /// memory). Each entry of those columns is summed afresh over its elements
  /// in their order, so it is the full combination's value bit for bit.
  /// factorize_newton_matrix() refactors from the first column changed.
  void combine_matrices(double cM, double cC, double cK, std::optional<double> D_cj) {
    const std::size_t elements = p.elements.size();
    double* s_lower = nullptr;
    double* d_lower = nullptr;
    const double cB = D_cj.value_or(0.0);
    const auto add = [&](std::size_t e, auto&& take) {
      const ancf::ElementDynamicMatrices& em = element_matrices[e];
      for (const LowerEntry& entry : lower_entries[e]) {
        if (!take(entry.column)) continue;
        const auto k = static_cast<std::size_t>(entry.ij);
        s_lower[entry.at] += cM * em.M[k] + cC * em.C[k] + cK * em.K[k];
        if (d_lower != nullptr) d_lower[entry.at] += cB * em.M[k] - em.C[k];
      }
    };
    if (!combined.same(cM, cC, cK, D_cj)) {
      S.reset(n, p.band);
      if (D_cj) D.reset(n, p.band);
      s_lower = S.lower_data();
      d_lower = D_cj ? D.lower_data() : nullptr;
      for (std::size_t e = 0; e < elements; ++e) add(e, [](int) { return true; });
      for (int i : fixed_dofs) S.lower(i, i) = 1.0;
      combined = {cM, cC, cK, D_cj};
      std::fill(element_changed.begin(), element_changed.end(), 0);
      first_changed_column = 0;
      return;
    }
    const int ld = p.band + 1;
    std::vector<int> columns;
    for (std::size_t e = 0; e < elements; ++e) {
      if (element_changed[e] == 0) continue;
      element_changed[e] = 0;
      // The columns of its lower entries are its free DOFs (each has its
      // diagonal entry): 12 to read instead of 78 entries.
      for (const int column : element_dofs[e]) {
        if (fixed(column)) continue;
        if (dirty_column[static_cast<std::size_t>(column)] == 0) {
          dirty_column[static_cast<std::size_t>(column)] = 1;
          columns.push_back(column);
        }
      }
    }
    if (columns.empty()) return;
    s_lower = S.lower_data();
    d_lower = D_cj ? D.lower_data() : nullptr;
    std::size_t first_element = elements, last_element = 0;
    for (const int column : columns) {
      std::fill_n(s_lower + static_cast<std::ptrdiff_t>(column) * ld, ld, 0.0);
      if (d_lower != nullptr) std::fill_n(d_lower + static_cast<std::ptrdiff_t>(column) * ld, ld, 0.0);
      for (const int e : column_elements[static_cast<std::size_t>(column)]) {
        element_touched[static_cast<std::size_t>(e)] = 1;
        first_element = std::min(first_element, static_cast<std::size_t>(e));
        last_element = std::max(last_element, static_cast<std::size_t>(e));
      }
      first_changed_column = std::min(first_changed_column, column);
    }
    for (std::size_t e = first_element; e <= last_element && e < elements; ++e) {
      if (element_touched[e] == 0) continue;
      element_touched[e] = 0;
      add(e, [&](int column) { return dirty_column[static_cast<std::size_t>(column)] != 0; });
    }
    for (int i : fixed_dofs)
      if (dirty_column[static_cast<std::size_t>(i)] != 0) S.lower(i, i) = 1.0;
    for (const int column : columns) dirty_column[static_cast<std::size_t>(column)] = 0;
  }

  /// Factors S from the first column changed since its last factorisation.
  bool factorize_newton_matrix() {
    const bool ok = S.factorize(first_changed_column);
    first_changed_column = n;
    return ok;
  }

  // The contact stiffness k ∫ S Sᵀ of an element near the touchdown point
  // (k L ≈ 1e7 N/m for the OC4 chain) dwarfs c² M at the step sizes of the
  // line's motion: a Newton matrix factored before an element's contact
  // changed makes the iteration diverge (rate > 0.9) until the
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

  void load_state(double t, const VectorConstRef& y, const VectorConstRef& yp) {
    qw = y.head(n);
    vw = y.tail(n);
    aw = yp.tail(n);
    apply_prescribed(t, qw, vw, aw);
  }

  void residual(double t, const VectorConstRef& y, const VectorConstRef& yp, VectorRef r) override {
    load_state(t, y, yp);
    assemble_forces(t, qw, vw, aw, G, &contact_now);
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
  bool setup_newton_matrix(double t, const VectorConstRef& y, const VectorConstRef& yp, double cj) override {
    load_state(t, y, yp);
    const bool selective = selective_refresh() && evaluated_at.size() == p.elements.size();
    if (selective_refresh() && !selective) evaluated_at.resize(p.elements.size());
    if (selective && element_waves && t != element_waves_time) {
      element_waves->evaluate(t, element_wave_velocity, element_wave_acceleration, &element_wave_gradients);
      element_waves_time = t;
    }
    for (std::size_t e = 0; e < p.elements.size(); ++e) {
      if (selective && element_stale[e] == 0 && !element_moved(t, e, qw, vw)) {
        ++element_matrices_kept;
        continue;
      }
      evaluate_element_matrices(t, e, qw, vw);
    }
    combine_matrices(cj * cj, -cj, -1.0, cj);
    return factorize_newton_matrix();
  }

  // A new c_j, and the elements whose contact changed re-evaluated; the
  // others keep the matrices of their last evaluation (as a Jacobian kept
  // over steps is everywhere).
  bool update_newton_matrix(double t, const VectorConstRef& y, const VectorConstRef& yp, double cj) override {
    load_state(t, y, yp);
    for (std::size_t e = 0; e < p.elements.size(); ++e) {
      if (element_stale[e] != 0) evaluate_element_matrices(t, e, qw, vw);
    }
    combine_matrices(cj * cj, -cj, -1.0, cj);
    return factorize_newton_matrix();
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
    write_corrections(cj, b);
  }

  /// Free DOFs: δq = rhs, δv = c δq − b_q (w holds b_q there); prescribed
  /// ones: δq = b_q, δv = b_v (identity rows).
  void write_corrections(double cj, Eigen::Ref<Eigen::VectorXd> b) {
    for (int i : fixed_dofs) {
      rhs[i] = b[i];
      w[i] = b[n + i];
    }
    b.tail(n) = cj * rhs - w;
    b.head(n) = rhs;
    for (int i : fixed_dofs) b[n + i] = w[i];
  }

  // --- End B attached: the line's part of the coupled Newton solve ---
  //
  // With end B moving with a body, the residual sees end B where the body
  // puts it: apply_prescribed overwrites the end's position, velocity and
  // acceleration with the body's (end_B_attached), and the line's own
  // end-B rows only ask that its states equal them. So the forces change
  // with the body's correction alone: end B moves by δx_B = P δq_h and its
  // velocity by c δx_B − β_B, β_B = P b_qh (P the end's 3 × 6 body
  // Jacobian, b_qh the body's position rows), as a free DOF's velocity
  // moves by c δq − b_q. The line's Newton system keeps its reduced form
  // S δq = b_v + D β over all DOFs (β = b_q at the free DOFs):
  //   δq_f = y_f − X δx_B,   y_f = S_ff⁻¹ (b_vf + D_ff β_f + D_fB β_B),
  // and the end force G_B (the line's force on the body) changes by
  //   δG_B = φ − Σ_B δx_B,   φ = −S_Bf y_f + D_Bf β_f + D_BB β_B,
  // Σ_B = S_BB − S_Bf X (the line's dynamic stiffness at its end: the
  // Schur complement of the free DOFs). Only the last element touches end B.
  // The end's own rows are corrected by what they lack besides: their
  // residual b_qB, b_vB (nonzero at a predictor, where the line's and the
  // body's extrapolations of the end differ). Counting that difference as
  // a motion of end B, as this solve once did, moved the free DOFs by
  // −X b_qB that the residual had never seen, and the next iteration took
  // it back: the coupled Newton iteration converged at a rate ≈ 0.5 instead
  // of the single lines' ≈ 0.02 (docs/decisions/coupled-dynamics-performance.md).

  double end_S_at(int i, int j) const { return end_S[static_cast<std::size_t>(kElementDofs * i + j)]; }
  double end_D_at(int i, int j) const { return end_D[static_cast<std::size_t>(kElementDofs * i + j)]; }
  int end_dof(int k) const { return element_dofs.back()[static_cast<std::size_t>(k)]; }

  /// After a setup or update at c_j: the last element's S and D, which the
  /// split solve applies at end B (they must match the factored S and D).
  void prepare_end_B_matrices(double cj) {
    const ancf::ElementDynamicMatrices& em = element_matrices.back();
    for (std::size_t k = 0; k < end_S.size(); ++k) {
      end_S[k] = cj * cj * em.M[k] - cj * em.C[k] - em.K[k];
      end_D[k] = cj * em.M[k] - em.C[k];
    }
  }

  /// X and Σ_B from the factored S (three back-solves). A partial update
  /// may keep them from the last full setup: X is the line's response to a
  /// unit end motion, which a few elements changing their seabed contact
  /// far from end B hardly alter, and Σ_B enters only the hull's Newton
  /// matrix (both only change how fast the Newton iteration converges).
  void condense_end_B() {
    end_B_influence.setZero(n, 3);
    int first = n;
    for (int k = 0; k < kElementDofs; ++k) {
      if (fixed(end_dof(k))) continue;
      first = std::min(first, end_dof(k));
      for (int c = 0; c < 3; ++c) end_B_influence(end_dof(k), c) = end_S_at(k, kEndBLocal + c);
    }
    S.solve_end_columns(end_B_influence, first);
    for (int a = 0; a < 3; ++a) {
      for (int c = 0; c < 3; ++c) {
        double sum = end_S_at(kEndBLocal + a, kEndBLocal + c);
        for (int k = 0; k < kElementDofs; ++k) {
          if (!fixed(end_dof(k))) sum -= end_S_at(kEndBLocal + a, k) * end_B_influence(end_dof(k), c);
        }
        end_B_schur(a, c) = sum;
      }
    }
  }

  /// First half of the solve: y_f (kept in `rhs`) and φ.
  Eigen::Vector3d solve_free(const Eigen::Ref<const Eigen::VectorXd>& b, const Eigen::Vector3d& beta_B) {
    w = b.head(n);
    rhs = b.tail(n);
    for (int i : fixed_dofs) w[i] = 0.0;
    D.multiply_add(w, rhs);
    for (int k = 0; k < kElementDofs; ++k) {
      const int dof = end_dof(k);
      if (fixed(dof)) continue;
      for (int c = 0; c < 3; ++c) rhs[dof] += end_D_at(k, kEndBLocal + c) * beta_B[c];
    }
    for (int i : fixed_dofs) rhs[i] = 0.0;
    S.solve_in_place(rhs);
    Eigen::Vector3d phi = Eigen::Vector3d::Zero();
    for (int a = 0; a < 3; ++a) {
      for (int k = 0; k < kElementDofs; ++k) {
        const int dof = end_dof(k);
        if (fixed(dof)) continue;
        phi[a] += -end_S_at(kEndBLocal + a, k) * rhs[dof] + end_D_at(kEndBLocal + a, k) * w[dof];
      }
      for (int c = 0; c < 3; ++c) phi[a] += end_D_at(kEndBLocal + a, kEndBLocal + c) * beta_B[c];
    }
    return phi;
  }

  /// Second half: the corrections of every DOF written into b, given end
  /// B's motion δx_B = P δq_h and β_B of solve_free.
  void finish_solve(double cj, Eigen::Ref<Eigen::VectorXd> b, const Eigen::Vector3d& motion_B,
                    const Eigen::Vector3d& beta_B) {
    rhs.noalias() -= end_B_influence * motion_B;
    write_corrections(cj, b);  // end B's rows: their own residuals b_qB, b_vB
    const int rb = p.r_dof.back();
    b.segment<3>(rb) += motion_B;
    b.segment<3>(n + rb) += cj * motion_B - beta_B;
  }

  /// The line's force on end B at the last residual evaluation.
  Eigen::Vector3d end_B_force_of_residual() const { return G.segment<3>(p.r_dof.back()); }

  /// Builds the line from a static solution (FeLineDynamics' constructor);
  /// returns the consistent initial values and the integrator settings
  /// (tolerances per state, algebraic end DOFs).
  struct Start {
    Eigen::VectorXd y0, yp0;
    IdaOptions ida;
  };
  Start initialize(const FeLineModel& model, const FeDynamicEnvironment& environment, const FeStaticsResult& initial,
                   const FeDynamicsOptions& options);
};

}  // namespace spiral::engine::fe_detail
