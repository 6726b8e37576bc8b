// spiral — integrated mooring–riser design-spiral application. CLI wiring only:
// parse arguments, call the design layer, print, map errors to exit codes.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/atomic_file.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "app/version.hpp"
#include "design/project/command_line_reference.hpp"
#include "design/project/input_error.hpp"
#include "design/analysis/level_comparison.hpp"
#include "design/results/level_comparison_output.hpp"
#include "design/project/model_hash.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/project_summary.hpp"
#include "design/analysis/dynamic_analysis.hpp"
#include "design/results/dynamic_analysis_output.hpp"
#include "design/analysis/static_case.hpp"
#include "design/results/static_case_output.hpp"
#include "design/results/statics_output.hpp"
#include "design/soz/soz.hpp"
#include "design/results/soz_output.hpp"
#include "design/stages/static_stage.hpp"
#include "design/analysis/statics_study.hpp"
#include "design/project/validated_project.hpp"
#include "engine/common/file_format_error.hpp"
#include "engine/common/solver_error.hpp"
#include "design/stages/advanced_stage.hpp"
#include "design/stages/intermediate_stage.hpp"
#include "report/advanced_stage_report.hpp"
#include "report/intermediate_stage_report.hpp"
#include "report/report_writer.hpp"
#include "report/static_stage_report.hpp"

namespace {

using namespace spiral;

constexpr const char* kExitCodeHelp =
    "Exit codes: 0 ok, 1 internal error, 2 bad input (project file or arguments), "
    "3 solver failure, 4 output could not be written.";

int run_validate(const std::string& project_file) {
  const design::ValidatedProject loaded = design::load_validated_project(project_file);
  fmt::print("{}", design::project_summary(loaded.project, loaded.line_types));
  fmt::print("\n{}: valid\n", project_file);
  return app::kExitOk;
}

int run_statics(const std::string& project_file, const std::vector<double>& offset_input, bool json) {
  const design::ValidatedProject loaded = design::load_validated_project(project_file);
  engine::Vector6d offset = engine::Vector6d::Zero();
  for (int i = 0; i < 6; ++i) {
    // Rotations are given in degrees on the command line, SI (rad) inside.
    offset(i) = offset_input[static_cast<std::size_t>(i)] * (i < 3 ? 1.0 : std::numbers::pi / 180.0);
  }
  design::LineArrayModel model = design::build_mooring_model(loaded.project);
  const design::StaticsResult result = design::run_statics(model, offset);
  if (json) {
    fmt::print("{}\n", design::statics_to_json(result, loaded.project.name).dump(2));
  } else {
    fmt::print("{}", design::statics_table(result, loaded.project.name));
  }
  return app::kExitOk;
}

enum class StaticCaseView { equilibrium, stiffness };

int run_static_case_command(const std::string& project_file, const design::StaticCaseRequest& request,
                            bool json, StaticCaseView view) {
  const design::ValidatedProject loaded = design::load_validated_project(project_file);
  const design::StaticCaseResult result = design::run_static_case(loaded, request);
  if (json) {
    fmt::print("{}\n", design::static_case_to_json(result, loaded.project.name).dump(2));
  } else if (view == StaticCaseView::equilibrium) {
    fmt::print("{}", design::equilibrium_table(result, loaded.project.name));
  } else {
    fmt::print("{}", design::stiffness_table(result, loaded.project.name));
  }
  return app::kExitOk;
}

enum class SozView { table, json, csv };

int run_soz_command(const std::string& project_file, const design::SozOptions& options, SozView view) {
  const design::ValidatedProject loaded = design::load_validated_project(project_file);
  const design::SozResult result = design::run_soz(loaded, options);
  if (view == SozView::json) {
    fmt::print("{}\n", design::soz_to_json(result).dump(2));
  } else if (view == SozView::csv) {
    fmt::print("{}", design::soz_to_csv(result));
  } else {
    fmt::print("{}", design::soz_table(result));
  }
  // A riser that fails its criteria with the hull at rest has no zone: the
  // riser or its criteria are wrong, which is an input problem.
  bool failed = false;
  for (const design::RiserSoz& z : result.risers) {
    if (!z.fails_at_zero_offset) continue;
    fmt::print(stderr,
               "{}: riser '{}' fails its criteria at zero offset ({}): {} utilization {:.3f} > 1 — it has no safe "
               "zone; check its criteria (criteria.risers, risers[].criteria) or its design\n",
               project_file, z.name, result.conditions.name, z.zero_offset_governing_criterion,
               z.zero_offset_utilization);
    failed = true;
  }
  return failed ? app::kExitBadInput : app::kExitOk;
}

/// UTC date of the report; SOURCE_DATE_EPOCH (reproducible-builds.org) fixes it.
std::string report_date() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) now = static_cast<std::time_t>(std::atoll(epoch));
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &utc);
  return buffer;
}

