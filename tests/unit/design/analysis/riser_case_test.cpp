// Risers in the coupled static case: the default scenario's risers at rest
// leave the hull at their design angles, their loads balance the hull's
// deballast, and a riser that cannot reach the seabed is an input error.
#include <gtest/gtest.h>

#include "design/project/input_error.hpp"
#include "design/analysis/static_case.hpp"

namespace spiral::design {
namespace {

ValidatedProject deepwater() {
  return load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
}

TEST(RiserCase, RisersAtRestLeaveAtTheirDesignAngles) {
  const auto project = deepwater();
  const auto result = run_static_case(project, {});
  ASSERT_EQ(result.risers.size(), 12u);
  for (std::size_t i = 0; i < result.risers.size(); ++i) {
    const double design_deg = project.project.risers[i].top_angle_rad * 180.0 / 3.141592653589793;
    // The foot is placed with the catenary (no bending); the FE riser's
    // bending stiffness and the hull's tiny rest offset move the angle by
    // hundredths of a degree.
    EXPECT_NEAR(result.risers[i].top_angle_deg, design_deg, 0.1) << result.risers[i].name;
    EXPECT_GT(result.risers[i].min_effective_tension_N, 0.0);
    EXPECT_TRUE(result.risers[i].passes) << result.risers[i].governing_criterion;
  }
  // The scenario's ballast was set for these riser and mooring loads
  // (reference-platforms.md §2.4): the hull floats within centimetres of its draft.
  EXPECT_LT(std::abs(result.offset_summary.heave_m), 0.05);
}

TEST(RiserCase, RiserThatCannotReachTheSeabedIsAnInputError) {
  auto project = deepwater();
  project.project.risers[0].sections[0].length_m = 1500.0;  // 1772 m of water below the hang-off
  try {
    run_static_case(project, {});
    FAIL();
  } catch (const InputError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("risers[0].sections"), std::string::npos) << text;
    EXPECT_NE(text.find("does not reach the seabed"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace spiral::design
