// `spiral statics`: every mooring line solved quasi-statically at one hull offset.
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "design/analysis/statics_study.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/statics_output.hpp"
#include "report/terminal/statics_table.hpp"

namespace spiral::app {
namespace {

class StaticsCommand : public Command {
 public:
  StaticsCommand() : Command("statics", "Quasi-static solution of every mooring line at a hull offset") {}

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    engine::Vector6d offset = engine::Vector6d::Zero();
    for (int i = 0; i < 6; ++i) {
      // Rotations are given in degrees on the command line, SI (rad) inside.
      offset(i) = offset_input_[static_cast<std::size_t>(i)] * (i < 3 ? 1.0 : std::numbers::pi / 180.0);
    }
    design::LineArrayModel model = design::build_mooring_model(loaded.project);
    const design::StaticsResult result = design::run_statics(model, offset);
    if (json_) {
      fmt::print("{}\n", design::statics_to_json(result, loaded.project.name).dump(2));
    } else {
      fmt::print("{}", report::statics_table(result, loaded.project.name));
    }
    return kExitOk;
  }

 private:
  void add_options(CLI::App& sub) override {
    sub.add_option("--offset", offset_input_,
                   "Hull offset x,y,z (m), rx,ry,rz (deg) of the reference point, global axes")
        ->expected(6)
        ->delimiter(',')
        ->allow_extra_args(false);
    sub.add_flag("--json", json_, "Machine output (docs/output-format.md) instead of the table");
  }

  std::vector<double> offset_input_ = std::vector<double>(6, 0.0);
  bool json_ = false;
};

}  // namespace

std::unique_ptr<Command> statics_command() { return std::make_unique<StaticsCommand>(); }

}  // namespace spiral::app
