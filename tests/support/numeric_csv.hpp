#pragma once
// A comma-separated table of numbers as the validation data under
// tests/data/validation/ store them: lines that are blank or start with '#'
// are comments, the first other line names the columns, every later line is
// one row of numbers. Shared by the tests that read such a reference.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace spiral::test {

struct NumericCsv {
  std::string header;                     ///< the column names, as written
  std::vector<std::vector<double>> rows;  ///< one entry per data line, as many values as it has cells
};

/// An unreadable file is a test failure (and an empty table).
inline NumericCsv read_numeric_csv(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  NumericCsv table;
  std::string row;
  bool header_seen = false;
  while (std::getline(in, row)) {
    if (row.empty() || row[0] == '#') continue;
    if (!header_seen) {
      table.header = row;
      header_seen = true;
      continue;
    }
    std::vector<double> values;
    std::stringstream cells(row);
    std::string cell;
    while (std::getline(cells, cell, ',')) values.push_back(std::stod(cell));
    table.rows.push_back(std::move(values));
  }
  return table;
}

}  // namespace spiral::test
