// The validation pass: valid projects pass; each named problem is reported
// with the position of the offending node; all issues come together.

#include "design/project/project_validation.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "design/project/project_loader.hpp"
#include "support/project_fixture.hpp"
#include "support/temp_folder.hpp"

namespace spiral::design {
namespace {

const std::string kSample = std::string(SPIRAL_SOURCE_DIR) + "/tests/data/format-sample.yaml";

std::vector<InputIssue> check(const std::string& text, const LineCheckTable& table = {}) {
  return check_project(parse_project(text, "test.yaml"), table);
}

std::vector<std::string> conditions(const std::vector<InputIssue>& issues) {
  std::vector<std::string> out;
  for (const auto& issue : issues) out.push_back(issue.problem);
  return out;
}

std::string all(const std::vector<InputIssue>& issues) {
  std::string out;
  for (const auto& issue : issues) out += format_issue(issue) + "\n";
  return out;
}

/// One issue with the given problem and path.
void expect_single(const std::vector<InputIssue>& issues, const std::string& problem, const std::string& path) {
  ASSERT_EQ(issues.size(), 1u) << all(issues);
  EXPECT_EQ(issues[0].problem, problem) << all(issues);
  EXPECT_EQ(issues[0].path, path) << all(issues);
  EXPECT_TRUE(issues[0].line.has_value()) << all(issues);
}

const std::string kSteelRiser = R"(risers:
  - name: R1
    kind: scr
    hang_off: [30.0, 0.0, -10.0]
    azimuth_deg: 0.0
    top_angle_deg: 10.0
    sections:
      - {length: 300.0, outer_diameter: 0.3, wall_thickness: 0.02, youngs_modulus: 2.07e11,
         yield_stress: 4.48e8, steel_density: 7850.0, contents_density: 800.0}
)";

TEST(ProjectValidation, FormatSampleIsValid) {
  const auto issues = check_project(load_project(kSample));
  EXPECT_TRUE(issues.empty()) << all(issues);
}

TEST(ProjectValidation, MinimalProjectWithRiserIsValid) {
  const auto issues = check(kMinimal + kSteelRiser);
  EXPECT_TRUE(issues.empty()) << all(issues);
  EXPECT_NO_THROW(validate_project(parse_project(kMinimal, "test.yaml")));
}

TEST(ProjectValidation, NegativeLengthMessageHasTheDocumentedForm) {
  const auto issues = check(replace(kMinimal, "length: 550.0", "length: -20"));
  ASSERT_EQ(issues.size(), 1u) << all(issues);
  EXPECT_EQ(issues[0].problem, "segment_length_positive");
  EXPECT_EQ(format_issue(issues[0]), "test.yaml:16:29: mooring.lines[0].segments[0].length: must be > 0 m, got -20 m");
}

TEST(ProjectValidation, UndefinedLineTypeIsReported) {
  const auto issues = check(replace(kMinimal, "{type: c,", "{type: chain,"));
  expect_single(issues, "line_type_defined", "mooring.lines[0].segments[0].type");
  EXPECT_EQ(issues[0].message, "undefined line type \"chain\" (defined: c)");
  EXPECT_EQ(issues[0].line, 16);
}

TEST(ProjectValidation, UndefinedReferencesInLoadCasesAndGroups) {
  std::string text = replace(kMinimal, "environment: calm}", "environment: storm, damaged_line: L9}");
  text = replace(text, "hull:\n", "  groups:\n    - {name: g, lines: [L1, L2]}\nhull:\n");
  const auto issues = check(text);
  ASSERT_EQ(issues.size(), 3u) << all(issues);
  EXPECT_EQ(conditions(issues), (std::vector<std::string>{"line_defined", "environment_defined", "line_defined"}));
  EXPECT_EQ(issues[0].path, "mooring.groups[0].lines[1]");
}

TEST(ProjectValidation, DuplicateNamesAreReported) {
  const std::string second_type =
      "  - {name: c, kind: user, diameter: 0.1, mass_per_length: 90.0, axial_stiffness: 1.0e9, "
      "breaking_load: 5.0e6}\nmooring:\n";
  std::string text = replace(kMinimal, "mooring:\n", second_type);
  text = replace(text, "  - {name: lc1, environment: calm}\n",
                 "  - {name: lc1, environment: calm}\n  - {name: lc1, environment: calm}\n");
  const auto issues = check(text);
  ASSERT_EQ(issues.size(), 2u) << all(issues);
  EXPECT_EQ(issues[0].problem, "line_type_name_unique");
  EXPECT_EQ(issues[0].path, "line_types[1].name");
  EXPECT_EQ(issues[0].message, "duplicate line type name \"c\", first used by line_types[0]");
  EXPECT_EQ(issues[1].problem, "load_case_name_unique");
}

TEST(ProjectValidation, AnchorBelowSeabed) {
  const auto issues = check(replace(kMinimal, "azimuth_deg: 0.0}", "azimuth_deg: 0.0, z: -105.0}"));
  expect_single(issues, "anchor_below_seabed", "mooring.lines[0].anchor");
  EXPECT_EQ(issues[0].message, "anchor is 5 m below the seabed: z = -105 m, seabed at z = -100 m");
}

TEST(ProjectValidation, AnchorOnTheSeabedWithinRoundOffIsAccepted) {
  const auto issues = check(replace(kMinimal, "azimuth_deg: 0.0}", "azimuth_deg: 0.0, z: -100.0000000001}"));
  EXPECT_TRUE(issues.empty()) << all(issues);
}

TEST(ProjectValidation, FairleadAboveWater) {
  const auto issues = check(replace(kMinimal, "[10.0, 0.0, -10.0]", "[10.0, 0.0, 5.0]"));
  expect_single(issues, "fairlead_above_water", "mooring.lines[0].fairlead");
  EXPECT_EQ(issues[0].line, 14);
}

TEST(ProjectValidation, FairleadAboveWaterCountsTheHullReferencePoint) {
  const auto issues = check(replace(kMinimal, "reference_point: [0.0, 0.0, 0.0]", "reference_point: [0.0, 0.0, 12.0]"));
  expect_single(issues, "fairlead_above_water", "mooring.lines[0].fairlead");
}

// Geometry of kMinimal at rest: span 490 m, fairlead 90 m above the anchor,
// chord sqrt(490^2 + 90^2) = 498.2 m.

TEST(ProjectValidation, LineTooShortToReachWithoutBreaking) {
  // 450 m against 498.2 m: strain 10.7 %, EA 1e9 N -> about 1.07e8 N >> MBL 5e6 N.
  const auto issues = check(replace(kMinimal, "length: 550.0", "length: 450.0"));
  expect_single(issues, "line_too_short", "mooring.lines[0].segments");
  EXPECT_NE(issues[0].message.find("above the breaking load 5e+06 N of line type \"c\""), std::string::npos)
      << issues[0].message;
}

TEST(ProjectValidation, TautLineSlightlyShorterThanChordIsAcceptedWhenItHolds) {
  // 495 m: strain 0.65 %; with EA 1e9 N the tension is ~6.5e6 N, below an MBL of 2e7 N.
  const LineCheckTable resolved = {{"c", {1.0e9, 2.0e7, 900.0}}};
  EXPECT_TRUE(check(replace(kMinimal, "length: 550.0", "length: 495.0"), resolved).empty());
  // ...but not with the explicit MBL of 5e6 N.
  const auto issues = check(replace(kMinimal, "length: 550.0", "length: 495.0"));
  expect_single(issues, "line_too_short", "mooring.lines[0].segments");
}

TEST(ProjectValidation, LineTooShortWithoutPropertiesUsesTheStrainLimit) {
  const LineCheckTable unknown = {{"c", {}}};
  EXPECT_TRUE(check(replace(kMinimal, "length: 550.0", "length: 495.0"), unknown).empty());
  const auto issues = check(replace(kMinimal, "length: 550.0", "length: 440.0"), unknown);
  expect_single(issues, "line_too_short", "mooring.lines[0].segments");
  EXPECT_NE(issues[0].message.find("more than 10 %"), std::string::npos) << issues[0].message;
}

TEST(ProjectValidation, LineTooLongLiesSlack) {
  // 700 - 90 = 610 m > 490 m span.
  const auto issues = check(replace(kMinimal, "length: 550.0", "length: 700.0"));
  expect_single(issues, "line_slack", "mooring.lines[0].segments");
  EXPECT_NE(issues[0].message.find("by 120 m"), std::string::npos) << issues[0].message;
}

TEST(ProjectValidation, RiserWallThickerThanRadius) {
  const auto issues = check(kMinimal + replace(kSteelRiser, "wall_thickness: 0.02", "wall_thickness: 0.2"));
  expect_single(issues, "wall_thinner_than_radius", "risers[0].sections[0].wall_thickness");
  EXPECT_EQ(issues[0].message, "must be < outer_diameter / 2 = 0.15 m, got 0.2 m");
}

TEST(ProjectValidation, LazyWaveNeedsABuoyancySection) {
  const auto issues = check(kMinimal + replace(kSteelRiser, "kind: scr", "kind: lazy_wave"));
  expect_single(issues, "lazy_wave_buoyancy_section", "risers[0].sections");
  const std::string buoyant = replace(kSteelRiser, "kind: scr", "kind: lazy_wave") +
                              "      - {length: 200.0, outer_diameter: 0.3, wall_thickness: 0.02,\n"
                              "         youngs_modulus: 2.07e11, yield_stress: 4.48e8,\n"
                              "         steel_density: 7850.0, contents_density: 800.0,\n"
                              "         buoyancy_outer_diameter: 0.9, buoyancy_density: 500.0}\n";
  EXPECT_TRUE(check(kMinimal + buoyant).empty()) << all(check(kMinimal + buoyant));
}

TEST(ProjectValidation, BadSpectrumParameters) {
  const std::string text = replace(kMinimal, "  - name: calm\n",
                                   "  - name: calm\n    waves: {spectrum: jonswap, hs: 3.0, tp: "
                                   "0.0, gamma: 0.5, heading_deg: 0}\n");
  const auto issues = check(text);
  ASSERT_EQ(issues.size(), 2u) << all(issues);
  EXPECT_EQ(conditions(issues), (std::vector<std::string>{"tp_positive", "gamma_at_least_one"}));
  EXPECT_EQ(issues[0].message, "must be > 0 s, got 0 s");
  EXPECT_EQ(issues[1].message, "must be >= 1, got 0.5");
}

TEST(ProjectValidation, CurrentProfileMustBeInTheWaterAndSorted) {
  const std::string text = replace(kMinimal, "  - name: calm\n",
                                   "  - name: calm\n    current: {heading_deg: 0, profile: "
                                   "[[0.0, 1.0], [-50.0, 0.5], [-40.0, 0.4], [-150.0, 0.1]]}\n");
  const auto issues = check(text);
  ASSERT_EQ(issues.size(), 2u) << all(issues);
  EXPECT_EQ(issues[0].path, "environments[0].current.profile[2][0]");
  EXPECT_EQ(issues[1].path, "environments[0].current.profile[3][0]");
}

TEST(ProjectValidation, SafetyFactorsBelowOne) {
  const auto issues =
      check(replace(kMinimal, "{code: api_rp_2sk}", "{code: api_rp_2sk, safety_factors: {damaged_dynamic: 0.9}}"));
  expect_single(issues, "safety_factor_at_least_one", "criteria.mooring.safety_factors.damaged_dynamic");
}

TEST(ProjectValidation, HullHydrostaticsMustBeComplete) {
  const auto issues = check(replace(kMinimal, "  waterplane_area: 400.0\n", ""));
  expect_single(issues, "hull_hydrostatics_complete", "hull");
}

TEST(ProjectValidation, SeveralErrorsAreReportedAtOnceInFileOrder) {
  std::string text = replace(kMinimal, "depth: 100.0", "depth: -100.0");
  text = replace(text, "length: 550.0", "length: -20");
  text = replace(text, "[10.0, 0.0, -10.0]", "[10.0, 0.0, 5.0]");
  text = replace(text, "environment: calm}", "environment: storm}");
  text += replace(kSteelRiser, "wall_thickness: 0.02", "wall_thickness: 0.2");
  try {
    validate_project(parse_project(text, "test.yaml"));
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const auto& issues = e.issues();
    EXPECT_EQ(conditions(issues),
              (std::vector<std::string>{"depth_positive", "fairlead_above_water", "segment_length_positive",
                                        "environment_defined", "wall_thinner_than_radius"}))
        << e.what();
    const std::string what = e.what();
    EXPECT_EQ(std::count(what.begin(), what.end(), '\n'), 4);
    EXPECT_NE(what.find("test.yaml:4:10: site.depth: must be > 0 m, got -100 m"), std::string::npos) << what;
  }
}

// ------------------------------------------ coupled-statics format additions ----

const std::string kLine = "        - {type: c, length: 550.0}\n";
const std::string kWaterplane = "  waterplane_inertia: [1.0e5, 1.0e5]\n";

std::string with_hull(const std::string& keys) { return replace(kMinimal, kWaterplane, kWaterplane + keys); }

const std::string kFlexibleRiser = R"(risers:
  - name: F1
    kind: flexible
    hang_off: [30.0, 0.0, -10.0]
    azimuth_deg: 0.0
    top_angle_deg: 8.0
    sections:
      - {length: 150.0, outer_diameter: 0.396, inner_diameter: 0.2032, axial_stiffness: 5.0e8,
         bending_stiffness: 1.208e5, mass_per_length: 165.0, contents_density: 800.0}
)";

