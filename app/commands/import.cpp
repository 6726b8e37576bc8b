// `spiral import moordyn DECK`: a MoorDyn deck as a spiral project file
// (design/import/moordyn_import.hpp; docs/moordyn.md).
#include <filesystem>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "app/atomic_file.hpp"
#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "design/import/moordyn_deck.hpp"
#include "design/import/moordyn_import.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::app {
namespace {

class ImportCommand : public Command {
 public:
  ImportCommand()
      : Command("import",
                "Write a spiral project from another tool's file. moordyn: a MoorDyn v1 or v2 input file (line "
                "types, points, lines, options); what has no spiral meaning is listed in the file's header") {}

  int run() const override {
    const std::filesystem::path deck_file = project_file_;
    const design::MoorDynDeck deck = design::read_moordyn_deck(deck_file);
    design::MoorDynImportOptions options;
    if (depth_m_ > 0.0) options.depth_m = depth_m_;
    const design::MoorDynImport imported = design::import_moordyn(deck, options);
    const std::filesystem::path out =
        out_.empty() ? std::filesystem::path(deck_file.stem().string() + ".yaml") : std::filesystem::path(out_);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    write_file_atomically(out, design::moordyn_import_yaml(imported, deck_file.filename().string()));
    // The written project must read back as a valid project; if it does not,
    // the issues name the written file's lines (exit 2, the file is kept to look at).
    design::load_validated_project(out);
    for (const std::string& note : imported.notes) fmt::print(stderr, "note: {}\n", note);
    fmt::print("{}: {} line types, {} mooring lines, depth {} m -> {}\n", deck_file.string(),
               imported.project.line_types.size(), imported.project.mooring.lines.size(), imported.project.site.depth_m,
               out.string());
    return kExitOk;
  }

 private:
  void add_leading_arguments(CLI::App& sub) override {
    sub.add_option("FORMAT", format_, "The file's format: moordyn")->required()->check(CLI::IsMember({"moordyn"}));
  }
  std::pair<std::string, std::string> main_argument() const override {
    return {"DECK", "MoorDyn input file (v1 or v2)"};
  }
  void add_options(CLI::App& sub) override {
    sub.add_option("--depth", depth_m_, "Water depth in m (default: the deck's WtrDpth, else its deepest anchor)")
        ->check(CLI::PositiveNumber);
    sub.add_option("--out", out_, "Project file to write (default <deck stem>.yaml in the current folder)");
  }

  std::string format_, out_;
  double depth_m_ = 0.0;
};

}  // namespace

std::unique_ptr<Command> import_command() { return std::make_unique<ImportCommand>(); }

}  // namespace spiral::app
