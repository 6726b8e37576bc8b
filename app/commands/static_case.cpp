// `spiral equilibrium` and `spiral stiffness`: one static case (hull + every
// line at equilibrium for a load case), seen as its equilibrium or as its 6x6
// stiffness. Both write the same JSON document; stiffness adds the
// finite-difference check of K.
#include <string>
#include <utility>

#include <fmt/format.h>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "design/analysis/static_case.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/static_case_output.hpp"
#include "report/terminal/static_case_tables.hpp"

namespace spiral::app {
namespace {

enum class StaticCaseView { equilibrium, stiffness };

class StaticCaseCommand : public Command {
 public:
  StaticCaseCommand(StaticCaseView view, std::string name, std::string description)
      : Command(std::move(name), std::move(description)), view_(view) {}

  int run() const override {
    design::StaticCaseRequest request;
    if (!case_name_.empty()) request.load_case = case_name_;
    if (!damaged_line_.empty()) request.damaged_line = damaged_line_;
    request.finite_difference_check = view_ == StaticCaseView::stiffness;
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    const design::StaticCaseResult result = design::run_static_case(loaded, request);
    if (json_) {
      fmt::print("{}\n", design::static_case_to_json(result, loaded.project.name).dump(2));
    } else if (view_ == StaticCaseView::equilibrium) {
      fmt::print("{}", report::equilibrium_table(result, loaded.project.name));
    } else {
      fmt::print("{}", report::stiffness_table(result, loaded.project.name));
    }
    return kExitOk;
  }

 private:
  void add_options(CLI::App& sub) override {
    sub.add_option("--case", case_name_, "Load case name (default: still water, no environment)");
    sub.add_option("--damaged", damaged_line_, "Mooring line to remove (damaged condition)");
    sub.add_flag("--json", json_, "Machine output (docs/output-format.md) instead of the table");
  }

  StaticCaseView view_;
  std::string case_name_;
  std::string damaged_line_;
  bool json_ = false;
};

}  // namespace

std::unique_ptr<Command> equilibrium_command() {
  return std::make_unique<StaticCaseCommand>(StaticCaseView::equilibrium, "equilibrium",
                                             "Coupled static equilibrium of hull + every line for a load case");
}

std::unique_ptr<Command> stiffness_command() {
  return std::make_unique<StaticCaseCommand>(
      StaticCaseView::stiffness, "stiffness",
      "6x6 line-array stiffness and force vector at the static equilibrium of a load case");
}

}  // namespace spiral::app
