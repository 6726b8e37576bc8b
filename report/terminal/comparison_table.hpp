#pragma once
// `spiral compare` in a terminal: the side-by-side table of the analysis levels.

#include <string>

#include "design/analysis/level_comparison.hpp"

namespace spiral::report {

/// A compact side-by-side table (max and MPM per level, % against coupled).
std::string comparison_table(const design::LevelComparison& comparison);

}  // namespace spiral::report
