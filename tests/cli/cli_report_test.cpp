// End-to-end `spiral report`: the PDF opens and holds the results, the HTML
// index links only files that exist, bad output folders fail cleanly.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace spiral::test {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) { return fresh_temp_folder(name); }

class CliReport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fresh_dir("spiral-cli-report"));
    result_ = new CommandResult(
        run_spiral("report " + scenario("deepwater-fps.yaml") + " --out '" + (*dir_ / "report").string() + "'"));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    delete result_;
  }
  static fs::path* dir_;
  static CommandResult* result_;
};
fs::path* CliReport::dir_ = nullptr;
CommandResult* CliReport::result_ = nullptr;

void PdfRendersWithTheReportedPageCount(const CommandResult* result_, const fs::path* dir_) {
  ASSERT_EQ(result_->exit_code, app::kExitOk) << result_->err;
  const fs::path pdf = *dir_ / "report" / "report.pdf";
  ASSERT_TRUE(fs::exists(pdf));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(result_->out, m, std::regex(R"(\((\d+) pages\))"))) << result_->out;
  const int pages = std::stoi(m[1]);
  EXPECT_GE(pages, 6);  // title + five sections
  const fs::path png_dir = *dir_ / "png";
  fs::create_directories(png_dir);
  ASSERT_EQ(
      std::system(fmt::format("pdftoppm -r 20 -png '{}' '{}/p' 2>/dev/null", pdf.string(), png_dir.string()).c_str()),
      0);
  int count = 0;
  for (const auto& e : fs::directory_iterator(png_dir)) count += e.path().extension() == ".png" ? 1 : 0;
  EXPECT_EQ(count, pages);
}

void PdfTextHoldsTheResultsTableValues(const CommandResult* result_, const fs::path* dir_) {
  ASSERT_EQ(result_->exit_code, app::kExitOk) << result_->err;
  const fs::path txt = *dir_ / "report.txt";
  ASSERT_EQ(
      std::system(
          fmt::format("pdftotext -layout '{}' '{}'", (*dir_ / "report" / "report.pdf").string(), txt.string()).c_str()),
      0);
  const std::string text = read_text(txt);
  // Pretensions from `spiral statics`, the damaged case from `spiral equilibrium`.
  const auto statics = nlohmann::json::parse(run_spiral("statics --json " + scenario("deepwater-fps.yaml")).out);
  for (const auto& line : statics["lines"]) {
    const std::string value = fmt::format("{:.1f}", line["fairlead_tension_N"].get<double>() / 1000.0);
    EXPECT_NE(text.find(value), std::string::npos) << line["name"] << " pretension " << value;
  }
  const auto damaged = nlohmann::json::parse(
      run_spiral("equilibrium --json --case lc3-survival-45deg-damaged-L10 " + scenario("deepwater-fps.yaml")).out);
  int found = 0;
  for (const auto& line : damaged["lines"]) {
    const std::string value = fmt::format("{:.1f}", line["max_tension_N"].get<double>() / 1000.0);
    found += text.find(value) != std::string::npos ? 1 : 0;
  }
  EXPECT_EQ(found, static_cast<int>(damaged["lines"].size()));
}

void HtmlReferencesOnlyFilesThatExist(const CommandResult* result_, const fs::path* dir_) {
  ASSERT_EQ(result_->exit_code, app::kExitOk) << result_->err;
  const fs::path folder = *dir_ / "report";
  const std::string html = read_text(folder / "index.html");
  const std::regex ref(R"re((?:src|href)="([^"#][^"]*)")re");
  int refs = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), ref); it != std::sregex_iterator(); ++it) {
    const std::string target = (*it)[1];
    EXPECT_EQ(target.find("://"), std::string::npos) << target;
    EXPECT_TRUE(fs::exists(folder / target)) << target;
    ++refs;
  }
  EXPECT_GT(refs, 10);
  EXPECT_TRUE(fs::exists(folder / "tables" / "pretensions.csv"));
}

