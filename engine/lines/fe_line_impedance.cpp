#include "engine/lines/fe_line_impedance.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <fmt/format.h>

#include "engine/common/solver_error.hpp"
#include "engine/lines/fe_dynamic_line.hpp"

namespace spiral::engine {

std::vector<Matrix3cd> end_B_dynamic_stiffness(const FeLineModel& model, const FeDynamicEnvironment& environment,
                                               const FeStaticsResult& state, std::span<const double> omegas_rad_per_s) {
  using Complex = std::complex<double>;
  fe_detail::DynamicLine line;
  FeDynamicsOptions options;
  options.end_B = FeEndCondition::fixed;                // its DOFs are the input X below
  line.initialize(model, environment, state, options);  // evaluates every element's M, C, K at rest

  // Free DOFs numbered 0.. for the sparse system; end B's three position DOFs apart.
  const int end_B = line.p.r_dof.back();
  std::vector<int> index(static_cast<std::size_t>(line.n), -1);
  int free_count = 0;
  for (int i = 0; i < line.n; ++i) {
    if (!line.fixed(i)) index[static_cast<std::size_t>(i)] = free_count++;
  }
  auto input_of = [&](int dof) { return dof >= end_B && dof < end_B + 3 ? dof - end_B : -1; };

  std::vector<Matrix3cd> out;
  // One ordering and symbolic analysis for every frequency: the pattern is the mesh's.
  Eigen::SparseLU<Eigen::SparseMatrix<Complex>> lu;
  bool analysed = false;
  for (const double omega : omegas_rad_per_s) {
    if (!(omega >= 0.0)) throw SolverError(fmt::format("end_B_dynamic_stiffness: omega must be >= 0, got {}", omega));
    std::vector<Eigen::Triplet<Complex>> ff;
    Eigen::Matrix<Complex, Eigen::Dynamic, 3> fB = Eigen::Matrix<Complex, Eigen::Dynamic, 3>::Zero(free_count, 3);
    Eigen::Matrix<Complex, 3, Eigen::Dynamic> Bf = Eigen::Matrix<Complex, 3, Eigen::Dynamic>::Zero(3, free_count);
    Matrix3cd BB = Matrix3cd::Zero();
    for (std::size_t e = 0; e < line.p.elements.size(); ++e) {
      const ancf::ElementDynamicMatrices& m = line.element_matrices[e];
      for (int a = 0; a < fe_detail::kElementDofs; ++a) {
        const int ga = line.element_dofs[e][static_cast<std::size_t>(a)];
        for (int b = 0; b < fe_detail::kElementDofs; ++b) {
          const int gb = line.element_dofs[e][static_cast<std::size_t>(b)];
          const auto k = static_cast<std::size_t>(fe_detail::kElementDofs * a + b);
          const Complex d(m.K[k] + omega * omega * m.M[k], omega * m.C[k]);
          const int ia = index[static_cast<std::size_t>(ga)], ib = index[static_cast<std::size_t>(gb)];
          const int xa = input_of(ga), xb = input_of(gb);
          if (ia >= 0 && ib >= 0)
            ff.emplace_back(ia, ib, d);
          else if (ia >= 0 && xb >= 0)
            fB(ia, xb) += d;
          else if (xa >= 0 && ib >= 0)
            Bf(xa, ib) += d;
          else if (xa >= 0 && xb >= 0)
            BB(xa, xb) += d;
        }
      }
    }
    Eigen::SparseMatrix<Complex> D(free_count, free_count);
    D.setFromTriplets(ff.begin(), ff.end());
    if (!analysed) {
      lu.analyzePattern(D);
      analysed = true;
    }
    lu.factorize(D);
    if (lu.info() != Eigen::Success) {
      throw SolverError(
          fmt::format("end_B_dynamic_stiffness: the line's dynamic matrix at {} rad/s is singular", omega));
    }
    const Eigen::Matrix<Complex, Eigen::Dynamic, 3> response = lu.solve(fB);
    out.push_back(-(BB - Bf * response));
  }
  return out;
}

}  // namespace spiral::engine
