#pragma once
// The report of the intermediate stage (design::run_intermediate_stage):
// title page with the verdict, model summary, load cases, the ranking of the
// load cases and the critical ones, the SOZ with every storm's MPM offset,
// and the storms of the critical cases. Reads results only.

#include "design/stages/intermediate_stage.hpp"
#include "design/project/validated_project.hpp"
#include "report/document.hpp"
#include "report/static_stage_report.hpp"

namespace spiral::report {

ReportDocument intermediate_stage_report(const design::ValidatedProject& project,
                                         const design::IntermediateStageResults& results, const ReportInfo& info);

}  // namespace spiral::report
