// The band LU (LAPACK dgbtf2/dgbtrs layout) against a dense solve, with
// pivoting forced; and a factorised matrix reset on its own storage (as each
// Newton iteration of the FE line statics does) starts from zeros and
// solves as well.
#include "engine/common/banded_lu.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
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

/// Solves with `band` (factorised here) and returns the normwise backward
/// error ‖A x − b‖∞ / (‖A‖∞ ‖x‖∞ + ‖b‖∞) of the matrix `entries` describe
/// (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., Thm.
/// 7.1): a few ε for a stable LU whatever the conditioning of these random
/// matrices, orders of magnitude more for a wrong factor or stale entries.
double backward_error(BandMatrix& band, const std::vector<Entry>& entries, int n) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  EXPECT_TRUE(band.factorize());
  Eigen::VectorXd x = b;
  band.solve_in_place(x);
  Eigen::VectorXd r = -b, row_sums = Eigen::VectorXd::Zero(n);
  for (const Entry& e : entries) {
    r[e.i] += e.v * x[e.j];
    row_sums[e.i] += std::abs(e.v);
  }
  return r.lpNorm<Eigen::Infinity>() /
         (row_sums.maxCoeff() * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
}

TEST(BandedLu, SolvesAsADenseLuWithRowSwaps) {
  constexpr int n = 300;
  BandMatrix band(n, kLower, kUpper);
  const std::vector<Entry> entries = fill(band, n, 1);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (const Entry& e : entries) dense(e.i, e.j) = e.v;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
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
  EXPECT_LT(backward_error(band, used, n), 1e-13);  // the fill-in rows written too
  for (const int size : {n, n / 2, n}) {
    band.reset(size, kLower, kUpper);
    for (int j = 0; j < size; ++j)
      for (int i = std::max(0, j - kUpper - kLower); i <= std::min(size - 1, j + kLower); ++i)
        ASSERT_EQ(band.at(i, j), 0.0) << size << ": (" << i << ", " << j << ")";
    const std::vector<Entry> entries = fill(band, size, 3);
    EXPECT_LT(backward_error(band, entries, size), 1e-13);
  }
}

}  // namespace
}  // namespace spiral::engine
