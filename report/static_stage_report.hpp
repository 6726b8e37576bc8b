#pragma once
// The report of the preliminary stage's static analyses (design::run_static_stage):
// title page, model summary, load cases, pretensions, static-case results
// with the mooring code check, stiffness and natural periods, and the 3D
// views and plots. Reads results only.

#include <string>

#include "design/static_stage.hpp"
#include "design/validated_project.hpp"
#include "report/document.hpp"

namespace spiral::report {

/// What the title page says about the run.
struct ReportInfo {
  std::string project_file;
  std::string model_hash;  ///< design::model_hash of the project file
  std::string date;        ///< e.g. "2026-11-22 14:03 UTC"
  std::string version;     ///< spiral version
};

struct StaticStageReportOptions {
  int view_width = 1600;  ///< 3D views, px
  int view_height = 1200;
};

/// Builds the document (renders the 3D views). Throws std::runtime_error
/// when a view cannot be rendered.
ReportDocument static_stage_report(const design::ValidatedProject& project,
                                   const design::StaticStageResults& results,
                                   const ReportInfo& info,
                                   const StaticStageReportOptions& options = {});

}  // namespace spiral::report
