#include "engine/lines/fe_line_impedance.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>
#include <vector>

#include "engine/common/complex_band_lu.hpp"
#include "engine/common/solver_error.hpp"
#include "engine/lines/fe_dynamic_line.hpp"
#include "engine/lines/stochastic_drag.hpp"

namespace spiral::engine {
namespace {

using Complex = std::complex<double>;

/// D(ω) = K + iω C + ω² M of the line, partitioned into its free DOFs (f)
/// and end B's position (B).
struct PartitionedDynamicMatrix {
  ComplexBandLu ff;  // free DOFs in the mesh's order: within the mesh's band
  Eigen::Matrix<Complex, Eigen::Dynamic, 3> fB;
  Eigen::Matrix<Complex, 3, Eigen::Dynamic> Bf;
  Matrix3cd BB;
};

struct DofPartition {
  std::vector<int> index;  // free DOF number, −1 for a fixed DOF
  int free_count = 0;
  int end_B = 0;  // end B's first position DOF
  int input_of(int dof) const { return dof >= end_B && dof < end_B + 3 ? dof - end_B : -1; }
};

PartitionedDynamicMatrix partitioned_matrix(const fe_detail::DynamicLine& line, const DofPartition& dofs,
                                            double omega) {
  PartitionedDynamicMatrix D{ComplexBandLu(dofs.free_count, line.p.band), {}, {}, {}};
  D.fB = Eigen::Matrix<Complex, Eigen::Dynamic, 3>::Zero(dofs.free_count, 3);
  D.Bf = Eigen::Matrix<Complex, 3, Eigen::Dynamic>::Zero(3, dofs.free_count);
  D.BB = Matrix3cd::Zero();
  for (std::size_t e = 0; e < line.p.elements.size(); ++e) {
    const ancf::ElementDynamicMatrices& m = line.element_matrices[e];
    for (int a = 0; a < fe_detail::kElementDofs; ++a) {
      const int ga = line.element_dofs[e][static_cast<std::size_t>(a)];
      for (int b = 0; b < fe_detail::kElementDofs; ++b) {
        const int gb = line.element_dofs[e][static_cast<std::size_t>(b)];
        const auto k = static_cast<std::size_t>(fe_detail::kElementDofs * a + b);
        const Complex d(m.K[k] + omega * omega * m.M[k], omega * m.C[k]);
        const int ia = dofs.index[static_cast<std::size_t>(ga)], ib = dofs.index[static_cast<std::size_t>(gb)];
        const int xa = dofs.input_of(ga), xb = dofs.input_of(gb);
        if (ia >= 0 && ib >= 0)
          D.ff.at(ia, ib) += d;
        else if (ia >= 0 && xb >= 0)
          D.fB(ia, xb) += d;
        else if (xa >= 0 && ib >= 0)
          D.Bf(xa, ib) += d;
        else if (xa >= 0 && xb >= 0)
          D.BB(xa, xb) += d;
      }
    }
  }
  return D;
}

/// Re-linearizes every element's normal drag in C on the line's own motion:
/// the expected slope of |w| w (stochastic_drag.hpp) for the normal relative
/// velocity w = current − ṙ with ṙ the quasi-static response of the line to
/// end B's velocity, ṙ = J v_B, J = −K_ff⁻¹ K_fB interpolated to the
/// element's middle (see below) — the enhanced S-C's quasi-static reduction
/// does the same with the catenary's shape derivative
/// (design/analysis/line_hydrodynamics.hpp).
/// The tangential drag keeps its slope at the current (its coefficient is a
/// tenth of the normal one's, and a motion along the line is small).
void linearize_drag_on_motion(fe_detail::DynamicLine& line, const DofPartition& dofs,
                              const Eigen::Matrix<Complex, Eigen::Dynamic, 3>& static_response,
                              const Eigen::Matrix3d& end_B_velocity_covariance, const Eigen::VectorXd& q0) {
  for (std::size_t e = 0; e < line.p.elements.size(); ++e) {
    const ancf::ElementProperties& element = line.p.elements[e];
    if (!(element.normal_drag_N_s2_per_m3 > 0.0)) continue;
    // Each element DOF's quasi-static motion per unit end-B motion.
    Eigen::Matrix<double, fe_detail::kElementDofs, 3> transfer =
        Eigen::Matrix<double, fe_detail::kElementDofs, 3>::Zero();
    for (int a = 0; a < fe_detail::kElementDofs; ++a) {
      const int g = line.element_dofs[e][static_cast<std::size_t>(a)];
      if (const int i = dofs.index[static_cast<std::size_t>(g)]; i >= 0)
        transfer.row(a) = -static_response.row(i).real();
      else if (const int x = dofs.input_of(g); x >= 0)
        transfer(a, x) = 1.0;
    }
    const fe_detail::ElementState qe = fe_detail::gather(line.p, q0, e);
    ancf::ElementFluid fluid;
    if (!line.still_water) line.fluid_at(line.options.start_time_s, e, qe.data(), fluid);
    // The expected slope's change at the element's middle Gauss point (ξ =
    // ½), each Gauss point taking it on its own normal plane: the quadrature
    // of the expectation costs ~1,000 evaluations, a riser has 4,000 Gauss
    // points, and over one element the line's shape, current and motion
    // vary little.
    constexpr std::size_t kMiddle = ancf::kGaussXi.size() / 2;
    static_assert(ancf::kGaussXi[kMiddle] == 0.5);
    const auto tangent_at = [&](std::size_t gp) {
      Eigen::Vector3d slope = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k)
        slope += line.shapes[e][gp].dS[k] * Eigen::Vector3d(qe[3 * k], qe[3 * k + 1], qe[3 * k + 2]);
      return slope;
    };
    Eigen::Matrix3d middle_change;
    {
      const Eigen::Vector3d t = tangent_at(kMiddle).normalized();
      const Eigen::Matrix3d Pn = Eigen::Matrix3d::Identity() - t * t.transpose();
      Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 4; ++k) J += line.shapes[e][kMiddle].S[k] * transfer.middleRows<3>(3 * k);
      const Eigen::Vector3d u(fluid.velocity[kMiddle][0], fluid.velocity[kMiddle][1], fluid.velocity[kMiddle][2]);
      const Eigen::Matrix3d PJ = Pn * J;
      middle_change = expected_drag_slope(t, Pn * u, PJ * end_B_velocity_covariance * PJ.transpose()) -
                      expected_drag_slope(t, Pn * u, Eigen::Matrix3d::Zero());
    }
    for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp) {
      const ancf::ShapeAt& sh = line.shapes[e][gp];
      const Eigen::Vector3d slope = tangent_at(gp);
      const double stretched = slope.norm();
      const Eigen::Vector3d t = slope / stretched;
      const Eigen::Matrix3d Pn = Eigen::Matrix3d::Identity() - t * t.transpose();
      const Eigen::Matrix3d change = Pn * middle_change * Pn;
      // C = ∂G/∂ṙ and ∂w/∂ṙ = −I.
      double block[3][3];
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) block[x][y] = -element.normal_drag_N_s2_per_m3 * stretched * change(x, y);
      ancf::detail::add_outer(line.element_matrices[e].C, sh.S, sh.S, block, ancf::kGaussW[gp] * element.length_m);
    }
  }
}

}  // namespace