TEST(ProjectValidation, NegativeElementLengthIsReportedAtItsKey) {
  const auto issues = check(replace(kMinimal, kLine, kLine + "      fe: {element_length: -5}\n"));
  expect_single(issues, "fe_mesh_positive", "mooring.lines[0].fe.element_length");
  EXPECT_EQ(format_issue(issues[0]), "test.yaml:17:28: mooring.lines[0].fe.element_length: must be > 0 m, got -5 m");
}

TEST(ProjectValidation, RiserElementLengthAndRefinementMustBePositive) {
  const auto issues =
      check(kMinimal + kSteelRiser +
            "    fe: {element_length: 0.0, touchdown_refinement: {length: -10.0, element_length: 1}}\n");
  ASSERT_EQ(issues.size(), 3u) << all(issues);
  EXPECT_EQ(conditions(issues),
            (std::vector<std::string>{"fe_mesh_positive", "fe_mesh_positive", "touchdown_refinement_finer"}));
  EXPECT_EQ(issues[0].path, "risers[0].fe.element_length");
  EXPECT_EQ(issues[1].path, "risers[0].fe.touchdown_refinement.length");
}

TEST(ProjectValidation, TouchdownRefinementMustBeFinerThanTheMesh) {
  const auto issues = check(
      replace(kMinimal, kLine, kLine + "      fe: {touchdown_refinement: {length: 100.0, element_length: 20.0}}\n"));
  expect_single(issues, "touchdown_refinement_finer", "mooring.lines[0].fe.touchdown_refinement.element_length");
  EXPECT_EQ(issues[0].message, "must be <= element_length 10 m (a refinement), got 20 m");
}

