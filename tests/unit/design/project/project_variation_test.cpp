// Variation files (`extends`): a project that takes every top-level section
// it does not write from a base file; issues name the file a section was
// written in, data files resolve from it, and edits refuse the base's fields.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "design/project/input_error.hpp"
#include "design/project/model_hash.hpp"
#include "design/project/project_edit.hpp"
#include "design/project/project_loader.hpp"
#include "design/project/validated_project.hpp"
#include "support/project_fixture.hpp"
#include "support/temp_folder.hpp"

namespace spiral::design {
namespace {

namespace fs = std::filesystem;

fs::path fresh_folder(const std::string& name) { return test::fresh_temp_folder(name); }

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

std::vector<InputIssue> issues_loading(const fs::path& file) {
  try {
    load_validated_project(file);
  } catch (const InputError& e) {
    return e.issues();
  }
  ADD_FAILURE() << file << " loaded";
  return {};
}

const std::string kVariation = R"(version: 1
extends: base.yaml
name: variation
load_cases:
  - {name: lc1, environment: calm}
  - {name: lc2, environment: calm, damaged_line: L1}
)";

TEST(ProjectVariation, WrittenSectionsReplaceTheBaseOnesWholeAndTheRestComeFromTheBase) {
  const fs::path dir = fresh_folder("spiral-variation-sections");
  write(dir / "base.yaml", kMinimal);
  write(dir / "variation.yaml", kVariation);
  const Project p = load_project(dir / "variation.yaml");
  EXPECT_EQ(p.name, "variation");
  ASSERT_EQ(p.load_cases.size(), 2u);  // the variation's list, not the base's one case added to it
  EXPECT_EQ(p.load_cases[1].damaged_line, "L1");
  ASSERT_EQ(p.mooring.lines.size(), 1u);  // from the base
  EXPECT_EQ(p.mooring.lines[0].segments[0].length_m, 550.0);
  ASSERT_EQ(p.base_files.size(), 1u);
  EXPECT_EQ(fs::path(p.base_files[0]), dir / "base.yaml");
  EXPECT_EQ(p.source_file, (dir / "variation.yaml").string());
  fs::remove_all(dir);
}

TEST(ProjectVariation, IssuesNameTheFileTheSectionWasWrittenIn) {
  const fs::path dir = fresh_folder("spiral-variation-issues");
  // A loader issue (unknown key) and a validation issue (a negative length) in
  // the base's mooring, an unknown environment in the variation's load cases.
  write(dir / "base.yaml", replace(replace(kMinimal, "length: 550.0", "length: -550.0"), "  depth: 100.0\n",
                                   "  depth: 100.0\n  deph: 1.0\n"));
  write(dir / "variation.yaml",
        replace(kVariation, "{name: lc1, environment: calm}", "{name: lc1, environment: storm}"));
  const auto issues = issues_loading(dir / "variation.yaml");
  ASSERT_FALSE(issues.empty());
  // The unknown key stops the loader before validation: it is reported alone.
  EXPECT_EQ(issues[0].problem, "unknown_key");
  EXPECT_EQ(issues[0].file, (dir / "base.yaml").string());
  EXPECT_EQ(issues[0].line, 5);

  write(dir / "base.yaml", replace(kMinimal, "length: 550.0", "length: -550.0"));
  bool base_issue = false, variation_issue = false;
  for (const InputIssue& issue : issues_loading(dir / "variation.yaml")) {
    if (issue.path.starts_with("mooring.lines[0].segments[0]")) {
      base_issue = true;
      EXPECT_EQ(issue.file, (dir / "base.yaml").string()) << format_issue(issue);
      EXPECT_EQ(issue.line, 16) << format_issue(issue);
    }
    if (issue.path.starts_with("load_cases[0]")) {
      variation_issue = true;
      EXPECT_EQ(issue.file, (dir / "variation.yaml").string()) << format_issue(issue);
      EXPECT_EQ(issue.line, 5) << format_issue(issue);
    }
  }
  EXPECT_TRUE(base_issue);
  EXPECT_TRUE(variation_issue);
  fs::remove_all(dir);
}

TEST(ProjectVariation, DataFilesResolveFromTheFileThatHoldsTheHull) {
  const fs::path dir = fresh_folder("spiral-variation-data");
  write(dir / "platform" / "base.yaml",
        replace(kMinimal, "  waterplane_area: 400.0\n", "  waterplane_area: 400.0\n  hydrostatics_file: hull.hst\n"));
  write(dir / "studies" / "variation.yaml",
        replace(kVariation, "extends: base.yaml", "extends: ../platform/base.yaml"));
  const Project p = load_project(dir / "studies" / "variation.yaml");
  ASSERT_TRUE(p.hull.hydrostatics_file.has_value());
  EXPECT_EQ(fs::weakly_canonical(*p.hull.hydrostatics_file), fs::weakly_canonical(dir / "platform" / "hull.hst"));
  // A data folder given for the variation (a spiral-run iteration file
  // written elsewhere) is for its own sections, not for the base's hull.
  const Project elsewhere = load_project(dir / "studies" / "variation.yaml", dir / "run");
  EXPECT_EQ(fs::weakly_canonical(*elsewhere.hull.hydrostatics_file),
            fs::weakly_canonical(dir / "platform" / "hull.hst"));
  fs::remove_all(dir);
}

TEST(ProjectVariation, AMissingBaseAndACycleAreIssuesAtTheExtends) {
  const fs::path dir = fresh_folder("spiral-variation-chain");
  write(dir / "variation.yaml", replace(kVariation, "extends: base.yaml", "extends: nowhere.yaml"));
  auto issues = issues_loading(dir / "variation.yaml");
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "missing_file");
  EXPECT_EQ(issues[0].path, "extends");
  EXPECT_EQ(issues[0].line, 2);
  EXPECT_NE(issues[0].message.find("nowhere.yaml"), std::string::npos) << issues[0].message;

