#include "app/report_info.hpp"

#include <cstdlib>
#include <ctime>

#include "app/version.hpp"
#include "design/project/model_hash.hpp"

namespace spiral::app {

namespace {

/// UTC date of the report; SOURCE_DATE_EPOCH (reproducible-builds.org) fixes it.
std::string report_date() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) now = static_cast<std::time_t>(std::atoll(epoch));
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &utc);
  return buffer;
}

}  // namespace

report::ReportInfo report_info(const std::string& project_file) {
  report::ReportInfo info;
  info.project_file = project_file;
  info.model_hash = design::model_hash(project_file);
  info.date = report_date();
  info.version = kVersion;
  return info;
}

}  // namespace spiral::app