int run_report(const std::string& project_file, const std::string& stage, const std::string& out) {
  const design::ValidatedProject loaded = design::load_validated_project(project_file);
  bool listed = loaded.project.stages.empty();
  for (const auto& s : loaded.project.stages) listed = listed || s.name == stage;
  // The stages of DESIGN.md §2; a user-named stage has no analyses of its own.
  const bool available = stage == "preliminary" || stage == "intermediate" || stage == "advanced";
  if (!listed || !available) {
    design::InputIssue issue;
    issue.file = project_file;
    issue.path = "--stage";
    issue.message =
        !listed ? fmt::format("stage '{}' is not among the project's stages", stage)
                : fmt::format("no analyses are defined for stage '{}'; available: preliminary, intermediate, "
                              "advanced",
                              stage);
    issue.condition = "command_line_reference";
    throw design::InputError({issue});
  }
  const auto start = std::chrono::steady_clock::now();
  report::ReportInfo info;
  info.project_file = project_file;
  info.model_hash = design::model_hash(project_file);
  info.date = report_date();
  info.version = app::kVersion;
  bool pass = true;
  report::ReportDocument document;
  bool solver_failed = false;
  if (stage == "advanced") {
    const design::AdvancedStageResults results = design::run_advanced_stage(loaded);
    pass = results.pass;
    solver_failed = results.failed_runs > 0;
    document = report::advanced_stage_report(loaded, results, info);
    for (const auto& c : results.cases)
      if (c.error) fmt::print(stderr, "{}: case {}: {}\n", project_file, c.case_name, *c.error);
  } else if (stage == "intermediate") {
    const design::IntermediateStageResults results = design::run_intermediate_stage(loaded);
    pass = results.pass;
    document = report::intermediate_stage_report(loaded, results, info);
  } else {
    const design::StaticStageResults results = design::run_static_stage(loaded);
    pass = results.pass;
    document = report::static_stage_report(loaded, results, info);
  }
  const report::WrittenReport written = report::write_report(document, app::output_folder(out, project_file, stage));
  fmt::print("{} stage report of '{}' ({}): {}\n", stage, loaded.project.name, pass ? "PASS" : "FAIL",
             written.folder.string());
  fmt::print("  {} ({} pages)\n  {}\n  written in {:.2f} s\n", written.pdf.string(), written.pages,
             written.html.string(),
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  // As `spiral compare`: the report of every other case is written; the exit
  // code says a solver failed.
  return solver_failed ? app::kExitSolverFailure : app::kExitOk;
}

struct AnalyzeOptions {
  std::string case_name;
  std::string level = "sc";
  double duration_s = 10800.0;
  double step_s = 0.5;
  std::uint64_t seed = 1;
  std::string out;
  bool line_dynamics = false;
};

/// `spiral analyze`: one load case at one level in the time domain; CSV time
/// series + JSON summary (docs/output-format.md). A progress bar goes to
/// stderr only when stderr is a terminal.
int run_analyze(const std::string& project_file, const AnalyzeOptions& o) {
  const design::ValidatedProject loaded = design::load_validated_project(project_file);
  design::DynamicAnalysisRequest request;
  request.load_case = o.case_name;
  request.level = design::parse_analysis_level(o.level, loaded.project);
  request.duration_s = o.duration_s;
  request.output_step_s = o.step_s;
  request.seed = o.seed;
  request.line_dynamics = o.line_dynamics;
  if (isatty(STDERR_FILENO)) {
    request.progress = [](double fraction) {
      const int width = 40;
      const int filled = static_cast<int>(fraction * width);
      fmt::print(stderr, "\r  dynamics [{}{}] {:3.0f} %", std::string(static_cast<std::size_t>(filled), '#'),
                 std::string(static_cast<std::size_t>(width - filled), ' '), 100.0 * fraction);
      if (fraction >= 1.0) fmt::print(stderr, "\n");
      std::fflush(stderr);
    };
  }
  design::DynamicAnalysisResult result;
  try {
    result = design::run_dynamic_analysis(loaded, request);
  } catch (const engine::FileFormatError& error) {
    fmt::print(stderr, "{}\n", error.what());
    return app::kExitBadInput;
  }
  const std::filesystem::path folder =
      app::output_folder(o.out, project_file,
                         std::filesystem::path("analyze") / fmt::format("{}-{}-seed{}", o.case_name, o.level, o.seed));
  try {
    std::filesystem::create_directories(folder);
    app::write_file_atomically(folder / "time_series.csv", design::dynamic_time_series_csv(result));
    app::write_file_atomically(folder / "summary.json",
                               design::dynamic_analysis_to_json(result, loaded.project.name).dump(2) + "\n");
  } catch (const std::exception& error) {
    fmt::print(stderr, "output error: {}\n", error.what());
    return app::kExitOutputError;
  }
  fmt::print("{} analysis of '{}', case {} (seed {}, {:.0f} s): {}\n", o.level, loaded.project.name, o.case_name,
             o.seed, o.duration_s, folder.string());
  fmt::print("  equilibrium {:.3f} s, reduction {:.3f} s, forcing {:.3f} s, dynamics {:.3f} s, WF {:.3f} s, "
             "tensions {:.3f} s\n",
             result.equilibrium_wall_s, result.reduction_wall_s, result.forcing_wall_s, result.dynamics_wall_s,
             result.wave_frequency_wall_s, result.tensions_wall_s);
  if (result.coupled_solver) {
    const engine::IdaStatistics& s = *result.coupled_solver;
    fmt::print("  coupled: {} lines, {} states; {} steps, {} Newton-matrix setups ({} partial), {} residuals; "
               "{:.1f}x real time\n",
               result.coupled_lines, result.coupled_state_size, s.steps, s.newton_matrix_setups,
               s.newton_matrix_updates, s.residual_evaluations,
               result.dynamics_wall_s > 0.0 ? o.duration_s / result.dynamics_wall_s : 0.0);
  }
  if (!result.dynamic_tensions.empty()) {
    fmt::print("  line dynamics {:.3f} s; max fairlead tension, quasi-static vs dynamic:\n", result.line_dynamics_wall_s);
    for (std::size_t l = 0; l < result.dynamic_tensions.size() && l < result.tensions.size(); ++l) {
      const auto& qs = result.tensions[l].tension_N;
      const auto& dy = result.dynamic_tensions[l].tension_N;
      fmt::print("    {:<12} {:10.1f} kN  {:10.1f} kN  ({} steps)\n", result.dynamic_tensions[l].line,
                 *std::max_element(qs.begin(), qs.end()) / 1e3, *std::max_element(dy.begin(), dy.end()) / 1e3,
                 result.dynamic_tensions[l].solver.steps);
    }
    for (std::size_t l = result.tensions.size(); l < result.dynamic_tensions.size(); ++l) {
      const auto& dy = result.dynamic_tensions[l].tension_N;
      fmt::print("    {:<12} {:>13}  {:10.1f} kN  (riser top)\n", result.dynamic_tensions[l].line, "",
                 *std::max_element(dy.begin(), dy.end()) / 1e3);
    }
  }
  for (const auto& note : result.notes) fmt::print("  note: {}\n", note);
  return app::kExitOk;
}

struct CompareOptions {
  std::string case_name;
  double duration_s = 10800.0;
  double step_s = 0.5;
  std::uint64_t seed = 1;
  std::string out;
};

/// `spiral compare`: the four levels on one case and realization, side by
/// side (terminal table, comparison.json).
int run_compare(const std::string& project_file, const CompareOptions& o) {
  const design::ValidatedProject loaded = design::load_validated_project(project_file);
  design::find_load_case(loaded.project, o.case_name);  // an unknown case fails before any run
  design::ComparisonRequest request;
  request.load_case = o.case_name;
  request.duration_s = o.duration_s;
  request.output_step_s = o.step_s;
  request.seed = o.seed;
  if (isatty(STDERR_FILENO)) {
    request.progress = [](const std::string& level, double fraction) {
      fmt::print(stderr, "\r  {:<12} {:3.0f} %", level, 100.0 * fraction);
      if (fraction >= 1.0) fmt::print(stderr, "\n");
      std::fflush(stderr);
    };
  }
  design::LevelComparison comparison;
  try {
    comparison = design::compare_levels(loaded, request);
  } catch (const engine::FileFormatError& error) {
    fmt::print(stderr, "{}\n", error.what());
    return app::kExitBadInput;
  }
  const std::filesystem::path folder = app::output_folder(
      o.out, project_file, std::filesystem::path("compare") / fmt::format("{}-seed{}", o.case_name, o.seed));
  const std::string table = design::comparison_table(comparison);
  try {
    std::filesystem::create_directories(folder);
    app::write_file_atomically(folder / "comparison.json", design::comparison_to_json(comparison).dump(2) + "\n");
    app::write_file_atomically(folder / "comparison.txt", table);
  } catch (const std::exception& error) {
    fmt::print(stderr, "output error: {}\n", error.what());
    fmt::print("{}", table);  // the finished comparison is not lost
    return app::kExitOutputError;
  }
  fmt::print("levels of '{}', case {} (seed {}, {:.0f} s): {}\n", loaded.project.name, o.case_name, o.seed,
             o.duration_s, folder.string());
  fmt::print("{}", table);
  for (const auto& level : comparison.levels) {
    if (level.error) return app::kExitSolverFailure;  // the other levels are written above
  }
  return app::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"spiral: integrated mooring-riser design spiral for floating production systems"};
  cli.footer(kExitCodeHelp);
  cli.require_subcommand(1);
  cli.set_version_flag("--version", fmt::format("spiral {} (commit {})", app::kVersion, app::kGitCommit));

  std::string project_file;
  CLI::App* validate = cli.add_subcommand("validate", "Check a project file and print a summary");
  validate->add_option("PROJECT", project_file, "Project YAML file")->required();
  validate->footer(kExitCodeHelp);

  CLI::App* statics = cli.add_subcommand(
      "statics", "Quasi-static solution of every mooring line at a hull offset");
  statics->add_option("PROJECT", project_file, "Project YAML file")->required();
  std::vector<double> offset_input(6, 0.0);
  statics
      ->add_option("--offset", offset_input,
                   "Hull offset x,y,z (m), rx,ry,rz (deg) of the reference point, global axes")
      ->expected(6)
      ->delimiter(',')
      ->allow_extra_args(false);
  bool json = false;
  statics->add_flag("--json", json, "Machine output (docs/output-format.md) instead of the table");
  statics->footer(kExitCodeHelp);

  design::StaticCaseRequest case_request;
  std::string case_name, damaged_line;
  CLI::App* equilibrium = cli.add_subcommand(
      "equilibrium", "Coupled static equilibrium of hull + every line for a load case");
  CLI::App* stiffness = cli.add_subcommand(
      "stiffness", "6x6 line-array stiffness and force vector at the static equilibrium of a load case");
  for (CLI::App* sub : {equilibrium, stiffness}) {
    sub->add_option("PROJECT", project_file, "Project YAML file")->required();
    sub->add_option("--case", case_name, "Load case name (default: still water, no environment)");
    sub->add_option("--damaged", damaged_line, "Mooring line to remove (damaged condition)");
    sub->add_flag("--json", json, "Machine output (docs/output-format.md) instead of the table");
    sub->footer(kExitCodeHelp);
  }

  CLI::App* report_cmd = cli.add_subcommand(
      "report", "Run a stage's analyses and write its report (PDF, HTML index, figures, CSV tables)");
  report_cmd->add_option("PROJECT", project_file, "Project YAML file")->required();
  std::string stage_name = "preliminary", out_dir;
  report_cmd->add_option("--stage", stage_name,
                         "Stage: preliminary (default), intermediate or advanced (fully coupled verification of the critical cases)");
  report_cmd->add_option("--out", out_dir, "Output folder (default: out/<project-stem>/<stage>)");
  report_cmd->footer(kExitCodeHelp);

  CLI::App* soz_cmd = cli.add_subcommand(
      "soz", "Riser safe operational zones (allowable hull offset per direction) and the offset check");
  soz_cmd->add_option("PROJECT", project_file, "Project YAML file")->required();
  design::SozOptions soz_options;
  std::string soz_condition, soz_model = "fe";
  bool csv = false;
  soz_cmd->add_option("--case", case_name,
                      "Load case: its current on the risers, mean heave/rotations and design condition "
                      "(default: still water, offset check of every load case)");
  soz_cmd->add_option("--step-deg", soz_options.step_deg, "Direction step, deg (must divide 360; default 5)");
  soz_cmd->add_option("--tolerance", soz_options.tolerance_m, "Tolerance of each allowable offset, m (default 0.1)");
  soz_cmd->add_option("--search-limit", soz_options.search_limit_pct_depth,
                      "Largest offset searched, % of depth (default 20)");
  soz_cmd->add_option("--march-step", soz_options.march_step_pct_depth,
                      "Coarse march step, % of depth (default 2.5)");
  soz_cmd->add_option("--condition", soz_condition,
                      "Design condition without --case: normal (default), extreme, survival")
      ->check(CLI::IsMember({"normal", "extreme", "survival"}));
  soz_cmd->add_option("--model", soz_model, "Riser model: fe (reference, default) or catenary (screening)")
      ->check(CLI::IsMember({"fe", "catenary"}));
  soz_cmd->add_option("--exclude", soz_options.exclude_risers, "Risers to leave out (repeatable)");
  soz_cmd->add_option("--threads", soz_options.threads, "Threads (default: all cores)");
  bool no_check = false;
  soz_cmd->add_flag("--no-check", no_check, "Skip the load cases' equilibria and the offset check");
  bool still_water_only = false;
  soz_cmd->add_flag("--still-water-only", still_water_only,
                    "Without --case: check every case against the still-water zone (no zone per current)");
  bool soz_extreme = false;
  design::SozExtremeOptions soz_extreme_options;
  CLI::Option* extreme_flag = soz_cmd->add_flag("--extreme", soz_extreme,
                    "Also check the extreme offsets: enhanced S-C time-domain analysis of each case, 3-h MPM");
  soz_cmd->add_option("--duration", soz_extreme_options.duration_s,
                      "With --extreme: simulated time per case, s (default 10800)")
      ->needs(extreme_flag);
  soz_cmd->add_option("--seed", soz_extreme_options.seed,
                      "With --extreme: seed of the wave and wind realizations (default 1)")
      ->needs(extreme_flag);
  soz_cmd->add_flag("--json", json, "Machine output spiral.soz (docs/output-format.md) instead of the table");
  soz_cmd->add_flag("--csv", csv, "CSV per direction and riser instead of the table");
  soz_cmd->footer(kExitCodeHelp);

  AnalyzeOptions analyze_options;
  CLI::App* analyze = cli.add_subcommand(
      "analyze", "Time-domain analysis of a load case (uncoupled | sc | sc-enhanced | coupled): CSV + JSON");
  analyze->add_option("PROJECT", project_file, "Project YAML file")->required();
  analyze->add_option("--case", analyze_options.case_name, "Load case name")->required();
  analyze->add_option("--level", analyze_options.level, "uncoupled | sc | sc-enhanced | coupled (default: sc)");
  analyze->add_option("--duration", analyze_options.duration_s, "Simulated time, s (default: 10800)");
  analyze->add_option("--step", analyze_options.step_s, "Output step, s (default: 0.5)");
  analyze->add_option("--seed", analyze_options.seed, "Random seed of the wave and wind realizations (default: 1)");
  analyze->add_flag("--line-dynamics", analyze_options.line_dynamics,
                    "Also dynamic tensions: every mooring line as a dynamic FE line driven by the hull motion");
  analyze->add_option("--out", analyze_options.out,
                      "Output folder (default: out/<project-stem>/analyze/<case>-<level>-seed<N>)");
  analyze->footer(kExitCodeHelp);

  CompareOptions compare_options;
  CLI::App* compare = cli.add_subcommand(
      "compare", "All analysis levels (uncoupled, sc, sc-enhanced, coupled) on one case and realization");
  compare->add_option("PROJECT", project_file, "Project YAML file")->required();
  compare->add_option("--case", compare_options.case_name, "Load case name")->required();
  compare->add_option("--duration", compare_options.duration_s, "Simulated time, s (default: 10800)");
  compare->add_option("--step", compare_options.step_s, "Output step, s (default: 0.5)");
  compare->add_option("--seed", compare_options.seed, "Random seed of the realizations (default: 1)");
  compare->add_option("--out", compare_options.out,
                      "Output folder (default: out/<project-stem>/compare/<case>-seed<N>)");
  compare->footer(kExitCodeHelp);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = cli.exit(error);  // prints help, version or the error
    return code == 0 ? app::kExitOk : app::kExitBadInput;
  }

  try {
    if (validate->parsed()) return run_validate(project_file);
    if (statics->parsed()) return run_statics(project_file, offset_input, json);
    if (soz_cmd->parsed()) {
      if (!case_name.empty()) soz_options.load_case = case_name;
      if (soz_condition == "extreme") soz_options.condition = design::DesignCondition::extreme;
      if (soz_condition == "survival") soz_options.condition = design::DesignCondition::survival;
      soz_options.model = soz_model == "catenary" ? design::SozModel::catenary : design::SozModel::fe;
      soz_options.offset_check = !no_check;
      if (soz_extreme) soz_options.extreme = soz_extreme_options;
      soz_options.zone_per_current = !still_water_only;
      return run_soz_command(project_file, soz_options, json ? SozView::json : csv ? SozView::csv : SozView::table);
    }
    if (report_cmd->parsed()) return run_report(project_file, stage_name, out_dir);
    if (analyze->parsed()) return run_analyze(project_file, analyze_options);
    if (compare->parsed()) return run_compare(project_file, compare_options);
    if (equilibrium->parsed() || stiffness->parsed()) {
      if (!case_name.empty()) case_request.load_case = case_name;
      if (!damaged_line.empty()) case_request.damaged_line = damaged_line;
      case_request.finite_difference_check = stiffness->parsed();
      return run_static_case_command(project_file, case_request, json,
                                     equilibrium->parsed() ? StaticCaseView::equilibrium
                                                           : StaticCaseView::stiffness);
    }
  } catch (const design::InputError& error) {
    fmt::print(stderr, "{}\n", error.what());
    return app::kExitBadInput;
  } catch (const engine::FileFormatError& error) {
    // A data file the project names (hydrodynamic database, panel mesh) is malformed.
    fmt::print(stderr, "{}\n", error.what());
    return app::kExitBadInput;
  } catch (const report::OutputError& error) {
    fmt::print(stderr, "output error: {}\n", error.what());
    return app::kExitOutputError;
  } catch (const engine::SolverError& error) {
    const auto& d = error.diagnostics();
    fmt::print(stderr, "solver failure: {}\n", error.what());
    if (d.iterations > 0) {
      fmt::print(stderr, "  after {} iterations, residual {:.3g} {}\n", d.iterations, d.residual,
                 d.residual_unit);
    }
    fmt::print(stderr,
               "  check the line lengths against the anchor-fairlead span and the hull offset.\n");
    return app::kExitSolverFailure;
  } catch (const std::exception& error) {
    fmt::print(stderr, "internal error: {}\n", error.what());
    return app::kExitInternalError;
  }
  return app::kExitInternalError;
}
