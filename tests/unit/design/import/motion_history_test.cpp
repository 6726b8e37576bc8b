// The motion history reader: columns by name and unit, delimiters, and every
// bad input reported at its line and column.
#include "design/import/motion_history.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "design/project/input_error.hpp"

namespace spiral::design {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

InputError error_of(const std::string& text) {
  try {
    parse_motion_history(text, "motion.csv");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError({});
}

TEST(MotionHistory, ReadsColumnsByNameInAnyOrderWithTheirUnits) {
  const MotionHistory m = parse_motion_history(
      "# from another program\n"
      "yaw_deg, time_s, surge_m, sway_m, heave_m, roll_rad, pitch (deg)\n"
      "1.0, 0.0, 2.0, 3.0, 4.0, 0.1, 5.0\n"
      "\n"
      "2.0, 0.5, 2.5, 3.5, 4.5, 0.2, 6.0\r\n",
      "motion.csv");
  ASSERT_EQ(m.time_s.size(), 2u);
  EXPECT_DOUBLE_EQ(m.time_s[1], 0.5);
  EXPECT_DOUBLE_EQ(m.offset(0, 0), 2.0);
  EXPECT_DOUBLE_EQ(m.offset(1, 1), 3.5);
  EXPECT_DOUBLE_EQ(m.offset(2, 0), 4.0);
  EXPECT_DOUBLE_EQ(m.offset(3, 1), 0.2);  // rad as given
  EXPECT_NEAR(m.offset(4, 0), 5.0 * kDeg, 1e-15);
  EXPECT_NEAR(m.offset(5, 1), 2.0 * kDeg, 1e-15);
  EXPECT_TRUE(m.notes.empty());
}

TEST(MotionHistory, ReadsAnalyzeTimeSeriesAndListsWhatItIgnores) {
  // spiral analyze's own CSV: the total motion, then _lf/_wf parts and tensions.
  const MotionHistory m = parse_motion_history(
      "time_s,surge_m,sway_m,heave_m,roll_deg,pitch_deg,yaw_deg,surge_lf_m,tension_L1_N\n"
      "0.000,1,0,0,0,0,0,0.9,1e6\n"
      "0.500,2,0,0,0,0,0,1.8,1.1e6\n",
      "time_series.csv");
  EXPECT_DOUBLE_EQ(m.offset(0, 1), 2.0);
  ASSERT_EQ(m.notes.size(), 1u);
  EXPECT_NE(m.notes[0].find("surge_lf_m, tension_L1_N"), std::string::npos) << m.notes[0];
}

TEST(MotionHistory, ReadsTabsAndBlanksAndDefaultsRotationsToDegrees) {
  const MotionHistory tabs = parse_motion_history(
      "t\tsurge\tsway\theave\troll\tpitch\tyaw\n0\t1\t0\t0\t0\t0\t10\n1\t2\t0\t0\t0\t0\t20\n", "m.txt");
  EXPECT_NEAR(tabs.offset(5, 1), 20.0 * kDeg, 1e-15);
  ASSERT_EQ(tabs.notes.size(), 1u);
  EXPECT_NE(tabs.notes[0].find("roll, pitch, yaw without a unit read in deg"), std::string::npos) << tabs.notes[0];
  const MotionHistory blanks = parse_motion_history(
      "  time  surge sway heave roll pitch yaw\n 0   +1 0 0 0 0 0\n 2  -1e-1 0 0 0 0 0\n", "m.txt");
  EXPECT_DOUBLE_EQ(blanks.time_s[1], 2.0);
  EXPECT_DOUBLE_EQ(blanks.offset(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(blanks.offset(0, 1), -0.1);
}

TEST(MotionHistory, NamesEveryBadValueAtItsLineAndColumn) {
  const InputError e = error_of(
      "time,surge,sway,heave,roll,pitch,yaw\n"
      "0,0,0,0,0,0,0\n"
      "1,abc,0,0,0,0,0\n"
      "2,0,0,nan,0,0,0\n"
      "0,0,0,0,0,0,0\n"
      "3,0,0\n");
  ASSERT_EQ(e.issues().size(), 4u) << e.what();
  EXPECT_EQ(e.issues()[0].line, 3);
  EXPECT_EQ(e.issues()[0].column, 3);
  EXPECT_EQ(e.issues()[0].path, "surge");
  EXPECT_EQ(e.issues()[0].problem, "motion_value_not_a_number");
  EXPECT_EQ(e.issues()[1].line, 4);
  EXPECT_EQ(e.issues()[1].column, 7);
  EXPECT_EQ(e.issues()[1].path, "heave");
  EXPECT_EQ(e.issues()[2].line, 5);
  EXPECT_EQ(e.issues()[2].problem, "motion_time_not_increasing");
  EXPECT_EQ(e.issues()[3].line, 6);
  EXPECT_EQ(e.issues()[3].problem, "motion_row_short");
  EXPECT_NE(std::string(e.what()).find("motion.csv:3:3: surge: \"abc\" is not a finite number (m)"), std::string::npos)
      << e.what();
}

TEST(MotionHistory, NamesMissingRepeatedAndUnknownUnitColumnsInTheHeader) {
  const InputError missing = error_of("time,surge,heave,roll,pitch\n0,0,0,0,0\n1,0,0,0,0\n");
  ASSERT_EQ(missing.issues().size(), 1u);
  EXPECT_EQ(missing.issues()[0].problem, "motion_column_missing");
  EXPECT_NE(missing.issues()[0].message.find("no column sway, yaw"), std::string::npos);
  const InputError repeated = error_of("time,surge,sway,heave,roll,pitch,yaw,surge\n");
  EXPECT_EQ(repeated.issues()[0].problem, "motion_column_repeated");
  EXPECT_EQ(repeated.issues()[0].column, 38);
  const InputError unit = error_of("time,surge_ft,sway,heave,roll_grad,pitch,yaw\n");
  ASSERT_EQ(unit.issues().size(), 2u);
  EXPECT_EQ(unit.issues()[0].problem, "motion_unit_unknown");
  EXPECT_EQ(unit.issues()[0].column, 6);
  EXPECT_NE(unit.issues()[1].message.find("write deg or rad"), std::string::npos);
}

TEST(MotionHistory, RefusesEmptyAndOneRowFilesAndStopsCountingAtTheCap) {
  EXPECT_EQ(error_of("").issues()[0].problem, "empty_motion");
  EXPECT_EQ(error_of("# only a comment\n\n").issues()[0].line, 1);
  EXPECT_EQ(error_of("time,surge,sway,heave,roll,pitch,yaw\n0,0,0,0,0,0,0\n").issues()[0].problem, "motion_too_short");
  std::string many = "time,surge,sway,heave,roll,pitch,yaw\n";
  for (int k = 0; k < 200; ++k) many += "x,0,0,0,0,0,0\n";
  const InputError capped = error_of(many);
  EXPECT_EQ(capped.issues().size(), kMaxMotionIssues);
  EXPECT_EQ(capped.issues().back().problem, "motion_too_many_issues");
}

TEST(MotionHistory, AMissingFileOrAFolderIsNamed) {
  try {
    read_motion_history("/nonexistent/motion.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.issues()[0].file, "/nonexistent/motion.csv");
    EXPECT_EQ(e.issues()[0].problem, "missing_file");
  }
  try {
    read_motion_history("/tmp");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.issues()[0].message.find("is a folder"), std::string::npos);
  }
}

}  // namespace
}  // namespace spiral::design
