#pragma once
// Output of `spiral optimize`: the JSON documents (optimization.json,
// target_pretension.json, docs/output-format.md) and the comment header of
// the project file it writes. Its terminal tables: report/terminal.

#include <string>

#include <nlohmann/json.hpp>

#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_target.hpp"

namespace spiral::design {

/// {"format": "spiral.optimization", "status", "objective", "algorithm",
/// "groups", "payouts", "lines", "scenarios": {before, after}, "history",
/// "active_constraints", ...} (docs/output-format.md).
nlohmann::json optimization_to_json(const OptimizationResult& result);

/// {"format": "spiral.target_pretension", "lines": [...]}.
nlohmann::json target_pretension_to_json(const TargetPretensionResult& result);

/// The comment header of the optimized project file: how it was made.
std::string optimized_project_header(const OptimizationResult& result, const std::string& source_file);
std::string target_pretension_header(const std::string& source_file);

}  // namespace spiral::design
