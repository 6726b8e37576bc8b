#pragma once
// The design spiral (DESIGN.md §2, §9, §10): the project's stages in order —
// preliminary → intermediate → advanced by default — each planned as tasks
// (task_batch.hpp) against one results store (results_store.hpp), so that a
// stopped run resumes where it stopped and a stage takes what an earlier one
// computed (the intermediate stage does not solve the static cases again).
//
// Tasks of a stage:
//   preliminary   the mooring overview (pretensions, restoring curves), the
//                 static case of still water and of every load case, the
//                 still-water SOZ (with risers); reduced to the checks; then
//                 the enhanced S-C storm of the governing case;
//   intermediate  the same static tasks (taken from the store) and the
//                 enhanced S-C storm of every load case; reduced to the ranking;
//   advanced      per critical case, the coupled run and the enhanced S-C run
//                 on the same sea, and the final checks.
//
// Feedback (DESIGN.md §2): when the preliminary stage's offset or tension
// checks fail (mooring code, offset limit, offset against the SOZ, dynamic
// tension, extreme offset), or its stage entry asks (`optimize: true`), the
// pretension optimizer runs (itself a stored task); its payouts make a new
// iteration of the project — written to <out>/iterations/iteration-<k>.yaml,
// its content hash recorded — and the stage runs again, up to the stage's
// `max_iterations`. When no pretension meets the checks (the optimizer finds
// nothing feasible, or nothing to change), that is reported as a finding and
// the spiral goes on with the best mooring it has.
//
// A task whose solver fails is stored as failed with its message; the stage
// reports it and the run's outcome says a solver failed. A stage that lacks a
// task it cannot do without (the mooring overview, still water, the zone)
// is not completed and the stages after it do not run.

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_study.hpp"
#include "design/project/validated_project.hpp"
#include "design/stages/advanced_stage.hpp"
#include "design/stages/intermediate_stage.hpp"
#include "design/stages/static_stage.hpp"
#include "design/workflow/cluster.hpp"

namespace spiral::design {

/// The stages spiral run knows, in order.
inline const std::vector<std::string> kSpiralStages{"preliminary", "intermediate", "advanced"};

struct SpiralRunOptions {
  std::filesystem::path out_folder;  ///< the run folder: results.sqlite, iterations/
  int jobs = 0;                      ///< tasks at a time; 0: every core
  bool fresh = false;                ///< start a new store instead of resuming
  std::optional<std::string> until;  ///< the last stage to run (one of kSpiralStages)
  AdvancedStageOptions advanced;     ///< duration override, coupled work limits
  std::string version;               ///< of spiral, recorded with the run
  /// Progress lines (one per finished task, stage start and end); may be empty.
  std::function<void(const std::string&)> log;
  /// The MPI ranks to share the tasks over (cluster.hpp); none: this process
  /// alone, on `jobs` threads. Every rank calls run_spiral alike; rank 0 owns
  /// the store and logs.
  const Cluster* cluster = nullptr;
  /// Feedback through the pretension optimizer (DESIGN.md §2). Off: the
  /// project as given, one iteration, failing checks reported as a finding
  /// (`spiral report` of one stage).
  bool feedback = true;
};

/// One stage of one iteration.
struct StageRun {
  std::string stage;
  int iteration = 1;
  std::string model_hash;  ///< project_content_hash of the iteration's project
  std::shared_ptr<const ValidatedProject> project;
  std::optional<StaticStageResults> preliminary;
  std::optional<IntermediateStageResults> intermediate;
  std::optional<AdvancedStageResults> advanced;
  bool completed = false;  ///< its results exist (a task it cannot do without may have failed)
  bool pass = false;
  std::string governing;              ///< the check that decides the verdict
  std::vector<std::string> failures;  ///< failed tasks: "<task> <case>: <message>"
  int tasks = 0, tasks_failed = 0, tasks_reused = 0;
  double wall_s = 0.0;
};

/// The optimizer's step between two iterations of the preliminary stage.
struct FeedbackStep {
  int from_iteration = 1;
  std::string reason;  ///< why it ran
  std::optional<OptimizationResult> optimization;
  std::string error;                        ///< the optimizer's solver failure
  bool applied = false;                     ///< its payouts made the next iteration
  std::filesystem::path project_file;       ///< the next iteration's project (applied)
  std::map<std::string, double> payouts_m;  ///< per line (applied)
};

struct SpiralRunResult {
  int run_id = 0;
  std::filesystem::path store_file;
  std::vector<StageRun> stages;  ///< every stage of every iteration, in run order
  std::vector<FeedbackStep> feedback;
  std::vector<std::string> findings;  ///< what no pretension can fix (riser design), and the like
  bool pass = false;                  ///< every stage run last passes
  bool solver_failures = false;       ///< a task's solver failed
  bool completed = false;             ///< every requested stage has results
};

/// Runs the spiral of `project_file`. `stage_done` is called after each
/// stage with its results (the app writes its report there). Throws
/// InputError for a bad project or request, OutputError when the store cannot
/// be written, engine::FileFormatError for a malformed data file.
SpiralRunResult run_spiral(const std::filesystem::path& project_file, const SpiralRunOptions& options,
                           const std::function<void(const StageRun&)>& stage_done = {});

/// The project's pretension optimization (as the preliminary stage's
/// feedback runs it on the project as given: the same stored task) and its
/// pretension study of every group together over `study_points` points —
/// `spiral report --stage optimization` — as tasks of the run folder's
/// results store: a second call on the same project takes both from it.
struct OptimizationStudy {
  OptimizationResult optimization;
  PretensionStudyResult study;
  int tasks_reused = 0;  ///< of the two
  std::filesystem::path store_file;
};

/// Throws as run_spiral; a solver failure of either task as
/// engine::SolverError with its stored message.
OptimizationStudy run_optimization_study(const std::filesystem::path& project_file, const SpiralRunOptions& options,
                                         int study_points);

/// The risers whose top tension fails in the advanced stage's coupled
/// storms, one finding each (the worst case, the mean and the dynamic range
/// against the limit): the static checks before that stage, and the S-C
/// levels' quasi-static riser criteria, do not see a riser's own dynamics
/// under the hull's wave-frequency motion, and the pretensions move its mean
/// top tension, not that range — the riser design's (hang-off capacity,
/// configuration) to answer.
std::vector<std::string> advanced_riser_findings(const AdvancedStageResults& advanced, int iteration);

/// The stages the project asks for (its stages[] names among kSpiralStages,
/// else all three), up to `until`. Throws InputError for an unknown `until`.
std::vector<std::string> spiral_stages(const Project& project, const std::optional<std::string>& until);

}  // namespace spiral::design