TEST(ProjectValidation, GlobalAnalysisMeshMustBePositive) {
  const auto issues = check(kMinimal + "global_analysis: {element_length: -40.0}\n");
  expect_single(issues, "fe_mesh_positive", "global_analysis.element_length");
  EXPECT_EQ(issues[0].message, "must be > 0 m, got -40 m");
}

TEST(ProjectValidation, GlobalAnalysisMeshNeedsTenElementsOnTheShortestLine) {
  // L1 is 550 m, the riser 300 m: 40 m leaves the riser 7.5 elements.
  EXPECT_TRUE(check(kMinimal + kSteelRiser + "global_analysis: {element_length: 30.0}\n").empty());
  const auto issues = check(kMinimal + kSteelRiser + "global_analysis: {element_length: 40.0}\n");
  expect_single(issues, "global_analysis_elements", "global_analysis.element_length");
  EXPECT_EQ(issues[0].message, "40 m leaves riser R1 (300 m) 7.5 elements; at most 30 m (10 elements per line)");
}

TEST(ProjectValidation, CoefficientListsMustMatchTheHeadings) {
  const auto issues =
      check(with_hull("  wind_coefficients: {headings_deg: [0, 90, 180], surge: [1, 0, -1], sway: [0, 1],"
                      " yaw: [0, 0, 0]}\n"));
  expect_single(issues, "table_lengths_match", "hull.wind_coefficients.sway");
  EXPECT_EQ(format_issue(issues[0]),
            "test.yaml:26:76: hull.wind_coefficients.sway: must have one value per entry of "
            "headings_deg (3), got 2");
}

