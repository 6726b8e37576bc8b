// The project loader: the format sample loads with the expected values, and
// each class of input error is reported with file, line, column and path.

#include "design/project/project_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include "support/project_fixture.hpp"

namespace spiral::design {
namespace {

const std::string kSample = std::string(SPIRAL_SOURCE_DIR) + "/tests/data/format-sample.yaml";

// Values are written in decimal in the file and compared after at most one
// multiplication (deg -> rad, polar -> Cartesian): a few ulp.
constexpr double kTol = 1e-12;

/// Parses `text` and returns the thrown InputError's issues (fails if none).
std::vector<InputIssue> issues_of(const std::string& text) {
  try {
    parse_project(text, "test.yaml");
  } catch (const InputError& e) {
    return e.issues();
  }
  ADD_FAILURE() << "parse_project accepted:\n" << text;
  return {};
}

TEST(ProjectLoader, MinimalProjectLoadsWithDefaults) {
  const Project p = parse_project(kMinimal, "minimal.yaml");
  EXPECT_EQ(p.name, "minimal");
  EXPECT_FALSE(p.description.has_value());
  // Anchor z defaults to the seabed.
  EXPECT_NEAR(p.mooring.lines[0].anchor_g.z(), -100.0, kTol);
  ASSERT_EQ(p.stages.size(), 3u);
  EXPECT_EQ(p.stages[0].name, "preliminary");
  ASSERT_TRUE(p.criteria.mooring.api_rp_2sk.has_value());
  EXPECT_DOUBLE_EQ(p.criteria.mooring.api_rp_2sk->intact_quasi_static, 2.00);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.api_rp_2sk->intact_dynamic, 1.67);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.api_rp_2sk->damaged_quasi_static, 1.43);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.api_rp_2sk->damaged_dynamic, 1.25);
  EXPECT_FALSE(p.criteria.mooring.dnv_os_e301.has_value());
  // Format additions for coupled statics: all optional, with documented defaults.
  EXPECT_DOUBLE_EQ(p.site.air_density_kg_per_m3, 1.225);
  EXPECT_EQ(p.mooring.lines[0].model, LineModel::catenary);
  EXPECT_DOUBLE_EQ(p.mooring.lines[0].fe.element_length_m, 10.0);
  EXPECT_FALSE(p.mooring.lines[0].fe.touchdown_refinement.has_value());
  EXPECT_FALSE(p.hull.wind_coefficients || p.hull.current_coefficients || p.hull.mean_drift || p.hull.geometry);
  EXPECT_EQ(p.load_cases[0].condition, DesignCondition::extreme);
  // Nothing given at project level: a riser gets its kind's defaults.
  EXPECT_FALSE(p.criteria.risers.design_factor_normal || p.criteria.risers.max_top_tension_N ||
               p.criteria.risers.min_bending_radius_m);
  Riser scr;
  scr.kind = RiserKind::scr;
  const RiserCriteria c = riser_criteria(p.criteria, scr);
  EXPECT_DOUBLE_EQ(c.design_factor.normal, 0.67);
  EXPECT_DOUBLE_EQ(c.design_factor.extreme, 0.80);
  EXPECT_DOUBLE_EQ(c.design_factor.survival, 1.00);
  EXPECT_DOUBLE_EQ(c.min_effective_tension_N, 0.0);
  EXPECT_FALSE(c.max_top_tension_N.has_value());
  EXPECT_FALSE(c.min_bending_radius_m.has_value());
  EXPECT_DOUBLE_EQ(design_factor(c.design_factor, DesignCondition::normal), 0.67);
}

