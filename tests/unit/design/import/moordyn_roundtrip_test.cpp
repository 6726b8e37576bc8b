// import(export(p)) gives p's mooring lines back: both shipped scenarios
// (OC4: one chain type, 3 single-segment lines; deep-water FPS: chain -
// polyester - chain lines with formula-derived types, and 12 SCRs exported as
// MoorDyn lines with their EI) written as a MoorDyn v2 deck and read back.
// Numbers are printed as the shortest text that reads back to the same
// double, so lines, segments, positions and the resolved line-type values
// come back to the last bit (EXPECT_DOUBLE_EQ: 4 ulp, for the one value
// recomputed on import, the submerged weight).
#include <gtest/gtest.h>

#include <string>

#include "design/import/moordyn_deck.hpp"
#include "design/import/moordyn_export.hpp"
#include "design/import/moordyn_import.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/project_loader.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {
namespace {

ValidatedProject scenario_project(const std::string& scenario) {
  return load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/" + scenario);
}

void expect_round_trip(const ValidatedProject& original) {
  SCOPED_TRACE(original.project.name);
  const std::string deck = export_moordyn(original.project, original.line_types);
  const MoorDynImport back = import_moordyn(parse_moordyn_deck(deck, "exported.dat"));
  const Project& p = original.project;
  const Project& q = back.project;
  EXPECT_EQ(q.site.depth_m, p.site.depth_m);
  EXPECT_EQ(q.site.gravity_m_per_s2, p.site.gravity_m_per_s2);
  EXPECT_EQ(q.site.water_density_kg_per_m3, p.site.water_density_kg_per_m3);
  EXPECT_EQ(q.site.seabed.friction_axial, p.site.seabed.friction_axial);
  EXPECT_EQ(q.site.seabed.friction_lateral, p.site.seabed.friction_lateral);
  EXPECT_EQ(q.site.seabed.normal_stiffness_Pa_per_m, p.site.seabed.normal_stiffness_Pa_per_m);
  EXPECT_TRUE(back.placeholder_breaking_loads.empty());  // the MBL comes back through the front matter
  ASSERT_EQ(q.mooring.lines.size(), p.mooring.lines.size());
  const std::vector<LineTypeProperties> types = resolve_line_types(q);
  for (std::size_t i = 0; i < p.mooring.lines.size(); ++i) {
    const MooringLine& a = p.mooring.lines[i];
    const MooringLine& b = q.mooring.lines[i];
    SCOPED_TRACE(a.name);
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.anchor_g, a.anchor_g);
    EXPECT_EQ(b.fairlead_b, a.fairlead_b);
    EXPECT_EQ(b.fe.element_length_m, a.fe.element_length_m);
    ASSERT_EQ(b.segments.size(), a.segments.size());
    for (std::size_t k = 0; k < a.segments.size(); ++k) {
      EXPECT_EQ(b.segments[k].type, a.segments[k].type);
      EXPECT_EQ(b.segments[k].length_m, a.segments[k].length_m);
      const LineTypeProperties& ta = find_type(original.line_types, a.segments[k].type);
      const LineTypeProperties& tb = find_type(types, b.segments[k].type);
      EXPECT_EQ(tb.hydrodynamic_diameter_m, ta.hydrodynamic_diameter_m);
      EXPECT_EQ(tb.mass_per_length_kg_per_m, ta.mass_per_length_kg_per_m);
      EXPECT_DOUBLE_EQ(tb.submerged_weight_N_per_m, ta.submerged_weight_N_per_m);
      EXPECT_EQ(tb.axial_stiffness_N, ta.axial_stiffness_N);
      EXPECT_EQ(tb.breaking_load_N, ta.breaking_load_N);
      EXPECT_EQ(tb.drag_normal, ta.drag_normal);
      EXPECT_EQ(tb.drag_axial, ta.drag_axial);
      EXPECT_EQ(tb.added_mass_normal, ta.added_mass_normal);
      EXPECT_EQ(tb.added_mass_axial, ta.added_mass_axial);
    }
    ASSERT_EQ(b.attachments.size(), a.attachments.size());
    for (std::size_t k = 0; k < a.attachments.size(); ++k) {
      EXPECT_EQ(b.attachments[k].after_segment, a.attachments[k].after_segment);
      EXPECT_EQ(b.attachments[k].kind, a.attachments[k].kind);
      EXPECT_EQ(b.attachments[k].mass_kg, a.attachments[k].mass_kg);
      EXPECT_EQ(b.attachments[k].volume_m3, a.attachments[k].volume_m3);
    }
  }
  // The risers went out as MoorDyn lines (with EI) and are named, not re-imported as mooring.
  for (const Riser& riser : p.risers) {
    EXPECT_NE(deck.find("spiral: riser " + riser.name + " lines"), std::string::npos) << riser.name;
    bool noted = false;
    for (const std::string& note : back.notes)
      noted |= note.find("spiral riser " + riser.name + " ") != std::string::npos;
    EXPECT_TRUE(noted) << riser.name;
  }
  // The written project validates.
  EXPECT_NO_THROW(validate_loaded_project(parse_project(moordyn_import_yaml(back, "exported.dat"), "back.yaml")));
}

TEST(MoorDynRoundTrip, Oc4Scenario) { expect_round_trip(scenario_project("oc4-semisubmersible.yaml")); }
TEST(MoorDynRoundTrip, DeepwaterScenarioWithRisers) { expect_round_trip(scenario_project("deepwater-fps.yaml")); }

// Joints with a clump and a buoy become Free points with mass and volume and come back.
TEST(MoorDynRoundTrip, AttachmentsAtJoints) {
  ValidatedProject p = scenario_project("oc4-semisubmersible.yaml");
  MooringLine& line = p.project.mooring.lines[0];
  line.segments = {{"chain76", 300.0}, {"chain76", 235.35}, {"chain76", 300.0}};
  line.attachments = {{0, AttachmentKind::clump, 5000.0, 0.25}, {1, AttachmentKind::buoy, 800.0, 12.5}};
  line.fe.element_length_m = 7.5;
  expect_round_trip(validate_loaded_project(p.project));
}

TEST(MoorDynExport, RisersCarryTheirBendingStiffness) {
  const ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  const MoorDynDeck deck = parse_moordyn_deck(export_moordyn(p.project, p.line_types), "exported.dat");
  EXPECT_EQ(deck.format_version, 2);
  int risers_with_EI = 0;
  for (const MoorDynLineType& t : deck.line_types) risers_with_EI += t.EI_N_m2 > 0.0;
  EXPECT_GE(risers_with_EI, static_cast<int>(p.project.risers.size()));
  // One MoorDyn line per segment and per riser section.
  std::size_t pieces = 0;
  for (const MooringLine& line : p.project.mooring.lines) pieces += line.segments.size();
  for (const Riser& riser : p.project.risers) pieces += riser.sections.size();
  EXPECT_EQ(deck.lines.size(), pieces);
}

}  // namespace
}  // namespace spiral::design