TEST(ProjectValidation, HeadingsOutOfRange) {
  const auto issues =
      check(with_hull("  current_coefficients: {headings_deg: [0, 180, 360], surge: [1, -1, 1],"
                      " sway: [0, 0, 0], yaw: [0, 0, 0]}\n"));
  expect_single(issues, "headings_valid", "hull.current_coefficients.headings_deg[2]");
  EXPECT_EQ(format_issue(issues[0]),
            "test.yaml:26:49: hull.current_coefficients.headings_deg[2]: must be in [0, 360) "
            "deg, got 360 deg");
  const auto negative =
      check(with_hull("  current_coefficients: {headings_deg: [-90, 90], surge: [0, 0], sway: [1, -1],"
                      " yaw: [0, 0]}\n"));
  expect_single(negative, "headings_valid", "hull.current_coefficients.headings_deg[0]");
}

TEST(ProjectValidation, HeadingsMustIncreaseAndBeAtLeastTwo) {
  auto issues =
      check(with_hull("  wind_coefficients: {headings_deg: [0, 180, 90], surge: [1, -1, 0], sway: [0, 0, 1],"
                      " yaw: [0, 0, 0]}\n"));
  expect_single(issues, "headings_valid", "hull.wind_coefficients.headings_deg[2]");
  EXPECT_EQ(issues[0].message, "headings must increase strictly, got 90 deg after 180 deg");
  issues = check(with_hull("  wind_coefficients: {headings_deg: [0], surge: [1], sway: [0], yaw: [0]}\n"));
  expect_single(issues, "headings_valid", "hull.wind_coefficients.headings_deg");
}

