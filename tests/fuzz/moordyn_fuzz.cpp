// libFuzzer harness: a MoorDyn deck as `spiral import moordyn` takes it — the
// deck reader, the mapping to a project, the project's YAML and that text read
// back and validated (the command validates the file it wrote).
// Documented rejection: design::InputError naming the deck (or the written
// project) with a line and column.

#include <cstddef>
#include <cstdint>

#include "design/import/moordyn_deck.hpp"
#include "design/import/moordyn_import.hpp"
#include "design/project/project_loader.hpp"
#include "design/project/validated_project.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spiral;
  const std::string deck_name = "fuzz-input.dat";
  const std::string project_name = "fuzz-input.yaml";
  try {
    const design::MoorDynDeck deck = design::parse_moordyn_deck(fuzz::input_text(data, size), deck_name);
    const design::MoorDynImport imported = design::import_moordyn(deck);
    const std::string yaml = design::moordyn_import_yaml(imported, deck_name);
    design::validate_loaded_project(design::parse_project(yaml, project_name));
  } catch (const design::InputError& error) {
    fuzz::check_input_error(error, deck_name, project_name);
  }
  return 0;
}
