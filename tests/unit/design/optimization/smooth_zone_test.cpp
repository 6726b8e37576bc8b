// The smooth zone of the optimizer's offset constraint: exact for a circle,
// inside the polygon zone everywhere, continuous in value and slope.

#include "design/optimization/smooth_zone.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace spiral::design {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

TEST(SmoothZone, CircleIsReproduced) {
  const SmoothZone zone([](double) { return 120.0; });
  for (double deg = 0.0; deg < 360.0; deg += 7.3) {
    EXPECT_NEAR(zone.allowable_m(deg * kDegToRad), 120.0, 1e-12);
    EXPECT_NEAR(zone.slope_m_per_rad(deg * kDegToRad), 0.0, 1e-12);
  }
  EXPECT_NEAR(zone.conservatism_m(), 0.0, 1e-12);
}

/// Two risers' polygons on a 15° grid, the platform zone their minimum:
/// kinks at the grid and where the governing riser changes.
double polygon_zone(double deg) {
  const auto riser = [](double d, double phase) {
    const double grid = 15.0;
    const double k = std::floor(d / grid);
    const auto value = [&](double at) { return 100.0 + 40.0 * std::cos((at - phase) * kDegToRad); };
    const double t = (d - k * grid) / grid;
    return (1.0 - t) * value(k * grid) + t * value((k + 1.0) * grid);
  };
  return std::min(riser(deg, 0.0), riser(deg, 120.0));
}

TEST(SmoothZone, StaysInsideThePolygonZone) {
  const SmoothZone zone(polygon_zone);
  for (double deg = 0.0; deg < 360.0; deg += 0.003)
    ASSERT_LE(zone.allowable_m(deg * kDegToRad), polygon_zone(deg) + 1e-3) << deg;
  // The lowering is what the kinks cost: well below the zone's size.
  EXPECT_GT(zone.conservatism_m(), 0.0);
  EXPECT_LT(zone.conservatism_m(), 1.0);
}

TEST(SmoothZone, SlopeIsTheDerivativeAndContinuous) {
  const SmoothZone zone(polygon_zone);
  const double h = 1e-8;  // small: across a sample the second derivative jumps (C¹, not C²)
  for (double deg = 0.1; deg < 360.0; deg += 0.37) {
    const double rad = deg * kDegToRad;
    const double numeric = (zone.allowable_m(rad + h) - zone.allowable_m(rad - h)) / (2.0 * h);
    EXPECT_NEAR(zone.slope_m_per_rad(rad), numeric, 1e-4 * std::max(1.0, std::abs(numeric))) << deg;
  }
  // Across a sample boundary (0.25° steps) value and slope do not jump.
  for (double deg = 0.25; deg < 360.0; deg += 0.25) {
    const double rad = deg * kDegToRad;
    EXPECT_NEAR(zone.allowable_m(rad - 1e-9), zone.allowable_m(rad + 1e-9), 1e-6);
    EXPECT_NEAR(zone.slope_m_per_rad(rad - 1e-9), zone.slope_m_per_rad(rad + 1e-9), 1e-3);
  }
}

}  // namespace
}  // namespace spiral::design
