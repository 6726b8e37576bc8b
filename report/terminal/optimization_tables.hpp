#pragma once
// `spiral optimize` and `spiral study pretension` in a terminal: the history,
// the payout table per line, the scenarios before/after and the active
// constraints; the target-pretension table; the pretension sweep.

#include <string>

#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_study.hpp"
#include "design/optimization/pretension_target.hpp"

namespace spiral::report {

std::string optimization_table(const design::OptimizationResult& result);
std::string target_pretension_table(const design::TargetPretensionResult& result);
std::string pretension_study_table(const design::PretensionStudyResult& result);

}  // namespace spiral::report
