#include "app/commands/command.hpp"

#include <utility>

#include "app/exit_codes.hpp"

namespace spiral::app {

Command::Command(std::string name, std::string description)
    : name_(std::move(name)), description_(std::move(description)) {}

void Command::add_to(CLI::App& cli) {
  subcommand_ = cli.add_subcommand(name_, description_);
  add_leading_arguments(*subcommand_);
  const auto [argument, help] = main_argument();
  subcommand_->add_option(argument, project_file_, help)->required();
  add_options(*subcommand_);
  subcommand_->footer(kExitCodeHelp);
}

}  // namespace spiral::app