TEST(ProjectValidation, MeanDriftFileMustExist) {
  const auto issues = check(with_hull("  mean_drift: {file: no-such-hull.12d, ulen: 2.0}\n"));
  expect_single(issues, "file_exists", "hull.mean_drift.file");
  EXPECT_EQ(issues[0].message, "file not found: no-such-hull.12d");
  EXPECT_EQ(issues[0].line, 26);
}

TEST(ProjectValidation, MeanDriftFileThatExistsIsAccepted) {
  const std::filesystem::path folder = spiral::test::scratch_root() / "spiral-validation-mean-drift";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "hull.12d") << "    0.62832E+01    0.62832E+01    0.0    0.0    1    0.0    "
                                        "0.0    0.0    0.0\n";
  const Project p = parse_project(with_hull("  mean_drift: {file: hull.12d}\n"), (folder / "p.yaml").string());
  const auto issues = check_project(p);
  EXPECT_TRUE(issues.empty()) << all(issues);
  std::filesystem::remove_all(folder);
}

TEST(ProjectValidation, MeanDriftHeadingRuleRanges) {
  const std::string table =
      "headings_deg: [0, 180], frequencies: [0.5], surge: [[1], [-1]], sway: [[0], [0]], yaw: [[0], [0]]";
  auto issues = check(with_hull("  mean_drift: {" + table + ", symmetry: {rotations: 0}}\n"));
  expect_single(issues, "hull_value_positive", "hull.mean_drift.symmetry.rotations");
  issues = check(with_hull("  mean_drift: {" + table + ", wave_frame_fill: {max_span_deg: 400.0}}\n"));
  expect_single(issues, "hull_value_positive", "hull.mean_drift.wave_frame_fill.max_span_deg");
  EXPECT_EQ(issues[0].message, "must be in (0, 360] deg, got 400 deg");
  issues = check(with_hull("  mean_drift: {" + table +
                           ", symmetry: {rotations: 2, mirror_xz: true}, wave_frame_fill: {max_span_deg: 360}}\n"));
  EXPECT_TRUE(issues.empty()) << all(issues);
}

TEST(ProjectValidation, MeanDriftTableShapeAndFrequencies) {
  const auto issues =
      check(with_hull("  mean_drift: {headings_deg: [0, 180], frequencies: [0.4, 0.4, 0.8],\n"
                      "               surge: [[1, 2, 3], [1, 2]], sway: [[0, 0, 0]],\n"
                      "               yaw: [[0, 0, 0], [0, 0, 0]]}\n"));
  ASSERT_EQ(issues.size(), 3u) << all(issues);
  EXPECT_EQ(conditions(issues),
            (std::vector<std::string>{"frequencies_valid", "table_lengths_match", "table_lengths_match"}));
  EXPECT_EQ(issues[0].path, "hull.mean_drift.frequencies[1]");
  EXPECT_EQ(issues[1].path, "hull.mean_drift.surge[1]");
  EXPECT_EQ(issues[1].message, "must have one value per entry of frequencies (3), got 2");
  EXPECT_EQ(issues[2].path, "hull.mean_drift.sway");
}

