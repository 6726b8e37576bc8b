// libFuzzer harness: a WAMIT .12d file (difference-frequency QTFs, of which
// the mean drift diagonal is kept) as a hull's `mean_drift.file` reaches
// engine::parse_wamit_12d_mean_drift. Documented rejection:
// engine::FileFormatError naming the file and line.

#include <cstddef>
#include <cstdint>
#include <sstream>

#include "engine/hull/wamit_12d.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spiral;
  const std::string source = "fuzz-input.12d";
  std::istringstream text(fuzz::input_text(data, size));
  try {
    (void)engine::parse_wamit_12d_mean_drift(text, source, 1025.0, 9.80665, 1.0);
  } catch (const engine::FileFormatError& error) {
    fuzz::check_file_format_error(error, source);
  }
  return 0;
}
