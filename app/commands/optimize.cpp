// `spiral optimize`: pretension optimization of the mooring (or, with
// --target-pretension, the payouts that give each group its target
// pretension), the optimized project written beside the original.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "app/atomic_file.hpp"
#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "app/output_folder.hpp"
#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_target.hpp"
#include "design/project/project_edit.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/optimization_output.hpp"
#include "report/terminal/optimization_tables.hpp"

namespace spiral::app {
namespace {

std::string read_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// `<folder>/<stem>.<suffix>.yaml` beside the project file: never the file itself.
std::filesystem::path beside(const std::string& project_file, const std::string& suffix) {
  const std::filesystem::path p(project_file);
  return p.parent_path() / (p.stem().string() + "." + suffix + ".yaml");
}

class OptimizeCommand : public Command {
 public:
  OptimizeCommand()
      : Command("optimize",
                "Pretension optimization: the payout of each line group that meets every line's code check and "
                "keeps every load case (intact and damaged) inside the risers' SOZ, best for the objective") {}

  int run() const override {
    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    const std::filesystem::path folder = output_folder(out_, project_file_, "optimize");
    std::filesystem::create_directories(folder);
    if (target_) return run_target(loaded, folder);

    design::OptimizationRequest request;
    if (!objective_.empty()) request.objective = objective_of(objective_);
    if (!algorithm_.empty()) request.algorithm = algorithm_of(algorithm_);
    if (!damaged_.empty())
      request.damaged =
          damaged_ == "every_line" ? design::DamagedConditions::every_line : design::DamagedConditions::load_cases;
    request.cases = cases_;
    if (max_evaluations_ > 0) request.max_evaluations = max_evaluations_;
    request.threads = threads_;
    if (level_ == "sc-enhanced") request.dynamic = design::DynamicLevelOptions{duration_s_, seed_};
    const design::OptimizationResult result = design::optimize_pretension(loaded, request);

    const std::string json = design::optimization_to_json(result).dump(2);
    write_file_atomically(folder / "optimization.json", json + "\n");
    fmt::print("{}", json_ ? json + "\n" : report::optimization_table(result));
    std::fflush(stdout);  // the table before the messages below on a terminal
    if (!result.most_violated) {
      std::map<std::string, double> payouts;
      for (const design::LinePayout& l : result.lines) payouts[l.name] = l.payout_m;
      const std::filesystem::path written = beside(project_file_, "optimized");
      write_edited_project("optimized project", written, folder / "optimization.json", [&] {
        return with_payouts(loaded.project, payouts, design::optimized_project_header(result, project_file_));
      });
    } else {
      fmt::print(stderr, "{}: no feasible pretension: {} by {:.4g}; results: {}\n", project_file_,
                 result.most_violated->describe(), result.most_violated->value,
                 (folder / "optimization.json").string());
    }
    for (const std::string& f : result.findings) fmt::print(stderr, "{}: finding: {}\n", project_file_, f);
    return result.status == design::OptimizationStatus::optimal ? kExitOk : kExitSolverFailure;
  }

 private:
  int run_target(const design::ValidatedProject& loaded, const std::filesystem::path& folder) const {
    const design::TargetPretensionResult result = design::solve_target_pretensions(loaded.project);
    const std::string json = design::target_pretension_to_json(result).dump(2);
    write_file_atomically(folder / "target_pretension.json", json + "\n");
    fmt::print("{}", json_ ? json + "\n" : report::target_pretension_table(result));
    std::fflush(stdout);
    std::map<std::string, double> payouts;
    for (const design::TargetPretensionRow& l : result.lines) payouts[l.line] = l.payout_m;
    const std::filesystem::path written = beside(project_file_, "pretensioned");
    write_edited_project("pretensioned project", written, folder / "target_pretension.json", [&] {
      return with_payouts(loaded.project, payouts, design::target_pretension_header(project_file_));
    });
    return kExitOk;
  }