  write(dir / "a.yaml", "version: 1\nextends: b.yaml\nname: a\n");
  write(dir / "b.yaml", "version: 1\nextends: a.yaml\nname: b\n");
  issues = issues_loading(dir / "a.yaml");
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "extends_cycle");
  EXPECT_EQ(issues[0].file, (dir / "b.yaml").string());
  fs::remove_all(dir);
}

TEST(ProjectVariation, AnEditOfAFieldTheBaseWroteIsRefusedNamingTheBase) {
  const fs::path dir = fresh_folder("spiral-variation-edit");
  write(dir / "base.yaml", kMinimal);
  write(dir / "variation.yaml", kVariation);
  const Project p = load_project(dir / "variation.yaml");
  try {
    with_field_values(kVariation, p, {{"mooring.lines[0].segments[0].length", "540.0"}});
    FAIL() << "the edit was applied to the variation's text";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("base.yaml"), std::string::npos) << e.what();
  }
  // The variation's own fields edit as before.
  const std::string edited = with_field_values(kVariation, p, {{"name", "renamed"}});
  EXPECT_NE(edited.find("name: renamed"), std::string::npos) << edited;
  fs::remove_all(dir);
}

TEST(ProjectVariation, PayoutsOfABaseMooringMakeAVariationOfTheVariation) {
  const fs::path dir = fresh_folder("spiral-variation-payouts");
  // A second line and comments in the base's mooring, the hull section after it.
  const std::string base = replace(replace(kMinimal, "        - {type: c, length: 550.0}\n",
                                           "        - {type: c, length: 300.0}   # bottom chain\n"
                                           "        - {type: c, length: 250.0}   # top chain\n"
                                           "    - name: L2   # the second line\n"
                                           "      anchor: {radius: 500.0, azimuth_deg: 180.0}\n"
                                           "      fairlead: [-10.0, 0.0, -10.0]\n"
                                           "      segments:\n"
                                           "        - {type: c, length: 550.0}\n"),
                                   "hull:\n", "# the hull\nhull:\n");
  write(dir / "base.yaml", base);
  write(dir / "variation.yaml", kVariation);
  const Project p = load_project(dir / "variation.yaml");
  ASSERT_TRUE(mooring_from_base_file(p));
  EXPECT_FALSE(mooring_from_base_file(load_project(dir / "base.yaml")));
  const std::string text =
      mooring_variation_with_payouts(p, {{"L1", -2.5}, {"L2", 1.25}}, "made by a test", "variation.yaml");
  EXPECT_EQ(text.rfind("# made by a test\n", 0), 0u) << text;
  EXPECT_NE(text.find("extends: variation.yaml\n"), std::string::npos) << text;
  EXPECT_NE(text.find("{type: c, length: 247.5000}   # top chain"), std::string::npos) << text;
  EXPECT_NE(text.find("{type: c, length: 300.0}   # bottom chain"), std::string::npos) << text;
  EXPECT_NE(text.find("- name: L2   # the second line"), std::string::npos) << text;
  EXPECT_EQ(text.find("hull"), std::string::npos) << "only the mooring section is written:\n" << text;
  write(dir / "variation.optimized.yaml", text);
  const Project q = load_project(dir / "variation.optimized.yaml");
  ASSERT_EQ(q.mooring.lines.size(), 2u);
  EXPECT_EQ(q.mooring.lines[0].segments[1].length_m, 247.5);
  EXPECT_EQ(q.mooring.lines[0].segments[0].length_m, 300.0);
  EXPECT_EQ(q.mooring.lines[1].segments[0].length_m, 551.25);
  EXPECT_EQ(q.load_cases.size(), 2u);  // the variation's own section, through the chain
  EXPECT_EQ(q.name, "variation");
  EXPECT_FALSE(mooring_from_base_file(q));  // the next feedback edits it in place
  // A project that writes its own mooring is edited in place, not wrapped.
  EXPECT_THROW(mooring_variation_with_payouts(q, {{"L1", 1.0}}, "", "x.yaml"), std::invalid_argument);
  EXPECT_THROW(mooring_variation_with_payouts(p, {{"L9", 1.0}}, "", "variation.yaml"), std::invalid_argument);
  fs::remove_all(dir);
}