TEST(ProjectLoader, FormatSampleLoadsWithExpectedValues) {
  const Project p = load_project(kSample);
  EXPECT_EQ(p.version, 1);
  EXPECT_EQ(p.name, "format sample");
  ASSERT_TRUE(p.description.has_value());
  EXPECT_EQ(p.source_file, kSample);

  EXPECT_DOUBLE_EQ(p.site.depth_m, 200.0);
  EXPECT_DOUBLE_EQ(p.site.water_density_kg_per_m3, 1025.0);
  EXPECT_DOUBLE_EQ(p.site.gravity_m_per_s2, 9.80665);
  EXPECT_DOUBLE_EQ(p.site.seabed.normal_stiffness_Pa_per_m, 1.0e5);
  EXPECT_DOUBLE_EQ(p.site.air_density_kg_per_m3, 1.225);

  ASSERT_EQ(p.line_types.size(), 4u);
  EXPECT_EQ(p.line_types[0].name, "chain76");
  EXPECT_EQ(p.line_types[0].kind, LineKind::user);
  EXPECT_DOUBLE_EQ(*p.line_types[0].mass_per_length_kg_per_m, 113.35);
  EXPECT_DOUBLE_EQ(*p.line_types[0].axial_stiffness_N, 7.536e8);
  EXPECT_DOUBLE_EQ(*p.line_types[0].breaking_load_N, 6.0e6);
  EXPECT_EQ(p.line_types[1].kind, LineKind::chain);
  EXPECT_EQ(p.line_types[1].grade, ChainGrade::R4);
  EXPECT_EQ(p.line_types[1].chain_construction, ChainConstruction::studless);
  EXPECT_EQ(p.line_types[2].kind, LineKind::polyester);
  EXPECT_DOUBLE_EQ(*p.line_types[2].static_stiffness_mbl, 13.0);
  ASSERT_TRUE(p.line_types[2].dynamic_stiffness_mbl.has_value());
  EXPECT_DOUBLE_EQ((*p.line_types[2].dynamic_stiffness_mbl)[1], 0.35);
  EXPECT_EQ(p.line_types[3].wire_construction, WireConstruction::spiral_strand);
  EXPECT_FALSE(p.line_types[3].grade.has_value());

  ASSERT_EQ(p.mooring.lines.size(), 3u);
  const MooringLine& l2 = p.mooring.lines[1];
  EXPECT_EQ(l2.name, "L2");
  // Polar {radius 837.6, azimuth 180 deg}, z on the seabed.
  EXPECT_NEAR(l2.anchor_g.x(), -837.6, kTol * 837.6);
  EXPECT_NEAR(l2.anchor_g.y(), 0.0, kTol * 837.6);
  EXPECT_DOUBLE_EQ(l2.anchor_g.z(), -200.0);
  EXPECT_NEAR(l2.fairlead_b.x(), -40.868, kTol * 40.868);
  EXPECT_DOUBLE_EQ(l2.fairlead_b.z(), -14.0);
  ASSERT_EQ(l2.segments.size(), 3u);
  EXPECT_EQ(l2.segments[1].type, "poly254");
  EXPECT_DOUBLE_EQ(l2.segments[1].length_m, 600.0);
  ASSERT_EQ(l2.attachments.size(), 2u);
  EXPECT_EQ(l2.attachments[1].after_segment, 1);
  EXPECT_EQ(l2.attachments[1].kind, AttachmentKind::buoy);
  EXPECT_DOUBLE_EQ(l2.attachments[1].volume_m3, 30.0);
  EXPECT_DOUBLE_EQ(p.mooring.lines[0].anchor_g.y(), 725.383);
  EXPECT_EQ(p.mooring.lines[0].model, LineModel::catenary);
  EXPECT_DOUBLE_EQ(p.mooring.lines[0].fe.element_length_m, 10.0);
  const MooringLine& l3 = p.mooring.lines[2];
  EXPECT_EQ(l3.model, LineModel::fe);
  EXPECT_DOUBLE_EQ(l3.fe.element_length_m, 8.0);
  ASSERT_TRUE(l3.fe.touchdown_refinement.has_value());
  EXPECT_DOUBLE_EQ(l3.fe.touchdown_refinement->length_m, 100.0);
  EXPECT_DOUBLE_EQ(l3.fe.touchdown_refinement->element_length_m, 2.0);
  ASSERT_EQ(p.mooring.groups.size(), 1u);
  EXPECT_EQ(p.mooring.groups[0].lines, (std::vector<std::string>{"L1", "L2", "L3"}));

  EXPECT_DOUBLE_EQ(p.hull.mass_kg, 1.40751e7);
  ASSERT_TRUE(p.hull.radii_of_gyration_m.has_value());
  EXPECT_DOUBLE_EQ(p.hull.radii_of_gyration_m->z(), 29.5);
  EXPECT_FALSE(p.hull.inertia_kg_m2.has_value());
  EXPECT_DOUBLE_EQ(*p.hull.displaced_volume_m3, 13917.0);
  EXPECT_DOUBLE_EQ(p.hull.center_of_buoyancy_b->z(), -13.15);
  EXPECT_DOUBLE_EQ(p.hull.waterplane_inertia_m4->y(), 144513.0);
  EXPECT_FALSE(p.hull.hydrostatics_file.has_value());

  ASSERT_TRUE(p.hull.wind_coefficients.has_value());
  const WindCoefficients& wind = *p.hull.wind_coefficients;
  ASSERT_EQ(wind.headings_rad.size(), 4u);
  EXPECT_NEAR(wind.headings_rad[3], 1.5 * std::numbers::pi, kTol);
  EXPECT_DOUBLE_EQ(wind.surge_m2[2], -1500.0);
  EXPECT_DOUBLE_EQ(wind.sway_m2[1], 1600.0);
  EXPECT_DOUBLE_EQ(wind.yaw_m3[3], -2000.0);
  EXPECT_DOUBLE_EQ(wind.reference_height_m, 10.0);
  ASSERT_TRUE(p.hull.current_coefficients.has_value());
  EXPECT_EQ(p.hull.current_coefficients->headings_rad.size(), 2u);
  EXPECT_DOUBLE_EQ(p.hull.current_coefficients->surge_m2[0], 900.0);
  ASSERT_TRUE(p.hull.mean_drift.has_value());
  const auto* drift = std::get_if<MeanDriftTable>(&*p.hull.mean_drift);
  ASSERT_NE(drift, nullptr);
  EXPECT_EQ(drift->frequencies_rad_per_s, (std::vector<double>{0.3, 0.6, 0.9}));
  ASSERT_EQ(drift->surge_N_per_m2.size(), 2u);
  EXPECT_DOUBLE_EQ(drift->surge_N_per_m2[1][2], -2.0e4);
  EXPECT_EQ(drift->yaw_N_m_per_m2[0].size(), 3u);
  ASSERT_TRUE(p.hull.geometry.has_value());
  ASSERT_EQ(p.hull.geometry->columns.size(), 1u);
  EXPECT_DOUBLE_EQ(p.hull.geometry->columns[0].z_bottom_m, -20.0);
  EXPECT_DOUBLE_EQ(p.hull.geometry->columns[0].diameter_m, 6.5);
  ASSERT_EQ(p.hull.geometry->pontoons.size(), 1u);
  EXPECT_DOUBLE_EQ(p.hull.geometry->pontoons[0].to_b.y(), 14.608);

  ASSERT_EQ(p.risers.size(), 2u);
  const Riser& riser = p.risers[0];
  EXPECT_EQ(riser.kind, RiserKind::scr);
  EXPECT_NEAR(riser.hang_off_b.y(), 35.0, kTol * 35.0);
  EXPECT_NEAR(riser.azimuth_rad, std::numbers::pi / 2, kTol);
  EXPECT_NEAR(riser.top_angle_rad, 12.0 * std::numbers::pi / 180.0, kTol);
  ASSERT_EQ(riser.sections.size(), 1u);
  EXPECT_DOUBLE_EQ(*riser.sections[0].wall_thickness_m, 0.0254);
  EXPECT_DOUBLE_EQ(riser.sections[0].contents_density_kg_per_m3, 800.0);
  EXPECT_FALSE(riser.sections[0].coating_thickness_m.has_value());
  EXPECT_DOUBLE_EQ(riser.internal_pressure_Pa, 1.0e7);
  EXPECT_DOUBLE_EQ(riser.fe.element_length_m, 4.0);
  ASSERT_TRUE(riser.fe.touchdown_refinement.has_value());
  EXPECT_DOUBLE_EQ(riser.fe.touchdown_refinement->length_m, 50.0);
  EXPECT_DOUBLE_EQ(riser.fe.touchdown_refinement->element_length_m, 1.0);
  EXPECT_NEAR(*riser.criteria.max_top_angle_rad, 15.0 * std::numbers::pi / 180.0, kTol);
  EXPECT_FALSE(riser.criteria.max_top_tension_N.has_value());
  const Riser& flexible = p.risers[1];
  EXPECT_EQ(flexible.kind, RiserKind::flexible);
  EXPECT_DOUBLE_EQ(*flexible.sections[0].bending_stiffness_N_m2, 1.208e5);
  EXPECT_DOUBLE_EQ(*flexible.criteria.min_bending_radius_m, 3.0);
  EXPECT_DOUBLE_EQ(flexible.internal_pressure_Pa, 0.0);  // default
  EXPECT_DOUBLE_EQ(flexible.fe.element_length_m, 5.0);   // riser default
  EXPECT_FALSE(flexible.fe.touchdown_refinement.has_value());

  ASSERT_EQ(p.environments.size(), 2u);
  EXPECT_FALSE(p.environments[0].waves.has_value());
  const Environment& op = p.environments[1];
  ASSERT_TRUE(op.waves && op.wind && op.current);
  EXPECT_EQ(op.waves->spectrum, WaveSpectrum::jonswap);
  EXPECT_DOUBLE_EQ(op.waves->hs_m, 4.0);
  EXPECT_DOUBLE_EQ(*op.waves->gamma, 1.0);
  EXPECT_NEAR(op.waves->heading_rad, std::numbers::pi / 4, kTol);
  EXPECT_EQ(op.wind->spectrum, WindSpectrum::api);
  EXPECT_DOUBLE_EQ(op.wind->reference_height_m, 10.0);
  ASSERT_EQ(op.current->profile.size(), 3u);
  EXPECT_DOUBLE_EQ(op.current->profile[1].z_m, -50.0);
  EXPECT_DOUBLE_EQ(op.current->profile[1].speed_m_per_s, 0.9);

  ASSERT_EQ(p.load_cases.size(), 2u);
  EXPECT_FALSE(p.load_cases[0].damaged_line.has_value());
  EXPECT_EQ(p.load_cases[1].damaged_line, "L1");
  EXPECT_EQ(p.load_cases[0].condition, DesignCondition::normal);
  EXPECT_EQ(p.load_cases[1].condition, DesignCondition::extreme);  // default

  EXPECT_EQ(p.criteria.mooring.code, MooringCode::api_rp_2sk);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.api_rp_2sk->damaged_dynamic, 1.25);
  EXPECT_DOUBLE_EQ(*p.criteria.max_offset_pct_depth, 10.0);
  const RiserCriteriaOverrides& rc = p.criteria.risers;  // as written
  EXPECT_DOUBLE_EQ(*rc.design_factor_normal, 0.67);
  EXPECT_DOUBLE_EQ(*rc.design_factor_survival, 1.0);
  EXPECT_DOUBLE_EQ(*rc.min_effective_tension_N, 0.0);
  EXPECT_DOUBLE_EQ(*rc.max_top_tension_N, 4.0e6);
  EXPECT_NEAR(*rc.max_top_angle_rad, 20.0 * std::numbers::pi / 180.0, kTol);
  EXPECT_NEAR(*rc.max_flex_joint_rotation_rad, 12.0 * std::numbers::pi / 180.0, kTol);
  EXPECT_FALSE(rc.min_bending_radius_m.has_value());
  EXPECT_DOUBLE_EQ(*rc.max_touchdown_excursion_m, 50.0);
  // Per-riser overrides replace only the keys they give.
  const RiserCriteria p1 = riser_criteria(p.criteria, p.risers[0]);
  EXPECT_NEAR(*p1.max_top_angle_rad, 15.0 * std::numbers::pi / 180.0, kTol);
  EXPECT_DOUBLE_EQ(*p1.max_top_tension_N, 4.0e6);
  EXPECT_DOUBLE_EQ(*riser_criteria(p.criteria, p.risers[1]).min_bending_radius_m, 3.0);
  ASSERT_EQ(p.stages.size(), 3u);
  EXPECT_EQ(p.stages[2].name, "advanced");

  // Positions are kept for the validation pass.
  const auto at = p.source_map.find("mooring.lines[1].segments[1].length");
  ASSERT_NE(at, p.source_map.end());
  EXPECT_EQ(at->second.line, 56);  // the `{type: poly254, length: 600.0}` row of the sample
}

