// The reduced Newton matrix's end-column solve (the coupled line's
// condensation onto its end) against the single-column solve it replaces.

#include "engine/lines/fe_band_matrices.hpp"

#include <gtest/gtest.h>

#include <random>

namespace spiral::engine::fe_detail {
namespace {

// A band matrix of a line-like size; `definite`: diagonally dominant
// (Cholesky), else with a negative pivot (the band LU fallback).
NewtonMatrix band_matrix(int n, int half_band, bool definite) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  NewtonMatrix s;
  s.reset(n, half_band);
  for (int j = 0; j < n; ++j) {
    for (int i = j; i <= std::min(n - 1, j + half_band); ++i) s.lower(i, j) = i == j ? 4.0 * half_band : u(rng);
  }
  if (!definite) s.lower(n / 2, n / 2) = -1.0;
  EXPECT_TRUE(s.factorize());
  return s;
}

// Right-hand sides that are zero above the end element's rows, as the
// condensation's: the same result as three single solves, bit for bit.
void expect_same_as_single_solves(int half_band, bool definite) {
  const int n = 200, first = n - 12;
  const NewtonMatrix s = band_matrix(n, half_band, definite);
  Eigen::Matrix<double, Eigen::Dynamic, 3> x = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(n, 3);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = first; i < n; ++i) {
    for (int c = 0; c < 3; ++c) x(i, c) = u(rng);
  }
  Eigen::Matrix<double, Eigen::Dynamic, 3> fused = x;
  s.solve_end_columns(fused, first);
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd single = x.col(c);
    s.solve_in_place(single);
    for (int i = 0; i < n; ++i) EXPECT_EQ(fused(i, c), single[i]) << "row " << i << ", column " << c;
  }
}

TEST(NewtonMatrix, EndColumnsSolveAsSingleColumnsOnTheCholeskyPath) {
  expect_same_as_single_solves(11, true);  // the compile-time band of a line
  expect_same_as_single_solves(7, true);   // a run-time band
}

TEST(NewtonMatrix, EndColumnsSolveAsSingleColumnsOnTheLuPath) { expect_same_as_single_solves(11, false); }

}  // namespace
}  // namespace spiral::engine::fe_detail
