#pragma once
// Output of the statics study: the human table and the machine JSON whose keys
// are the contract documented in docs/output-format.md.

#include <string>

#include <nlohmann/json.hpp>

#include "design/analysis/statics_study.hpp"

namespace spiral::design {

/// JSON document `spiral.statics` v1 (docs/output-format.md).
nlohmann::json statics_to_json(const StaticsResult& result, const std::string& project_name);

/// Fixed-width table for a terminal: one row per line, then the hull force.
std::string statics_table(const StaticsResult& result, const std::string& project_name);

}  // namespace spiral::design
