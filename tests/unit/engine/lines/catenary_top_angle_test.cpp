// The catenary posed by its top angle (engine/lines/catenary_top_angle.hpp):
// the inextensible closed form of a single-segment riser, a round trip
// through solve_catenary for a lazy wave, and the error cases.
#include "engine/lines/catenary_top_angle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace spiral::engine {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// EA = 1e16 N leaves a strain of ~1e-10 at these tensions: the elastic
// solution matches the inextensible closed form to that order.
constexpr double kInextensibleEA_N = 1e16;
constexpr double kClosedFormRelTol = 1e-8;
// Round trip through the other solver: both close to ~1e-9 m on 2 km spans.
constexpr double kRoundTripAngleTol_rad = 1e-9;

TEST(CatenaryTopAngle, SingleSegmentMatchesTheInextensibleClosedForm) {
  // reference-platforms §2.5: a = Z / (1/sin θ − 1), H = w a, suspended
  // length s = a cot θ, touchdown a asinh(cot θ) from the hang-off.
  const double w = 1237.0, L = 2490.0, Z = 1772.0, theta = 12.0 * kDeg;
  const CatenaryLine line{{{L, w, kInextensibleEA_N}}, {}, 0.0};
  const TopAngleCatenary r = solve_catenary_for_top_angle(line, Z, theta);
  const double a = Z / (1.0 / std::sin(theta) - 1.0);
  const double s = a / std::tan(theta);
  const double x = a * std::asinh(1.0 / std::tan(theta)) + (L - s);
  EXPECT_NEAR(r.fairlead_horizontal_N, w * a, kClosedFormRelTol * w * a);
  EXPECT_NEAR(r.fairlead_vertical_N, w * s, kClosedFormRelTol * w * s);
  EXPECT_NEAR(r.laid_length_m, L - s, kClosedFormRelTol * L);
  EXPECT_NEAR(r.horizontal_span_m, x, kClosedFormRelTol * x);
}

TEST(CatenaryTopAngle, LazyWaveRoundTripsThroughTheCatenarySolver) {
  // Heavy – buoyant – heavy (foot first): 1500 m, 300 m at −4284 N/m, 1500 m.
  const CatenaryLine line{{{1500.0, 1237.0, 4.09e9}, {300.0, -4284.0, 4.09e9}, {1500.0, 1237.0, 4.09e9}}, {}, 0.0};
  const double Z = 1772.0, theta = 10.0 * kDeg;
  const TopAngleCatenary r = solve_catenary_for_top_angle(line, Z, theta);
  EXPECT_GT(r.laid_length_m, 0.0);
  EXPECT_LT(r.laid_length_m, 1500.0);  // the buoyant section stays suspended
  const CatenarySolution c = solve_catenary(line, {r.horizontal_span_m, Z, 0.0});
  EXPECT_NEAR(std::atan2(c.fairlead_horizontal_N, c.fairlead_vertical_N), theta, kRoundTripAngleTol_rad);
  EXPECT_NEAR(c.laid_length_m, r.laid_length_m, 1e-6);
}

TEST(CatenaryTopAngle, ImpossibleGeometriesSayWhy) {
  // Too short: 1800 m of line cannot leave the top at 60° and still reach 1772 m down.
  const CatenaryLine short_line{{{1800.0, 1237.0, 4.09e9}}, {}, 0.0};
  try {
    solve_catenary_for_top_angle(short_line, 1772.0, 60.0 * kDeg);
    FAIL();
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("too short"), std::string::npos) << e.what();
  }
  // 1 km of buoyant line between two 10 m heavy ends under a top 100 m
  // above the foot: at any top tension it stands higher than the top.
  const CatenaryLine floating{{{10.0, 1237.0, 4.09e9}, {1000.0, -4284.0, 4.09e9}, {10.0, 1237.0, 4.09e9}}, {}, 0.0};
  try {
    solve_catenary_for_top_angle(floating, 100.0, 10.0 * kDeg);
    FAIL();
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("buoyant segment would have to lie on the seabed"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace spiral::engine