  /// The project file with the payouts, to be written beside it: edited in
  /// place, or — a variation whose mooring is its base file's — a variation
  /// of it that writes the mooring with the payouts.
  std::string with_payouts(const design::Project& project, const std::map<std::string, double>& payouts,
                           const std::string& header) const {
    if (design::mooring_from_base_file(project))
      return design::mooring_variation_with_payouts(project, payouts, header,
                                                    std::filesystem::path(project_file_).filename().string());
    return design::with_line_payouts(read_text(project_file_), project, payouts, header);
  }

  /// Writes the project with the payouts applied; when it cannot be written
  /// the payouts stay in the results file, and the message says why.
  template <class Edit>
  void write_edited_project(std::string_view label, const std::filesystem::path& written,
                            const std::filesystem::path& results, const Edit& edit) const {
    std::string text;
    try {
      text = edit();
    } catch (const std::invalid_argument& error) {
      fmt::print(stderr, "{}: no {} written: {}; the payouts are in {}\n", project_file_, label, error.what(),
                 results.string());
      return;
    }
    write_file_atomically(written, text);
    fmt::print(stderr, "{}: {}\nresults: {}\n", label, written.string(), results.string());
  }

  static design::OptimizationObjective objective_of(const std::string& s) {
    if (s == "min_max_utilization") return design::OptimizationObjective::min_max_utilization;
    if (s == "min_total_payout") return design::OptimizationObjective::min_total_payout;
    if (s == "min_max_offset") return design::OptimizationObjective::min_max_offset;
    return design::OptimizationObjective::max_soz_margin;
  }
  static design::OptimizationAlgorithm algorithm_of(const std::string& s) {
    if (s == "ccsaq") return design::OptimizationAlgorithm::ccsaq;
    if (s == "cobyla") return design::OptimizationAlgorithm::cobyla;
    return design::OptimizationAlgorithm::slsqp;
  }

  void add_options(CLI::App& sub) override {
    sub.add_option("--objective", objective_,
                   "max_soz_margin (default), min_max_utilization, min_total_payout or min_max_offset "
                   "(default: optimization.objective)")
        ->check(CLI::IsMember({"max_soz_margin", "min_max_utilization", "min_total_payout", "min_max_offset"}));
    sub.add_option("--algorithm", algorithm_, "slsqp (default), ccsaq (both with gradients) or cobyla (without)")
        ->check(CLI::IsMember({"slsqp", "ccsaq", "cobyla"}));
    sub.add_option("--damaged", damaged_,
                   "load_cases: the load cases as written; every_line: also every intact case with each line "
                   "removed (default: optimization.damaged)")
        ->check(CLI::IsMember({"load_cases", "every_line"}));
    sub.add_option("--cases", cases_, "Load cases to constrain (default: optimization.cases, else all)")
        ->delimiter(',');
    sub.add_option("--max-evaluations", max_evaluations_, "Evaluation cap (default: optimization.max_evaluations)");
    sub.add_option("--threads", threads_, "Scenarios evaluated in parallel (default: all cores)");
    sub.add_option("--level", level_,
                   "static (default: equilibria, analytic gradients) or sc-enhanced (the 3-h MPM offset and tensions "
                   "of each case's enhanced S-C storm; COBYLA)")
        ->check(CLI::IsMember({"static", "sc-enhanced"}));
    sub.add_option("--duration", duration_s_, "With --level sc-enhanced: simulated time per storm, s (default 10800)");
    sub.add_option("--seed", seed_, "With --level sc-enhanced: seed of the wave and wind realizations (default 1)");
    sub.add_flag("--target-pretension", target_,
                 "Instead: the payout of every line that gives its group's optimization.target_pretension at rest");
    sub.add_flag("--json", json_, "Machine output (docs/output-format.md) instead of the tables");
    sub.add_option("--out", out_, "Results folder (default out/<project>/optimize)");
  }

  std::string objective_, algorithm_, damaged_, out_, level_ = "static";
  double duration_s_ = 10800.0;
  std::uint64_t seed_ = 1;
  std::vector<std::string> cases_;
  int max_evaluations_ = 0;
  int threads_ = 0;
  bool target_ = false;
  bool json_ = false;
};

}  // namespace

std::unique_ptr<Command> optimize_command() { return std::make_unique<OptimizeCommand>(); }

}  // namespace spiral::app
