#pragma once
// Output of a coupled static case: `spiral equilibrium` and `spiral stiffness`
// tables and the JSON documented in docs/output-format.md.

#include <string>

#include <nlohmann/json.hpp>

#include "design/analysis/static_case.hpp"

namespace spiral::design {

/// JSON document `spiral.static_case` v1.
nlohmann::json static_case_to_json(const StaticCaseResult& result, const std::string& project_name);

/// Equilibrium table: offsets, per-line quantities, force balance.
std::string equilibrium_table(const StaticCaseResult& result, const std::string& project_name);

/// Stiffness table: the 6×6 matrix, the force vector, the FD check, natural periods.
std::string stiffness_table(const StaticCaseResult& result, const std::string& project_name);

}  // namespace spiral::design
