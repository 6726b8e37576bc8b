// solve_catenary fails clearly: SolverError (never NaN) whose message names the
// cause or the offending field.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "engine/lines/catenary.hpp"

namespace spiral::engine {
namespace {

CatenaryLine chain(double L = 500.0) {
  CatenaryLine line;
  line.segments = {{L, 1000.0, 5e8}};
  return line;
}

// Runs the solver and returns the SolverError's message ("" if none was thrown).
std::string error_of(const CatenaryLine& line, const CatenaryGeometry& g, const CatenaryOptions& o = {}) {
  try {
    solve_catenary(line, g, o);
  } catch (const SolverError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_MESSAGE_HAS(message, word) \
  EXPECT_NE((message).find(word), std::string::npos) << "message: '" << (message) << "'"

TEST(CatenaryErrors, LineTooShortForItsSpan) {
  // Chord 600 m on a 400 m line: mean strain 50 % > max_strain 30 %.
  const std::string m = error_of(chain(400.0), {480.0, 360.0, 0.0});
  EXPECT_MESSAGE_HAS(m, "line too short for its span");
  EXPECT_MESSAGE_HAS(m, "needs mean strain 50.00 %");
}

TEST(CatenaryErrors, InvalidSegmentData) {
  CatenaryLine line = chain();
  line.segments[0].length_m = -20.0;
  EXPECT_MESSAGE_HAS(error_of(line, {300.0, 100.0, 0.0}), "segments[0].length_m");
  line = chain();
  line.segments[0].EA_N = 0.0;
  EXPECT_MESSAGE_HAS(error_of(line, {300.0, 100.0, 0.0}), "segments[0].EA_N");
  line = chain();
  line.segments[0].weight_N_per_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_MESSAGE_HAS(error_of(line, {300.0, 100.0, 0.0}), "segments[0].weight_N_per_m");
  line = chain();
  line.seabed_friction = -0.1;
  EXPECT_MESSAGE_HAS(error_of(line, {300.0, 100.0, 0.0}), "seabed_friction");
  line = chain();
  line.segments.push_back({100.0, 100.0, 1e8});
  line.joint_load_N = {1.0, 2.0};
  EXPECT_MESSAGE_HAS(error_of(line, {300.0, 100.0, 0.0}), "joint_load_N");
  line.joint_load_N = {std::numeric_limits<double>::infinity()};
  EXPECT_MESSAGE_HAS(error_of(line, {300.0, 100.0, 0.0}), "joint_load_N[0]");
  EXPECT_MESSAGE_HAS(error_of(CatenaryLine{}, {300.0, 100.0, 0.0}), "segments");
}

TEST(CatenaryErrors, InvalidGeometryAndOptions) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_MESSAGE_HAS(error_of(chain(), {-1.0, 100.0, 0.0}), "horizontal_span_m");
  EXPECT_MESSAGE_HAS(error_of(chain(), {nan, 100.0, 0.0}), "horizontal_span_m");
  EXPECT_MESSAGE_HAS(error_of(chain(), {300.0, nan, 0.0}), "vertical_span_m");
  EXPECT_MESSAGE_HAS(error_of(chain(), {300.0, 100.0, -5.0}), "anchor_height_above_seabed_m");
  EXPECT_MESSAGE_HAS(error_of(chain(), {300.0, -10.0, 0.0}), "fairlead must be above the seabed");
  CatenaryOptions o;
  o.tolerance_m = 0.0;
  EXPECT_MESSAGE_HAS(error_of(chain(), {300.0, 100.0, 0.0}, o), "tolerance_m");
  o = {};
  o.max_iterations = 0;
  EXPECT_MESSAGE_HAS(error_of(chain(), {300.0, 100.0, 0.0}, o), "max_iterations");
}

TEST(CatenaryErrors, BuoyantSegmentOnSeabed) {
  // Buoyant segment at the anchor, heavy chain above, slack: the chain's sag
  // would push the buoyant part onto the seabed.
  CatenaryLine line;
  line.segments = {{300.0, -200.0, 1e8}, {700.0, 1500.0, 8e8}};
  const std::string m = error_of(line, {500.0, 150.0, 0.0});
  EXPECT_MESSAGE_HAS(m, "segments[0] is buoyant");
  EXPECT_MESSAGE_HAS(m, "seabed");
}

TEST(CatenaryErrors, BuoyOnSeabed) {
  CatenaryLine line;
  line.segments = {{300.0, 800.0, 8e8}, {700.0, 800.0, 8e8}};
  line.joint_load_N = {-5e4};
  const std::string m = error_of(line, {500.0, 150.0, 0.0});
  EXPECT_MESSAGE_HAS(m, "buoy at joint_load_N[0]");
}

TEST(CatenaryErrors, NonConvergenceReportsIterationsAndResidual) {
  CatenaryOptions o;
  o.max_iterations = 1;
  o.tolerance_m = 1e-12;
  try {
    solve_catenary(chain(), {480.0, 50.0, 30.0}, o);
    GTEST_SKIP() << "converged in one step; nothing to report";
  } catch (const SolverError& e) {
    const std::string m = e.what();
    EXPECT_MESSAGE_HAS(m, "no convergence after");
    EXPECT_MESSAGE_HAS(m, "residual");
    EXPECT_GT(e.diagnostics().iterations, 0);
    EXPECT_EQ(e.diagnostics().residual_unit, "m");
    EXPECT_TRUE(std::isfinite(e.diagnostics().residual));
  }
}

}  // namespace
}  // namespace spiral::engine
