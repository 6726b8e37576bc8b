// The heading rule shared by the hull's heading tables and the drift table's
// images and fill (engine/hull/heading_rule.hpp).

#include "engine/hull/heading_rule.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

TEST(HeadingRule, WrapsIntoZeroToTwoPiAndSnapsOnlyWhenAsked) {
  EXPECT_DOUBLE_EQ(wrap_0_2pi(-0.5 * kPi), 1.5 * kPi);
  EXPECT_DOUBLE_EQ(wrap_0_2pi(5.0 * kPi), kPi);
  EXPECT_DOUBLE_EQ(wrap_0_2pi(2.0 * kPi), 0.0);
  const double just_below = 2.0 * kPi - 1e-7;
  EXPECT_DOUBLE_EQ(wrap_0_2pi(just_below), just_below);
  EXPECT_DOUBLE_EQ(wrap_0_2pi(just_below, kHeadingTolerance_rad), 0.0);
}

TEST(HeadingRule, ATableCoveringTheCircleWrapsAroundAHalfCircleDoesNot) {
  // 0..345° every 15°: the wrap gap 15° equals the interior ones.
  std::vector<double> circle;
  for (int d = 0; d < 360; d += 15) circle.push_back(d * kDeg);
  EXPECT_TRUE(wraps_around(circle));
  EXPECT_NEAR(widest_interpolated_gap(circle), 15.0 * kDeg, 1e-12);
  // 0..180° every 45°: the wrap gap is 180°.
  const std::vector<double> half = {0.0, 45 * kDeg, 90 * kDeg, 135 * kDeg, 180 * kDeg};
  EXPECT_FALSE(wraps_around(half));
  EXPECT_NEAR(widest_interpolated_gap(half), 45.0 * kDeg, 1e-12);
  // Degrees written to 5 digits: a wrap gap a hair wider (1e-5°) still
  // counts, 0.1° wider does not.
  EXPECT_TRUE(wraps_around({0.0, 119.99999 * kDeg, 239.99999 * kDeg}));
  EXPECT_FALSE(wraps_around({0.0, 119.9 * kDeg, 239.9 * kDeg}));
  EXPECT_FALSE(wraps_around({1.0}));
  EXPECT_EQ(widest_interpolated_gap({1.0}), 0.0);
}

}  // namespace
}  // namespace spiral::engine
