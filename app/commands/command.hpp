#pragma once
// A `spiral` subcommand: it adds itself and its options to the CLI, and runs
// when chosen. Each command lives in its own file (app/commands/<name>.cpp);
// main.cpp registers them and maps what they throw to exit codes.
#include <memory>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

namespace spiral::app {

class Command {
 public:
  virtual ~Command() = default;

  /// Adds the subcommand with its PROJECT argument, its options and the
  /// exit-code footer to `cli`.
  void add_to(CLI::App& cli);
  bool chosen() const { return subcommand_ != nullptr && subcommand_->parsed(); }
  /// Its exit code; failures are thrown to main's exit-code ladder, except
  /// those a command reports itself (it still has output to give).
  virtual int run() const = 0;

 protected:
  Command(std::string name, std::string description);
  virtual void add_options(CLI::App& subcommand) = 0;
  /// Positional arguments before PROJECT (e.g. the kind of a study).
  virtual void add_leading_arguments(CLI::App& /*subcommand*/) {}
  /// The main positional argument: a project file unless the command reads
  /// something else (`spiral results` reads a run folder).
  virtual std::pair<std::string, std::string> main_argument() const { return {"PROJECT", "Project YAML file"}; }

  std::string project_file_;

 private:
  std::string name_;
  std::string description_;
  CLI::App* subcommand_ = nullptr;
};

std::unique_ptr<Command> validate_command();
std::unique_ptr<Command> statics_command();
std::unique_ptr<Command> equilibrium_command();
std::unique_ptr<Command> stiffness_command();
std::unique_ptr<Command> report_command();
std::unique_ptr<Command> soz_command();
std::unique_ptr<Command> analyze_command();
std::unique_ptr<Command> compare_command();
std::unique_ptr<Command> optimize_command();
std::unique_ptr<Command> study_command();
std::unique_ptr<Command> run_command();
std::unique_ptr<Command> results_command();
std::unique_ptr<Command> import_command();
std::unique_ptr<Command> export_command();
std::unique_ptr<Command> lines_command();

}  // namespace spiral::app