/// Rows of a CSV written by the report (no quoted commas in these tables).
std::vector<std::vector<std::string>> read_csv(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_text(file));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream cell(line);
    for (std::string c; std::getline(cell, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

/// The text with every run of whitespace as one space (pdftotext wraps the verdict).
std::string squeeze(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
    if (!space || (!out.empty() && out.back() != ' ')) out.push_back(space ? ' ' : c);
  }
  return out;
}

// The title page's verdict against the riser checks of `spiral equilibrium`
// for every load case: the scenario fails on riser criteria only (its
// mooring lines and offsets pass), so the verdict must be FAIL with that
// count of failing cases, and name the failing riser check of largest
// utilization as the governing one.
void VerdictNamesTheFailingCasesAndTheGoverningCheck(const CommandResult* result_, const fs::path* dir_) {
  ASSERT_EQ(result_->exit_code, app::kExitOk) << result_->err;
  const fs::path txt = *dir_ / "verdict.txt";
  ASSERT_EQ(
      std::system(
          fmt::format("pdftotext -l 1 '{}' '{}'", (*dir_ / "report" / "report.pdf").string(), txt.string()).c_str()),
      0);
  const std::string text = squeeze(read_text(txt));
  const std::size_t contents = text.find("Contents");
  ASSERT_NE(contents, std::string::npos);
  const std::string title = text.substr(0, contents);
  // The load cases as the project lists them (the report's load-case table).
  const auto load_cases = read_csv(*dir_ / "report" / "tables" / "load-cases.csv");
  ASSERT_GT(load_cases.size(), 1u);
  int failing_cases = 0;
  double governing = 0.0;
  std::string governing_text;
  for (std::size_t row = 1; row < load_cases.size(); ++row) {
    const std::string& name = load_cases[row][0];
    const auto eq = nlohmann::json::parse(
        run_spiral("equilibrium --json --case " + name + " " + scenario("deepwater-fps.yaml")).out);
    bool fails = false;
    for (const auto& riser : eq["risers"]) {
      if (riser["passes"].get<bool>()) continue;
      fails = true;
      if (riser["utilization"].get<double>() > governing) {
        governing = riser["utilization"].get<double>();
        governing_text = fmt::format("governing failing check: riser criteria {} {}, utilization {:.3f} in {}",
                                     riser["name"].get<std::string>(), riser["governing_criterion"].get<std::string>(),
                                     governing, name);
      }
    }
    failing_cases += fails ? 1 : 0;
  }
  if (failing_cases == 0) {
    // Every riser passes in every case (independent equilibria above); the
    // mooring code and offset limit pass on this scenario too (the static
    // stage's own tables), so the title must say PASS and name no failure.
    for (const auto& row : read_csv(*dir_ / "report" / "tables" / "code-check-summary.csv"))
      if (row[0] != "Case") {
        EXPECT_EQ(row.back(), "PASS") << row[0];
      }
    EXPECT_NE(title.find(fmt::format("PASS — all {} cases meet", load_cases.size())), std::string::npos) << title;
    EXPECT_EQ(title.find("FAIL —"), std::string::npos) << title;
    return;
  }
  EXPECT_NE(title.find(fmt::format("FAIL — {} of {} cases fail (mooring code: 0, offset limit: 0, riser criteria: {}",
                                   failing_cases, load_cases.size(), failing_cases)),
            std::string::npos)
      << title;
  EXPECT_NE(title.find(governing_text), std::string::npos) << governing_text << "\n" << title;
  EXPECT_EQ(title.find("PASS —"), std::string::npos) << title;
}

// One process generates the default scenario's report once (it runs every
// static case with FE risers) and all checks read it.
TEST_F(CliReport, DefaultScenarioReport) {
  {
    SCOPED_TRACE("PdfRendersWithTheReportedPageCount");
    PdfRendersWithTheReportedPageCount(result_, dir_);
  }
  {
    SCOPED_TRACE("PdfTextHoldsTheResultsTableValues");
    PdfTextHoldsTheResultsTableValues(result_, dir_);
  }
  {
    SCOPED_TRACE("HtmlReferencesOnlyFilesThatExist");
    HtmlReferencesOnlyFilesThatExist(result_, dir_);
  }
  {
    SCOPED_TRACE("VerdictNamesTheFailingCasesAndTheGoverningCheck");
    VerdictNamesTheFailingCasesAndTheGoverningCheck(result_, dir_);
  }
}

TEST(CliReportErrors, UnwritableOutputFolderExitsFourNamingItAndLeavesNothing) {
  const fs::path dir = fresh_dir("spiral-cli-report-bad");
  std::ofstream(dir / "a-file") << "not a folder";
  const fs::path out = dir / "a-file" / "report";
  const auto result = run_spiral("report " + scenario("oc4-semisubmersible.yaml") + " --out '" + out.string() + "'");
  EXPECT_EQ(result.exit_code, app::kExitOutputError) << result.err;
  EXPECT_NE(result.err.find(out.string()), std::string::npos) << result.err;
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);  // only a-file
  fs::remove_all(dir);
}

