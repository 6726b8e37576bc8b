// libFuzzer harness: a project file as `spiral validate` reads it — the
// strict YAML reader (design::parse_project), then the validation pass
// (design::validate_loaded_project, what load_validated_project runs).
// Documented rejection: design::InputError naming the file, line and column.

#include <cstddef>
#include <cstdint>

#include "design/project/project_loader.hpp"
#include "design/project/validated_project.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spiral;
  const std::string source = "fuzz-input.yaml";
  try {
    design::validate_loaded_project(design::parse_project(fuzz::input_text(data, size), source));
  } catch (const design::InputError& error) {
    fuzz::check_input_error(error, source);
  }
  return 0;
}
