// `spiral soz`: riser safe operational zones and the offset check.
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/soz_output.hpp"
#include "design/soz/soz.hpp"
#include "report/terminal/soz_table.hpp"

namespace spiral::app {
namespace {

class SozCommand : public Command {
 public:
  SozCommand()
      : Command("soz", "Riser safe operational zones (allowable hull offset per direction) and the offset check") {}

  int run() const override {
    design::SozOptions options = options_;
    if (!case_name_.empty()) options.load_case = case_name_;
    if (condition_ == "extreme") options.condition = design::DesignCondition::extreme;
    if (condition_ == "survival") options.condition = design::DesignCondition::survival;
    options.model = model_ == "catenary" ? design::SozModel::catenary : design::SozModel::fe;
    options.offset_check = !no_check_;
    if (extreme_) options.extreme = extreme_options_;
    options.zone_per_current = !still_water_only_;

    const design::ValidatedProject loaded = design::load_validated_project(project_file_);
    const design::SozResult result = design::run_soz(loaded, options);
    if (json_) {
      fmt::print("{}\n", design::soz_to_json(result).dump(2));
    } else if (csv_) {
      fmt::print("{}", design::soz_to_csv(result));
    } else {
      fmt::print("{}", report::soz_table(result));
    }
    // A riser that fails its criteria with the hull at rest has no zone: the
    // riser or its criteria are wrong, which is an input problem.
    bool failed = false;
    for (const design::RiserSoz& z : result.risers) {
      if (!z.fails_at_zero_offset) continue;
      fmt::print(stderr,
                 "{}: riser '{}' fails its criteria at zero offset ({}): {} utilization {:.3f} > 1 — it has no safe "
                 "zone; check its criteria (criteria.risers, risers[].criteria) or its design\n",
                 project_file_, z.name, result.conditions.name, z.zero_offset_governing_criterion,
                 z.zero_offset_utilization);
      failed = true;
    }
    return failed ? kExitBadInput : kExitOk;
  }

 private:
  void add_options(CLI::App& sub) override {
    sub.add_option("--case", case_name_,
                   "Load case: its current on the risers, mean heave/rotations and design condition "
                   "(default: still water, offset check of every load case)");
    sub.add_option("--step-deg", options_.step_deg, "Direction step, deg (must divide 360; default 5)");
    sub.add_option("--tolerance", options_.tolerance_m, "Tolerance of each allowable offset, m (default 0.1)");
    sub.add_option("--search-limit", options_.search_limit_pct_depth,
                   "Largest offset searched, % of depth (default 20)");
    sub.add_option("--march-step", options_.march_step_pct_depth, "Coarse march step, % of depth (default 2.5)");
    sub.add_option("--condition", condition_, "Design condition without --case: normal (default), extreme, survival")
        ->check(CLI::IsMember({"normal", "extreme", "survival"}));
    sub.add_option("--model", model_, "Riser model: fe (reference, default) or catenary (screening)")
        ->check(CLI::IsMember({"fe", "catenary"}));
    sub.add_option("--exclude", options_.exclude_risers, "Risers to leave out (repeatable)");
    sub.add_option("--threads", options_.threads, "Threads (default: all cores)");
    sub.add_flag("--no-check", no_check_, "Skip the load cases' equilibria and the offset check");
    sub.add_flag("--still-water-only", still_water_only_,
                 "Without --case: check every case against the still-water zone (no zone per current)");
    CLI::Option* extreme_flag =
        sub.add_flag("--extreme", extreme_,
                     "Also check the extreme offsets: enhanced S-C time-domain analysis of each case, 3-h MPM");
    sub.add_option("--duration", extreme_options_.duration_s,
                   "With --extreme: simulated time per case, s (default 10800)")
        ->needs(extreme_flag);
    sub.add_option("--seed", extreme_options_.seed,
                   "With --extreme: seed of the wave and wind realizations (default 1)")
        ->needs(extreme_flag);
    sub.add_flag("--json", json_, "Machine output spiral.soz (docs/output-format.md) instead of the table");
    sub.add_flag("--csv", csv_, "CSV per direction and riser instead of the table");
  }

  design::SozOptions options_;
  design::SozExtremeOptions extreme_options_;
  std::string case_name_;
  std::string condition_;
  std::string model_ = "fe";
  bool no_check_ = false;
  bool still_water_only_ = false;
  bool extreme_ = false;
  bool json_ = false;
  bool csv_ = false;
};

}  // namespace

std::unique_ptr<Command> soz_command() { return std::make_unique<SozCommand>(); }

}  // namespace spiral::app
