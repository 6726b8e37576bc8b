#pragma once
// `spiral statics` in a terminal: the fixed-width table of the statics study.

#include <string>

#include "design/analysis/statics_study.hpp"

namespace spiral::report {

/// Fixed-width table for a terminal: one row per line, then the hull force.
std::string statics_table(const design::StaticsResult& result, const std::string& project_name);

}  // namespace spiral::report
