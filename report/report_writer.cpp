#include "report/report_writer.hpp"

#include <fmt/format.h>
#include <unistd.h>

namespace spiral::report {

namespace fs = std::filesystem;

namespace {

fs::path sibling(const fs::path& folder, const std::string& suffix) {
  return folder.parent_path() / (folder.filename().string() + suffix + std::to_string(::getpid()));
}

}  // namespace

WrittenReport write_report(const ReportDocument& document, const fs::path& requested) {
  const fs::path folder = fs::absolute(requested).lexically_normal();
  const fs::path tmp = sibling(folder, ".tmp-");
  std::error_code ec;
  fs::create_directories(folder.parent_path(), ec);
  if (ec) {
    throw OutputError(fmt::format("cannot write the report to '{}': cannot create '{}' ({})", requested.string(),
                                  folder.parent_path().string(), ec.message()));
  }
  fs::remove_all(tmp, ec);
  if (!fs::create_directory(tmp, ec) || ec) {
    throw OutputError(fmt::format("cannot write the report to '{}': cannot create a folder in '{}' ({})",
                                  requested.string(), folder.parent_path().string(),
                                  ec ? ec.message() : "it already exists"));
  }
  WrittenReport written;
  try {
    written.pages = write_pdf(document, (tmp / "report.pdf").string());
    write_html(document, tmp.string());
  } catch (const std::exception& error) {
    fs::remove_all(tmp, ec);
    throw OutputError(fmt::format("cannot write the report to '{}': {}", requested.string(), error.what()));
  }
  // Swap in the complete folder; the old one goes only once the new one is in place.
  const fs::path old = sibling(folder, ".old-");
  const bool had_old = fs::exists(folder);
  if (had_old) {
    fs::remove_all(old, ec);
    fs::rename(folder, old, ec);
    if (ec) {
      fs::remove_all(tmp);
      throw OutputError(fmt::format("cannot replace the report folder '{}' ({})", requested.string(), ec.message()));
    }
  }
  fs::rename(tmp, folder, ec);
  if (ec) {
    if (had_old) fs::rename(old, folder);
    fs::remove_all(tmp);
    throw OutputError(fmt::format("cannot write the report to '{}' ({})", requested.string(), ec.message()));
  }
  if (had_old) fs::remove_all(old, ec);
  written.folder = folder;
  written.pdf = folder / "report.pdf";
  written.html = folder / "index.html";
  return written;
}

}  // namespace spiral::report
