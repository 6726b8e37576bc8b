#pragma once
// Relative comparisons of doubles and Eigen objects for GoogleTest, with
// failure messages that show both values, the difference, the allowed
// difference and the tolerance, so a failing validation explains itself.
//
//   EXPECT_REL_NEAR(actual, expected, rel_tol);
//       |actual - expected| <= rel_tol * |expected|   (expected == 0: exact)
//   EXPECT_REL_NEAR_SCALE(actual, expected, rel_tol, scale);
//       |actual - expected| <= rel_tol * |scale|       (for values that may be ~0)
//   EXPECT_EIGEN_REL_NEAR(actual, expected, rel_tol);
//       max|actual - expected| <= rel_tol * max|expected|, element-wise report

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace spiral::test {

inline ::testing::AssertionResult rel_near_scale(const char* actual_expr, const char* expected_expr,
                                                 const char* /*tol_expr*/, const char* scale_expr, double actual,
                                                 double expected, double rel_tol, double scale) {
  const double diff = std::abs(actual - expected);
  const double allowed = rel_tol * std::abs(scale);
  if (std::isfinite(actual) && diff <= allowed) return ::testing::AssertionSuccess();
  std::ostringstream m;
  m.precision(17);
  m << actual_expr << " = " << actual << "\n  expected " << expected_expr << " = " << expected
    << "\n  |difference| = " << diff << " > allowed " << allowed << " (relative tolerance " << rel_tol << " of "
    << scale_expr << " = " << scale << "; relative difference " << (scale != 0.0 ? diff / std::abs(scale) : diff)
    << ")";
  return ::testing::AssertionFailure() << m.str();
}

inline ::testing::AssertionResult rel_near(const char* actual_expr, const char* expected_expr, const char* tol_expr,
                                           double actual, double expected, double rel_tol) {
  return rel_near_scale(actual_expr, expected_expr, tol_expr, "|expected|", actual, expected, rel_tol, expected);
}

template <typename A, typename B>
::testing::AssertionResult eigen_rel_near(const char* actual_expr, const char* expected_expr, const char* /*tol_expr*/,
                                          const Eigen::MatrixBase<A>& actual, const Eigen::MatrixBase<B>& expected,
                                          double rel_tol) {
  if (actual.rows() != expected.rows() || actual.cols() != expected.cols()) {
    return ::testing::AssertionFailure() << actual_expr << " is " << actual.rows() << "x" << actual.cols() << " but "
                                         << expected_expr << " is " << expected.rows() << "x" << expected.cols();
  }
  const double scale = expected.cwiseAbs().maxCoeff();
  const double allowed = rel_tol * scale;
  const auto diff = (actual.derived().template cast<double>() - expected.derived().template cast<double>()).eval();
  const double worst = diff.cwiseAbs().maxCoeff();
  if (actual.allFinite() && worst <= allowed) return ::testing::AssertionSuccess();
  std::ostringstream m;
  m.precision(12);
  const Eigen::IOFormat fmt(Eigen::StreamPrecision, 0, ", ", "\n", "    [", "]");
  m << actual_expr << " differs from " << expected_expr << ": max |difference| = " << worst << " > allowed " << allowed
    << " (relative tolerance " << rel_tol << " of max|expected| = " << scale << ")\n  actual:\n"
    << actual.format(fmt) << "\n  expected:\n"
    << expected.format(fmt) << "\n  difference:\n"
    << diff.format(fmt);
  return ::testing::AssertionFailure() << m.str();
}

}  // namespace spiral::test

#define EXPECT_REL_NEAR(actual, expected, rel_tol) \
  EXPECT_PRED_FORMAT3(::spiral::test::rel_near, actual, expected, rel_tol)
#define ASSERT_REL_NEAR(actual, expected, rel_tol) \
  ASSERT_PRED_FORMAT3(::spiral::test::rel_near, actual, expected, rel_tol)
#define EXPECT_REL_NEAR_SCALE(actual, expected, rel_tol, scale) \
  EXPECT_PRED_FORMAT4(::spiral::test::rel_near_scale, actual, expected, rel_tol, scale)
#define EXPECT_EIGEN_REL_NEAR(actual, expected, rel_tol) \
  EXPECT_PRED_FORMAT3(::spiral::test::eigen_rel_near, actual, expected, rel_tol)
