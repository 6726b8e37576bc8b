// spiral — integrated mooring–riser design-spiral application. CLI wiring
// only: each command (app/commands) adds its options and calls the design
// layer; here they are registered, and what they throw becomes an exit code.
#include <exception>
#include <memory>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/request_arguments.hpp"
#include "app/version.hpp"
#include "design/project/input_error.hpp"
#include "engine/common/file_format_error.hpp"
#include "engine/common/solver_error.hpp"
#include "report/report_writer.hpp"

int main(int argc, char** argv) {
  using namespace spiral;
  CLI::App cli{"spiral: integrated mooring-riser design spiral for floating production systems"};
  cli.footer(app::kExitCodeHelp);
  cli.require_subcommand(1);
  cli.set_version_flag("--version", fmt::format("spiral {} (commit {})", app::kVersion, app::kGitCommit));
  // In the order of `spiral --help`.
  const std::unique_ptr<app::Command> commands[] = {
      app::run_command(),         app::results_command(),   app::validate_command(), app::statics_command(),
      app::equilibrium_command(), app::stiffness_command(), app::report_command(),   app::soz_command(),
      app::optimize_command(),    app::study_command(),     app::analyze_command(),  app::compare_command(),
      app::import_command(),      app::export_command(),    app::lines_command()};
  for (const auto& command : commands) command->add_to(cli);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = cli.exit(error);  // prints help, version or the error
    return code == 0 ? app::kExitOk : app::kExitBadInput;
  }

  try {
    for (const auto& command : commands)
      if (command->chosen()) return command->run();
  } catch (const design::InputError& error) {
    // The project file or an option referring into it; the message names the file and the field (or flag).
    fmt::print(stderr, "{}\n", app::describe(error));
    return app::kExitBadInput;
  } catch (const engine::FileFormatError& error) {
    // A data file the project names (hydrodynamic database, panel mesh) is malformed.
    fmt::print(stderr, "{}\n", error.what());
    return app::kExitBadInput;
  } catch (const report::OutputError& error) {
    // The report folder could not be written; an existing one is left as it was.
    fmt::print(stderr, "output error: {}\n", error.what());
    return app::kExitOutputError;
  } catch (const engine::SolverError& error) {
    const auto& d = error.diagnostics();
    fmt::print(stderr, "solver failure: {}\n", error.what());
    if (d.iterations > 0) {
      fmt::print(stderr, "  after {} iterations, residual {:.3g} {}\n", d.iterations, d.residual, d.residual_unit);
    }
    fmt::print(stderr, "  check the line lengths against the anchor-fairlead span and the hull offset.\n");
    return app::kExitSolverFailure;
  } catch (const std::exception& error) {
    // Anything else is a bug (kExitInternalError: please report it).
    fmt::print(stderr, "internal error: {}\n", error.what());
    return app::kExitInternalError;
  }
  return app::kExitInternalError;
}
