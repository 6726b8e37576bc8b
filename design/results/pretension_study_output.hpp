#pragma once
// Output of `spiral study pretension`: JSON (spiral.pretension_study,
// docs/output-format.md), CSV (one row per sweep point) and the terminal table.

#include <string>

#include <nlohmann/json.hpp>

#include "design/optimization/pretension_study.hpp"

namespace spiral::design {

nlohmann::json pretension_study_to_json(const PretensionStudyResult& result);
std::string pretension_study_csv(const PretensionStudyResult& result);

}  // namespace spiral::design
