// The OPTIONS an exported deck carries for both MoorDyn programs: MoorDyn-C
// v2.7.1 skips `rhoW`, `mu_kA` and `mu_kT` (MoorDyn-F's names) with a warning
// and took its default density and no friction, and without a dtM its own
// CFL-0.5 step made the exported OC4 deck diverge at 0.14 s (run on
// 2026-12-02, docs/moordyn.md "Run in MoorDyn"). The deck now names the
// density and friction both ways and writes a dtM.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "design/import/moordyn_deck.hpp"
#include "design/import/moordyn_export.hpp"
#include "design/import/moordyn_import.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {
namespace {

ValidatedProject oc4() {
  return load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
}

bool has_line(const std::string& deck, const std::string& line_start) {
  return deck.find("\n" + line_start) != std::string::npos;
}

TEST(MoorDynExportOptions, DensityAndFrictionUnderMoorDynCAndMoorDynFNames) {
  const ValidatedProject p = oc4();
  const std::string deck = export_moordyn(p.project, p.line_types);
  EXPECT_TRUE(has_line(deck, "1025  rho  ")) << deck;
  EXPECT_TRUE(has_line(deck, "1025  rhoW  "));
  EXPECT_TRUE(has_line(deck, "1  FrictionCoefficient  "));  // OC4: 1.0 both ways
  EXPECT_TRUE(has_line(deck, "1  mu_kA  "));
  EXPECT_TRUE(has_line(deck, "1  mu_kT  "));
  EXPECT_EQ(deck.find("isotropic FrictionCoefficient: the axial"), std::string::npos);  // no note: equal
}

TEST(MoorDynExportOptions, TimeStepIsAFifthOfTheShortestAxialTransitRoundedDown) {
  const ValidatedProject p = oc4();
  const std::string deck = export_moordyn(p.project, p.line_types);
  // OC4: 835.35 m in 84 elements of 9.945 m; c = √(7.536e8 / 113.35) =
  // 2578.5 m/s; l/c = 3.857 ms; 0.2 of it 0.771 ms -> 0.0007 s.
  const double l_m = 835.35 / 84.0, c_m_per_s = std::sqrt(7.536e8 / 113.35);
  EXPECT_NEAR(kExportTimeStepFraction * l_m / c_m_per_s, 0.000771, 1e-6);
  EXPECT_TRUE(has_line(deck, "0.0007  dtM  ")) << deck;
}

TEST(MoorDynExportOptions, UnequalFrictionWritesTheAxialOneForMoorDynCWithANote) {
  Project project = oc4().project;
  project.site.seabed.friction_axial = 0.6;
  project.site.seabed.friction_lateral = 1.2;
  const ValidatedProject p = validate_loaded_project(project);
  const std::string deck = export_moordyn(p.project, p.line_types);
  EXPECT_TRUE(has_line(deck, "0.6  FrictionCoefficient  "));
  EXPECT_TRUE(has_line(deck, "0.6  mu_kA  "));
  EXPECT_TRUE(has_line(deck, "1.2  mu_kT  "));
  EXPECT_NE(deck.find("spiral note: MoorDyn-C has one isotropic FrictionCoefficient: the axial 0.6 is written, "
                      "not the lateral 1.2"),
            std::string::npos);
  // spiral's own import keeps MoorDyn-F's pair (the more detailed one).
  const MoorDynImport back = import_moordyn(parse_moordyn_deck(deck, "exported.dat"));
  EXPECT_EQ(back.project.site.seabed.friction_axial, 0.6);
  EXPECT_EQ(back.project.site.seabed.friction_lateral, 1.2);
}

}  // namespace
}  // namespace spiral::design
