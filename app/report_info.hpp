#pragma once
// What every report's title page says about its run: the project file, its
// hash, the date (SOURCE_DATE_EPOCH fixes it, reproducible-builds.org) and
// the spiral version.
#include <string>

#include "report/static_stage_report.hpp"

namespace spiral::app {

report::ReportInfo report_info(const std::string& project_file);

}  // namespace spiral::app