std::vector<Matrix3cd> end_B_dynamic_stiffness(const FeLineModel& model, const FeDynamicEnvironment& environment,
                                               const FeStaticsResult& state, std::span<const double> omegas_rad_per_s,
                                               const Eigen::Matrix3d& end_B_velocity_covariance) {
  fe_detail::DynamicLine line;
  FeDynamicsOptions options;
  options.end_B = FeEndCondition::fixed;                // its DOFs are the input X below
  line.initialize(model, environment, state, options);  // evaluates every element's M, C, K at rest

  // Free DOFs numbered 0.. for the sparse system; end B's three position DOFs apart.
  DofPartition dofs;
  dofs.end_B = line.p.r_dof.back();
  dofs.index.assign(static_cast<std::size_t>(line.n), -1);
  for (int i = 0; i < line.n; ++i) {
    if (!line.fixed(i)) dofs.index[static_cast<std::size_t>(i)] = dofs.free_count++;
  }

  auto solve = [&](double omega) {
    PartitionedDynamicMatrix D = partitioned_matrix(line, dofs, omega);
    Eigen::Matrix<Complex, Eigen::Dynamic, 3> response = D.fB;
    ComplexBandLu factor = D.ff;
    if (factor.factorize()) {
      factor.solve_in_place(response);
    } else {
      Eigen::SparseLU<Eigen::SparseMatrix<Complex>> lu(D.ff.to_sparse());
      if (lu.info() != Eigen::Success) {
        throw SolverError(
            fmt::format("end_B_dynamic_stiffness: the line's dynamic matrix at {} rad/s is singular", omega));
      }
      response = lu.solve(D.fB);
    }
    return std::pair{std::move(D), std::move(response)};
  };

  auto condensed = [](const PartitionedDynamicMatrix& D, const Eigen::Matrix<Complex, Eigen::Dynamic, 3>& response) {
    return Matrix3cd(-(D.BB - D.Bf * response));
  };
  // The condensation alone: D_Bf D_ff⁻¹ D_fB from the factors' tails
  // (ComplexBandLu::inverse_form) instead of three solves over the whole line.
  auto condensed_at = [&](double omega) {
    PartitionedDynamicMatrix D = partitioned_matrix(line, dofs, omega);
    if (D.ff.factorize()) return Matrix3cd(-(D.BB - D.ff.inverse_form(D.Bf, D.fB)));
    const auto [again, response] = solve(omega);
    return condensed(again, response);
  };
  // At ω = 0 the damping does not enter: the solve that gives the drag's
  // transfer gives K_dyn(0) too.
  std::optional<Matrix3cd> at_rest;
  if (!end_B_velocity_covariance.isZero(0.0)) {
    const auto [D, response] = solve(0.0);
    at_rest = condensed(D, response);
    linearize_drag_on_motion(line, dofs, response, end_B_velocity_covariance, state.state);
  }

  std::vector<Matrix3cd> out;
  for (const double omega : omegas_rad_per_s) {
    if (!(omega >= 0.0)) throw SolverError(fmt::format("end_B_dynamic_stiffness: omega must be >= 0, got {}", omega));
    if (omega == 0.0 && at_rest) {
      out.push_back(*at_rest);
      continue;
    }
    out.push_back(condensed_at(omega));
  }
  return out;
}

}  // namespace spiral::engine