TEST(ProjectValidation, HullGeometryMembersMustBeSolid) {
  const auto issues =
      check(with_hull("  geometry:\n"
                      "    columns: [{center: [0, 0], z_bottom: 10, z_top: -20, diameter: 6.5}]\n"
                      "    pontoons: [{from: [1, 2, -17], to: [1, 2, -17], diameter: -1.6}]\n"));
  ASSERT_EQ(issues.size(), 3u) << all(issues);
  EXPECT_EQ(conditions(issues),
            (std::vector<std::string>{"column_top_above_bottom", "pontoon_length_positive", "hull_value_positive"}));
  EXPECT_EQ(issues[0].path, "hull.geometry.columns[0].z_top");
  EXPECT_EQ(issues[2].path, "hull.geometry.pontoons[0].diameter");
  expect_single(check(with_hull("  geometry: {}\n")), "hull_geometry_members", "hull.geometry");
}

TEST(ProjectValidation, FlexibleRiserNeedsAMinimumBendingRadius) {
  const auto issues = check(kMinimal + kFlexibleRiser);
  expect_single(issues, "flexible_min_bending_radius", "risers[0].criteria.min_bending_radius");
  EXPECT_EQ(issues[0].line, 33);  // the riser entry: no criteria map was written
  // The message the user sees: file:line:col: field path: problem.
  EXPECT_EQ(format_issue(issues[0]).rfind(
                fmt::format("{}:33:{}: risers[0].criteria.min_bending_radius: a flexible riser needs "
                            "min_bending_radius (m)",
                            issues[0].file, issues[0].column.value_or(0)),
                0),
            0u)
      << format_issue(issues[0]);
  // Either level satisfies it.
  EXPECT_TRUE(check(kMinimal + kFlexibleRiser + "    criteria: {min_bending_radius: 3.0}\n").empty());
  const std::string project_level = replace(kMinimal, "  mooring: {code: api_rp_2sk}\n",
                                            "  mooring: {code: api_rp_2sk}\n  risers: {min_bending_radius: 3.0}\n");
  EXPECT_TRUE(check(project_level + kFlexibleRiser).empty());
  // A steel riser does not need one.
  EXPECT_TRUE(check(kMinimal + kSteelRiser).empty());
}

TEST(ProjectValidation, FlexibleWithoutSteelWallNeedsItsBore) {
  const std::string with_mbr = kFlexibleRiser + "    criteria: {min_bending_radius: 3.0}\n";
  expect_single(check(kMinimal + replace(with_mbr, " inner_diameter: 0.2032,", "")), "flexible_riser_complete",
                "risers[0].sections[0]");
  expect_single(check(kMinimal + replace(with_mbr, "inner_diameter: 0.2032", "inner_diameter: 0.5")),
                "bore_inside_pipe", "risers[0].sections[0].inner_diameter");
  // A steel section has its bore from the wall: an inner_diameter too is a conflict.
  expect_single(
      check(kMinimal + replace(kSteelRiser, "wall_thickness: 0.02,", "wall_thickness: 0.02, inner_diameter: 0.26,")),
      "bore_defined_once", "risers[0].sections[0].inner_diameter");
}

TEST(ProjectValidation, RiserCriteriaRanges) {
  const std::string text = replace(kMinimal, "  mooring: {code: api_rp_2sk}\n",
                                   "  mooring: {code: api_rp_2sk}\n  risers: {design_factor: {survival: 1.2}, "
                                   "min_effective_tension: -1.0, max_top_angle_deg: 95.0}\n") +
                           kSteelRiser + "    internal_pressure: -1.0e5\n    criteria: {max_top_tension: 0.0}\n";
  const auto issues = check(text);
  ASSERT_EQ(issues.size(), 5u) << all(issues);
  EXPECT_EQ(conditions(issues),
            (std::vector<std::string>{"design_factor_range", "riser_criterion_non_negative", "riser_angle_limit_range",
                                      "riser_value_non_negative", "riser_criterion_positive"}));
  EXPECT_EQ(issues[0].path, "criteria.risers.design_factor.survival");
  EXPECT_EQ(issues[0].message, "must be in (0, 1] (fraction of the yield stress), got 1.2");
  EXPECT_EQ(issues[2].path, "criteria.risers.max_top_angle_deg");
  EXPECT_EQ(issues[2].message, "must be in (0, 90) deg, got 95 deg");
  EXPECT_EQ(issues[3].path, "risers[0].internal_pressure");
  EXPECT_EQ(issues[4].path, "risers[0].criteria.max_top_tension");
}

TEST(ProjectValidation, AirDensityMustBePositive) {
  const auto issues = check(replace(kMinimal, "  gravity: 9.81\n", "  gravity: 9.81\n  air_density: 0\n"));
  expect_single(issues, "air_density_positive", "site.air_density");
}

