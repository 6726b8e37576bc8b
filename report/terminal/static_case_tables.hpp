#pragma once
// `spiral equilibrium` and `spiral stiffness` in a terminal: the tables of a
// coupled static case.

#include <string>

#include "design/analysis/static_case.hpp"

namespace spiral::report {

/// Equilibrium table: offsets, per-line quantities, force balance.
std::string equilibrium_table(const design::StaticCaseResult& result, const std::string& project_name);

/// Stiffness table: the 6×6 matrix, the force vector, the FD check, natural periods.
std::string stiffness_table(const design::StaticCaseResult& result, const std::string& project_name);

}  // namespace spiral::report
