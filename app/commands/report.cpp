// `spiral report`: run a stage's analyses and write its report folder.
#include <chrono>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "app/report_info.hpp"
#include "design/project/request_error.hpp"
#include "design/project/validated_project.hpp"
#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_study.hpp"
#include "design/stages/advanced_stage.hpp"
#include "design/stages/intermediate_stage.hpp"
#include "design/stages/static_stage.hpp"
#include "report/advanced_stage_report.hpp"
#include "report/intermediate_stage_report.hpp"
#include "report/optimization_report.hpp"
#include "report/report_writer.hpp"
#include "report/static_stage_report.hpp"

namespace spiral::app {
namespace {

class ReportCommand : public Command {
 public:
  ReportCommand()
      : Command("report", "Run a stage's analyses and write its report (PDF, HTML index, figures, CSV tables)") {}

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    check_stage(loaded);
    const auto start = std::chrono::steady_clock::now();
    const report::ReportInfo info = report_info(project_file_);
    bool pass = true;
    report::ReportDocument document;
    bool solver_failed = false;
    if (stage_ == "optimization") {
      // The project's optimization, and the study of all groups together
      // (11 points) for the trade-off plot.
      const design::OptimizationResult result = design::optimize_pretension(loaded, {});
      design::PretensionStudyRequest study;
      study.points = 11;
      const design::PretensionStudyResult sweep = design::run_pretension_study(loaded, study);
      pass = result.status == design::OptimizationStatus::optimal;
      solver_failed = !pass;
      document = report::optimization_report(loaded, result, sweep, info);
    } else if (stage_ == "advanced") {
      const design::AdvancedStageResults results = design::run_advanced_stage(loaded);
      pass = results.pass;
      solver_failed = results.failed_runs > 0;
      document = report::advanced_stage_report(loaded, results, info);
      for (const auto& c : results.cases)
        if (c.error) fmt::print(stderr, "{}: case {}: {}\n", project_file_, c.case_name, *c.error);
    } else if (stage_ == "intermediate") {
      const design::IntermediateStageResults results = design::run_intermediate_stage(loaded);
      pass = results.pass;
      document = report::intermediate_stage_report(loaded, results, info);
    } else {
      const design::StaticStageResults results = design::run_static_stage(loaded);
      pass = results.pass;
      document = report::static_stage_report(loaded, results, info);
    }
    const report::WrittenReport written = report::write_report(document, output_folder(out_, project_file_, stage_));
    fmt::print("{} stage report of '{}' ({}): {}\n", stage_, loaded.project.name, pass ? "PASS" : "FAIL",
               written.folder.string());
    fmt::print("  {} ({} pages)\n  {}\n  written in {:.2f} s\n", written.pdf.string(), written.pages,
               written.html.string(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    // As `spiral compare`: the report of every other case is written; the exit
    // code says a solver failed.
    return solver_failed ? kExitSolverFailure : kExitOk;
  }

 private:
  void add_options(CLI::App& sub) override {
    sub.add_option("--stage", stage_,
                   "Stage: preliminary (default), intermediate, advanced (fully coupled verification of the "
                   "critical cases) or optimization (pretension optimization and study)");
    sub.add_option("--out", out_, "Output folder (default: out/<project-stem>/<stage>)");
  }

  void check_stage(const design::ValidatedProject& loaded) const {
    if (stage_ == "optimization") return;  // a study of the project, not one of its stages
    bool listed = loaded.project.stages.empty();
    for (const auto& s : loaded.project.stages) listed = listed || s.name == stage_;
    // The stages of DESIGN.md §2; a user-named stage has no analyses of its own.
    const bool available = stage_ == "preliminary" || stage_ == "intermediate" || stage_ == "advanced";
    if (!listed) {
      throw design::request_error(loaded.project, "stage",
                                  fmt::format("stage '{}' is not among the project's stages", stage_));
    }
    if (!available) {
      throw design::request_error(
          loaded.project, "stage",
          fmt::format("no analyses are defined for stage '{}'; available: preliminary, intermediate, advanced",
                      stage_));
    }
  }

  std::string stage_ = "preliminary";
  std::string out_;
};

}  // namespace

std::unique_ptr<Command> report_command() { return std::make_unique<ReportCommand>(); }

}  // namespace spiral::app
