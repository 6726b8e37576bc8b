// The project loader: the format sample loads with the expected values, and
// each class of input error is reported with file, line, column and path.

#include "design/project_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "unit/project_fixture.hpp"

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

  ASSERT_EQ(p.risers.size(), 1u);
  const Riser& riser = p.risers[0];
  EXPECT_EQ(riser.kind, RiserKind::scr);
  EXPECT_NEAR(riser.hang_off_b.y(), 35.0, kTol * 35.0);
  EXPECT_NEAR(riser.azimuth_rad, std::numbers::pi / 2, kTol);
  EXPECT_NEAR(riser.top_angle_rad, 12.0 * std::numbers::pi / 180.0, kTol);
  ASSERT_EQ(riser.sections.size(), 1u);
  EXPECT_DOUBLE_EQ(*riser.sections[0].wall_thickness_m, 0.0254);
  EXPECT_DOUBLE_EQ(riser.sections[0].contents_density_kg_per_m3, 800.0);
  EXPECT_FALSE(riser.sections[0].coating_thickness_m.has_value());

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

  EXPECT_EQ(p.criteria.mooring.code, MooringCode::api_rp_2sk);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.api_rp_2sk->damaged_dynamic, 1.25);
  EXPECT_DOUBLE_EQ(*p.criteria.max_offset_pct_depth, 10.0);
  ASSERT_EQ(p.stages.size(), 3u);
  EXPECT_EQ(p.stages[2].name, "advanced");

  // Positions are kept for the validation pass.
  const auto at = p.source_map.find("mooring.lines[1].segments[1].length");
  ASSERT_NE(at, p.source_map.end());
  EXPECT_EQ(at->second.line, 55);  // the `{type: poly254, length: 600.0}` row of the sample
}

TEST(ProjectLoader, UnknownKeyIsReportedWithPositionAndSuggestion) {
  const auto issues =
      issues_of(replace(kMinimal, "  gravity: 9.81\n", "  gravity: 9.81\n  gravty: 9.8\n"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].condition, "unknown_key");
  EXPECT_EQ(format_issue(issues[0]),
            "test.yaml:7:3: site.gravty: unknown key \"gravty\" (did you mean \"gravity\"?)");
}

TEST(ProjectLoader, WrongTypeNamesExpectedTypeAndUnit) {
  const auto issues = issues_of(replace(kMinimal, "depth: 100.0", "depth: deep"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].condition, "wrong_type");
  EXPECT_EQ(format_issue(issues[0]),
            "test.yaml:4:10: site.depth: expected a finite number in m, got \"deep\"");
}

TEST(ProjectLoader, QuotedNumberIsAString) {
  const auto issues = issues_of(replace(kMinimal, "mass: 1.0e7", "mass: \"1.0e7\""));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].path, "hull.mass");
  EXPECT_EQ(issues[0].condition, "wrong_type");
}

TEST(ProjectLoader, BadEnumListsAllowedValues) {
  const auto issues = issues_of(replace(kMinimal, "kind: user", "kind: chian"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].condition, "bad_enum");
  EXPECT_EQ(format_issue(issues[0]),
            "test.yaml:9:21: line_types[0].kind: unknown value \"chian\"; allowed: chain | wire | "
            "polyester | user (did you mean \"chain\"?)");
}

TEST(ProjectLoader, MissingRequiredKeyIsReportedAtItsParent) {
  const auto issues = issues_of(replace(kMinimal, "  mass: 1.0e7\n", ""));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].condition, "missing_key");
  EXPECT_EQ(format_issue(issues[0]), "test.yaml:18:3: hull.mass: required key is missing (kg)");
}

TEST(ProjectLoader, PolarFairleadNeedsZ) {
  const auto issues = issues_of(replace(kMinimal, "fairlead: [10.0, 0.0, -10.0]",
                                        "fairlead: {radius: 10.0, azimuth_deg: 0}"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].path, "mooring.lines[0].fairlead.z");
  EXPECT_EQ(issues[0].condition, "missing_key");
}

TEST(ProjectLoader, ConstructionMustMatchKind) {
  const auto issues =
      issues_of(replace(kMinimal, "kind: user,", "kind: user, construction: studless,"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].path, "line_types[0].construction");
  EXPECT_EQ(issues[0].condition, "key_not_applicable");
}

TEST(ProjectLoader, DuplicateKeyIsAnError) {
  const auto issues = issues_of(replace(kMinimal, "name: minimal", "name: minimal\nname: again"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].condition, "duplicate_key");
  EXPECT_EQ(issues[0].line, 3);
}

TEST(ProjectLoader, UnsupportedVersionIsAnError) {
  const auto issues = issues_of(replace(kMinimal, "version: 1", "version: 2"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].condition, "unsupported_version");
}

TEST(ProjectLoader, YamlSyntaxErrorHasLineAndColumn) {
  const auto issues = issues_of(replace(kMinimal, "[10.0, 0.0, -10.0]", "[10.0, 0.0, -10.0"));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].condition, "yaml_syntax");
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
    EXPECT_EQ(e.issues()[0].condition, "missing_file");
    EXPECT_FALSE(e.issues()[0].line.has_value());
    EXPECT_EQ(std::string(e.what()), "/nonexistent/folder/project.yaml: project file not found");
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
  const auto p = parse_project(
      replace(kMinimal, "{code: api_rp_2sk}", "{code: dnv_os_e301, consequence_class: 2}"),
      "t.yaml");
  ASSERT_TRUE(p.criteria.mooring.dnv_os_e301.has_value());
  EXPECT_DOUBLE_EQ(p.criteria.mooring.dnv_os_e301->uls_mean, 1.40);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.dnv_os_e301->uls_dynamic, 2.10);
  EXPECT_DOUBLE_EQ(p.criteria.mooring.dnv_os_e301->als_dynamic, 1.10);
}

TEST(ProjectLoader, HydrostaticsFileResolvesAgainstTheProjectFolder) {
  const auto p = parse_project(replace(kMinimal, "  waterplane_area: 400.0\n",
                                       "  waterplane_area: 400.0\n  hydrostatics_file: hull.hst\n"),
                               "/some/dir/p.yaml");
  ASSERT_TRUE(p.hull.hydrostatics_file.has_value());
  EXPECT_EQ(*p.hull.hydrostatics_file, std::filesystem::path("/some/dir/hull.hst"));
}

TEST(ProjectLoader, InertiaAcceptsSixComponents) {
  const auto p = parse_project(replace(kMinimal, "radii_of_gyration: [30.0, 30.0, 30.0]",
                                       "inertia: [1.0e10, 2.0e10, 3.0e10, 1.0e8, 0, 0]"),
                               "t.yaml");
  ASSERT_TRUE(p.hull.inertia_kg_m2.has_value());
  EXPECT_DOUBLE_EQ((*p.hull.inertia_kg_m2)(0, 1), 1.0e8);
  EXPECT_DOUBLE_EQ((*p.hull.inertia_kg_m2)(1, 0), 1.0e8);
  EXPECT_DOUBLE_EQ((*p.hull.inertia_kg_m2)(2, 2), 3.0e10);
}

}  // namespace
}  // namespace spiral::design
