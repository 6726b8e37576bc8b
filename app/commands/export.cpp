// `spiral export moordyn PROJECT.yaml`: the project's mooring and risers as a
// MoorDyn v2 deck (design/import/moordyn_export.hpp; docs/moordyn.md).
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "app/atomic_file.hpp"
#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "design/import/moordyn_export.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::app {
namespace {

class ExportCommand : public Command {
 public:
  ExportCommand()
      : Command("export",
                "Write the project in another tool's format. moordyn: the mooring lines and risers as a MoorDyn v2 "
                "input file") {}

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    const std::string deck = design::export_moordyn(loaded.project, loaded.line_types);
    const std::filesystem::path out =
        out_.empty() ? std::filesystem::path(std::filesystem::path(project_file_).stem().string() + ".moordyn.dat")
                     : std::filesystem::path(out_);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    write_file_atomically(out, deck);
    fmt::print("{}: {} mooring lines, {} risers -> {}\n", project_file_, loaded.project.mooring.lines.size(),
               loaded.project.risers.size(), out.string());
    return kExitOk;
  }

 private:
  void add_leading_arguments(CLI::App& sub) override {
    sub.add_option("FORMAT", format_, "The format to write: moordyn")->required()->check(CLI::IsMember({"moordyn"}));
  }
  void add_options(CLI::App& sub) override {
    sub.add_option("--out", out_, "Deck to write (default <project stem>.moordyn.dat in the current folder)");
  }

  std::string format_, out_;
};

}  // namespace

std::unique_ptr<Command> export_command() { return std::make_unique<ExportCommand>(); }

}  // namespace spiral::app