TEST(ProjectLoader, UnknownKeyIsReportedWithPositionAndSuggestion) {
  const auto issues = issues_of(replace(kMinimal, "  gravity: 9.81\n", "  gravity: 9.81\n  gravty: 9.8\n"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "unknown_key");
  EXPECT_EQ(format_issue(issues[0]), "test.yaml:7:3: site.gravty: unknown key \"gravty\" (did you mean \"gravity\"?)");
}

TEST(ProjectLoader, WrongTypeNamesExpectedTypeAndUnit) {
  const auto issues = issues_of(replace(kMinimal, "depth: 100.0", "depth: deep"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "wrong_type");
  EXPECT_EQ(format_issue(issues[0]), "test.yaml:4:10: site.depth: expected a finite number in m, got \"deep\"");
}

TEST(ProjectLoader, QuotedNumberIsAString) {
  const auto issues = issues_of(replace(kMinimal, "mass: 1.0e7", "mass: \"1.0e7\""));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].path, "hull.mass");
  EXPECT_EQ(issues[0].problem, "wrong_type");
}

TEST(ProjectLoader, BadEnumListsAllowedValues) {
  const auto issues = issues_of(replace(kMinimal, "kind: user", "kind: chian"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "bad_enum");
  EXPECT_EQ(format_issue(issues[0]),
            "test.yaml:9:21: line_types[0].kind: unknown value \"chian\"; allowed: chain | wire | "
            "polyester | user (did you mean \"chain\"?)");
}

TEST(ProjectLoader, MissingRequiredKeyIsReportedAtItsParent) {
  const auto issues = issues_of(replace(kMinimal, "  mass: 1.0e7\n", ""));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "missing_key");
  EXPECT_EQ(format_issue(issues[0]), "test.yaml:18:3: hull.mass: required key is missing (kg)");
}

