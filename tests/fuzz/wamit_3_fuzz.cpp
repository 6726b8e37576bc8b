// libFuzzer harness: a WAMIT .3 file (excitation per unit wave amplitude)
// as a hull's data reaches engine::parse_wamit_3, read with either first column
// a project may declare, then interpolated at a tabulated node as the wave
// response does. Documented rejection: engine::FileFormatError naming the
// file and line.

#include <cstddef>
#include <cstdint>

#include "engine/hull/wamit_3.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spiral;
  fuzz::read_with_each_frequency_column(
      fuzz::input_text(data, size), "fuzz-input.3", engine::parse_wamit_3, [](const engine::WaveTransferTable& table) {
        if (table.omega_rad_per_s.empty() || table.headings_rad.empty()) return;
        (void)engine::transfer_at(table, table.omega_rad_per_s.front(), table.headings_rad.back());
      });
  return 0;
}
