#pragma once
// What every reader harness checks about a rejected input: the message names
// the file (the source name the harness passed) and, where the reader reports
// lines, the line. A harness that finds otherwise aborts, so libFuzzer keeps
// the input as a crash (docs/fuzzing.md).

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>

#include "design/project/input_error.hpp"
#include "engine/common/file_format_error.hpp"
#include "engine/hull/wamit_format.hpp"

namespace spiral::fuzz {

[[noreturn]] inline void fail(std::string_view what, std::string_view message) {
  std::fprintf(stderr, "fuzz harness: %.*s\n--- message ---\n%.*s\n", static_cast<int>(what.size()), what.data(),
               static_cast<int>(message.size()), message.data());
  std::abort();
}

/// The input as the reader's text.
inline std::string input_text(const unsigned char* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// A FileFormatError about `source` names it, and its text starts
/// `source:line: ` (or `source: ` for a whole-file problem, line 0).
inline void check_file_format_error(const engine::FileFormatError& error, const std::string& source) {
  const std::string_view text = error.what();
  if (error.file() != source) fail("FileFormatError names another file", text);
  const std::string prefix = error.line() == 0 ? source + ": " : source + ":" + std::to_string(error.line()) + ": ";
  if (!text.starts_with(prefix)) fail("FileFormatError text does not start with file:line:", text);
  if (error.message().empty()) fail("FileFormatError without a problem", text);
}

/// Every issue of an InputError names one of `sources` and a line and column
/// (a text input always has a position to point at; only a missing file has none).
inline void check_input_error(const design::InputError& error, std::string_view source,
                              std::string_view other_source = {}) {
  const std::string_view text = error.what();
  if (error.issues().empty()) fail("InputError without issues", text);
  for (const design::InputIssue& issue : error.issues()) {
    if (issue.file != source && (other_source.empty() || issue.file != other_source)) {
      fail("InputError issue names another file", text);
    }
    if (!issue.line || *issue.line < 1) fail("InputError issue without a line", text);
    if (!issue.column || *issue.column < 1) fail("InputError issue without a column", text);
    if (issue.message.empty()) fail("InputError issue without a message", text);
  }
}

/// The readers of frequency tables (.1, .3, .4) on the input, read with
/// either first column a project may declare (period or angular frequency):
/// `use(parse(text, source, options))`, a FileFormatError checked.
template <class Parse, class Use>
void read_with_each_frequency_column(const std::string& input, const std::string& source, Parse parse, Use use) {
  for (const auto column : {engine::FrequencyColumn::period_s, engine::FrequencyColumn::angular_frequency}) {
    engine::WamitReadOptions options;
    options.frequency_column = column;
    std::istringstream text(input);
    try {
      use(parse(text, source, options));
    } catch (const engine::FileFormatError& error) {
      check_file_format_error(error, source);
    }
  }
}

}  // namespace spiral::fuzz
