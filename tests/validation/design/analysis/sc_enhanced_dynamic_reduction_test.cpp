// The enhanced S-C with the lines' dynamic reduction (LineReduction::dynamic,
// design/analysis/line_dynamic_reduction.hpp) against the coupled level on
// every case of the default FPS and on OC4 (issue 17 §1: the offset's
// standard deviation within 5 %), where the quasi-static reduction is 6–9 %
// low in four of the FPS's five cases (lc3's damaged L2 also needs the
// catenary start of its FE statics).
//
// The coupled statistics are stored, not recomputed (a coupled 1800 s run
// takes 8 minutes): `spiral analyze scenarios/deepwater-fps.yaml --case C
// --level coupled --duration 1800` (seed 1), 2026-12-07, the build of 06685f9,
// and OC4's `--case intact-raft-jonswap --duration 1200` —
// the horizontal offset sqrt(surge² + sway²) of the whole record. A change
// of the coupled level that moves them must update them here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "design/analysis/dynamic_analysis.hpp"

namespace spiral::design {
namespace {

double horizontal_offset_std_m(const DynamicAnalysisResult& r) {
  const Eigen::ArrayXd offset = (r.total.row(0).array().square() + r.total.row(1).array().square()).sqrt();
  return std::sqrt((offset - offset.mean()).square().mean());
}

struct Case {
  const char* scenario;
  const char* name;
  double duration_s;
  double coupled_offset_std_m;
  bool quasi_static_misses;  ///< the quasi-static reduction is more than 5 % low there
};

// Measured, dynamic reduction (quasi-static): lc1 −4.6 % (+0.1 %), lc2
// −3.5 % (−6.3 %), lc3 −3.3 % (−8.3 %), lc4 −4.5 % (−6.2 %), lc5 −1.1 %
// (−8.8 %), OC4 +1.5 % (+2.9 %).
TEST(ScEnhancedDynamicReduction, EveryCaseComesWithinFivePercentOfCoupled) {
  for (const Case& c : {Case{"deepwater-fps", "lc1-survival-collinear-0deg", 1800.0, 1.5436, false},
                        Case{"deepwater-fps", "lc2-survival-collinear-45deg", 1800.0, 1.5644, true},
                        Case{"deepwater-fps", "lc3-survival-45deg-damaged-L10", 1800.0, 1.6278, true},
                        Case{"deepwater-fps", "lc4-survival-noncollinear", 1800.0, 0.7131, true},
                        Case{"deepwater-fps", "lc5-operating-45deg", 1800.0, 0.2685, true},
                        Case{"oc4-semisubmersible", "intact-raft-jonswap", 1200.0, 1.0864, false}}) {
    const ValidatedProject project =
        load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/" + c.scenario + ".yaml");
    DynamicAnalysisRequest request;
    request.load_case = c.name;
    request.level = AnalysisLevel::semi_coupled_enhanced;
    request.line_reduction = LineReduction::dynamic;
    request.duration_s = c.duration_s;
    request.compute_tensions = false;
    const DynamicAnalysisResult dynamic = run_dynamic_analysis(project, request);
    const double std_dynamic = horizontal_offset_std_m(dynamic);
    EXPECT_NEAR(std_dynamic, c.coupled_offset_std_m, 0.05 * c.coupled_offset_std_m) << c.name;

    if (c.quasi_static_misses) {
      ASSERT_EQ(dynamic.line_relaxations.size(), 4u) << "two per group: mooring lines and risers";
      // The quasi-static reduction on the same sea, for contrast.
      request.line_reduction = LineReduction::quasi_static;
      const double std_quasi_static = horizontal_offset_std_m(run_dynamic_analysis(project, request));
      EXPECT_LT(std_quasi_static, 0.95 * c.coupled_offset_std_m) << c.name;
    }
  }
}

}  // namespace
}  // namespace spiral::design

namespace spiral::design {
namespace {

// A line with a resonance of its own in the band: the IEA 15 MW
// VolturnUS-S's 850 m chains in 200 m of water damp most near 0.13 rad/s,
// which a dashpot and relaxations cannot hold (the fit over 0.005–0.2 rad/s
// left 84 % and the offset std came out −6.8 % against coupled). The band
// is shortened from the top until the fit holds (8 frequencies, up to
// 0.088 rad/s, above 1.2× the hull's yaw natural frequency, 0.071 rad/s):
// measured +2.9 % against the coupled run made here (3 lines, 1200 s: a few
// seconds); the quasi-static reduction +6.7 %.
TEST(ScEnhancedDynamicReduction, ALineResonanceInTheBandShortensTheFittedBand) {
  const ValidatedProject project =
      load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/iea15-volturnus-s.yaml");
  DynamicAnalysisRequest request;
  request.load_case = "intact-hydrodyn-sea";
  request.duration_s = 1200.0;
  request.compute_tensions = false;
  request.level = AnalysisLevel::coupled;
  const double coupled_std_m = horizontal_offset_std_m(run_dynamic_analysis(project, request));

  request.level = AnalysisLevel::semi_coupled_enhanced;
  request.line_reduction = LineReduction::dynamic;
  const DynamicAnalysisResult dynamic = run_dynamic_analysis(project, request);
  ASSERT_EQ(dynamic.line_reduction, LineReduction::dynamic);
  bool shortened = false;
  for (const std::string& note : dynamic.notes)
    shortened = shortened || note.find("(8 frequencies, 0.005-0.0881 rad/s)") != std::string::npos;
  EXPECT_TRUE(shortened) << "the band fitted is named in the notes";
  EXPECT_NEAR(horizontal_offset_std_m(dynamic), coupled_std_m, 0.05 * coupled_std_m);

  request.line_reduction = LineReduction::quasi_static;
  EXPECT_GT(horizontal_offset_std_m(run_dynamic_analysis(project, request)), 1.05 * coupled_std_m);
}

}  // namespace
}  // namespace spiral::design
