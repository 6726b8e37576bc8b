// libFuzzer harness: a WAMIT .gdf panel mesh as a hull's `panel_mesh`
// reaches engine::parse_gdf, then mirrored to the whole surface as the
// static stage does. Documented rejection: engine::FileFormatError naming
// the file and line.

#include <cstddef>
#include <cstdint>
#include <sstream>

#include "engine/hull/wamit_gdf.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spiral;
  const std::string source = "fuzz-input.gdf";
  std::istringstream text(fuzz::input_text(data, size));
  try {
    (void)engine::full_surface(engine::parse_gdf(text, source));
  } catch (const engine::FileFormatError& error) {
    fuzz::check_file_format_error(error, source);
  }
  return 0;
}