// The intermediate stage: every load case gets an enhanced S-C storm; the
// ranking is sorted by score, the score is the largest measure, the critical
// cases are the top three plus the failing ones, and the riser measure is the
// case's riser utilization as `spiral equilibrium` computes it.
TEST(CliReportStages, IntermediateRanksEveryLoadCase) {
  const fs::path dir = fresh_dir("spiral-cli-report-intermediate");
  const auto result = run_spiral("report " + scenario("deepwater-fps.yaml") + " --stage intermediate --out '" +
                                 (dir / "report").string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  const auto rows = read_csv(dir / "report" / "tables" / "ranking.csv");
  ASSERT_EQ(rows.size(), 6u);  // header + the scenario's five load cases
  ASSERT_EQ(rows[0][8], "Score");
  double previous = 1e300;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& r = rows[i];
    const double tension = std::stod(r[3]), offset = std::stod(r[5]), riser = std::stod(r[6]), score = std::stod(r[8]);
    EXPECT_EQ(std::stoi(r[0]), static_cast<int>(i));
    EXPECT_DOUBLE_EQ(score, std::max({tension, offset, riser})) << r[1];
    EXPECT_LE(score, previous) << r[1];
    previous = score;
    EXPECT_GT(tension, 0.0) << r[1];
  }
  // Critical: failing, or among the three most severe by any one measure
  // (tension, offset/SOZ, riser), counted from the table itself.
  for (std::size_t i = 1; i < rows.size(); ++i) {
    bool top_three = false;
    for (const int column : {3, 5, 6}) {
      int above = 0;
      for (std::size_t j = 1; j < rows.size(); ++j)
        if (std::stod(rows[j][column]) > std::stod(rows[i][column])) ++above;
      top_three = top_three || (above < 3 && std::stod(rows[i][column]) > 0.0);
    }
    EXPECT_EQ(rows[i][10] == "yes", top_three || rows[i][11] == "FAIL") << rows[i][1];
  }
  // The top case's riser measure against the equilibrium's own riser rows.
  const auto eq = nlohmann::json::parse(
      run_spiral("equilibrium --json --case " + rows[1][1] + " " + scenario("deepwater-fps.yaml")).out);
  double worst = 0.0;
  for (const auto& riser : eq["risers"]) worst = std::max(worst, riser["utilization"].get<double>());
  EXPECT_NEAR(std::stod(rows[1][6]), worst, 1e-8 * worst);
  const fs::path txt = dir / "report.txt";
  ASSERT_EQ(
      std::system(
          fmt::format("pdftotext -layout '{}' '{}'", (dir / "report" / "report.pdf").string(), txt.string()).c_str()),
      0);
  EXPECT_NE(read_text(txt).find("Critical case #1: " + rows[1][1]), std::string::npos);
  fs::remove_all(dir);
}

/// The OC4 scenario (two load cases, both critical) with its advanced stage's
/// verification runs `duration_s` long, written into `dir` with absolute data paths.
fs::path oc4_with_advanced_duration(const fs::path& dir, double duration_s) {
  std::string yaml = read_text(fs::path(SPIRAL_SOURCE_DIR) / "scenarios" / "oc4-semisubmersible.yaml");
  const std::string relative = "data/hydro/", absolute = SPIRAL_SCENARIO_DATA_DIR "/hydro/";
  for (std::size_t at = 0; (at = yaml.find(relative, at)) != std::string::npos; at += absolute.size())
    yaml.replace(at, relative.size(), absolute);
  const std::string key = "- {name: advanced}";
  const std::size_t at = yaml.find(key);
  EXPECT_NE(at, std::string::npos);
  yaml.replace(at, key.size(), fmt::format("- {{name: advanced, duration: {}}}", duration_s));
  const fs::path file = dir / "oc4-advanced.yaml";
  std::ofstream(file) << yaml;
  return file;
}

