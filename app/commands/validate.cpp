// `spiral validate`: load and check a project file, print its summary.
#include <fmt/format.h>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "design/project/project_summary.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::app {
namespace {

class ValidateCommand : public Command {
 public:
  ValidateCommand() : Command("validate", "Check a project file and print a summary") {}

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    fmt::print("{}", design::project_summary(loaded.project, loaded.line_types));
    fmt::print("\n{}: valid\n", project_file_);
    return kExitOk;
  }

 private:
  void add_options(CLI::App&) override {}
};

}  // namespace

std::unique_ptr<Command> validate_command() { return std::make_unique<ValidateCommand>(); }

}  // namespace spiral::app