TEST(ProjectLoader, PolarFairleadNeedsZ) {
  const auto issues =
      issues_of(replace(kMinimal, "fairlead: [10.0, 0.0, -10.0]", "fairlead: {radius: 10.0, azimuth_deg: 0}"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].path, "mooring.lines[0].fairlead.z");
  EXPECT_EQ(issues[0].problem, "missing_key");
}

TEST(ProjectLoader, ConstructionMustMatchKind) {
  const auto issues = issues_of(replace(kMinimal, "kind: user,", "kind: user, construction: studless,"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].path, "line_types[0].construction");
  EXPECT_EQ(issues[0].problem, "key_not_applicable");
}

TEST(ProjectLoader, DuplicateKeyIsAnError) {
  const auto issues = issues_of(replace(kMinimal, "name: minimal", "name: minimal\nname: again"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "duplicate_key");
  EXPECT_EQ(issues[0].line, 3);
}

TEST(ProjectLoader, UnsupportedVersionIsAnError) {
  const auto issues = issues_of(replace(kMinimal, "version: 1", "version: 2"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "unsupported_version");
}

TEST(ProjectLoader, YamlSyntaxErrorHasLineAndColumn) {
  const auto issues = issues_of(replace(kMinimal, "[10.0, 0.0, -10.0]", "[10.0, 0.0, -10.0"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "yaml_syntax");
  ASSERT_TRUE(issues[0].line.has_value());
  EXPECT_GE(*issues[0].line, 14);
  EXPECT_NE(issues[0].message.find("YAML syntax error"), std::string::npos);
}

TEST(ProjectLoader, MissingFileNamesTheFile) {
  try {
    load_project("/nonexistent/folder/project.yaml");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 1u);
    EXPECT_EQ(e.issues()[0].problem, "missing_file");
    EXPECT_FALSE(e.issues()[0].line.has_value());
    EXPECT_EQ(std::string(e.what()), "/nonexistent/folder/project.yaml: project file not found");
  }
}

TEST(ProjectLoader, AFolderIsSaidToBeAFolder) {
  const std::string folder = std::string(SPIRAL_SOURCE_DIR) + "/scenarios";
  try {
    load_project(folder);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ASSERT_EQ(e.issues().size(), 1u);
    EXPECT_EQ(e.issues()[0].problem, "not_a_file");
    EXPECT_EQ(std::string(e.what()), folder + ": is a folder, not a project file (give the .yaml file in it)");
  }
}

// Found by tests/fuzz/project_fuzz.cpp: an empty or comment-only file had no
// node to point at, so its one issue had no line.
TEST(ProjectLoader, AnEmptyFileIsAnErrorAtLineOne) {
  for (const char* text : {"", "# only a comment\n", "~\n"}) {
    try {
      parse_project(text, "empty.yaml");
      FAIL() << "no InputError for \"" << text << "\"";
    } catch (const InputError& e) {
      ASSERT_EQ(e.issues().size(), 1u);
      EXPECT_EQ(e.issues()[0].line, 1) << e.what();
      EXPECT_EQ(e.issues()[0].column, 1) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("empty.yaml:1:1: a project file is a map", 0), 0u) << e.what();
    }
  }
}

TEST(ProjectLoader, AllErrorsOfAFileAreReportedTogetherInFileOrder) {
  std::string text = replace(kMinimal, "depth: 100.0", "depth: deep");
  text = replace(text, "kind: user", "kind: rope");
  text = replace(text, "    - name: L1\n", "    - nmae: L1\n");
  text = replace(text, "code: api_rp_2sk", "code: api");
  const auto issues = issues_of(text);
  ASSERT_EQ(issues.size(), 5u);  // the typo is both unknown and leaves name missing
  EXPECT_EQ(issues[0].path, "site.depth");
  EXPECT_EQ(issues[1].path, "line_types[0].kind");
  std::vector<std::string> paths;
  for (const auto& issue : issues) paths.push_back(issue.path);
  EXPECT_NE(std::find(paths.begin(), paths.end(), "mooring.lines[0].nmae"), paths.end());
  EXPECT_NE(std::find(paths.begin(), paths.end(), "mooring.lines[0].name"), paths.end());
  EXPECT_EQ(issues.back().path, "criteria.mooring.code");
  for (std::size_t i = 1; i < issues.size(); ++i) {
    EXPECT_LE(*issues[i - 1].line, *issues[i].line);
  }
  // what() has one line per issue.
  const std::string what = InputError(issues).what();
  EXPECT_EQ(std::count(what.begin(), what.end(), '\n'), 4);
}

TEST(ProjectLoader, DnvCriteriaTakeConsequenceClassDefaults) {
  const auto p =
      parse_project(replace(kMinimal, "{code: api_rp_2sk}", "{code: dnv_os_e301, consequence_class: 2}"), "t.yaml");
  ASSERT_TRUE(p.criteria.mooring.dnv_os_e301.has_value());
  EXPECT_DOUBLE_EQ(p.criteria.mooring.dnv_os_e301->uls_mean, 1.40);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.dnv_os_e301->uls_dynamic, 2.10);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.dnv_os_e301->als_dynamic, 1.10);
}