// The advanced stage: the critical cases run coupled and sc-enhanced for the
// project's duration; the comparison table's differences are those of its
// own values, S-C is cheaper than coupled, every line's final utilization is
// its coupled MPM with the API dynamic factor, the PDF renders page by page
// and its text holds the comparison values and the verdict with its governing check.
TEST(CliReportStages, AdvancedVerifiesTheCriticalCasesCoupled) {
  const fs::path dir = fresh_dir("spiral-cli-report-advanced");
  const fs::path folder = dir / "report";
  const auto result = run_spiral("report '" + oc4_with_advanced_duration(dir, 300.0).string() +
                                 "' --stage advanced --out '" + folder.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(result.out, m, std::regex(R"(\((\d+) pages\))"))) << result.out;
  const int pages = std::stoi(m[1]);
  EXPECT_GE(pages, 6);  // title, model, load cases, critical cases, final check, one section per case
  const fs::path png_dir = dir / "png";
  fs::create_directories(png_dir);
  ASSERT_EQ(std::system(fmt::format("pdftoppm -r 20 -png '{}' '{}/p' 2>/dev/null", (folder / "report.pdf").string(),
                                    png_dir.string())
                            .c_str()),
            0);
  int count = 0;
  for (const auto& e : fs::directory_iterator(png_dir)) count += e.path().extension() == ".png" ? 1 : 0;
  EXPECT_EQ(count, pages);
  const fs::path txt = dir / "report.txt";
  ASSERT_EQ(
      std::system(fmt::format("pdftotext -layout '{}' '{}'", (folder / "report.pdf").string(), txt.string()).c_str()),
      0);
  const std::string text = read_text(txt);
  const std::string flat = squeeze(text);

  // Coupled vs S-C: rows in (sc-enhanced, coupled) pairs; Δ = 100 (S-C − coupled) / |coupled|.
  const auto cmp = read_csv(folder / "tables" / "case-intact-raft-jonswap-comparison.csv");
  ASSERT_EQ(cmp.size(), 1u + 2u * 3u);  // offset, surge, tension of the most loaded line
  ASSERT_EQ(cmp[0][5], "MPM");
  ASSERT_EQ(cmp[0][9], "Δ MPM (%)");
  for (std::size_t i = 1; i + 1 < cmp.size(); i += 2) {
    const auto &sc = cmp[i], &coupled = cmp[i + 1];
    ASSERT_EQ(sc[1], "sc-enhanced");
    ASSERT_EQ(coupled[1], "coupled");
    for (int col = 2; col <= 5; ++col) {
      const double s = std::stod(sc[col]), c = std::stod(coupled[col]);
      // The CSV keeps 10 significant digits: 1e-6 relative is far above their rounding.
      const double expected = c == 0.0 ? 0.0 : 100.0 * (s - c) / std::abs(c);
      EXPECT_NEAR(std::stod(sc[col + 4]), expected, 1e-6 * (1.0 + std::abs(expected)))
          << sc[0] << " column " << cmp[0][col];
    }
    // The coupled MPM as the PDF table shows it (kN to 1 decimal, m to 3).
    const bool tension = coupled[0].rfind("tension", 0) == 0;
    const std::string shown = fmt::format("{:.{}f}", std::stod(coupled[5]), tension ? 1 : 3);
    EXPECT_NE(text.find(shown), std::string::npos) << coupled[0] << " MPM " << shown;
  }
  const auto cost = read_csv(folder / "tables" / "case-intact-raft-jonswap-cost.csv");
  ASSERT_EQ(cost.size(), 3u);
  ASSERT_EQ(cost[1][0], "sc-enhanced");
  const double sc_wall = std::stod(cost[1][1]), coupled_wall = std::stod(cost[2][1]);
  EXPECT_NEAR(std::stod(cost[1][3]), coupled_wall / sc_wall, 1e-9 * coupled_wall / sc_wall);
  EXPECT_GT(std::stod(cost[1][3]), 1.0) << "S-C must be cheaper than coupled";
  EXPECT_NEAR(std::stod(cost[1][2]), 300.0 / sc_wall, 1e-9 * 300.0 / sc_wall);
  EXPECT_TRUE(fs::exists(folder / "figures" / "case-intact-raft-jonswap-levels.svg"));

  // Final check: API RP 2SK intact dynamic factor 1.67 on every line's coupled MPM.
  const auto lines = read_csv(folder / "tables" / "final-tension.csv");
  ASSERT_EQ(lines.size(), 1u + 2u * 3u);  // both cases, three lines
  double worst = 0.0;
  std::string worst_text;
  bool all_pass = true;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const double mpm = std::stod(lines[i][4]), mbl = std::stod(lines[i][5]), u = std::stod(lines[i][7]);
    EXPECT_NEAR(u, mpm * 1.67 / mbl, 1e-8 * u) << lines[i][0] << " " << lines[i][1];
    EXPECT_EQ(lines[i][8], u <= 1.0 ? "PASS" : "FAIL");
    all_pass = all_pass && u <= 1.0;
    if (u > worst) worst = u, worst_text = fmt::format("{}: dynamic tension {} {:.3f}", lines[i][0], lines[i][1], u);
  }
  const auto offsets = read_csv(folder / "tables" / "final-offset.csv");
  ASSERT_EQ(offsets.size(), 3u);
  for (std::size_t i = 1; i < offsets.size(); ++i) {
    const double ratio = std::stod(offsets[i][3]);
    EXPECT_NEAR(ratio, std::stod(offsets[i][1]) / 20.0, 1e-9);  // 10 % of 200 m
    all_pass = all_pass && ratio <= 1.0;
    if (ratio > worst)
      worst = ratio, worst_text = fmt::format("{}: MPM offset {:.2f} m", offsets[i][0], std::stod(offsets[i][1]));
  }
  EXPECT_NE(result.out.find(all_pass ? "(PASS)" : "(FAIL)"), std::string::npos) << result.out;
  EXPECT_NE(flat.find(all_pass ? "PASS — all 2 critical cases verified fully coupled" : "FAIL —"), std::string::npos);
  EXPECT_NE(flat.find(worst_text), std::string::npos) << worst_text;
  EXPECT_NE(flat.find("coupled and sc-enhanced, 300 s each"), std::string::npos);
  fs::remove_all(dir);
}

