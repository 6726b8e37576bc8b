// `spiral report`: run a stage's analyses and write its report folder. The
// spiral's stages go through the spiral's own runner (design/workflow) and
// its results store, so a stage reuses what `spiral run` or an earlier report
// computed; the optimization study runs here.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "app/report_info.hpp"
#include "app/version.hpp"
#include "design/project/request_error.hpp"
#include "design/project/validated_project.hpp"
#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_study.hpp"
#include "design/workflow/spiral_run.hpp"
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
      // (11 points) for the trade-off plot: two tasks of the run folder's
      // store, as the stages' are.
      std::optional<std::filesystem::path> scratch;
      const design::SpiralRunOptions options = store_options(scratch);
      design::OptimizationStudy stored;
      try {
        stored = design::run_optimization_study(project_file_, options, 11);
      } catch (...) {
        if (scratch) std::filesystem::remove_all(*scratch);
        throw;
      }
      if (scratch)
        std::filesystem::remove_all(*scratch);
      else
        fmt::print("  results store {} ({} of the 2 tasks reused)\n", stored.store_file.string(), stored.tasks_reused);
      pass = stored.optimization.status == design::OptimizationStatus::optimal;
      solver_failed = !pass;
      document = report::optimization_report(loaded, stored.optimization, stored.study, info);
    } else {
      // A stage of the spiral, as `spiral run` makes it (design/workflow):
      // its tasks and those of the stages before it come from the run
      // folder's results store when they are there, and what is computed is
      // kept for the next command. No feedback: the project as given.
      const std::optional<design::StageRun> stage = run_stage();
      if (!stage) return kExitSolverFailure;
      pass = stage->pass;
      solver_failed = stage->tasks_failed > 0 || !stage->failures.empty();
      report::ReportInfo stage_info = info;
      stage_info.model_hash = stage->model_hash;
      if (stage->preliminary)
        document = report::static_stage_report(loaded, *stage->preliminary, stage_info);
      else if (stage->intermediate)
        document = report::intermediate_stage_report(loaded, *stage->intermediate, stage_info);
      else
        document = report::advanced_stage_report(loaded, *stage->advanced, stage_info);
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
    sub.add_option("--run", run_,
                   "Run folder whose results store (results.sqlite) the stage reuses and adds to (default: "
                   "out/<project-stem>, as spiral run, when --out is not given; with --out and no --run, a "
                   "temporary store)");
    sub.add_option("--jobs", jobs_, "Tasks run at a time (default 0: every core)");
  }

  /// The requested stage through the spiral's runner; empty (after printing
  /// why) when it could not finish.
  /// The run folder whose store the command reuses (--run; out/<stem> when
  /// --out is not given), or a temporary one it removes (`scratch`).
  design::SpiralRunOptions store_options(std::optional<std::filesystem::path>& scratch) const {
    design::SpiralRunOptions options;
    if (!run_.empty()) {
      options.out_folder = run_;
    } else if (out_.empty()) {
      options.out_folder = std::filesystem::path("out") / std::filesystem::path(project_file_).stem();
    } else {
      scratch = std::filesystem::temp_directory_path() / fmt::format("spiral-report-{}", ::getpid());
      options.out_folder = *scratch;
    }
    options.jobs = jobs_;
    options.version = kVersion;
    return options;
  }

  std::optional<design::StageRun> run_stage() const {
    std::optional<std::filesystem::path> scratch;
    design::SpiralRunOptions options = store_options(scratch);
    options.until = stage_;
    options.feedback = false;
    options.log = [](const std::string& line) {
      if (!line.starts_with("[")) fmt::print(stderr, "{}\n", line);  // stage lines, not every task
    };
    std::optional<design::StageRun> wanted;
    design::SpiralRunResult result;
    try {
      result = design::run_spiral(project_file_, options, [&](const design::StageRun& s) {
        if (s.stage == stage_) wanted = s;
      });
    } catch (...) {
      if (scratch) std::filesystem::remove_all(*scratch);
      throw;
    }
    if (scratch) std::filesystem::remove_all(*scratch);
    for (const design::StageRun& s : result.stages)
      for (const std::string& f : s.failures) fmt::print(stderr, "{}: {} stage: {}\n", project_file_, s.stage, f);
    if (!wanted || !wanted->completed) {
      fmt::print(stderr, "{}: the {} stage could not finish (see above); no report written\n", project_file_, stage_);
      return std::nullopt;
    }
    if (!run_.empty() || out_.empty())
      fmt::print("  results store {} ({} of the stage's {} tasks reused)\n", result.store_file.string(),
                 wanted->tasks_reused, wanted->tasks);
    return wanted;
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
  std::string run_;
  int jobs_ = 0;
};

}  // namespace

std::unique_ptr<Command> report_command() { return std::make_unique<ReportCommand>(); }

}  // namespace spiral::app
