// `spiral analyze`: one load case at one level in the time domain; CSV time
// series + JSON summary (docs/output-format.md). A progress bar goes to
// stderr only when stderr is a terminal.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/atomic_file.hpp"
#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "design/analysis/dynamic_analysis.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/dynamic_analysis_output.hpp"
#include "design/project/warning_note.hpp"

namespace spiral::app {
namespace {

void print_progress(double fraction) {
  const int width = 40;
  const int filled = static_cast<int>(fraction * width);
  fmt::print(stderr, "\r  dynamics [{}{}] {:3.0f} %", std::string(static_cast<std::size_t>(filled), '#'),
             std::string(static_cast<std::size_t>(width - filled), ' '), 100.0 * fraction);
  if (fraction >= 1.0) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

/// Where the time went, the coupled integrator's work and the line tensions, on the terminal.
void print_run_summary(const design::DynamicAnalysisResult& result, double duration_s) {
  fmt::print(
      "  equilibrium {:.3f} s, reduction {:.3f} s, forcing {:.3f} s, dynamics {:.3f} s, WF {:.3f} s, "
      "tensions {:.3f} s\n",
      result.timing.equilibrium_s, result.timing.reduction_s, result.timing.forcing_s, result.timing.dynamics_s,
      result.timing.wave_frequency_s, result.timing.tensions_s);
  if (result.coupled_solver) {
    const engine::IdaStatistics& s = *result.coupled_solver;
    fmt::print(
        "  coupled: {} lines, {} states; {} steps, {} Newton-matrix setups ({} partial), {} residuals, "
        "{} Newton restarts on a fresh matrix, {} failed Newton solves; {} element matrices evaluated, {} "
        "kept by full setups (the element had not moved); {:.1f}x real time\n",
        result.coupled_lines, result.coupled_state_size, s.steps, s.newton_matrix_setups, s.newton_matrix_updates,
        s.residual_evaluations, s.newton_restarts, s.nonlinear_convergence_failures,
        result.coupled_element_matrix_evaluations, result.coupled_element_matrices_kept,
        result.timing.dynamics_s > 0.0 ? duration_s / result.timing.dynamics_s : 0.0);
  }
  if (!result.dynamic_tensions.empty()) {
    fmt::print("  line dynamics {:.3f} s; max fairlead tension, quasi-static vs dynamic:\n",
               result.timing.line_dynamics_s);
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
  // Warnings (design/project/warning_note.hpp) print as they are written.
  for (const auto& note : result.notes) fmt::print("  {}{}\n", design::is_warning(note) ? "" : "note: ", note);
}

class AnalyzeCommand : public Command {
 public:
  AnalyzeCommand()
      : Command("analyze", "Time-domain analysis of a load case (uncoupled | sc | sc-enhanced | coupled): CSV + JSON") {
  }

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    design::DynamicAnalysisRequest request;
    request.load_case = case_name_;
    request.level = design::parse_analysis_level(level_, loaded.project);
    request.duration_s = duration_s_;
    request.output_step_s = step_s_;
    request.seed = seed_;
    request.line_dynamics = line_dynamics_;
    request.tolerance_scale = tolerance_scale_;
    request.detailed_line_mesh = detailed_mesh_;
    request.line_reduction =
        line_reduction_ == "dynamic" ? design::LineReduction::dynamic : design::LineReduction::quasi_static;
    if (!decay_.empty()) {
      // m for the translations, deg for the rotations (as every output); the request takes rad.
      design::DynamicAnalysisRequest::FreeDecay decay;
      for (int d = 0; d < 6; ++d)
        decay.displacement(d) = decay_[static_cast<std::size_t>(d)] * (d < 3 ? 1.0 : std::numbers::pi / 180.0);
      decay.release_s = release_s_;
      request.decay = decay;
    }
    if (isatty(STDERR_FILENO)) request.progress = print_progress;
    const design::DynamicAnalysisResult result = design::run_dynamic_analysis(loaded, request);
    const std::filesystem::path folder = output_folder(
        out_, project_file_, std::filesystem::path("analyze") / fmt::format("{}-{}-seed{}", case_name_, level_, seed_));
    try {
      std::filesystem::create_directories(folder);
      write_file_atomically(folder / "time_series.csv", design::dynamic_time_series_csv(result));
      write_file_atomically(folder / "summary.json",
                            design::dynamic_analysis_to_json(result, loaded.project.name).dump(2) + "\n");
    } catch (const std::exception& error) {
      fmt::print(stderr, "output error: {}\n", error.what());
      return kExitOutputError;
    }
    fmt::print("{} analysis of '{}', case {} (seed {}, {:.0f} s): {}\n", level_, loaded.project.name, case_name_, seed_,
               duration_s_, folder.string());
    print_run_summary(result, duration_s_);
    return kExitOk;
  }

 private:
  void add_options(CLI::App& sub) override {
    sub.add_option("--case", case_name_, "Load case name")->required();
    sub.add_option("--level", level_, "uncoupled | sc | sc-enhanced | coupled (default: sc)");
    sub.add_option("--duration", duration_s_, "Simulated time, s (default: 10800)");
    sub.add_option("--step", step_s_, "Output step, s (default: 0.5)");
    sub.add_option("--seed", seed_, "Random seed of the wave and wind realizations (default: 1)");
    sub.add_flag("--line-dynamics", line_dynamics_,
                 "Also dynamic tensions: every mooring line as a dynamic FE line driven by the hull motion");
    sub.add_option("--tolerance-scale", tolerance_scale_,
                   "The dynamic FE lines' (and the coupled system's) integrator tolerances x this; < 1 for a "
                   "convergence reference (default: 1)");
    sub.add_flag("--detailed-mesh", detailed_mesh_,
                 "The coupled level's and --line-dynamics' FE lines on each line's own fe mesh instead of the "
                 "project's global_analysis.element_length (to check that mesh)");
    sub.add_option("--line-reduction", line_reduction_,
                   "sc-enhanced: the lines' damping, added mass and low-frequency stiffening from their dynamic FE "
                   "models (dynamic, the default) or their damping and added mass from their quasi-static shape "
                   "(quasi-static)")
        ->check(CLI::IsMember({"quasi-static", "dynamic"}));
    sub.add_option("--decay", decay_,
                   "Free decay: the hull pulled this far from its static equilibrium and released, "
                   "surge,sway,heave (m),roll,pitch,yaw (deg); e.g. 10,0,0,0,0,0")
        ->expected(6)
        ->delimiter(',');
    sub.add_option("--release", release_s_,
                   "Free decay: the release time, s (default: 300; the pull builds up "
                   "over its first half)");
    sub.add_option("--out", out_, "Output folder (default: out/<project-stem>/analyze/<case>-<level>-seed<N>)");
  }

  std::string case_name_;
  std::string level_ = "sc";
  double duration_s_ = 10800.0;
  double step_s_ = 0.5;
  std::uint64_t seed_ = 1;
  std::string out_;
  bool line_dynamics_ = false;
  double tolerance_scale_ = 1.0;
  bool detailed_mesh_ = false;
  std::vector<double> decay_;
  std::string line_reduction_ = "dynamic";
  double release_s_ = 300.0;
};

}  // namespace

std::unique_ptr<Command> analyze_command() { return std::make_unique<AnalyzeCommand>(); }

}  // namespace spiral::app
