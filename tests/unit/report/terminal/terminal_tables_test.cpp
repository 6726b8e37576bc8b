// The terminal tables of the CLI: what each row shows and in which unit.
#include <gtest/gtest.h>

#include <string>

#include "report/terminal/comparison_table.hpp"
#include "report/terminal/statics_table.hpp"

namespace spiral::report {
namespace {

TEST(TerminalTables, StaticsTableHasOneRowPerLineInKilonewtons) {
  design::StaticsResult result;
  design::LineStaticsRow row;
  row.name = "L1";
  row.fairlead_tension_N = 1234.5e3;
  row.utilization = 0.4321;
  row.regime = engine::LineRegime::touchdown;
  result.lines.push_back(row);
  result.hull_force(0) = -2000.0e3;
  const std::string table = statics_table(result, "demo");
  EXPECT_NE(table.find("Mooring statics — demo"), std::string::npos) << table;
  EXPECT_NE(table.find("L1"), std::string::npos) << table;
  EXPECT_NE(table.find("1234.5"), std::string::npos) << table;
  EXPECT_NE(table.find("0.432"), std::string::npos) << table;
  EXPECT_NE(table.find("touchdown"), std::string::npos) << table;
  EXPECT_NE(table.find("Fx -2000.0 kN"), std::string::npos) << table;
}

TEST(TerminalTables, ComparisonTableGivesMpmDifferenceAgainstCoupled) {
  design::LevelComparison c;
  auto level = [](design::AnalysisLevel l, double mpm, double wall_s) {
    design::LevelSummary s;
    s.level = l;
    s.wall_s = wall_s;
    design::ChannelSummary offset;
    offset.name = "offset_m";
    offset.unit = "m";
    offset.moments.maximum = mpm;
    offset.mpm = mpm;
    s.channels.push_back(offset);
    return s;
  };
  c.levels.push_back(level(design::AnalysisLevel::semi_coupled, 11.0, 1.0));
  c.levels.push_back(level(design::AnalysisLevel::coupled, 10.0, 100.0));
  engine::DofDamping surge;
  surge.dof = 0;
  surge.natural_period_s = 110.4;
  surge.damping_ratio = 0.0412;
  c.levels.front().low_frequency_damping.push_back(surge);
  const std::string table = comparison_table(c);
  EXPECT_NE(table.find("offset_m [m]"), std::string::npos) << table;
  EXPECT_NE(table.find("+10%"), std::string::npos) << table;    // sc against coupled
  EXPECT_NE(table.find("100.0x"), std::string::npos) << table;  // speed-up of sc
  // The slow surge's damping ratio of each level that reduces the lines to
  // one; the coupled level has none.
  const std::size_t row = table.find("surge LF damping [%]");
  ASSERT_NE(row, std::string::npos) << table;
  const std::string line = table.substr(row, table.find('\n', row) - row);
  EXPECT_NE(line.find("4.12 at 110 s"), std::string::npos) << line;
  EXPECT_NE(line.find("| " + std::string(23, ' ') + "-"), std::string::npos) << line;
}

}  // namespace
}  // namespace spiral::report
