// `spiral results`: what a run folder's results store holds.
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "app/commands/command.hpp"
#include "app/exit_codes.hpp"
#include "design/results/results_store.hpp"

namespace spiral::app {
namespace {

class ResultsCommand : public Command {
 public:
  ResultsCommand()
      : Command("results",
                "What a run folder's results store holds: tasks done and failed per stage, the verdicts "
                "and iterations of the latest run") {}

  int run() const override {
    const design::StoreSummary s = design::open_existing_store(project_file_)->summary();
    if (json_) {
      nlohmann::json j;
      j["format"] = "spiral.results";
      j["format_version"] = 1;
      j["schema_version"] = s.schema_version;
      j["runs"] = s.runs;
      j["tasks"] = {{"done", s.tasks_done}, {"failed", s.tasks_failed}};
      j["stages"] = nlohmann::json::array();
      for (const auto& c : s.stages)
        j["stages"].push_back({{"stage", c.stage}, {"done", c.done}, {"failed", c.failed}});
      j["last_run"] = {{"outcome", s.last_run_outcome},
                       {"stages", nlohmann::json::array()},
                       {"iterations", nlohmann::json::array()}};
      for (const auto& v : s.last_run)
        j["last_run"]["stages"].push_back({{"stage", v.stage},
                                           {"iteration", v.iteration},
                                           {"model_hash", v.model_hash},
                                           {"pass", v.pass},
                                           {"governing", v.governing},
                                           {"tasks_done", v.tasks_done},
                                           {"tasks_failed", v.tasks_failed},
                                           {"tasks_reused", v.tasks_reused},
                                           {"wall_s", v.wall_s}});
      for (const auto& it : s.iterations)
        j["last_run"]["iterations"].push_back({{"iteration", it.iteration},
                                               {"model_hash", it.model_hash},
                                               {"project_file", it.project_file},
                                               {"payouts_m", nlohmann::json::parse(it.payouts_json)},
                                               {"reason", it.reason}});
      j["failures"] = nlohmann::json::array();
      for (const auto& [task, error] : s.failures) j["failures"].push_back({{"task", task}, {"error", error}});
      fmt::print("{}\n", j.dump(2));
      return kExitOk;
    }
    fmt::print("results store {} (schema {}), {} run(s)\n", design::results_store_file(project_file_).string(),
               s.schema_version, s.runs);
    fmt::print("tasks: {} done, {} failed\n", s.tasks_done, s.tasks_failed);
    for (const auto& c : s.stages) fmt::print("  {:<13} {:>4} done {:>4} failed\n", c.stage, c.done, c.failed);
    fmt::print("latest run: {}\n", s.last_run_outcome.empty() ? "none" : s.last_run_outcome);
    for (const auto& it : s.iterations)
      fmt::print("  iteration {} (model {}): {}{}\n", it.iteration, it.model_hash, it.reason,
                 it.payouts_json == "{}" ? "" : "; payouts (m) " + it.payouts_json);
    for (const auto& v : s.last_run)
      fmt::print("  {:<13} iteration {} {:<5} {} ({} tasks, {} from the store, {} failed, {:.1f} s)\n", v.stage,
                 v.iteration, v.pass ? "PASS" : "FAIL", v.governing, v.tasks_done + v.tasks_failed, v.tasks_reused,
                 v.tasks_failed, v.wall_s);
    for (const auto& [task, error] : s.failures) fmt::print("failed: {}: {}\n", task, error);
    return kExitOk;
  }

 private:
  std::pair<std::string, std::string> main_argument() const override {
    return {"RUN_FOLDER", "Run folder of `spiral run` (holds results.sqlite)"};
  }
  void add_options(CLI::App& sub) override { sub.add_flag("--json", json_, "Print the summary as JSON"); }
  bool json_ = false;
};

}  // namespace

std::unique_ptr<Command> results_command() { return std::make_unique<ResultsCommand>(); }

}  // namespace spiral::app
