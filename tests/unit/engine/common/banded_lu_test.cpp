// The band LU (LAPACK dgbtf2/dgbtrs layout) against a dense solve, with
// pivoting forced; a factorised matrix reset on its own storage (as each
// Newton iteration of the FE line statics does) starts from zeros and
// solves as well; the diagonal pivot rule is stable on definite matrices
// however they are scaled, and falls back to row interchanges on indefinite
// ones; a right-hand side that starts with zeros solves as a full one.
#include "engine/common/banded_lu.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

namespace spiral::engine {
namespace {

constexpr int kLower = 5, kUpper = 7;

struct Entry {
  int i, j;
  double v;
};

/// Fills the band of `band` (n × n) with random entries whose diagonal is
/// small (partial pivoting must swap rows); returns them.
std::vector<Entry> fill(BandMatrix& band, int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::vector<Entry> entries;
  for (int j = 0; j < n; ++j) {
    for (int i = std::max(0, j - kUpper); i <= std::min(n - 1, j + kLower); ++i) {
      entries.push_back({i, j, i == j ? 1e-3 * entry(random) : entry(random)});
      band.at(i, j) = entries.back().v;
    }
  }
  return entries;
}

Eigen::VectorXd ramp(int n) { return Eigen::VectorXd::LinSpaced(n, -1.0, 2.0); }

/// Solves rhs with `band` (factorised here with `pivoting`) and returns the
/// componentwise-scaled backward error max_i |A x − rhs|_i / (Σ_j |a_ij|
/// ‖x‖∞ + |rhs_i|) of the matrix `entries` describe (Higham, Accuracy and Stability
/// of Numerical Algorithms, 2nd ed., §7.1, each row against its own size):
/// a few ε for a stable LU whatever the conditioning or the scaling of the
/// rows, orders of magnitude more for a wrong factor, stale entries or pivot
/// growth.
double backward_error(BandMatrix& band, const std::vector<Entry>& entries, int n, Pivoting pivoting,
                      const Eigen::VectorXd& rhs) {
  EXPECT_TRUE(band.factorize(pivoting));
  Eigen::VectorXd x = rhs;
  band.solve_in_place(x);
  Eigen::VectorXd r = -rhs, row_sums = Eigen::VectorXd::Zero(n);
  for (const Entry& e : entries) {
    r[e.i] += e.v * x[e.j];
    row_sums[e.i] += std::abs(e.v);
  }
  return (r.array().abs() / (row_sums.array() * x.lpNorm<Eigen::Infinity>() + rhs.array().abs())).maxCoeff();
}

TEST(BandedLu, SolvesAsADenseLuWithRowSwaps) {
  constexpr int n = 300;
  BandMatrix band(n, kLower, kUpper);
  const std::vector<Entry> entries = fill(band, n, 1);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (const Entry& e : entries) dense(e.i, e.j) = e.v;
  const Eigen::VectorXd b = ramp(n);
  const Eigen::VectorXd expected = dense.partialPivLu().solve(b);
  ASSERT_TRUE(band.factorize());
  Eigen::VectorXd x = b;
  band.solve_in_place(x);
  // Both pivot the same way on these entries; the difference is round-off
  // amplified by the condition number (small diagonal: up to ~1e4).
  EXPECT_LT((x - expected).norm() / expected.norm(), 1e-10);
}

TEST(BandedLu, AResetMatrixStartsFromZeros) {
  constexpr int n = 2500;
  BandMatrix band(n, kLower, kUpper);
  const std::vector<Entry> used = fill(band, n, 2);
  EXPECT_LT(backward_error(band, used, n, Pivoting::partial, ramp(n)), 1e-13);  // the fill-in rows written too
  for (const int size : {n, n / 2, n}) {
    band.reset(size, kLower, kUpper);
    for (int j = 0; j < size; ++j)
      for (int i = std::max(0, j - kUpper - kLower); i <= std::min(size - 1, j + kLower); ++i)
        ASSERT_EQ(band.at(i, j), 0.0) << size << ": (" << i << ", " << j << ")";
    const std::vector<Entry> entries = fill(band, size, 3);
    EXPECT_LT(backward_error(band, entries, size, Pivoting::partial, ramp(size)), 1e-13);
  }
}

/// −(B Bᵀ + I)·D² with a small unsymmetric part: a negative definite band
/// matrix (the FE statics' Jacobian of the net forces, −K plus drag) whose
/// rows and columns are scaled by D over six decades (positions against
/// slopes), so that its off-diagonal entries exceed the diagonal ones.
std::vector<Entry> definite(BandMatrix& band, int n, int half_band, bool indefinite) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = j; i <= std::min(n - 1, j + half_band / 2); ++i) B(i, j) = entry(random);
  Eigen::MatrixXd A = -(B * B.transpose() + Eigen::MatrixXd::Identity(n, n));
  if (indefinite) {
    // A saddle [−1e-17 1; 1 −0.7] (Higham §9.1's example): elimination
    // without interchanges loses the −0.7 to a 1e17 pivot growth.
    const int m = n / 2;
    A.row(m).setZero();
    A.col(m).setZero();
    A.row(m + 1).setZero();
    A.col(m + 1).setZero();
    A(m, m) = -1e-17;
    A(m + 1, m + 1) = -0.7;
    A(m, m + 1) = A(m + 1, m) = 1.0;
    A(m + 1, m + 2) = A(m + 2, m + 1) = 0.5;
  }
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d[i] = std::pow(10.0, 3.0 * std::sin(0.7 * i));
  std::vector<Entry> entries;
  for (int j = 0; j < n; ++j) {
    for (int i = std::max(0, j - half_band); i <= std::min(n - 1, j + half_band); ++i) {
      const double unsymmetric = i > j ? 1e-3 * entry(random) : 0.0;
      const double v = d[i] * d[j] * (A(i, j) + unsymmetric);
      if (v == 0.0) continue;
      entries.push_back({i, j, v});
      band.at(i, j) = v;
    }
  }
  return entries;
}