TEST(ProjectValidation, RadiationMemoryKeysParseAndTheDurationMustExceedTheStep) {
  const std::string semi = std::string(SPIRAL_SCENARIO_DATA_DIR) + "/hydro/oc4-semi/marin_semi.1";
  const std::string hull_line = "  waterplane_inertia: [1.0e5, 1.0e5]\n";
  const std::string text = replace(kMinimal, hull_line,
                                   hull_line + "  hydrodynamics: {radiation_file: " + semi +
                                       ", radiation: memory, memory_duration: 90.0, memory_time_step: 0.05}\n");
  const Project p = parse_project(text, "test.yaml");
  ASSERT_TRUE(p.hull.hydrodynamics.has_value());
  EXPECT_EQ(p.hull.hydrodynamics->radiation, RadiationModel::memory);
  EXPECT_DOUBLE_EQ(p.hull.hydrodynamics->memory_duration_s, 90.0);
  EXPECT_DOUBLE_EQ(p.hull.hydrodynamics->memory_time_step_s, 0.05);
  EXPECT_TRUE(check(text).empty()) << all(check(text));
  // Defaults: low_frequency, 60 s at 0.1 s.
  const Project d = parse_project(
      replace(kMinimal, hull_line, hull_line + "  hydrodynamics: {radiation_file: " + semi + "}\n"), "test.yaml");
  EXPECT_EQ(d.hull.hydrodynamics->radiation, RadiationModel::low_frequency);
  EXPECT_DOUBLE_EQ(d.hull.hydrodynamics->memory_duration_s, 60.0);
  EXPECT_DOUBLE_EQ(d.hull.hydrodynamics->memory_time_step_s, 0.1);
  expect_single(check(replace(text, "memory_duration: 90.0", "memory_duration: 0.01")), "memory_duration_above_step",
                "hull.hydrodynamics.memory_duration");
}

TEST(ProjectValidation, MorisonExcitationOfABemHullNeedsGeometryAndNoExcitationFile) {
  const std::string hull_line = "  waterplane_inertia: [1.0e5, 1.0e5]\n";
  const std::string radiation = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/data/hydro/oc4-semi/marin_semi.1";
  const std::string hydro = "  hydrodynamics: {radiation_file: " + radiation + ", excitation: morison_maccamy_fuchs}\n";
  const std::string geometry =
      "  geometry:\n    columns: [{center: [0, 0], z_bottom: -25, z_top: 10, diameter: 22.6}]\n";
  const std::string text = replace(kMinimal, hull_line, hull_line + hydro + geometry);
  EXPECT_EQ(parse_project(text, "test.yaml").hull.hydrodynamics->excitation, ExcitationSource::morison_maccamy_fuchs);
  EXPECT_TRUE(check(text).empty()) << all(check(text));
  expect_single(check(replace(kMinimal, hull_line, hull_line + hydro)), "morison_needs_geometry",
                "hull.hydrodynamics.excitation");
  expect_single(check(replace(text, "excitation: morison_maccamy_fuchs",
                              "excitation: morison_maccamy_fuchs, excitation_file: " + radiation)),
                "excitation_source_conflict", "hull.hydrodynamics.excitation");
  EXPECT_THROW(parse_project(replace(text, "morison_maccamy_fuchs", "morison"), "t.yaml"), InputError);
}

