// libFuzzer harness: a WAMIT .1 file (added mass and damping) as a hull's
// `radiation_file` reaches engine::parse_wamit_1, read with either first
// column a project may declare, then interpolated as the hull model does.
// Documented rejection: engine::FileFormatError naming the file and line.

#include <cstddef>
#include <cstdint>

#include "engine/hull/wamit_1.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spiral;
  fuzz::read_with_each_frequency_column(fuzz::input_text(data, size), "fuzz-input.1", engine::parse_wamit_1,
                                        [](const engine::HydroCoefficients& table) {
                                          if (table.omega_rad_per_s.empty()) return;
                                          const double w = table.omega_rad_per_s[table.omega_rad_per_s.size() / 2];
                                          (void)engine::added_mass_at(table, w);
                                          (void)engine::damping_at(table, 1.01 * w);
                                        });
  return 0;
}
