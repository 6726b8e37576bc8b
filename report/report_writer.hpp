#pragma once
// Writes a report folder as a whole or not at all: everything goes into
// `<DIR>.tmp-<pid>` next to DIR, which replaces DIR by rename only once
// complete (an old DIR is removed after the new one is in place). Any
// failure removes the temporary folder and leaves an existing DIR untouched.

#include <filesystem>
#include <stdexcept>
#include <string>

#include "design/results/output_error.hpp"
#include "report/document.hpp"

namespace spiral::report {

/// The report could not be written (the message names the folder or file).
using design::OutputError;

struct WrittenReport {
  std::filesystem::path folder;
  std::filesystem::path pdf;   ///< folder / "report.pdf"
  std::filesystem::path html;  ///< folder / "index.html"
  int pages = 0;
};

/// Writes report.pdf, index.html, figures/ and tables/ into `folder`.
/// Throws OutputError.
WrittenReport write_report(const ReportDocument& document, const std::filesystem::path& folder);

}  // namespace spiral::report
