// The enhanced S-C with the lines' dynamic reduction (LineReduction::dynamic,
// design/analysis/line_dynamic_reduction.hpp) against the coupled level on
// the default FPS's 45° cases, where the quasi-static reduction is 6–9 %
// low on the offset's standard deviation (issue 17 §1: within 5 %; lc3's
// damaged L2 also needs the catenary start of its FE statics).
//
// The coupled statistics are stored, not recomputed (a coupled 1800 s run
// takes 8 minutes): `spiral analyze scenarios/deepwater-fps.yaml --case C
// --level coupled --duration 1800` (seed 1), 2026-12-07, the build of 06685f9 —
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
  const char* name;
  double coupled_offset_std_m;
};

TEST(ScEnhancedDynamicReduction, The45DegreeCasesComeWithinFivePercentOfCoupled) {
  const ValidatedProject project =
      load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  for (const Case& c : {Case{"lc2-survival-collinear-45deg", 1.5644}, Case{"lc3-survival-45deg-damaged-L10", 1.6278},
                        Case{"lc5-operating-45deg", 0.2685}}) {
    DynamicAnalysisRequest request;
    request.load_case = c.name;
    request.level = AnalysisLevel::semi_coupled_enhanced;
    request.line_reduction = LineReduction::dynamic;
    request.duration_s = 1800.0;
    request.compute_tensions = false;
    const DynamicAnalysisResult dynamic = run_dynamic_analysis(project, request);
    ASSERT_EQ(dynamic.line_relaxations.size(), 4u) << "two per group: mooring lines and risers";
    const double std_dynamic = horizontal_offset_std_m(dynamic);
    EXPECT_NEAR(std_dynamic, c.coupled_offset_std_m, 0.05 * c.coupled_offset_std_m) << c.name;

    // The quasi-static reduction on the same sea, for contrast: more than 5 %
    // low (measured −6.3 %, −8.3 %, −8.8 %).
    request.line_reduction = LineReduction::quasi_static;
    const double std_quasi_static = horizontal_offset_std_m(run_dynamic_analysis(project, request));
    EXPECT_LT(std_quasi_static, 0.95 * c.coupled_offset_std_m) << c.name;
  }
}

}  // namespace
}  // namespace spiral::design
