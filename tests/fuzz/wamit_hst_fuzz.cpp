// libFuzzer harness: a WAMIT .hst file (hydrostatic restoring) as a hull's
// data reaches engine::parse_wamit_hst. Documented rejection:
// engine::FileFormatError naming the file and line.

#include <cstddef>
#include <cstdint>
#include <sstream>

#include "engine/hull/wamit_hst.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spiral;
  const std::string source = "fuzz-input.hst";
  std::istringstream text(fuzz::input_text(data, size));
  try {
    (void)engine::parse_wamit_hst(text, source, engine::WamitHstScaling{});
  } catch (const engine::FileFormatError& error) {
    fuzz::check_file_format_error(error, source);
  }
  return 0;
}