TEST(ProjectLoader, HydrostaticsFileResolvesAgainstTheProjectFolder) {
  const auto p = parse_project(
      replace(kMinimal, "  waterplane_area: 400.0\n", "  waterplane_area: 400.0\n  hydrostatics_file: hull.hst\n"),
      "/some/dir/p.yaml");
  ASSERT_TRUE(p.hull.hydrostatics_file.has_value());
  EXPECT_EQ(*p.hull.hydrostatics_file, std::filesystem::path("/some/dir/hull.hst"));
}

TEST(ProjectLoader, InertiaAcceptsSixComponents) {
  const auto p = parse_project(
      replace(kMinimal, "radii_of_gyration: [30.0, 30.0, 30.0]", "inertia: [1.0e10, 2.0e10, 3.0e10, 1.0e8, 0, 0]"),
      "t.yaml");
  ASSERT_TRUE(p.hull.inertia_kg_m2.has_value());
  EXPECT_DOUBLE_EQ((*p.hull.inertia_kg_m2)(0, 1), 1.0e8);
  EXPECT_DOUBLE_EQ((*p.hull.inertia_kg_m2)(1, 0), 1.0e8);
  EXPECT_DOUBLE_EQ((*p.hull.inertia_kg_m2)(2, 2), 3.0e10);
}

// ------------------------------------------ coupled-statics format additions ----

const std::string kLine = "        - {type: c, length: 550.0}\n";
const std::string kWaterplane = "  waterplane_inertia: [1.0e5, 1.0e5]\n";