/// The OC4 scenario with hull.geometry.panel_mesh set to `mesh`, written into
/// `dir` (its data paths made absolute so that it runs from there).
fs::path oc4_with_panel_mesh(const fs::path& dir, const std::string& mesh) {
  std::string yaml = read_text(fs::path(SPIRAL_SOURCE_DIR) / "scenarios" / "oc4-semisubmersible.yaml");
  const std::string relative = "data/hydro/", absolute = SPIRAL_SCENARIO_DATA_DIR "/hydro/";
  for (std::size_t at = 0; (at = yaml.find(relative, at)) != std::string::npos; at += absolute.size())
    yaml.replace(at, relative.size(), absolute);
  const std::string key = "\n  geometry:\n";
  const std::size_t at = yaml.find(key);
  EXPECT_NE(at, std::string::npos);
  yaml.insert(at + key.size(),
              "    panel_mesh: " + std::string(SPIRAL_SOURCE_DIR) + "/tests/data/panel-mesh/" + mesh + "\n");
  const fs::path file = dir / "oc4-mesh.yaml";
  std::ofstream(file) << yaml;
  return file;
}

TEST(CliReportPanelMesh, ReportRunsWithTheMeshNamedInTheModelSummary) {
  const fs::path dir = fresh_dir("spiral-cli-report-mesh");
  const auto result = run_spiral("report '" + oc4_with_panel_mesh(dir, "oc4-columns.gdf").string() + "' --out '" +
                                 (dir / "report").string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  ASSERT_EQ(std::system(fmt::format("pdftotext '{}' '{}'", (dir / "report" / "report.pdf").string(),
                                    (dir / "report.txt").string())
                            .c_str()),
            0);
  EXPECT_NE(read_text(dir / "report.txt").find("oc4-columns.gdf (drawn as the hull"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliReportPanelMesh, MalformedMeshExitsTwoNamingFileAndLine) {
  const fs::path dir = fresh_dir("spiral-cli-report-bad-mesh");
  const auto result = run_spiral("report '" + oc4_with_panel_mesh(dir, "malformed_line7.gdf").string() + "' --out '" +
                                 (dir / "report").string() + "'");
  EXPECT_EQ(result.exit_code, app::kExitBadInput) << result.err;
  EXPECT_NE(result.err.find("malformed_line7.gdf:7:"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir / "report"));
  fs::remove_all(dir);
}

TEST(CliReportErrors, UnknownStageIsBadInput) {
  const auto result = run_spiral("report " + scenario("oc4-semisubmersible.yaml") + " --stage nosuch --out /tmp/x");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("nosuch"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace spiral::test
