// The WAMIT readers' shared grid helpers and the reader errors found by the
// fuzz harnesses (tests/fuzz, docs/fuzzing.md), each on its reduced input.
#include "engine/hull/wamit_format.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "engine/common/file_format_error.hpp"
#include "engine/hull/wamit_1.hpp"
#include "engine/hull/wamit_3.hpp"

namespace spiral::engine {
namespace {

// Found by tests/fuzz/wamit_4_fuzz.cpp: 9e-6 and 1e-5 deg are 1e-6 deg + 1 ulp
// apart, so both are grid points, but the search for 1e-5 stopped at 9e-6.
TEST(WamitFormat, EveryValueOfTheGridIsFound) {
  const std::vector<double> headings = {0.0, 9e-6, 1e-5, 2.0};
  const std::vector<double> grid = detail::distinct_sorted(headings, 0.0, 1e-6);
  ASSERT_EQ(grid.size(), 4u);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_EQ(detail::index_in(grid, headings[i], 0.0, 1e-6), static_cast<int>(i)) << headings[i];
  }
  // A merged value finds its grid point; a value off the grid finds none.
  EXPECT_EQ(detail::index_in({1.0, 2.0}, 1.0 + 5e-7, 0.0, 1e-6), 0);
  EXPECT_EQ(detail::index_in({1.0, 2.0}, 1.5, 0.0, 1e-6), -1);
  EXPECT_EQ(detail::index_in({}, 1.5, 0.0, 1e-6), -1);
}

TEST(WamitFormat, HeadingsOneUlpBeyondTheToleranceReadAsTheirOwnRows) {
  std::istringstream text(
      "  6.0  0.000000  1  1.0 0.0  1.0 0.0\n"
      "  6.0  0.000009  1  1.0 0.0  2.0 0.0\n"
      "  6.0  0.000010  1  1.0 0.0  3.0 0.0\n");
  const MotionRaoTable table = parse_wamit_4(text, "headings.4", WamitReadOptions{});
  ASSERT_EQ(table.headings_rad.size(), 3u);
  EXPECT_EQ(table.values[0](2, 0).real(), 3.0);
}

// A period that parses as a finite number can still give 2π/PER = inf.
TEST(WamitFormat, PeriodWithoutAFiniteFrequencyIsALineError) {
  std::istringstream excitation("  1e-310  0.0  1  1.0 0.0  1.0 0.0\n");
  try {
    parse_wamit_3(excitation, "tiny.3", WamitReadOptions{});
    FAIL() << "no error";
  } catch (const FileFormatError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tiny.3:1: ", 0), 0u) << e.what();
  }
  std::istringstream radiation("  1e-310  1 1  1.0 0.5\n");
  try {
    parse_wamit_1(radiation, "tiny.1", WamitReadOptions{});
    FAIL() << "no error";
  } catch (const FileFormatError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tiny.1:1: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace spiral::engine
