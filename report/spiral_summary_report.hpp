#pragma once
// The summary report of a spiral run (design/workflow/spiral_run.hpp): the
// verdict, the findings, every stage of every iteration with its verdict and
// governing check, the feedback iterations (why the optimizer ran, the
// payouts it chose, what they did to the checks), the failed tasks, and
// where each stage's numbers come from (iteration, model hash, levels, seeds,
// durations, the results store).

#include "design/workflow/spiral_run.hpp"
#include "report/document.hpp"
#include "report/static_stage_report.hpp"

namespace spiral::report {

ReportDocument spiral_summary_report(const design::ValidatedProject& project, const design::SpiralRunResult& run,
                                     const ReportInfo& info);

}  // namespace spiral::report
