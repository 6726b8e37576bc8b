// The complex band LU without interchanges (engine/common/complex_band_lu.hpp):
// it solves what a dense pivoting LU solves on the band matrices it is for,
// and refuses a matrix whose elimination would need an interchange.
#include "engine/common/complex_band_lu.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

namespace spiral::engine {
namespace {

using Complex = std::complex<double>;

// A chain of springs and dashpots between neighbours up to b apart, grounded:
// K − ω² M + iω C with K, C symmetric positive definite and ω² M below the
// smallest stiffness — the kind of matrix an FE line gives at low frequency.
Eigen::MatrixXcd low_frequency_dynamic_stiffness(int n, int b, double omega, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.5, 2.0);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), C = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    K(i, i) += 0.1 * u(rng);  // grounding
    for (int j = i + 1; j <= std::min(n - 1, i + b); ++j) {
      const double k = u(rng), c = 0.1 * u(rng);
      K(i, i) += k, K(j, j) += k, K(i, j) -= k, K(j, i) -= k;
      C(i, i) += c, C(j, j) += c, C(i, j) -= c, C(j, i) -= c;
    }
  }
  Eigen::MatrixXcd D = K.cast<Complex>() + Complex(0.0, omega) * C.cast<Complex>();
  for (int i = 0; i < n; ++i) D(i, i) -= omega * omega * 0.01;
  return D;
}

ComplexBandLu band_of(const Eigen::MatrixXcd& A, int b) {
  ComplexBandLu band(static_cast<int>(A.rows()), b);
  for (int i = 0; i < A.rows(); ++i)
    for (int j = std::max(0, i - b); j <= std::min<int>(static_cast<int>(A.rows()) - 1, i + b); ++j)
      band.at(i, j) = A(i, j);
  return band;
}

// Against Eigen's dense partial-pivoting LU, three right-hand sides at once,
// to 1e-12 relative (the matrices are well conditioned: round-off only).
TEST(ComplexBandLu, SolvesAsADensePivotingLuDoes) {
  std::mt19937 rng(7);
  for (const auto& [n, b, omega] : {std::tuple{12, 2, 0.0}, std::tuple{60, 11, 0.1}, std::tuple{200, 5, 1.0}}) {
    const Eigen::MatrixXcd A = low_frequency_dynamic_stiffness(n, b, omega, rng);
    const Eigen::Matrix<Complex, Eigen::Dynamic, 3> rhs = Eigen::Matrix<Complex, Eigen::Dynamic, 3>::Random(n, 3);
    ComplexBandLu band = band_of(A, b);
    ASSERT_TRUE(band.factorize());
    Eigen::Matrix<Complex, Eigen::Dynamic, 3> x = rhs;
    band.solve_in_place(x);
    const Eigen::Matrix<Complex, Eigen::Dynamic, 3> reference = A.partialPivLu().solve(rhs);
    EXPECT_LE((x - reference).norm(), 1e-12 * reference.norm()) << n << " DOFs, half band " << b;
  }
}

// A pivot that elimination makes zero (the matrix needs a row interchange
// there) is refused: here the second, after the first column's elimination.
TEST(ComplexBandLu, RefusesAMatrixThatNeedsAnInterchange) {
  Eigen::MatrixXcd A(3, 3);
  A << 1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 2.0;
  ComplexBandLu band = band_of(A, 1);
  EXPECT_FALSE(band.factorize());
}

}  // namespace
}  // namespace spiral::engine