TEST(ProjectLoader, BadLineModelListsAllowedValues) {
  const auto issues = issues_of(replace(kMinimal, kLine, kLine + "      model: finite\n"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "bad_enum");
  EXPECT_EQ(format_issue(issues[0]),
            "test.yaml:17:14: mooring.lines[0].model: unknown value \"finite\"; allowed: "
            "catenary | fe");
}

TEST(ProjectLoader, UnknownKeyInFeMeshIsReported) {
  const auto issues = issues_of(replace(kMinimal, kLine, kLine + "      fe: {element_lenght: 5.0}\n"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "unknown_key");
  EXPECT_EQ(issues[0].path, "mooring.lines[0].fe.element_lenght");
  EXPECT_NE(issues[0].message.find("did you mean \"element_length\""), std::string::npos);
}

TEST(ProjectLoader, TouchdownRefinementNeedsBothValues) {
  const auto issues = issues_of(replace(kMinimal, kLine, kLine + "      fe: {touchdown_refinement: {length: 50.0}}\n"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "missing_key");
  EXPECT_EQ(issues[0].path, "mooring.lines[0].fe.touchdown_refinement.element_length");
}

TEST(ProjectLoader, BadLoadCaseConditionIsAnError) {
  const auto issues = issues_of(replace(kMinimal, "{name: lc1, environment: calm}",
                                        "{name: lc1, environment: calm, "
                                        "condition: survivl}"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "bad_enum");
  EXPECT_NE(issues[0].message.find("did you mean \"survival\""), std::string::npos);
}

TEST(ProjectLoader, CoefficientHeadingsAreReadInDegrees) {
  const auto p =
      parse_project(replace(kMinimal, kWaterplane,
                            kWaterplane + "  current_coefficients: {headings_deg: [0, 45, 315], surge: [1, 2, 3],"
                                          " sway: [0, 1, 0], yaw: [0, 0, 0]}\n"),
                    "t.yaml");
  ASSERT_TRUE(p.hull.current_coefficients.has_value());
  EXPECT_NEAR(p.hull.current_coefficients->headings_rad[1], std::numbers::pi / 4, kTol);
  EXPECT_NEAR(p.hull.current_coefficients->headings_rad[2], 1.75 * std::numbers::pi, kTol);
  // Each item is placed, for the validation pass.
  EXPECT_EQ(p.source_map.at("hull.current_coefficients.headings_deg[2]").line, 26);
}

TEST(ProjectLoader, CoefficientValuesMustBeNumbers) {
  const auto issues =
      issues_of(replace(kMinimal, kWaterplane,
                        kWaterplane + "  wind_coefficients: {headings_deg: [0, 180], surge: [1, big], sway: [0, 0],"
                                      " yaw: 0}\n"));
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].path, "hull.wind_coefficients.surge[1]");
  EXPECT_EQ(issues[0].message, "expected a finite number in m^2, got \"big\"");
  EXPECT_EQ(issues[1].path, "hull.wind_coefficients.yaw");
  EXPECT_EQ(issues[1].message, "expected a list of numbers in m^3, got \"0\"");
}

TEST(ProjectLoader, MeanDriftFileResolvesAgainstTheProjectFolder) {
  const auto p =
      parse_project(replace(kMinimal, kWaterplane, kWaterplane + "  mean_drift: {file: hydro/hull.12d, ulen: 2.0}\n"),
                    "/some/dir/p.yaml");
  ASSERT_TRUE(p.hull.mean_drift.has_value());
  const auto* file = std::get_if<MeanDriftFile>(&*p.hull.mean_drift);
  ASSERT_NE(file, nullptr);
  EXPECT_EQ(file->file, std::filesystem::path("/some/dir/hydro/hull.12d"));
  EXPECT_DOUBLE_EQ(file->ulen_m, 2.0);
  // ulen defaults to 1 m.
  const auto q =
      parse_project(replace(kMinimal, kWaterplane, kWaterplane + "  mean_drift: {file: hull.12d}\n"), "p.yaml");
  EXPECT_DOUBLE_EQ(std::get<MeanDriftFile>(*q.hull.mean_drift).ulen_m, 1.0);
}

TEST(ProjectLoader, MeanDriftHeadingRuleIsTheProjectsExplicitChoice) {
  // Absent: no symmetry, no fill (a heading outside the data is an input error).
  const auto plain =
      parse_project(replace(kMinimal, kWaterplane, kWaterplane + "  mean_drift: {file: hull.12d}\n"), "p.yaml");
  EXPECT_EQ(plain.hull.mean_drift_headings.symmetry_rotations, 1);
  EXPECT_FALSE(plain.hull.mean_drift_headings.symmetry_mirror_xz);
  EXPECT_FALSE(plain.hull.mean_drift_headings.wave_frame_fill_max_span_rad);
  const auto d3 =
      parse_project(replace(kMinimal, kWaterplane,
                            kWaterplane + "  mean_drift: {file: hull.12d, symmetry: {rotations: 3, mirror_xz: true}, "
                                          "wave_frame_fill: {max_span_deg: 120.0}}\n"),
                    "p.yaml");
  EXPECT_EQ(d3.hull.mean_drift_headings.symmetry_rotations, 3);
  EXPECT_TRUE(d3.hull.mean_drift_headings.symmetry_mirror_xz);
  ASSERT_TRUE(d3.hull.mean_drift_headings.wave_frame_fill_max_span_rad);
  EXPECT_NEAR(*d3.hull.mean_drift_headings.wave_frame_fill_max_span_rad, 2.0 * std::numbers::pi / 3.0, 1e-12);
  // A fill without its span, and an unknown key of the symmetry, say where.
  const auto issues = issues_of(
      replace(kMinimal, kWaterplane,
              kWaterplane + "  mean_drift: {file: hull.12d, symmetry: {rotation: 3}, wave_frame_fill: {}}\n"));
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].path, "hull.mean_drift.symmetry.rotation");
  EXPECT_EQ(issues[1].problem, "missing_key");
  EXPECT_EQ(issues[1].path, "hull.mean_drift.wave_frame_fill.max_span_deg");
}