// The rows differ by 1e12 in size: the backward error is measured per row.
TEST(BandedLu, DiagonalPivotsSolveADefiniteBadlyScaledMatrix) {
  constexpr int n = 600, half_band = 11;
  for (const bool indefinite : {false, true}) {
    BandMatrix band(n, half_band, half_band);
    const std::vector<Entry> entries = definite(band, n, half_band, indefinite);
    const Eigen::VectorXd b = ramp(n);
    EXPECT_LT(backward_error(band, entries, n, Pivoting::diagonal_while_definite, b), 1e-13) << indefinite;
    band.reset(n, half_band, half_band);
    definite(band, n, half_band, indefinite);
    EXPECT_LT(backward_error(band, entries, n, Pivoting::partial, b), 1e-13) << indefinite;
  }
}

// The fill-in rows are added at the first interchange, mid-factorisation for
// the saddle (the columns before it move, the solution is unchanged), and
// not at all for the definite matrix; a reset returns to the compact layout.
TEST(BandedLu, FillInRowsOnlyOnceARowInterchangeNeedsThem) {
  constexpr int n = 200, half_band = 11, compact = 2 * half_band + 1, wide = 3 * half_band + 1;
  BandMatrix band(n, half_band, half_band);
  const std::vector<Entry> definite_entries = definite(band, n, half_band, false);
  EXPECT_EQ(band.stored_diagonals(), compact);
  EXPECT_LT(backward_error(band, definite_entries, n, Pivoting::diagonal_while_definite, ramp(n)), 1e-13);
  EXPECT_EQ(band.stored_diagonals(), compact);
  band.reset(n, half_band, half_band);
  const std::vector<Entry> saddle_entries = definite(band, n, half_band, true);
  EXPECT_LT(backward_error(band, saddle_entries, n, Pivoting::diagonal_while_definite, ramp(n)), 1e-13);
  EXPECT_EQ(band.stored_diagonals(), wide);
  band.reset(n, half_band, half_band);
  EXPECT_EQ(band.stored_diagonals(), compact);
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - half_band); j <= std::min(n - 1, i + half_band); ++j) ASSERT_EQ(band.at(i, j), 0.0);
}

// The end-stiffness condensation's right-hand sides are zero but for end B's
// rows: the solve that starts below the zeros gives the full solve's result.
TEST(BandedLu, ARightHandSideStartingWithZerosSolvesAsAFullOne) {
  constexpr int n = 400, half_band = 11;
  for (const Pivoting pivoting : {Pivoting::partial, Pivoting::diagonal_while_definite}) {
    BandMatrix band(n, half_band, half_band);
    const std::vector<Entry> entries = definite(band, n, half_band, false);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    b.tail<3>() << 1.0, -2.0, 0.5;
    EXPECT_LT(backward_error(band, entries, n, pivoting, b), 1e-13);
  }
}

// Several right-hand sides at once give each column's single solve, bit for
// bit (four columns: one group of three and one alone), also as a block of a
// larger matrix.
TEST(BandedLu, ColumnsSolveAsSingleRightHandSides) {
  constexpr int n = 300, half_band = 11;
  for (const Pivoting pivoting : {Pivoting::partial, Pivoting::diagonal_while_definite}) {
    BandMatrix band(n, half_band, half_band);
    definite(band, n, half_band, true);
    ASSERT_TRUE(band.factorize(pivoting));
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, 4);
    b.col(0) = ramp(n);
    b.col(1).tail<3>() << 1.0, -2.0, 0.5;
    b(n / 2, 2) = 1.0;
    b.col(3) = -ramp(n);
    Eigen::MatrixXd together = b;
    band.solve_columns_in_place(together);
    // The same columns as the top block of a taller matrix (columns n + 5 apart).
    Eigen::MatrixXd taller = Eigen::MatrixXd::Constant(n + 5, 4, 7.0);
    taller.topRows(n) = b;
    band.solve_columns_in_place(taller.topRows(n));
    for (int c = 0; c < 4; ++c) {
      Eigen::VectorXd alone = b.col(c);
      band.solve_in_place(alone);
      for (int i = 0; i < n; ++i) ASSERT_EQ(together(i, c), alone[i]) << c << ", " << i;
      for (int i = 0; i < n; ++i) ASSERT_EQ(taller(i, c), alone[i]) << "block " << c << ", " << i;
      for (int i = n; i < n + 5; ++i) ASSERT_EQ(taller(i, c), 7.0) << "below the block " << c << ", " << i;
    }
  }
}

}  // namespace
}  // namespace spiral::engine
