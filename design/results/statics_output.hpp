#pragma once
// Output of the statics study: the machine JSON whose keys are the contract
// documented in docs/output-format.md (the terminal table: report/terminal).

#include <string>

#include <nlohmann/json.hpp>

#include "design/analysis/statics_study.hpp"

namespace spiral::design {

/// JSON document `spiral.statics` v1 (docs/output-format.md).
nlohmann::json statics_to_json(const StaticsResult& result, const std::string& project_name);

}  // namespace spiral::design