TEST(ProjectLoader, MeanDriftIsEitherAFileOrATable) {
  auto issues = issues_of(replace(
      kMinimal, kWaterplane, kWaterplane + "  mean_drift: {file: hull.12d, frequencies: [0.5], surge: [[1.0]]}\n"));
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].problem, "conflicting_keys");
  EXPECT_EQ(issues[0].path, "hull.mean_drift.frequencies");
  EXPECT_EQ(issues[1].path, "hull.mean_drift.surge");

  issues = issues_of(replace(kMinimal, kWaterplane,
                             kWaterplane + "  mean_drift: {ulen: 2.0, headings_deg: [0, 90], "
                                           "frequencies: [0.5], surge: [[1], [2]], sway: [[0], "
                                           "[0]]}\n"));
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].problem, "missing_key");  // yaw, reported at the map
  EXPECT_EQ(issues[0].path, "hull.mean_drift.yaw");
  EXPECT_EQ(issues[1].problem, "key_not_applicable");
  EXPECT_EQ(issues[1].path, "hull.mean_drift.ulen");
}

TEST(ProjectLoader, MeanDriftTableRowsMustBeLists) {
  const auto issues =
      issues_of(replace(kMinimal, kWaterplane,
                        kWaterplane + "  mean_drift: {headings_deg: [0, 90], frequencies: [0.5], surge: [1, 2], "
                                      "sway: [[0], [0]], yaw: [[0], [0]]}\n"));
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].problem, "wrong_type");
  EXPECT_EQ(issues[0].path, "hull.mean_drift.surge[0]");
  EXPECT_EQ(issues[1].path, "hull.mean_drift.surge[1]");
}

TEST(ProjectLoader, HullGeometryColumnsAndPontoons) {
  const auto p = parse_project(
      replace(kMinimal, kWaterplane,
              kWaterplane + "  geometry:\n"
                            "    columns: [{center: [28.868, 0.0], z_bottom: -20, z_top: 12, diameter: 12}]\n"
                            "    pontoons: [{from: {radius: 10.0, azimuth_deg: 90.0, z: -17.0},\n"
                            "                to: [0.0, 0.0, -17.0], diameter: 1.6}]\n"),
      "t.yaml");
  ASSERT_TRUE(p.hull.geometry.has_value());
  EXPECT_DOUBLE_EQ(p.hull.geometry->columns[0].center_b.x(), 28.868);
  EXPECT_DOUBLE_EQ(p.hull.geometry->columns[0].z_top_m, 12.0);
  EXPECT_NEAR(p.hull.geometry->pontoons[0].from_b.y(), 10.0, kTol * 10.0);
  EXPECT_DOUBLE_EQ(p.hull.geometry->pontoons[0].diameter_m, 1.6);
}

TEST(ProjectLoader, RiserCriteriaOverridesMergeWithTheProjectCriteria) {
  const std::string riser =
      "risers:\n"
      "  - name: R1\n"
      "    kind: scr\n"
      "    hang_off: [30.0, 0.0, -10.0]\n"
      "    azimuth_deg: 0.0\n"
      "    top_angle_deg: 10.0\n"
      "    sections:\n"
      "      - {length: 300.0, outer_diameter: 0.3, wall_thickness: 0.02, youngs_modulus: "
      "2.07e11,\n"
      "         yield_stress: 4.48e8, steel_density: 7850.0, contents_density: 800.0}\n"
      "    internal_pressure: 2.5e7\n"
      "    criteria: {design_factor: {extreme: 0.7}, max_top_tension: 3.0e6}\n";
  const std::string text = replace(kMinimal, "  mooring: {code: api_rp_2sk}\n",
                                   "  mooring: {code: api_rp_2sk}\n  risers: {design_factor: {normal: 0.6}, "
                                   "min_effective_tension: 1.0e4, max_top_tension: 5.0e6}\n") +
                           riser;
  const auto p = parse_project(text, "t.yaml");
  ASSERT_EQ(p.risers.size(), 1u);
  EXPECT_DOUBLE_EQ(p.risers[0].internal_pressure_Pa, 2.5e7);
  EXPECT_DOUBLE_EQ(p.risers[0].fe.element_length_m, 5.0);
  const RiserCriteria c = riser_criteria(p.criteria, p.risers[0]);
  EXPECT_DOUBLE_EQ(c.design_factor.normal, 0.6);    // project
  EXPECT_DOUBLE_EQ(c.design_factor.extreme, 0.7);   // riser
  EXPECT_DOUBLE_EQ(c.design_factor.survival, 1.0);  // default
  EXPECT_DOUBLE_EQ(c.min_effective_tension_N, 1.0e4);
  EXPECT_DOUBLE_EQ(*c.max_top_tension_N, 3.0e6);
  EXPECT_DOUBLE_EQ(design_factor(c.design_factor, DesignCondition::extreme), 0.7);
}

