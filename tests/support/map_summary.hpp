#pragma once
// The per-line table of a MAP++ .sum file (MAP++ 1.10, OpenFAST r-test):
// rows "Lb", "H", "V", "T", "HAnch" after a bar, one column per line. Read
// by the tests that compare against MAP++'s static solution of the OC4
// mooring (tests/data/validation/oc4/).

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace spiral::test {

struct MapLine {
  double Lb_m = 0.0;     ///< laid length
  double H_N = 0.0;      ///< fairlead horizontal force
  double V_N = 0.0;      ///< fairlead vertical force
  double T_N = 0.0;      ///< fairlead tension
  double HAnch_N = 0.0;  ///< anchor horizontal force
};

inline std::vector<MapLine> read_map_sum(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  std::vector<MapLine> lines;
  std::string row;
  while (std::getline(in, row)) {
    std::stringstream ss(row);
    std::string key;
    ss >> key;
    const auto bar = row.find('|');
    if (bar == std::string::npos) continue;
    const double value = std::atof(row.c_str() + bar + 1);
    if (key == "Lb") lines.push_back({value, 0, 0, 0, 0});
    if (lines.empty()) continue;
    if (key == "H") lines.back().H_N = value;
    if (key == "V") lines.back().V_N = value;
    if (key == "T") lines.back().T_N = value;
    if (key == "HAnch") lines.back().HAnch_N = value;
  }
  return lines;
}

}  // namespace spiral::test
