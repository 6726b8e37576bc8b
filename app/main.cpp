// spiral — integrated mooring–riser design-spiral application. CLI wiring only.
#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"spiral: integrated mooring-riser design spiral for floating production systems"};
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
