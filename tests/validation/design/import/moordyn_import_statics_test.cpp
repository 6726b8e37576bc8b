// The imported MoorDyn decks reproduce the catenary statics of published or
// independent solutions, through the whole import path (deck reader ->
// project -> resolved line types -> the engine catenary spiral statics uses):
//
//  - OC4-DeepCwind (tests/data/validation/oc4/, OpenFAST r-test): the MoorDyn
//    deck's three lines against MAP++'s static solution of the same mooring
//    (the .sum of the MAP++ deck). The MoorDyn deck gives no seabed friction
//    and MAP++ uses CB = 1.0 (MAP deck), so the test sets friction_axial = 1
//    as the MAP deck does; everything else comes from the MoorDyn deck.
//  - IEA-15 / VolturnUS-S (tests/data/validation/iea15-umaine-semi/): no
//    published fairlead tension of this deck is in the repository, so its
//    three lines are checked against the independent closed-form elastic
//    catenary of tests/support/elastic_catenary_reference.hpp (frictionless
//    seabed, as the deck), with the weight computed here from the deck's
//    numbers, not through spiral's line-type code.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "design/import/moordyn_deck.hpp"
#include "design/import/moordyn_import.hpp"
#include "design/model/mooring_model.hpp"
#include "engine/lines/catenary.hpp"
#include "support/elastic_catenary_reference.hpp"
#include "support/expect_near.hpp"
#include "support/map_summary.hpp"

namespace spiral::design {
namespace {

// MAP++ closes its spans to its own loose tolerance (lines 1 and 3, the same
// geometry, differ by 2.5e-6 in the .sum): the bound of the engine's own MAP++
// test (tests/validation/engine/lines/catenary_map_oc4_test.cpp).
constexpr double kMapRelTol = 2e-5;
// Both solvers converge to ~1e-11 of the line length; 1e-7 leaves room for the
// conditioning of a 3.27e9 N EA line without hiding a wrong weight (a 1 mm
// diameter error moves H by ~1e-3).
constexpr double kAnalyticRelTol = 1e-7;

using test::read_map_sum;

const std::string kData = std::string(SPIRAL_TEST_DATA_DIR) + "/validation/";

TEST(MoorDynImportStatics, Oc4LinesMatchMapPlusPlus) {
  // 200 m: the MAP++ deck's depth (the MoorDyn deck takes it from HydroDyn).
  MoorDynImport imported =
      import_moordyn(read_moordyn_deck(kData + "oc4/NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat"), {200.0, ""});
  Project& project = imported.project;
  project.site.seabed.friction_axial = 1.0;  // MAP deck CB
  const std::vector<LineTypeProperties> types = resolve_line_types(project);
  const auto map = read_map_sum(kData + "oc4/5MW_OC4Semi_WSt_WavesWN_simpler.macos-gnu.MAP.sum");
  ASSERT_EQ(map.size(), 3u);
  ASSERT_EQ(project.mooring.lines.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const MooringLine& line = project.mooring.lines[i];
    SCOPED_TRACE(line.name);
    const engine::CatenarySolution s =
        engine::solve_catenary(catenary_of(project, line, types), catenary_geometry_at_rest(project, line));
    EXPECT_REL_NEAR(s.fairlead_horizontal_N, map[i].H_N, kMapRelTol);
    EXPECT_REL_NEAR(s.fairlead_vertical_N, map[i].V_N, kMapRelTol);
    EXPECT_REL_NEAR(s.fairlead_tension_N, map[i].T_N, kMapRelTol);
    EXPECT_REL_NEAR(s.anchor_horizontal_N, map[i].HAnch_N, kMapRelTol);
    EXPECT_REL_NEAR(s.laid_length_m, map[i].Lb_m, kMapRelTol);
  }
}

TEST(MoorDynImportStatics, Iea15LinesMatchTheClosedFormElasticCatenary) {
  const MoorDynImport imported =
      import_moordyn(read_moordyn_deck(kData + "iea15-umaine-semi/IEA-15-240-RWT-UMaineSemi_MoorDyn.dat"));
  const Project& project = imported.project;
  const std::vector<LineTypeProperties> types = resolve_line_types(project);
  // The deck: 685 kg/m, d = 0.333 m, EA 3.27e9 N, 850 m; MoorDyn's defaults
  // rho 1025 kg/m³, g 9.80665 m/s²; anchors at radius 837.6 m, 200 m deep;
  // fairleads at radius 58 m, z = -14 m.
  const double w_N_per_m = (685.0 - 1025.0 * std::numbers::pi / 4.0 * 0.333 * 0.333) * 9.80665;
  const double XF_m = 837.6 - 58.0, ZF_m = 200.0 - 14.0;
  const test::ElasticCatenaryReference reference =
      test::solve_elastic_catenary(850.0, w_N_per_m, 3.27e9, XF_m, ZF_m, true);
  ASSERT_EQ(project.mooring.lines.size(), 3u);
  for (const MooringLine& line : project.mooring.lines) {
    SCOPED_TRACE(line.name);
    const engine::CatenaryGeometry geometry = catenary_geometry_at_rest(project, line);
    EXPECT_REL_NEAR(geometry.horizontal_span_m, XF_m, 1e-6);  // the deck prints 50.229 for 58 sin 60°
    const engine::CatenarySolution s = engine::solve_catenary(catenary_of(project, line, types), geometry);
    // Each line at its own printed span: the reference at that span.
    const test::ElasticCatenaryReference r =
        test::solve_elastic_catenary(850.0, w_N_per_m, 3.27e9, geometry.horizontal_span_m, ZF_m, true);
    EXPECT_REL_NEAR(s.fairlead_horizontal_N, r.H_N, kAnalyticRelTol);
    EXPECT_REL_NEAR(s.fairlead_vertical_N, r.V_N, kAnalyticRelTol);
    EXPECT_REL_NEAR(s.laid_length_m, r.laid_length_m, kAnalyticRelTol);
    // And all three near the nominal geometry's solution (printed positions).
    EXPECT_REL_NEAR(s.fairlead_tension_N, reference.fairlead_tension_N, 1e-4);
  }
  std::cout << "[ IEA-15  ] fairlead tension " << reference.fairlead_tension_N / 1e3 << " kN, H " << reference.H_N / 1e3
            << " kN, laid " << reference.laid_length_m << " m\n";
}

}  // namespace
}  // namespace spiral::design