TEST(ProjectValidation, MorisonHullNeedsGeometryAndTakesNoBemKeys) {
  const std::string hull_line = "  waterplane_inertia: [1.0e5, 1.0e5]\n";
  const std::string geometry =
      "  geometry:\n"
      "    columns: [{center: [0, 0], z_bottom: -25, z_top: 10, diameter: 22.6, drag: 0.7,\n"
      "               added_mass: 0.9, end_added_mass: 0.5, end_drag: 2.0}]\n"
      "    pontoons: [{from: [0, 0, -20], to: [30, 0, -20], diameter: 2.0, drag: 0.8}]\n";
  const std::string text =
      replace(kMinimal, hull_line, hull_line + "  hydrodynamics: {model: morison, strip_length: 0.5}\n" + geometry);
  const Project p = parse_project(text, "test.yaml");
  ASSERT_TRUE(p.hull.hydrodynamics && p.hull.geometry);
  EXPECT_EQ(p.hull.hydrodynamics->model, HullHydrodynamicsModel::morison);
  EXPECT_DOUBLE_EQ(p.hull.hydrodynamics->strip_length_m, 0.5);
  const HullColumn& c = p.hull.geometry->columns[0];
  EXPECT_DOUBLE_EQ(c.coefficients.drag, 0.7);
  EXPECT_DOUBLE_EQ(c.coefficients.added_mass, 0.9);
  EXPECT_DOUBLE_EQ(c.end_added_mass, 0.5);
  EXPECT_DOUBLE_EQ(c.end_drag, 2.0);
  EXPECT_DOUBLE_EQ(p.hull.geometry->pontoons[0].coefficients.drag, 0.8);
  EXPECT_DOUBLE_EQ(p.hull.geometry->pontoons[0].coefficients.added_mass, 1.0);  // default
  EXPECT_TRUE(check(text).empty()) << all(check(text));
  // Without geometry.
  expect_single(check(replace(kMinimal, hull_line, hull_line + "  hydrodynamics: {model: morison}\n")),
                "morison_needs_geometry", "hull.hydrodynamics.model");
  // A BEM key with model: morison, and strip_length with bem.
  EXPECT_THROW(parse_project(replace(text, "strip_length: 0.5", "radiation_file: x.1"), "t.yaml"), InputError);
  try {
    parse_project(replace(text, "model: morison, ", ""), "t.yaml");
    FAIL() << "strip_length accepted with model: bem";
  } catch (const InputError& e) {
    bool found = false;
    for (const auto& i : e.issues())
      found = found || (i.problem == "key_not_applicable" && i.path == "hull.hydrodynamics.strip_length");
    EXPECT_TRUE(found) << e.what();
  }
  // Negative coefficients.
  const auto issues = check(replace(text, "drag: 0.8", "drag: -0.8"));
  expect_single(issues, "coefficient_non_negative", "hull.geometry.pontoons[0].drag");
}

// stages[].duration: the advanced stage's verification runs only, > 0.
TEST(ProjectValidation, StageDurationOnlyOnTheAdvancedStageAndPositive) {
  const auto ok = check(kMinimal + "stages:\n  - {name: intermediate}\n  - {name: advanced, duration: 600.0}\n");
  EXPECT_TRUE(ok.empty()) << all(ok);
  EXPECT_DOUBLE_EQ(parse_project(kMinimal + "stages:\n  - {name: advanced, duration: 600.0}\n", "test.yaml")
                       .stages[0]
                       .duration_s.value_or(0.0),
                   600.0);
  expect_single(check(kMinimal + "stages:\n  - {name: intermediate, duration: 600.0}\n"),
                "stage_duration_advanced_only", "stages[0].duration");
  expect_single(check(kMinimal + "stages:\n  - {name: preliminary}\n  - {name: advanced, duration: 0.0}\n"),
                "stage_duration_positive", "stages[1].duration");
}

// stages[].optimize, max_iterations (spiral run's feedback) and the
// intermediate stage's critical_cases.
TEST(ProjectValidation, StageFeedbackAndCriticalCaseKeys) {
  const std::string good = kMinimal +
                           "stages:\n  - {name: preliminary, optimize: true, max_iterations: 5}\n"
                           "  - {name: intermediate, critical_cases: 2}\n";
  EXPECT_TRUE(check(good).empty()) << all(check(good));
  const Project p = parse_project(good, "test.yaml");
  EXPECT_TRUE(p.stages[0].optimize);
  EXPECT_EQ(p.stages[0].max_iterations, 5);
  EXPECT_EQ(p.stages[1].critical_cases.value_or(0), 2);
  EXPECT_FALSE(parse_project(kMinimal + "stages:\n  - {name: preliminary}\n", "test.yaml").stages[0].optimize);
  expect_single(check(kMinimal + "stages:\n  - {name: preliminary, max_iterations: 0}\n"), "stage_iterations_positive",
                "stages[0].max_iterations");
  expect_single(check(kMinimal + "stages:\n  - {name: advanced, critical_cases: 2}\n"),
                "stage_critical_cases_intermediate_only", "stages[0].critical_cases");
  expect_single(check(kMinimal + "stages:\n  - {name: intermediate, critical_cases: 0}\n"),
                "stage_critical_cases_positive", "stages[0].critical_cases");
  // YAML 1.2 booleans only: a "yes" is refused with the allowed values.
  try {
    parse_project(kMinimal + "stages:\n  - {name: preliminary, optimize: yes}\n", "test.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("true | false"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spiral::design
