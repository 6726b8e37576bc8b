// `spiral run`: the design spiral of a project — its stages in order with
// feedback, every task kept in the run folder's results store (resumable),
// a report per stage and the spiral's summary report.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>

#include <fmt/format.h>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/report_info.hpp"
#include "app/version.hpp"
#include "design/workflow/cluster.hpp"
#include "design/workflow/spiral_run.hpp"
#include "report/advanced_stage_report.hpp"
#include "report/intermediate_stage_report.hpp"
#include "report/report_writer.hpp"
#include "report/spiral_summary_report.hpp"
#include "report/static_stage_report.hpp"

namespace spiral::app {
namespace {

class RunCommand : public Command {
 public:
  RunCommand()
      : Command("run",
                "Run the design spiral: the project's stages in order (preliminary, intermediate, advanced) with "
                "pretension feedback, every task kept in <out>/results.sqlite (a second run resumes), a report per "
                "stage and a summary report") {}

  int run() const override {
    const auto start = std::chrono::steady_clock::now();
    const std::filesystem::path folder =
        out_.empty() ? std::filesystem::path("out") / std::filesystem::path(project_file_).stem()
                     : std::filesystem::path(out_);
    design::SpiralRunOptions options;
    options.out_folder = folder;
    options.jobs = jobs_;
    options.fresh = fresh_;
    if (!until_.empty()) options.until = until_;
    if (full_) options.advanced.duration_s = design::kAdvancedStageDuration_s;
    if (coupled_max_steps_ > 0) options.advanced.coupled_max_steps_between_outputs = coupled_max_steps_;
    options.version = kVersion;
    const bool terminal = isatty(fileno(stderr)) != 0;
    options.log = [terminal](const std::string& line) {
      // Task lines overwrite each other on a terminal; everything is a plain line in a log (CI).
      const bool task_line = line.starts_with("[");
      if (terminal && task_line)
        fmt::print(stderr, "\r\033[K{}", line);
      else
        fmt::print(stderr, "{}{}\n", terminal ? "\r\033[K" : "", line);
      std::fflush(stderr);
    };
    // Under mpirun every rank runs the spiral; rank 0 owns the store, logs and writes the reports.
    const std::unique_ptr<design::Cluster> cluster = design::launched_cluster();
    options.cluster = cluster.get();
    if (cluster && cluster->rank() != 0) {
      options.log = nullptr;
      const design::SpiralRunResult result = design::run_spiral(project_file_, options);
      return result.solver_failures || !result.completed ? kExitSolverFailure : kExitOk;
    }
    if (cluster) fmt::print(stderr, "spiral run on {} MPI ranks\n", cluster->size());
    const report::ReportInfo info = report_info(project_file_);
    std::vector<std::string> written;
    std::set<std::string> reported_stages;
    const auto stage_done = [&](const design::StageRun& stage) {
      if (!stage.completed) return;  // nothing to report; the summary says why
      const design::ValidatedProject& vp = *stage.project;
      report::ReportInfo stage_info = info;
      stage_info.model_hash = stage.model_hash;
      report::ReportDocument document;
      if (stage.preliminary)
        document = report::static_stage_report(vp, *stage.preliminary, stage_info);
      else if (stage.intermediate)
        document = report::intermediate_stage_report(vp, *stage.intermediate, stage_info);
      else
        document = report::advanced_stage_report(vp, *stage.advanced, stage_info);
      // A stage that runs again in a feedback iteration keeps the earlier
      // iteration's report beside its own.
      const std::string subfolder = reported_stages.insert(stage.stage).second
                                        ? stage.stage
                                        : fmt::format("{}-iteration-{}", stage.stage, stage.iteration);
      const report::WrittenReport report = report::write_report(document, folder / subfolder);
      written.push_back(fmt::format("{} (iteration {}): {}", stage.stage, stage.iteration, report.pdf.string()));
    };
    const design::SpiralRunResult result = design::run_spiral(project_file_, options, stage_done);

    const design::ValidatedProject& final_project =
        result.stages.empty() ? design::load_validated_project(project_file_) : *result.stages.back().project;
    const report::WrittenReport summary =
        report::write_report(report::spiral_summary_report(final_project, result, info), folder / "summary");
    fmt::print("spiral of '{}': {}\n", final_project.project.name,
               !result.completed ? "NOT COMPLETED" : (result.pass ? "PASS" : "FAIL"));
    for (const design::StageRun& s : result.stages) {
      fmt::print("  {:<12} iteration {}  {:<13} {}\n", s.stage, s.iteration,
                 !s.completed ? "NOT COMPLETED" : (s.pass ? "PASS" : "FAIL"), s.governing);
    }
    for (const std::string& f : result.findings) fmt::print("  finding: {}\n", f);
    for (const std::string& w : written) fmt::print("  report {}\n", w);
    fmt::print("  summary {}\n  results store {}\n  finished in {:.1f} s\n", summary.pdf.string(),
               result.store_file.string(),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    // As `spiral report`: a failing check is the verdict, exit 0; a solver
    // failure or a stage that could not finish is exit 3.
    return result.solver_failures || !result.completed ? kExitSolverFailure : kExitOk;
  }

 private:
  void add_options(CLI::App& sub) override {
    sub.add_option("--out", out_, "Run folder: results store, reports (default: out/<project-stem>)");
    sub.add_option("--jobs", jobs_, "Tasks run at a time (default 0: every core)");
    auto* fresh = sub.add_flag("--fresh", fresh_, "Start a new results store instead of resuming");
    sub.add_flag("--resume", resume_, "Resume from the run folder's results store (the default)")->excludes(fresh);
    sub.add_option("--until", until_, "Last stage to run: preliminary, intermediate or advanced");
    sub.add_flag("--full", full_,
                 "Advanced stage: the full 3-h coupled verification, whatever duration the project sets");
    sub.add_option("--coupled-max-steps", coupled_max_steps_,
                   "Advanced stage: the coupled integrator's work limit per output step (default 500000); a run "
                   "that needs more stops with a solver failure, recorded with its case");
  }

  std::string out_;
  int jobs_ = 0;
  bool fresh_ = false;
  bool resume_ = false;
  std::string until_;
  bool full_ = false;
  long coupled_max_steps_ = 0;
};

}  // namespace

std::unique_ptr<Command> run_command() { return std::make_unique<RunCommand>(); }

}  // namespace spiral::app
