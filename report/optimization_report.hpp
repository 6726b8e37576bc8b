#pragma once
// The report of a pretension optimization (`spiral report --stage
// optimization`): the verdict, the offsets of every scenario against the
// platform SOZ before and after (plan view, intact and damaged), the
// iteration history, the payout list as an installation table, the
// scenarios before/after, the active constraints, and — when the pretension
// study ran — its trade-off plot with the feasible band. Reads results only.

#include <optional>

#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_study.hpp"
#include "design/project/validated_project.hpp"
#include "report/document.hpp"
#include "report/static_stage_report.hpp"

namespace spiral::report {

ReportDocument optimization_report(const design::ValidatedProject& project, const design::OptimizationResult& result,
                                   const std::optional<design::PretensionStudyResult>& study, const ReportInfo& info);

}  // namespace spiral::report
