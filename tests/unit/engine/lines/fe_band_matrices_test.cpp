// The reduced Newton matrix's end-column solve (the coupled line's
// condensation onto its end) against the single-column solve it replaces,
// and its refactorisation from a changed column against a whole one.

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

// A coupled line's setup changes the columns of the elements that moved; the
// Cholesky factors of the columns before the first of them are kept and the
// rest refactored: the same factors as a whole factorisation, bit for bit.
void expect_refactor_from_column_as_whole(int half_band, int first_changed) {
  const int n = 200;
  NewtonMatrix partial = band_matrix(n, half_band, true);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = first_changed; j < n; ++j)
    for (int i = j; i <= std::min(n - 1, j + half_band); ++i) partial.lower(i, j) = i == j ? 5.0 * half_band : u(rng);
  NewtonMatrix whole;
  whole.reset(n, half_band);
  for (int j = 0; j < n; ++j)
    for (int i = j; i <= std::min(n - 1, j + half_band); ++i) whole.lower(i, j) = partial.lower(i, j);
  ASSERT_TRUE(partial.factorize(first_changed));
  ASSERT_TRUE(whole.factorize());
  Eigen::VectorXd x = Eigen::VectorXd::NullaryExpr(n, [&](Eigen::Index) { return u(rng); });
  Eigen::VectorXd y = x;
  partial.solve_in_place(x);
  whole.solve_in_place(y);
  for (int i = 0; i < n; ++i) EXPECT_EQ(x[i], y[i]) << "row " << i << ", first changed column " << first_changed;
  // Nothing changed since: the factors stand.
  ASSERT_TRUE(partial.factorize(n));
  Eigen::VectorXd z = Eigen::VectorXd::NullaryExpr(n, [&](Eigen::Index) { return u(rng); }), w = z;
  partial.solve_in_place(z);
  whole.solve_in_place(w);
  EXPECT_EQ(z, w);
}

TEST(NewtonMatrix, RefactorFromAChangedColumnIsTheWholeFactorisation) {
  for (int first : {1, 5, 11, 12, 90, 188, 195, 199}) {
    expect_refactor_from_column_as_whole(11, first);
    expect_refactor_from_column_as_whole(7, first);
  }
}

}  // namespace
}  // namespace spiral::engine::fe_detail
