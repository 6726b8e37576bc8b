#pragma once
// Output of `spiral compare`: the JSON document (comparison.json,
// docs/output-format.md) of a level comparison; its terminal table is in
// report/terminal.

#include <string>

#include <nlohmann/json.hpp>

#include "design/analysis/level_comparison.hpp"

namespace spiral::design {

/// {"load_case", "seed", "duration_s", "levels": {"sc": {"wall_s",
/// "speedup_vs_coupled", "max_offset_m", "channels": {name: {mean, std, max,
/// mpm, "diff_pct_vs_coupled": {…}}}}, …}} (docs/output-format.md).
nlohmann::json comparison_to_json(const LevelComparison& comparison);

}  // namespace spiral::design