TEST(ProjectLoader, RiserCriteriaDefaultByKindUnderTheProjectAndRiserValues) {
  Criteria criteria;
  Riser scr, flexible;
  scr.kind = RiserKind::scr;
  flexible.kind = RiserKind::flexible;
  // Kind defaults (docs/project-format.md): a steel riser has a flex joint,
  // a flexible a bend stiffener (no flex-joint check) and no MBR default.
  const RiserCriteria s = riser_criteria(criteria, scr);
  ASSERT_TRUE(s.max_flex_joint_rotation_rad.has_value());
  EXPECT_NEAR(*s.max_flex_joint_rotation_rad, 15.0 * std::numbers::pi / 180.0, kTol);
  EXPECT_DOUBLE_EQ(s.design_factor.extreme, 0.80);
  EXPECT_EQ(riser_criteria_defaults(RiserKind::lazy_wave).max_flex_joint_rotation_rad,
            riser_criteria_defaults(RiserKind::scr).max_flex_joint_rotation_rad);
  const RiserCriteria f = riser_criteria(criteria, flexible);
  EXPECT_FALSE(f.max_flex_joint_rotation_rad.has_value());
  EXPECT_FALSE(f.min_bending_radius_m.has_value());
  EXPECT_DOUBLE_EQ(f.min_effective_tension_N, 0.0);
  // A project value replaces the kind default; a riser value the project's.
  criteria.risers.max_flex_joint_rotation_rad = 10.0 * std::numbers::pi / 180.0;
  criteria.risers.min_bending_radius_m = 4.0;
  EXPECT_NEAR(*riser_criteria(criteria, scr).max_flex_joint_rotation_rad, 10.0 * std::numbers::pi / 180.0, kTol);
  flexible.criteria.min_bending_radius_m = 3.5;
  EXPECT_DOUBLE_EQ(*riser_criteria(criteria, flexible).min_bending_radius_m, 3.5);
  EXPECT_DOUBLE_EQ(*riser_criteria(criteria, scr).min_bending_radius_m, 4.0);
}

TEST(ProjectLoader, ScenariosCarryTheCoupledStaticsData) {
  const std::string folder = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/";
  const Project oc4 = load_project(folder + "oc4-semisubmersible.yaml");
  ASSERT_TRUE(oc4.hull.geometry.has_value());
  EXPECT_EQ(oc4.hull.geometry->columns.size(), 7u);    // main + 3 upper + 3 base (ref §1.3)
  EXPECT_EQ(oc4.hull.geometry->pontoons.size(), 15u);  // members 8-22
  EXPECT_FALSE(oc4.hull.wind_coefficients || oc4.hull.current_coefficients);
  // WAMIT data of the OC4 model (shared/data/hydro/oc4-semi), ULEN 1, periods as written.
  ASSERT_TRUE(oc4.hull.mean_drift && oc4.hull.hydrodynamics);
  EXPECT_DOUBLE_EQ(std::get<MeanDriftFile>(*oc4.hull.mean_drift).period_scale, 1.0);
  EXPECT_DOUBLE_EQ(oc4.hull.hydrodynamics->ulen_m, 1.0);

  const Project fps = load_project(folder + "deepwater-fps.yaml");
  ASSERT_TRUE(fps.hull.geometry && fps.hull.current_coefficients && fps.hull.wind_coefficients);
  // Mean drift: the OC4 .12d (heading 0 only), scaled, with the hull's D3
  // symmetry and the wave-frame fill across its 120 deg gaps, both chosen.
  ASSERT_TRUE(fps.hull.mean_drift.has_value());
  EXPECT_DOUBLE_EQ(std::get<MeanDriftFile>(*fps.hull.mean_drift).ulen_m, 2.0);
  EXPECT_EQ(fps.hull.mean_drift_headings.symmetry_rotations, 3);
  EXPECT_TRUE(fps.hull.mean_drift_headings.symmetry_mirror_xz);
  EXPECT_TRUE(fps.hull.mean_drift_headings.wave_frame_fill_max_span_rad.has_value());
  // The lambda = 2 proxy reuses the OC4 .1: ULEN 2, periods x sqrt(2).
  ASSERT_TRUE(fps.hull.hydrodynamics.has_value());
  EXPECT_DOUBLE_EQ(fps.hull.hydrodynamics->ulen_m, 2.0);
  EXPECT_NEAR(fps.hull.hydrodynamics->period_scale, std::sqrt(2.0), 1e-8);
  // The lambda = 2 geometry: main column 13 m from -40 to +20 m.
  EXPECT_DOUBLE_EQ(fps.hull.geometry->columns[0].diameter_m, 13.0);
  EXPECT_DOUBLE_EQ(fps.hull.geometry->columns[0].z_bottom_m, -40.0);
  // Current C A of the submerged columns (the scenario's arithmetic): 2,696 m^2.
  EXPECT_DOUBLE_EQ(fps.hull.current_coefficients->surge_m2[0], 2696.0);
  EXPECT_DOUBLE_EQ(fps.hull.current_coefficients->sway_m2[3], 2696.0);
  for (const Riser& riser : fps.risers) {
    ASSERT_TRUE(riser.fe.touchdown_refinement.has_value()) << riser.name;
    EXPECT_DOUBLE_EQ(riser.fe.touchdown_refinement->element_length_m, 1.0) << riser.name;
  }
  EXPECT_DOUBLE_EQ(*fps.criteria.risers.max_top_tension_N, 4.0e6);
  ASSERT_EQ(fps.load_cases.size(), 5u);
  EXPECT_EQ(fps.load_cases[0].condition, DesignCondition::extreme);
  EXPECT_EQ(fps.load_cases[2].condition, DesignCondition::survival);  // 100-yr, line damaged
  EXPECT_EQ(fps.load_cases[4].condition, DesignCondition::normal);    // 1-yr operating
}

}  // namespace
}  // namespace spiral::design
