// `spiral study pretension`: the pretension sweep a mooring designer decides from.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/atomic_file.hpp"
#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "design/optimization/pretension_study.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/pretension_study_output.hpp"
#include "report/terminal/optimization_tables.hpp"

namespace spiral::app {
namespace {

class StudyCommand : public Command {
 public:
  StudyCommand()
      : Command("study",
                "Design studies. pretension: sweep the payout of a group (or all together) against the largest "
                "offset, offset / SOZ and utilization, intact and damaged, with the feasible band") {}

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    design::PretensionStudyRequest request;
    request.groups = groups_;
    request.points = points_;
    request.with_optimum = with_optimum_;
    request.problem.cases = cases_;
    if (!damaged_.empty())
      request.problem.damaged =
          damaged_ == "every_line" ? design::DamagedConditions::every_line : design::DamagedConditions::load_cases;
    request.problem.threads = threads_;
    const design::PretensionStudyResult result = design::run_pretension_study(loaded, request);
    const std::filesystem::path folder = output_folder(out_, project_file_, "study-pretension");
    std::filesystem::create_directories(folder);
    const std::string json = design::pretension_study_to_json(result).dump(2);
    write_file_atomically(folder / "pretension_study.json", json + "\n");
    write_file_atomically(folder / "pretension_study.csv", design::pretension_study_csv(result));
    if (json_) {
      fmt::print("{}\n", json);
    } else if (csv_) {
      fmt::print("{}", design::pretension_study_csv(result));
    } else {
      fmt::print("{}", report::pretension_study_table(result));
    }
    std::fflush(stdout);
    fmt::print(stderr, "results: {}\n", folder.string());
    return kExitOk;
  }

 private:
  void add_leading_arguments(CLI::App& sub) override {
    sub.add_option("KIND", kind_, "The study: pretension")->required()->check(CLI::IsMember({"pretension"}));
  }
  void add_options(CLI::App& sub) override {
    sub.add_option("--groups", groups_, "Groups swept one at a time (default: every group together)")->delimiter(',');
    sub.add_option("--points", points_, "Points per sweep over the group's payout bounds (default 21)");
    sub.add_option("--cases", cases_, "Load cases (default: optimization.cases, else all)")->delimiter(',');
    sub.add_option("--damaged", damaged_, "load_cases or every_line (default: optimization.damaged)")
        ->check(CLI::IsMember({"load_cases", "every_line"}));
    sub.add_flag("--with-optimum", with_optimum_, "Also run the optimizer and mark its point");
    sub.add_option("--threads", threads_, "Scenarios evaluated in parallel (default: all cores)");
    sub.add_flag("--json", json_, "Machine output (docs/output-format.md) instead of the table");
    sub.add_flag("--csv", csv_, "CSV, one row per point, instead of the table");
    sub.add_option("--out", out_, "Results folder (default out/<project>/study-pretension)");
  }

  std::string kind_, damaged_, out_;
  std::vector<std::string> groups_, cases_;
  int points_ = 21;
  int threads_ = 0;
  bool with_optimum_ = false;
  bool json_ = false;
  bool csv_ = false;
};

}  // namespace

std::unique_ptr<Command> study_command() { return std::make_unique<StudyCommand>(); }

}  // namespace spiral::app
