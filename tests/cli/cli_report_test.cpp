// End-to-end `spiral report`: the PDF opens and holds the results, the HTML
// index links only files that exist, bad output folders fail cleanly.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"

namespace spiral::test {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

class CliReport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fresh_dir("spiral-cli-report"));
    result_ = new CommandResult(run_spiral("report " + scenario("deepwater-fps.yaml") + " --out '" +
                                           (*dir_ / "report").string() + "'"));
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
  ASSERT_EQ(std::system(fmt::format("pdftoppm -r 20 -png '{}' '{}/p' 2>/dev/null", pdf.string(),
                                    png_dir.string())
                            .c_str()),
            0);
  int count = 0;
  for (const auto& e : fs::directory_iterator(png_dir))
    count += e.path().extension() == ".png" ? 1 : 0;
  EXPECT_EQ(count, pages);
}

void PdfTextHoldsTheResultsTableValues(const CommandResult* result_, const fs::path* dir_) {
  ASSERT_EQ(result_->exit_code, app::kExitOk) << result_->err;
  const fs::path txt = *dir_ / "report.txt";
  ASSERT_EQ(std::system(fmt::format("pdftotext -layout '{}' '{}'",
                                    (*dir_ / "report" / "report.pdf").string(), txt.string())
                            .c_str()),
            0);
  const std::string text = read_text(txt);
  // Pretensions from `spiral statics`, the damaged case from `spiral equilibrium`.
  const auto statics =
      nlohmann::json::parse(run_spiral("statics --json " + scenario("deepwater-fps.yaml")).out);
  for (const auto& line : statics["lines"]) {
    const std::string value =
        fmt::format("{:.1f}", line["fairlead_tension_N"].get<double>() / 1000.0);
    EXPECT_NE(text.find(value), std::string::npos) << line["name"] << " pretension " << value;
  }
  const auto damaged =
      nlohmann::json::parse(run_spiral("equilibrium --json --case lc3-survival-45deg-damaged-L10 " +
                                       scenario("deepwater-fps.yaml"))
                                .out);
  int found = 0;
  for (const auto& line : damaged["lines"]) {
    const std::string value = fmt::format("{:.1f}", line["max_tension_N"].get<double>() / 1000.0);
    found += text.find(value) != std::string::npos ? 1 : 0;
  }
  EXPECT_EQ(found, static_cast<int>(damaged["lines"].size()));
  EXPECT_NE(text.find("PASS"), std::string::npos);
}

void HtmlReferencesOnlyFilesThatExist(const CommandResult* result_, const fs::path* dir_) {
  ASSERT_EQ(result_->exit_code, app::kExitOk) << result_->err;
  const fs::path folder = *dir_ / "report";
  const std::string html = read_text(folder / "index.html");
  const std::regex ref(R"re((?:src|href)="([^"#][^"]*)")re");
  int refs = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), ref); it != std::sregex_iterator();
       ++it) {
    const std::string target = (*it)[1];
    EXPECT_EQ(target.find("://"), std::string::npos) << target;
    EXPECT_TRUE(fs::exists(folder / target)) << target;
    ++refs;
  }
  EXPECT_GT(refs, 10);
  EXPECT_TRUE(fs::exists(folder / "tables" / "pretensions.csv"));
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
}

TEST(CliReportErrors, UnwritableOutputFolderExitsFourNamingItAndLeavesNothing) {
  const fs::path dir = fresh_dir("spiral-cli-report-bad");
  std::ofstream(dir / "a-file") << "not a folder";
  const fs::path out = dir / "a-file" / "report";
  const auto result = run_spiral("report " + scenario("oc4-semisubmersible.yaml") + " --out '" +
                                 out.string() + "'");
  EXPECT_EQ(result.exit_code, app::kExitOutputError) << result.err;
  EXPECT_NE(result.err.find(out.string()), std::string::npos) << result.err;
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);  // only a-file
  fs::remove_all(dir);
}

TEST(CliReportErrors, UnknownStageIsBadInput) {
  const auto result =
      run_spiral("report " + scenario("oc4-semisubmersible.yaml") + " --stage nosuch --out /tmp/x");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("nosuch"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace spiral::test
