#pragma once
// The report of the preliminary stage's static analyses (design::run_static_stage):
// title page, model summary, load cases, pretensions, static-case results
// with the mooring code check, stiffness and natural periods, and the 3D
// views and plots. Reads results only.

#include <string>

#include "design/stages/static_stage.hpp"
#include "design/project/validated_project.hpp"
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

/// Site, hull, line types, lines and risers (`code`: the mooring code's name).
Section model_summary_section(const design::ValidatedProject& project, const std::string& code);
/// The load cases and their environments.
Section load_cases_section(const design::Project& project);

/// A stage report's frame: the title page's facts (project file, date,
/// version, model hash, stage, code, wall time, SOZ model), running header and
/// footer; the caller adds the title, verdict and sections.
ReportDocument stage_document(const design::Project& project, const ReportInfo& info, const std::string& stage,
                              const std::string& code, const std::string& wall_time, const design::SozResult* soz);

/// Builds the document (renders the 3D views). Throws std::runtime_error
/// when a view cannot be rendered.
ReportDocument static_stage_report(const design::ValidatedProject& project, const design::StaticStageResults& results,
                                   const ReportInfo& info, const StaticStageReportOptions& options = {});

}  // namespace spiral::report
