#pragma once
// Output of `spiral optimize`: the JSON document (optimization.json,
// docs/output-format.md) and the terminal tables of a pretension
// optimization and of the target-pretension mode.

#include <string>

#include <nlohmann/json.hpp>

#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_target.hpp"

namespace spiral::design {

/// {"format": "spiral.optimization", "status", "objective", "algorithm",
/// "groups", "payouts", "lines", "scenarios": {before, after}, "history",
/// "active_constraints", ...} (docs/output-format.md).
nlohmann::json optimization_to_json(const OptimizationResult& result);

/// The history, the payout table per group and line, and the scenarios
/// before/after, for the terminal.
std::string optimization_table(const OptimizationResult& result);

/// {"format": "spiral.target_pretension", "lines": [...]}.
nlohmann::json target_pretension_to_json(const TargetPretensionResult& result);
std::string target_pretension_table(const TargetPretensionResult& result);

/// The comment header of the optimized project file: how it was made.
std::string optimized_project_header(const OptimizationResult& result, const std::string& source_file);
std::string target_pretension_header(const std::string& source_file);

}  // namespace spiral::design
