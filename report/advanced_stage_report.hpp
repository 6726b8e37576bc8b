#pragma once
// The report of the advanced stage (design::run_advanced_stage): title page
// with the final verdict, model summary, load cases, the critical cases
// chosen by the intermediate ranking, the final criteria check from the
// coupled runs, the SOZ with the coupled MPM offsets, and per critical case
// the coupled-vs-S-C comparison (statistics, % difference, wall clock and
// speed-up; surge, offset and tension of both levels on one plot) and the
// coupled storm. Reads results only.

#include "design/stages/advanced_stage.hpp"
#include "design/project/validated_project.hpp"
#include "report/document.hpp"
#include "report/static_stage_report.hpp"

namespace spiral::report {

ReportDocument advanced_stage_report(const design::ValidatedProject& project,
                                     const design::AdvancedStageResults& results, const ReportInfo& info);

}  // namespace spiral::report
