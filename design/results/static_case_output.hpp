#pragma once
// Output of a coupled static case: the JSON documented in
// docs/output-format.md (the `spiral equilibrium` and `spiral stiffness`
// tables: report/terminal).

#include <string>

#include <nlohmann/json.hpp>

#include "design/analysis/static_case.hpp"

namespace spiral::design {

/// JSON document `spiral.static_case` v1.
nlohmann::json static_case_to_json(const StaticCaseResult& result, const std::string& project_name);

}  // namespace spiral::design
