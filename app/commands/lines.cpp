// `spiral lines`: every selected mooring line and riser as a dynamic FE line
// under a given hull motion history (design/analysis/motion_lines.hpp); CSV
// time series + JSON summary (docs/lines.md).
#include <algorithm>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/atomic_file.hpp"
#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "design/analysis/motion_lines.hpp"
#include "design/import/motion_history.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/motion_lines_output.hpp"

namespace spiral::app {
namespace {

void print_summary(const nlohmann::json& summary) {
  for (const auto& line : summary["lines"]) {
    const auto& check = line["dynamic_tension_check"];
    if (check.is_null()) continue;
    fmt::print("    {:<12} fairlead {:10.1f} kN ({}), utilization {:.3f} {}\n", line["name"].get<std::string>(),
               check["extreme_N"].get<double>() / 1e3, check["basis"].get<std::string>(),
               check["utilization"].get<double>(), check["passes"].get<bool>() ? "pass" : "FAIL");
  }
  for (const auto& riser : summary["risers"]) {
    if (!riser.contains("governing_criterion")) continue;
    fmt::print("    {:<12} {:<24} utilization {:.3f} {}\n", riser["name"].get<std::string>(),
               riser["governing_criterion"].get<std::string>(), riser["utilization"].get<double>(),
               riser["passes"].get<bool>() ? "pass" : "FAIL");
  }
}

class LinesCommand : public Command {
 public:
  LinesCommand()
      : Command("lines",
                "Mooring lines and risers as dynamic FE lines under a given hull motion history (CSV): "
                "tensions, anchor, touchdown and riser criteria; CSV + JSON") {}

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    const design::MotionHistory history = design::read_motion_history(motion_file_);
    design::MotionLinesRequest request;
    request.load_case = case_name_;
    request.motion_times_s = history.time_s;
    request.motion = history.offset;
    for (const std::string& note : history.notes) request.motion_notes.push_back(motion_file_ + ": " + note);
    request.lines = lines_;
    request.output_step_s = step_s_;
    request.ramp_s = ramp_s_;
    request.waves_on_lines = !no_waves_;
    request.seed = seed_;
    request.tolerance_scale = tolerance_scale_;
    const design::MotionLinesResult result = design::run_motion_lines(loaded, request);
    const nlohmann::json summary = design::motion_lines_to_json(result, loaded, motion_file_);
    const std::filesystem::path folder =
        output_folder(out_, project_file_,
                      std::filesystem::path("lines") /
                          fmt::format("{}-{}", case_name_, std::filesystem::path(motion_file_).stem().string()));
    try {
      std::filesystem::create_directories(folder);
      write_file_atomically(folder / "time_series.csv", design::motion_lines_csv(result));
      write_file_atomically(folder / "summary.json", summary.dump(2) + "\n");
    } catch (const std::exception& error) {
      fmt::print(stderr, "output error: {}\n", error.what());
      return kExitOutputError;
    }
    fmt::print("lines of '{}' under {} ({} samples, {:.0f} s), case {}: {}\n", loaded.project.name, motion_file_,
               history.time_s.size(), history.time_s.back() - history.time_s.front(), case_name_, folder.string());
    fmt::print("  {} mooring lines, {} risers in {:.1f} s; statistics from {:g} s:\n", result.lines.size(),
               result.risers.size(), result.wall_s, result.statistics_from_s);
    print_summary(summary);
    for (const auto& note : summary["notes"]) fmt::print("  note: {}\n", note.get<std::string>());
    return kExitOk;
  }

 private:
  void add_options(CLI::App& sub) override {
    sub.add_option("--motion", motion_file_,
                   "Hull motion history: CSV with a header naming time, surge, sway, heave (m), roll, pitch, yaw "
                   "(deg) (docs/lines.md)")
        ->required();
    sub.add_option("--case", case_name_, "Load case: its current, waves, damaged line and design condition")
        ->required();
    sub.add_option("--lines", lines_, "Mooring lines and risers to run, comma separated (default: all intact)")
        ->delimiter(',');
    sub.add_option("--step", step_s_, "Output step, s (default: 0.5)");
    sub.add_option("--ramp", ramp_s_, "Build-up time of the motion, s; statistics start after it (default: 20)");
    sub.add_option("--seed", seed_, "Seed of the case's sea on the lines (default: the load case's seed)");
    sub.add_flag("--no-waves", no_waves_, "No waves on the lines (current and the hull motion only)");
    sub.add_option("--tolerance-scale", tolerance_scale_,
                   "The FE lines' integrator tolerances x this (default: 1, the single-line defaults); 0.1 for a "
                   "motion with wave-frequency content, as analyze and compare run the lines under it (docs/lines.md)");
    sub.add_option("--out", out_, "Output folder (default: out/<project-stem>/lines/<case>-<motion-stem>)");
  }

  std::string motion_file_;
  std::string case_name_;
  std::vector<std::string> lines_;
  double step_s_ = 0.5;
  double ramp_s_ = 20.0;
  std::optional<std::uint64_t> seed_;
  bool no_waves_ = false;
  double tolerance_scale_ = 1.0;
  std::string out_;
};

}  // namespace

std::unique_ptr<Command> lines_command() { return std::make_unique<LinesCommand>(); }

}  // namespace spiral::app