TEST(ProjectVariation, TheShippedMatrixScenarioHas157Cases) {
  const ValidatedProject p =
      load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps-matrix.yaml");
  EXPECT_EQ(p.project.load_cases.size(), 157u);
  EXPECT_EQ(p.project.mooring.lines.size(), 16u);
  EXPECT_EQ(p.project.risers.size(), 12u);
  EXPECT_TRUE(fs::exists(p.project.hull.hydrodynamics->radiation_file));
}

}  // namespace
}  // namespace spiral::design

namespace spiral::design {
namespace {

// The results store keys tasks on the content hash: an edited value in the
// base must change a variation's hash, a comment in the base must not.
TEST(ProjectVariation, TheContentHashCoversTheBase) {
  const fs::path dir = fresh_folder("spiral-variation-hash");
  write(dir / "base.yaml", kMinimal);
  write(dir / "variation.yaml", kVariation);
  const auto hash = [&] { return project_content_hash(dir / "variation.yaml", load_project(dir / "variation.yaml")); };
  const std::string original = hash();
  write(dir / "base.yaml", "# a comment\n" + kMinimal);
  EXPECT_EQ(hash(), original);
  write(dir / "base.yaml", replace(kMinimal, "length: 550.0", "length: 551.0"));
  EXPECT_NE(hash(), original);
  fs::remove_all(dir);
}

// Where the base lies is not the model: the same variation extending the
// same base from another folder (a clone elsewhere; spiral run's iteration
// files extend by absolute path) hashes alike, so its stored results are
// found again.
TEST(ProjectVariation, TheContentHashDoesNotDependOnWhereTheBaseLies) {
  const fs::path dir = fresh_folder("spiral-variation-hash-moved");
  write(dir / "base.yaml", kMinimal);
  write(dir / "variation.yaml", kVariation);
  write(dir / "elsewhere" / "base-copy.yaml", kMinimal);
  write(dir / "absolute.yaml",
        replace(kVariation, "extends: base.yaml", "extends: " + (dir / "elsewhere" / "base-copy.yaml").string()));
  const auto hash = [](const fs::path& file) { return project_content_hash(file, load_project(file)); };
  EXPECT_EQ(hash(dir / "absolute.yaml"), hash(dir / "variation.yaml"));
  write(dir / "elsewhere" / "base-copy.yaml", replace(kMinimal, "length: 550.0", "length: 551.0"));
  EXPECT_NE(hash(dir / "absolute.yaml"), hash(dir / "variation.yaml"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace spiral::design
