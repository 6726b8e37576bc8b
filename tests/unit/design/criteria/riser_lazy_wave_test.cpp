// Lazy-wave risers through the project path (parse, validate, riser design,
// FE statics, criteria): typical deep-water geometries are placed at their
// design top angle with the buoyant section suspended, forming a sag bend
// and a hog bend, with a touchdown and no compression.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "design/project/project_loader.hpp"
#include "design/project/project_validation.hpp"
#include "design/criteria/riser_checks.hpp"
#include "design/model/riser_model.hpp"
#include "support/project_fixture.hpp"

namespace spiral::design {
namespace {

// The FE riser bends (EI) where the placement catenary does not: the top
// angle moves by hundredths of a degree (as for the SCRs, riser_case_test).
constexpr double kTopAngleTolerance_deg = 0.1;
// A hog worth the name: the arch rises this far above the sag bend (m). The
// geometries below give tens to hundreds of metres.
constexpr double kMinimumArchHeight_m = 10.0;

/// The minimal project in 1800 m of water with one production lazy wave
/// (the default scenario's 273.1 × 25.4 mm oil SCR pipe, w_e 1237 N/m;
/// smeared syntactic-foam modules of 1.2 m equivalent OD, 500 kg/m³: net
/// buoyancy 4.28 kN/m) hung off at 28 m.
std::string lazy_wave_project(double top_m, double buoyant_m, double bottom_m, double top_angle_deg) {
  const std::string pipe =
      "outer_diameter: 0.2731, wall_thickness: 0.0254, youngs_modulus: 2.07e11, yield_stress: "
      "4.48e8, steel_density: 7850.0, contents_density: 800.0";
  std::string text = replace(kMinimal, "  depth: 100.0\n", "  depth: 1800.0\n");
  text = replace(text, "      anchor: {radius: 500.0, azimuth_deg: 0.0}\n",
                 "      anchor: {radius: 2300.0, azimuth_deg: 180.0}\n");
  text = replace(text, "      fairlead: [10.0, 0.0, -10.0]\n", "      fairlead: [-10.0, 0.0, -10.0]\n");
  text = replace(text, "        - {type: c, length: 550.0}\n", "        - {type: c, length: 2900.0}\n");
  text += fmt::format(R"(risers:
  - name: LW
    kind: lazy_wave
    hang_off: [30.0, 0.0, -28.0]
    azimuth_deg: 0.0
    top_angle_deg: {}
    sections:
      - {{length: {}, {}}}
      - {{length: {}, {}, buoyancy_outer_diameter: 1.2, buoyancy_density: 500.0}}
      - {{length: {}, {}}}
    fe: {{element_length: 5.0, touchdown_refinement: {{length: 200.0, element_length: 1.0}}}}
)",
                      top_angle_deg, top_m, pipe, buoyant_m, pipe, bottom_m, pipe);
  return text;
}

struct LazyWaveCase {
  double top_m, buoyant_m, bottom_m, top_angle_deg;
};

class LazyWave : public ::testing::TestWithParam<LazyWaveCase> {};

TEST_P(LazyWave, PlacedWithSagAndHogBendsTouchdownAndNoCompression) {
  const LazyWaveCase c = GetParam();
  const Project project =
      parse_project(lazy_wave_project(c.top_m, c.buoyant_m, c.bottom_m, c.top_angle_deg), "lazy-wave.yaml");
  ASSERT_TRUE(check_project(project).empty());
  const RiserDesign design = riser_design(project, project.risers.front());
  auto line = riser_static_line(project, design, std::nullopt);
  const Eigen::Vector3d hang_off_g = project.hull.reference_point_g + design.hang_off_b;
  line->solve(hang_off_g);
  const engine::FeStaticsResult& solution = *line->last_result();
  const RiserStaticsRow row =
      riser_statics_row(project, design, solution, DesignCondition::normal, Eigen::Matrix3d::Identity());

  EXPECT_NEAR(row.top_angle_deg, c.top_angle_deg, kTopAngleTolerance_deg);
  ASSERT_TRUE(solution.touchdown.has_value());
  EXPECT_GT(row.min_effective_tension_N, 0.0);

  // FE order: foot section (0), buoyant section (1), top section (2).
  const std::vector<int> sections = engine::node_sections(design.fe_model, solution);
  const auto& z = solution.node_position_m;
  std::size_t hog = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (sections[i] == 1 && (hog == 0 || z[i].z() > z[hog].z())) hog = i;
  }
  ASSERT_GT(hog, 0u);
  // An interior maximum of the buoyant section: the riser rises into it from
  // the touchdown and falls out of it towards the hull.
  const auto first_buoyant = std::find(sections.begin(), sections.end(), 1) - sections.begin();
  const auto last_buoyant = std::find(sections.begin(), sections.end(), 2) - sections.begin() - 1;
  EXPECT_GT(hog, static_cast<std::size_t>(first_buoyant));
  EXPECT_LT(hog, static_cast<std::size_t>(last_buoyant));
  // The sag bend: the lowest point between the hog and the hang-off.
  const auto sag = std::min_element(z.begin() + static_cast<long>(hog), z.end(),
                                    [](const auto& a, const auto& b) { return a.z() < b.z(); });
  EXPECT_GT(z[hog].z() - sag->z(), kMinimumArchHeight_m);
  EXPECT_GT(sag->z(), -project.site.depth_m + kMinimumArchHeight_m);  // the sag is suspended
  // The touchdown lies between the foot and the hog.
  EXPECT_LT(solution.touchdown->arc_length_m, solution.node_arc_length_m[hog]);
  RecordProperty("arch_height_m", fmt::format("{:.1f}", z[hog].z() - sag->z()));
  std::printf(
      "lazy wave %.0f/%.0f/%.0f at %.0f deg: hog z %.1f m, sag z %.1f m, TDP %.1f m from the foot, "
      "T_min %.1f kN, T_top %.1f kN\n",
      c.top_m, c.buoyant_m, c.bottom_m, c.top_angle_deg, z[hog].z(), sag->z(), solution.touchdown->arc_length_m,
      row.min_effective_tension_N / 1e3, row.top_tension_N / 1e3);
}

INSTANTIATE_TEST_SUITE_P(TypicalGeometries, LazyWave,
                         ::testing::Values(LazyWaveCase{1500.0, 300.0, 1500.0, 10.0},
                                           LazyWaveCase{1300.0, 300.0, 1400.0, 10.0},
                                           LazyWaveCase{1500.0, 300.0, 1500.0, 12.0}));

TEST(LazyWave, SagBendOnTheSeabedIsAGeometryError) {
  // A 2600 m top section at 4° sags ≈ 120 m below the seabed (1772 m below
  // the hang-off) before the buoyancy lifts it: it would lie there instead.
  const Project project = parse_project(lazy_wave_project(2600.0, 300.0, 1500.0, 4.0), "lazy-wave.yaml");
  try {
    riser_design(project, project.risers.front());
    FAIL() << "expected a SolverError";
  } catch (const engine::SolverError& error) {
    EXPECT_NE(std::string(error.what()).find("below the seabed"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace spiral::design
