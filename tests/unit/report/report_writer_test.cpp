// The report folder is written whole or not at all.
#include "report/report_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "support/temp_folder.hpp"

namespace spiral::report {
namespace {

namespace fs = std::filesystem;

ReportDocument small_document() {
  ReportDocument doc;
  doc.title.title = "Test report";
  doc.title.project = "test";
  doc.title.verdict = "PASS";
  Section s{"Results", {}, true};
  s.blocks.emplace_back(Paragraph{"Some text."});
  s.blocks.emplace_back(Table{
      "values", "Values.", {"Name", "Value (kN)"}, {{{"a", 1.5, CellStatus::none}, {"12.5", 12.5, CellStatus::pass}}}});
  Figure f;
  f.id = "plot";
  f.caption = "A plot.";
  f.draw = [](cairo_t*, double, double) {};
  s.blocks.emplace_back(f);
  doc.sections.push_back(s);
  return doc;
}

fs::path fresh_dir(const std::string& name) { return test::fresh_temp_folder(name); }

bool has_leftovers(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string n = entry.path().filename().string();
    if (n.find(".tmp-") != std::string::npos || n.find(".old-") != std::string::npos) return true;
  }
  return false;
}

TEST(ReportWriter, WritesPdfHtmlCsvAndReplacesAnOldReport) {
  const fs::path dir = fresh_dir("spiral-writer");
  const fs::path out = dir / "report";
  fs::create_directories(out);
  std::ofstream(out / "stale.txt") << "old";
  const WrittenReport written = write_report(small_document(), out);
  EXPECT_TRUE(fs::exists(out / "report.pdf"));
  EXPECT_TRUE(fs::exists(out / "index.html"));
  EXPECT_TRUE(fs::exists(out / "tables" / "values.csv"));
  EXPECT_TRUE(fs::exists(out / "figures" / "plot.svg"));
  EXPECT_FALSE(fs::exists(out / "stale.txt"));
  EXPECT_EQ(written.pages, 2);
  EXPECT_FALSE(has_leftovers(dir));
  fs::remove_all(dir);
}

TEST(ReportWriter, UnwritableFolderIsAnOutputErrorNamingIt) {
  const fs::path dir = fresh_dir("spiral-writer-bad");
  std::ofstream(dir / "a-file") << "not a folder";
  const fs::path out = dir / "a-file" / "report";
  try {
    write_report(small_document(), out);
    FAIL() << "expected OutputError";
  } catch (const OutputError& error) {
    EXPECT_NE(std::string(error.what()).find(out.string()), std::string::npos) << error.what();
  }
  EXPECT_FALSE(has_leftovers(dir));
  fs::remove_all(dir);
}

TEST(ReportWriter, FailureHalfwayLeavesTheOldReportAndNoTemporaryFolder) {
  const fs::path dir = fresh_dir("spiral-writer-half");
  const fs::path out = dir / "report";
  write_report(small_document(), out);
  const auto old_size = fs::file_size(out / "report.pdf");
  ReportDocument broken = small_document();
  Figure f;
  f.id = "broken";
  f.draw = [](cairo_t*, double, double) { throw std::runtime_error("figure failed"); };
  broken.sections[0].blocks.emplace_back(f);
  EXPECT_THROW(write_report(broken, out), OutputError);
  EXPECT_EQ(fs::file_size(out / "report.pdf"), old_size);
  EXPECT_FALSE(has_leftovers(dir));
  fs::remove_all(dir);
}

// A note the design layer marks "warning: " reads as a warning in the
// report; every other note as a note.
TEST(ReportWriter, WarningNotesReadAsWarnings) {
  EXPECT_EQ(note_paragraph("warning: surge is all but undamped").text, "Warning: surge is all but undamped.");
  EXPECT_EQ(note_paragraph("current on the lines").text, "Note: current on the lines.");
  EXPECT_EQ(note_paragraph("a warning: inside").text, "Note: a warning: inside.");
}

TEST(ReportWriter, CsvQuotesTextAndKeepsFullPrecision) {
  Table t{
      "t", "", {"Name", "Value"}, {{{"a, b", std::nullopt, CellStatus::none}, {"1.2", 1.23456789, CellStatus::none}}}};
  EXPECT_EQ(table_csv(t), "Name,Value\n\"a, b\",1.23456789\n");
}

}  // namespace
}  // namespace spiral::report
