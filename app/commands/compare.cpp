// `spiral compare`: the four levels on one case and realization, side by side
// (terminal table, comparison.json, comparison.txt).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "app/atomic_file.hpp"
#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "design/analysis/level_comparison.hpp"
#include "design/project/request_error.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/level_comparison_output.hpp"
#include "report/comparison_figure.hpp"
#include "report/terminal/comparison_table.hpp"

namespace spiral::app {
namespace {

void print_progress(const std::string& level, double fraction) {
  fmt::print(stderr, "\r  {:<12} {:3.0f} %", level, 100.0 * fraction);
  if (fraction >= 1.0) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

class CompareCommand : public Command {
 public:
  CompareCommand()
      : Command("compare", "All analysis levels (uncoupled, sc, sc-enhanced, coupled) on one case and realization") {}

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    design::find_load_case(loaded.project, case_name_);  // an unknown case fails before any run
    design::ComparisonRequest request;
    request.load_case = case_name_;
    request.duration_s = duration_s_;
    request.output_step_s = step_s_;
    request.seed = seed_;
    request.line_reduction =
        line_reduction_ == "dynamic" ? design::LineReduction::dynamic : design::LineReduction::quasi_static;
    request.detailed_line_mesh = detailed_mesh_;
    if (isatty(STDERR_FILENO)) request.progress = print_progress;
    const design::LevelComparison comparison = design::compare_levels(loaded, request);
    const std::filesystem::path folder = output_folder(
        out_, project_file_, std::filesystem::path("compare") / fmt::format("{}-seed{}", case_name_, seed_));
    const std::string table = report::comparison_table(comparison);
    try {
      std::filesystem::create_directories(folder);
      write_file_atomically(folder / "comparison.json", design::comparison_to_json(comparison).dump(2) + "\n");
      write_file_atomically(folder / "comparison.txt", table);
      report::write_svg(report::comparison_figure(comparison), (folder / "comparison.svg").string());
    } catch (const std::exception& error) {
      fmt::print(stderr, "output error: {}\n", error.what());
      fmt::print("{}", table);  // the finished comparison is not lost
      return kExitOutputError;
    }
    fmt::print("levels of '{}', case {} (seed {}, {:.0f} s): {}\n", loaded.project.name, case_name_, seed_, duration_s_,
               folder.string());
    fmt::print("{}", table);
    for (const auto& level : comparison.levels) {
      if (level.error) return kExitSolverFailure;  // the other levels are written above
    }
    return kExitOk;
  }

 private:
  void add_options(CLI::App& sub) override {
    sub.add_option("--case", case_name_, "Load case name")->required();
    sub.add_option("--duration", duration_s_, "Simulated time, s (default: 10800)");
    sub.add_option("--step", step_s_, "Output step, s (default: 0.5)");
    sub.add_option("--seed", seed_, "Random seed of the realizations (default: 1)");
    sub.add_option("--line-reduction", line_reduction_,
                   "sc-enhanced: the lines' damping, added mass and low-frequency stiffening from their dynamic FE "
                   "models (dynamic, the default) or their damping and added mass from their quasi-static shape "
                   "(quasi-static)")
        ->check(CLI::IsMember({"quasi-static", "dynamic"}));
    sub.add_flag("--detailed-mesh", detailed_mesh_,
                 "The dynamic FE lines (the coupled level, the other levels' dynamic tensions) on each line's "
                 "own fe mesh instead of the project's global_analysis.element_length");
    sub.add_option("--out", out_, "Output folder (default: out/<project-stem>/compare/<case>-seed<N>)");
  }

  std::string case_name_;
  double duration_s_ = 10800.0;
  double step_s_ = 0.5;
  std::uint64_t seed_ = 1;
  std::string line_reduction_ = "dynamic";
  bool detailed_mesh_ = false;
  std::string out_;
};

}  // namespace

std::unique_ptr<Command> compare_command() { return std::make_unique<CompareCommand>(); }

}  // namespace spiral::app
