#include "design/workflow/spiral_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <sstream>
#include <thread>

#include "design/analysis/coupled_analysis.hpp"
#include "design/project/model_hash.hpp"
#include "design/project/project_edit.hpp"
#include "design/project/request_error.hpp"
#include "design/results/optimization_output.hpp"
#include "design/results/output_error.hpp"
#include "design/results/results_store.hpp"
#include "design/workflow/task_batch.hpp"
#include "engine/common/solver_error.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

/// The storms of every stage: 3 h at 0.5 s, the case's seed, the lines'
/// dynamic reduction (stage_dynamics.hpp) — in the task's identity, so that
/// a store written with the quasi-static reduction is not reused.
constexpr const char* kStormOptions = "duration_s=10800 output_step_s=0.5 line_reduction=dynamic";

/// The coupled verifications' integrator convention (the lines at
/// kCoupledLineToleranceScale of the single-line tolerances: under
/// wave-frequency motion since 7b8091a, always since the change that
/// introduced the constant; the Newton solve's end B from the hull's
/// correction alone and full setups every 8 steps since 8f7a11a, which moved
/// the risers' top-tension std by up to 2 %; the lines' wave kinematics
/// sampled in time and interpolated since the change that added
/// `line_waves=sampled`), in the task's identity, so that a store written
/// before any of them is not reused.
std::string verification_options() {
  return fmt::format("coupled_line_tolerance_scale={:g} coupled_newton=2 line_waves=sampled",
                     kCoupledLineToleranceScale);
}

/// What one run shares between its stages.
struct RunContext {
  ResultsStore* store = nullptr;  ///< rank 0 (or the only process) only
  const SpiralRunOptions& options;
  int jobs = 1;
  int run_id = 0;
  bool root() const { return options.cluster == nullptr || options.cluster->rank() == 0; }
  void log(const std::string& line) const {
    if (options.log && root()) options.log(line);
  }
  /// Every rank waits here until rank 0 has arrived (after it wrote a file the others read).
  void barrier() const {
    if (options.cluster == nullptr || options.cluster->size() < 2) return;
    Bytes nothing;
    options.cluster->broadcast(nothing);
  }
};

/// One iteration's project and its fingerprint.
struct Iteration {
  int number = 1;
  std::filesystem::path project_file;
  std::shared_ptr<const ValidatedProject> project;
  std::string model_hash;
};

std::string eta(double seconds) {
  return seconds < 90.0 ? fmt::format("{:.0f} s", seconds) : fmt::format("{:.0f} min", seconds / 60.0);
}

/// Runs a batch of the stage on `jobs` threads (0: the run's); progress lines
/// name the stage and the step ("statics", "storms", …).
void run_batch(const RunContext& ctx, TaskBatch& batch, StageRun& stage, const std::string& step, int jobs = 0) {
  engine::Stopwatch start;
  int computed = 0;
  batch.run(
      ctx.store, jobs > 0 ? jobs : ctx.jobs,
      [&](const BatchProgress& p) {
        const std::string slowest = p.slowest_running.empty() ? ""
                                                              : fmt::format("; running {} for {:.0f} s",
                                                                            p.slowest_running, p.slowest_running_s);
        if (p.heartbeat) {
          ctx.log(fmt::format("[{} {} {}/{}]{}", p.stage, step, p.finished, p.total, slowest));
          return;
        }
        computed += p.last_reused ? 0 : 1;
        // Remaining tasks at the pace of those computed so far (wall clock, all jobs together).
        const std::string remaining =
            computed > 0 && p.finished < p.total
                ? fmt::format(", ETA {}", eta(start.seconds() / computed * (p.total - p.finished)))
                : "";
        ctx.log(fmt::format("[{} {} {}/{}] {} {}{}{}{}", p.stage, step, p.finished, p.total, p.last_task,
                            p.last_reused ? "(stored)" : fmt::format("{:.1f} s", p.last_wall_s),
                            p.last_failed ? " FAILED" : "", remaining, slowest));
      },
      ctx.options.cluster);
  stage.tasks += static_cast<int>(batch.size());
  stage.tasks_failed += batch.failed();
  stage.tasks_reused += batch.reused();
  for (std::size_t i = 0; i < batch.size(); ++i)
    if (batch.error(i)) stage.failures.push_back(fmt::format("{}: {}", task_name(batch.identity(i)), *batch.error(i)));
}

TaskIdentity identity(const Iteration& it, std::string kind, std::string case_name = {}, std::string level = {},
                      std::uint64_t seed = 0, std::string options = {}) {
  return {it.model_hash, std::move(kind), std::move(case_name), std::move(level), seed, std::move(options)};
}

// The queryable rows of each kind of task (results_store.hpp).

void describe_static_case(const StaticCaseResult& r, TaskResult& row) {
  for (const LineStaticsRow& line : r.lines)
    row.checks.push_back({"line tension", line.name, "T_max/MBL", line.utilization, line.utilization <= 1.0});
  for (const RiserStaticsRow& riser : r.risers)
    row.checks.push_back({"riser criteria", riser.name, riser.governing_criterion, riser.utilization, riser.passes});
  row.solver = fmt::format("equilibrium_iterations={}", r.equilibrium_iterations);
}

void describe_soz(const SozResult& r, TaskResult& row) {
  for (const RiserSoz& riser : r.risers)
    row.checks.push_back({"riser at zero offset", riser.name, riser.zero_offset_governing_criterion,
                          riser.zero_offset_utilization, !riser.fails_at_zero_offset});
  row.solver = fmt::format("riser_solves={}", r.solves);
}

StoredChannel stored_channel(const std::string& prefix, const StormChannel& c) {
  StoredChannel s;
  s.channel = prefix + c.name;
  s.unit = c.unit;
  s.mean = c.moments().mean;
  s.std_dev = c.moments().std_dev;
  s.minimum = c.moments().minimum;
  s.maximum = c.moments().maximum;
  s.mpm_max = c.mpm_max();
  s.mpm_min = c.mpm_min();
  return s;
}

void describe_storm(const StageDynamics& d, TaskResult& row) {
  for (const StormChannel& c : d.channels) row.channels.push_back(stored_channel("", c));
  if (!d.most_loaded_line.empty())
    row.checks.push_back(
        {"dynamic tension", d.most_loaded_line, "MPM tension·SF/MBL", d.tension_utilization, d.tension_pass});
  if (d.extreme_offset)
    row.checks.push_back({"extreme offset (SOZ)", d.extreme_offset->governing_riser, "MPM offset/allowable",
                          d.extreme_offset->ratio, d.extreme_offset->passes});
  row.solver = fmt::format("steps={}", d.solver_steps);
}

void describe_verification(const CriticalCaseVerification& v, TaskResult& row) {
  if (v.coupled)
    for (const StormChannel& c : v.coupled->channels) row.channels.push_back(stored_channel("coupled/", c));
  if (v.sc)
    for (const StormChannel& c : v.sc->channels) row.channels.push_back(stored_channel("sc-enhanced/", c));
  for (const FinalLineCheck& l : v.lines)
    row.checks.push_back({"dynamic tension", l.line, "MPM tension·DF/MBL", l.utilization, l.pass});
  if (v.offset_limit_m && *v.offset_limit_m > 0.0)
    row.checks.push_back(
        {"offset limit", "", "MPM offset/limit", v.mpm_offset_m / *v.offset_limit_m, v.offset_limit_pass});
  if (v.soz_offset)
    row.checks.push_back({"extreme offset (SOZ)", v.soz_offset->governing_riser, "MPM offset/allowable",
                          v.soz_offset->ratio, v.soz_offset->passes});
  for (const FinalRiserCheck& r : v.risers)
    if (r.limit_N) row.checks.push_back({"riser top tension", r.riser, "MPM/limit", r.utilization, r.pass});
  // The record stays (the S-C level and the checks that ran are results);
  // the error marks the task as one whose analysis failed.
  if (v.error) row.error = *v.error;
}

void describe_optimization(const OptimizationResult& r, TaskResult& row) {
  row.solver = fmt::format("status={} evaluations={} stop={}", to_string(r.status), r.evaluations, r.stop_reason);
  if (r.most_violated)
    row.checks.push_back({"most violated constraint", r.most_violated->subject, r.most_violated->kind,
                          1.0 + r.most_violated->value, false});
}

/// The static parts of a stage, from the store or computed.
struct StaticParts {
  std::optional<MooringOverview> overview;
  std::vector<StaticCaseResult> cases;  ///< still water first, then every load case that could be solved
  std::optional<SozResult> soz;
  std::vector<std::string> notes;  ///< the load cases left out and why
  bool complete = false;           ///< overview, still water and (with risers) the zone exist
};

StaticParts static_parts(const RunContext& ctx, const Iteration& it, StageRun& stage) {
  const ValidatedProject& vp = *it.project;
  const Project& p = vp.project;
  TaskBatch batch(stage.stage, it.number);
  const std::size_t overview =
      batch.add<MooringOverview>(identity(it, "mooring-overview"), [&vp] { return run_mooring_overview(vp); });
  // Cases sharing an environment (a matrix heading intact and with each line
  // removed) solve its FE lines at rest once; the results are those of cold
  // solves (static_case.hpp), whichever task runs first.
  RestSolutionCache rest_solutions;
  std::vector<std::size_t> cases;
  cases.push_back(batch.add<StaticCaseResult>(
      identity(it, "static-case", "still-water", "", 0, "finite_difference_check"),
      [&vp, &rest_solutions] { return run_stage_static_case(vp, std::nullopt, &rest_solutions); },
      describe_static_case));
  for (const LoadCase& lc : p.load_cases) {
    const std::string name = lc.name;
    cases.push_back(batch.add<StaticCaseResult>(
        identity(it, "static-case", name),
        [&vp, name, &rest_solutions] { return run_stage_static_case(vp, name, &rest_solutions); },
        describe_static_case));
  }
  std::optional<std::size_t> soz;
  if (!p.risers.empty()) {
    const StageSoz settings = preliminary_soz_settings(p);
    soz = batch.add<SozResult>(
        identity(it, "soz", "still-water", "", 0,
                 fmt::format("model={} step_deg={}", settings.model == StageSozModel::fe ? "fe" : "catenary",
                             settings.step_deg)),
        [&vp] { return *run_stage_soz(vp); }, describe_soz);
  }
  run_batch(ctx, batch, stage, "statics");

  StaticParts out;
  if (const auto* o = batch.value<MooringOverview>(overview)) out.overview = *o;
  if (soz)
    if (const auto* z = batch.value<SozResult>(*soz)) out.soz = *z;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    if (const auto* c = batch.value<StaticCaseResult>(cases[k]))
      out.cases.push_back(*c);
    else if (k > 0)
      out.notes.push_back(fmt::format("load case {} left out: its static equilibrium failed: {}",
                                      batch.identity(cases[k]).case_name, *batch.error(cases[k])));
  }
  out.complete = out.overview && batch.value<StaticCaseResult>(cases[0]) && (!soz || out.soz);
  return out;
}

StaticStageResults reduce_parts(const Iteration& it, const StaticParts& parts, const StaticStageOptions& options) {
  StaticStageResults r = reduce_static_stage(*it.project, *parts.overview, parts.cases, parts.soz,
                                             stage_hull_panels(it.project->project), options);
  for (const std::string& note : parts.notes) r.notes.push_back(note);
  if (!parts.notes.empty()) r.pass = false;  // an unsolved case is not a passing one
  return r;
}

TaskIdentity storm_identity(const Iteration& it, const std::string& case_name) {
  return identity(it, "storm", case_name, to_string(AnalysisLevel::semi_coupled_enhanced),
                  static_cast<std::uint64_t>(case_seed(it.project->project, case_name)), kStormOptions);
}

void finish(StageRun& stage, bool pass, std::string governing, const engine::Stopwatch& start) {
  stage.pass = pass && stage.tasks_failed == 0;
  stage.governing = std::move(governing);
  stage.wall_s = start.seconds();
}

std::string describe(const GoverningCheck& g) {
  if (g.check.empty()) return {};
  return fmt::format("{}: {}{} {} {:.3f}", g.case_name, g.check, g.item.empty() ? "" : " " + g.item, g.criterion,
                     g.utilization);
}

StageRun new_stage(std::string name, const Iteration& it) {
  StageRun stage;
  stage.stage = std::move(name);
  stage.iteration = it.number;
  stage.model_hash = it.model_hash;
  stage.project = it.project;
  return stage;
}

StageRun run_preliminary(const RunContext& ctx, const Iteration& it) {
  engine::Stopwatch start;
  StageRun stage = new_stage("preliminary", it);
  const StaticParts parts = static_parts(ctx, it, stage);
  if (!parts.complete) {
    finish(stage, false, "", start);
    return stage;
  }
  StaticStageResults r = reduce_parts(it, parts, {});
  if (const std::optional<StormChoice> choice = stage_storm_choice(it.project->project, r)) {
    TaskBatch batch(stage.stage, it.number);
    const ValidatedProject& vp = *it.project;
    const StaticStageResults& statics = r;
    const std::size_t index = choice->case_index;
    const std::size_t task = batch.add<StageDynamics>(
        storm_identity(it, r.cases[index].case_name),
        [&vp, &statics, index] { return run_case_storm(vp, statics, index); }, describe_storm);
    run_batch(ctx, batch, stage, "storm");
    if (const auto* storm = batch.value<StageDynamics>(task)) {
      StageDynamics chosen = *storm;
      chosen.selection = choice->why;  // the same storm the intermediate stage runs; only the reason differs
      add_stage_storm(r, std::move(chosen));
    } else {
      r.notes.push_back(fmt::format("the S-C storm of {} failed: {}", r.cases[index].case_name, *batch.error(task)));
      r.pass = false;
    }
  }
  stage.completed = true;
  // This run's wall time of the stage (tasks taken from the store cost none).
  r.wall_time_s = start.seconds();
  finish(stage, r.pass, describe(r.governing), start);
  stage.preliminary = std::move(r);
  return stage;
}

StageRun run_intermediate(const RunContext& ctx, const Iteration& it) {
  engine::Stopwatch start;
  StageRun stage = new_stage("intermediate", it);
  const StaticParts parts = static_parts(ctx, it, stage);
  if (!parts.complete) {
    finish(stage, false, "", start);
    return stage;
  }
  StaticStageOptions options;
  options.dynamics = false;
  StaticStageResults statics = reduce_parts(it, parts, options);
  TaskBatch batch(stage.stage, it.number);
  const ValidatedProject& vp = *it.project;
  RestSolutionCache rest_solutions;  // the storms' S-C static cases sharing an environment
  for (std::size_t i = 1; i < statics.cases.size(); ++i) {
    batch.add<StageDynamics>(
        storm_identity(it, statics.cases[i].case_name),
        [&vp, &statics, i, &rest_solutions] { return run_case_storm(vp, statics, i, &rest_solutions); },
        describe_storm);
  }
  engine::Stopwatch storms_start;
  run_batch(ctx, batch, stage, "storms");
  std::vector<CaseStorm> storms;
  for (std::size_t k = 0; k < batch.size(); ++k) {
    if (const auto* storm = batch.value<StageDynamics>(k)) {
      StageDynamics s = *storm;
      s.selection = "every case of the matrix";
      storms.push_back({k + 1, std::move(s)});
    } else {
      statics.notes.push_back(fmt::format("load case {} not ranked: its S-C storm failed: {}",
                                          statics.cases[k + 1].case_name, *batch.error(k)));
    }
  }
  IntermediateStageResults r =
      reduce_intermediate_stage(std::move(statics), std::move(storms), intermediate_critical_cases(vp.project));
  r.threads = ctx.jobs;
  r.storms_wall_s = storms_start.seconds();
  r.wall_time_s = start.seconds();
  if (batch.failed() > 0 || !parts.notes.empty()) r.pass = false;
  stage.completed = true;
  std::string governing;
  if (!r.ranked.empty()) {
    const RankedCase& top = r.ranked.front();
    governing = fmt::format("{}: {} {:.3f}", r.statics.cases[top.case_index].case_name,
                            to_string(top.governing_measure), top.score);
  }
  finish(stage, r.pass, governing, start);
  stage.intermediate = std::move(r);
  return stage;
}

StageRun run_advanced(const RunContext& ctx, const Iteration& it, const IntermediateStageResults& intermediate) {
  engine::Stopwatch start;
  StageRun stage = new_stage("advanced", it);
  const ValidatedProject& vp = *it.project;
  const AdvancedStageOptions& options = ctx.options.advanced;
  const DynamicAnalysisRequest base = advanced_stage_request(vp.project, options);
  TaskBatch batch(stage.stage, it.number);
  for (const RankedCase& ranked : intermediate.ranked) {
    // A case that is another's analysis under a second name shares its task.
    if (!ranked.critical || earlier_identical_case(vp.project, intermediate, ranked, options)) continue;
    const std::string& name = intermediate.statics.cases[ranked.case_index].case_name;
    const long max_steps = coupled_max_steps(options, name);
    // The rank and score are the intermediate stage's; they enter the key so
    // that a changed ranking does not reuse a record that names another rank.
    batch.add<CriticalCaseVerification>(
        identity(it, "verification", name, to_string(AnalysisLevel::coupled),
                 static_cast<std::uint64_t>(case_seed(vp.project, name)),
                 fmt::format("duration_s={} output_step_s={} max_steps={} rank={} score={:.17g} {}", base.duration_s,
                             base.output_step_s, max_steps, ranked.rank, ranked.score, verification_options())),
        [&vp, &intermediate, &ranked, base, max_steps] {
          return verify_critical_case(vp, intermediate, ranked, base, max_steps);
        },
        describe_verification);
  }
  engine::Stopwatch runs_start;
  // As many coupled runs at a time as cores: a run spreads its lines over
  // the cores it is given (engine::worker_count: none beside another run),
  // and one run on two cores is only 1.2-1.9x faster than on one (the
  // default scenario's four critical cases: 233 s one at a time on two
  // threads, 182 s two at a time on one each). The last run takes the
  // cores the others free when they end (CoupledOptions::take_freed_cores).
  run_batch(ctx, batch, stage, "verification", ctx.options.jobs);
  std::vector<CriticalCaseVerification> verified;
  for (std::size_t k = 0; k < batch.size(); ++k)
    if (const auto* v = batch.value<CriticalCaseVerification>(k)) verified.push_back(*v);
  AdvancedStageResults r = reduce_advanced_stage(
      intermediate, base, critical_case_verifications(vp.project, intermediate, options, verified));
  r.verification_wall_s = runs_start.seconds();
  r.wall_time_s = start.seconds();
  stage.completed = true;
  for (const CriticalCaseVerification& c : r.cases)
    if (c.error) stage.failures.push_back(fmt::format("verification {}: {}", c.case_name, *c.error));
  finish(stage, r.pass && r.failed_runs == 0, r.governing, start);
  stage.advanced = std::move(r);
  return stage;
}

/// Why the preliminary stage asks for the optimizer; empty when it does not.
/// The project's request (stages[].optimize) is met by one optimization:
/// after it (`request_met`) only failing checks make another iteration.
std::string feedback_reason(const Stage* settings, const StaticStageResults& r, bool request_met) {
  int code = 0, limit = 0, zone = 0;
  for (const CaseCheck& c : r.checks) {
    code += c.lines_pass ? 0 : 1;
    limit += c.offset_pass ? 0 : 1;
    zone += c.soz_pass ? 0 : 1;
  }
  std::vector<std::string> parts;
  if (code > 0) parts.push_back(fmt::format("the mooring code check fails in {} case(s)", code));
  if (limit > 0) parts.push_back(fmt::format("the offset limit is exceeded in {} case(s)", limit));
  if (zone > 0) parts.push_back(fmt::format("the static offset leaves the riser SOZ in {} case(s)", zone));
  if (r.dynamics && !r.dynamics->tension_pass)
    parts.push_back(fmt::format("the dynamic tension of {} fails", r.dynamics->case_name));
  if (r.dynamics && r.dynamics->extreme_offset && !r.dynamics->extreme_offset->passes)
    parts.push_back(fmt::format("the extreme offset of {} leaves the SOZ", r.dynamics->case_name));
  if (parts.empty() && settings && settings->optimize && !request_met)
    parts.push_back("the project asks (stages[].optimize)");
  std::string reason;
  for (const std::string& p : parts) reason += (reason.empty() ? "" : "; ") + p;
  return reason;
}

/// How far the preliminary stage is from passing the checks the optimizer
/// acts on: the failing checks counted, then their worst ratio. An iteration
/// that does not lower it ends the feedback.
std::pair<int, double> feedback_distance(const StaticStageResults& r) {
  int failing = 0;
  double worst = 0.0;
  const auto consider = [&](bool pass, double ratio) {
    failing += pass ? 0 : 1;
    if (!pass) worst = std::max(worst, ratio);
  };
  for (const CaseCheck& c : r.checks) {
    for (const LineCodeCheck& l : c.lines) consider(l.pass, l.utilization);
    if (c.offset_limit_m && *c.offset_limit_m > 0.0) consider(c.offset_pass, c.offset_m / *c.offset_limit_m);
    if (c.soz) consider(c.soz->passes, c.soz->ratio);
  }
  if (r.dynamics) {
    consider(r.dynamics->tension_pass, r.dynamics->tension_utilization);
    if (r.dynamics->extreme_offset) consider(r.dynamics->extreme_offset->passes, r.dynamics->extreme_offset->ratio);
  }
  return {failing, worst};
}

/// The risers that fail their criteria at a static equilibrium of the stage:
/// the optimizer's constraints (line codes, offset against the SOZ, offset
/// limit) do not reach them, so they are the riser design's to fix.
std::vector<std::string> riser_findings(const StaticStageResults& r, int iteration) {
  struct Worst {
    double utilization = 0.0;
    std::string criterion, case_name;
    int cases = 0;
  };
  std::map<std::string, Worst> risers;
  for (const StaticCaseResult& c : r.cases) {
    for (const RiserStaticsRow& row : c.risers) {
      if (row.passes) continue;
      Worst& w = risers[row.name];
      ++w.cases;
      if (row.utilization > w.utilization) w = {row.utilization, row.governing_criterion, c.case_name, w.cases};
    }
  }
  std::vector<std::string> out;
  for (const auto& [name, w] : risers) {
    out.push_back(fmt::format(
        "riser-design finding (iteration {}): riser {} fails {} in {} case(s), worst {:.3f} in {}, at the static "
        "equilibrium; the pretensions act on the offset, not on this check — revisit the riser's criteria or "
        "configuration",
        iteration, name, w.criterion, w.cases, w.utilization, w.case_name));
  }
  return out;
}

const Stage* stage_settings(const Project& p, const std::string& name) {
  for (const Stage& s : p.stages)
    if (s.name == name) return &s;
  return nullptr;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string payouts_json(const std::map<std::string, double>& payouts) {
  std::string out = "{";
  for (const auto& [line, payout] : payouts)
    out += fmt::format("{}\"{}\": {:.4f}", out.size() > 1 ? ", " : "", line, payout);
  return out + "}";
}

/// The iteration's pretension optimization as a task of `batch`.
std::size_t add_optimization(TaskBatch& batch, const Iteration& it, int jobs) {
  OptimizationRequest request;
  request.threads = jobs;
  return batch.add<OptimizationResult>(
      identity(it, "optimization", "", "static", 0, "project"),
      [project = it.project, request] { return optimize_pretension(*project, request); }, describe_optimization);
}

/// Runs the optimizer on the iteration (a stored task) and, when it finds
/// payouts that change the mooring, writes the next iteration's project.
std::optional<Iteration> feedback(const RunContext& ctx, const Iteration& it, const std::filesystem::path& data_folder,
                                  FeedbackStep& step, SpiralRunResult& result) {
  const ValidatedProject& vp = *it.project;
  TaskBatch batch("preliminary", it.number);
  const std::size_t task = add_optimization(batch, it, ctx.jobs);
  StageRun scratch;  // the optimizer's task counts in the store, not in a stage
  scratch.stage = "preliminary";
  run_batch(ctx, batch, scratch, "optimizer");
  const OptimizationResult* opt = batch.value<OptimizationResult>(task);
  if (!opt) {
    step.error = *batch.error(task);
    result.solver_failures = true;
    result.findings.push_back(fmt::format("iteration {}: the pretension optimizer failed: {}", it.number, step.error));
    return std::nullopt;
  }
  step.optimization = *opt;
  for (const std::string& f : opt->findings) result.findings.push_back(fmt::format("iteration {}: {}", it.number, f));
  if (opt->status != OptimizationStatus::optimal) {
    result.findings.push_back(fmt::format(
        "iteration {}: no pretension within the payout bounds meets every check{}; the spiral goes on with the "
        "mooring as it is",
        it.number, opt->most_violated ? fmt::format(" (most violated: {})", opt->most_violated->describe()) : ""));
    return std::nullopt;
  }
  const double tolerance_m = vp.project.optimization ? vp.project.optimization->payout_tolerance_m : 0.05;
  bool changes = false;
  for (const LinePayout& line : opt->lines) {
    step.payouts_m[line.name] = line.payout_m;
    changes = changes || std::abs(line.payout_m) > tolerance_m;
  }
  if (!changes) {
    result.findings.push_back(fmt::format(
        "iteration {}: the optimizer keeps the pretensions (every payout within {:.2f} m): what fails is not "
        "the mooring's to fix",
        it.number, tolerance_m));
    step.payouts_m.clear();
    return std::nullopt;
  }
  Iteration next;
  next.number = it.number + 1;
  next.project_file = ctx.options.out_folder / "iterations" / fmt::format("iteration-{}.yaml", next.number);
  if (ctx.root()) std::filesystem::create_directories(next.project_file.parent_path());
  const std::string header = optimized_project_header(*opt, it.project_file.string()) +
                             fmt::format("\nspiral run iteration {}; relative data files resolve from {}\n",
                                         next.number, std::filesystem::absolute(data_folder).string());
  std::string text;
  try {
    if (mooring_from_base_file(vp.project)) {
      // A variation whose mooring is its base's: the iteration is a variation
      // of this iteration's file that writes the mooring with the payouts.
      text = mooring_variation_with_payouts(vp.project, step.payouts_m, header,
                                            std::filesystem::absolute(it.project_file).string());
    } else {
      std::string written = read_text(it.project_file);
      // A variation's base is named relative to the variation: the iteration
      // file, written elsewhere, names it absolutely.
      if (!vp.project.base_files.empty()) {
        written = with_field_values(
            written, vp.project,
            {{"extends", fmt::format("\"{}\"", std::filesystem::absolute(vp.project.base_files.front()).string())}});
      }
      text = with_line_payouts(written, vp.project, step.payouts_m, header);
    }
  } catch (const std::invalid_argument& error) {
    // The payouts cannot be written (a length with no position of its own
    // in the file, a base file that cannot be read): they stand as the
    // optimizer's advice, not applied.
    result.findings.push_back(fmt::format(
        "iteration {}: the optimized payouts cannot be applied to {}: {}; the spiral goes on with the mooring as "
        "it is",
        it.number, it.project_file.string(), error.what()));
    step.payouts_m.clear();
    return std::nullopt;
  }
  if (ctx.root()) {
    // Whole or not at all: a run stopped here leaves no half-written project.
    const std::filesystem::path partial = next.project_file.string() + ".partial";
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    std::error_code ec;
    if (!out) throw OutputError(fmt::format("{}: cannot be written", partial.string()));
    std::filesystem::rename(partial, next.project_file, ec);
    if (ec) throw OutputError(fmt::format("{}: cannot be written: {}", next.project_file.string(), ec.message()));
  }
  ctx.barrier();  // the other ranks read what rank 0 wrote
  next.project = std::make_shared<const ValidatedProject>(load_validated_project(next.project_file, data_folder));
  next.model_hash = project_content_hash(next.project_file, next.project->project);
  step.applied = true;
  step.project_file = next.project_file;
  return next;
}

}  // namespace

std::vector<std::string> spiral_stages(const Project& project, const std::optional<std::string>& until) {
  if (until && std::find(kSpiralStages.begin(), kSpiralStages.end(), *until) == kSpiralStages.end()) {
    throw request_error(
        project, "until",
        fmt::format("unknown stage '{}'; the spiral's stages: preliminary, intermediate, advanced", *until));
  }
  std::vector<std::string> stages;
  for (const std::string& name : kSpiralStages) {
    const bool listed = project.stages.empty() || stage_settings(project, name) != nullptr;
    if (listed) stages.push_back(name);
    if (until && name == *until) break;
  }
  return stages;
}

namespace {

/// Iteration 1: the project as given. Throws InputError for a bad project
/// or a negative job count.
Iteration project_as_given(const std::filesystem::path& project_file, const SpiralRunOptions& options) {
  Iteration it;
  it.project_file = project_file;
  it.project = std::make_shared<const ValidatedProject>(load_validated_project(project_file));
  if (options.jobs < 0)
    throw request_error(it.project->project, "jobs", fmt::format("must be >= 0, got {}", options.jobs));
  it.model_hash = project_content_hash(project_file, it.project->project);
  return it;
}

/// Tasks at a time: the option, or every core.
int job_count(const SpiralRunOptions& options) {
  return options.jobs > 0 ? options.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

OptimizationStudy run_optimization_study(const std::filesystem::path& project_file, const SpiralRunOptions& options,
                                         int study_points) {
  const Iteration it = project_as_given(project_file, options);
  ResultsStore store(results_store_file(options.out_folder), options.fresh);
  RunContext ctx{&store, options};
  ctx.jobs = job_count(options);
  TaskBatch batch("optimization", it.number);
  const std::size_t optimization = add_optimization(batch, it, ctx.jobs);
  PretensionStudyRequest request;
  request.points = study_points;
  request.problem.threads = ctx.jobs;
  const std::size_t study = batch.add<PretensionStudyResult>(
      identity(it, "pretension-study", "", "static", 0, fmt::format("groups=all points={}", study_points)),
      [project = it.project, request] { return run_pretension_study(*project, request); });
  StageRun scratch;  // counts only
  scratch.stage = "optimization";
  // One at a time: each task already spreads its scenarios over the jobs.
  run_batch(ctx, batch, scratch, "tasks", 1);
  for (const std::size_t task : {optimization, study})
    if (batch.error(task))
      throw engine::SolverError(fmt::format("{}: {}", task_name(batch.identity(task)), *batch.error(task)));
  return {*batch.value<OptimizationResult>(optimization), *batch.value<PretensionStudyResult>(study), batch.reused(),
          store.file()};
}

std::vector<std::string> advanced_riser_findings(const AdvancedStageResults& r, int iteration) {
  struct Worst {
    const FinalRiserCheck* check = nullptr;
    std::string case_name;
    int cases = 0;
  };
  std::map<std::string, Worst> risers;
  for (const CriticalCaseVerification& c : r.cases) {
    for (const FinalRiserCheck& check : c.risers) {
      if (check.pass || !check.limit_N) continue;
      Worst& w = risers[check.riser];
      ++w.cases;
      if (!w.check || check.utilization > w.check->utilization) w.check = &check, w.case_name = c.case_name;
    }
  }
  std::vector<std::string> out;
  for (const auto& [name, w] : risers) {
    const FinalRiserCheck& c = *w.check;
    const std::string cause =
        c.mean_N > *c.limit_N
            ? "its mean top tension alone exceeds the limit: the offset's share is the mooring's to reduce"
            : fmt::format(
                  "its mean ({:.0f} kN) is within the limit, the storm's dynamic range ({:.0f} kN from mean "
                  "to MPM) is not: the riser's response to the hull's motion at its hang-off, which the "
                  "pretensions hardly change — revisit the hang-off capacity or the riser's configuration",
                  c.mean_N * 1e-3, (c.mpm_N - c.mean_N) * 1e-3);
    out.push_back(fmt::format(
        "riser-design finding (advanced stage, iteration {}): riser {} exceeds its maximum top tension in the "
        "coupled storms of {} of {} critical case(s), worst {:.3f} in {} (3-h MPM {:.0f} kN against {:.0f} kN); {}",
        iteration, name, w.cases, r.cases.size(), c.utilization, w.case_name, c.mpm_N * 1e-3, *c.limit_N * 1e-3,
        cause));
  }
  return out;
}

SpiralRunResult run_spiral(const std::filesystem::path& project_file, const SpiralRunOptions& options,
                           const std::function<void(const StageRun&)>& stage_done) {
  Iteration it = project_as_given(project_file, options);
  const std::vector<std::string> stages = spiral_stages(it.project->project, options.until);
  // Absolute: a file named without a folder (`spiral run project.yaml` in
  // its own folder) has an empty parent, which the iteration files' headers
  // and data references cannot be made absolute from.
  const std::filesystem::path data_folder = std::filesystem::absolute(project_file).parent_path();

  const bool root = options.cluster == nullptr || options.cluster->rank() == 0;
  std::unique_ptr<ResultsStore> store =
      root ? std::make_unique<ResultsStore>(results_store_file(options.out_folder), options.fresh) : nullptr;
  RunContext ctx{store.get(), options};
  ctx.jobs = job_count(options);
  SpiralRunResult result;
  result.store_file = results_store_file(options.out_folder);
  if (store) {
    const int ranks = options.cluster ? options.cluster->size() : 1;
    result.run_id = ctx.run_id =
        store->begin_run(project_file.string(), it.model_hash, ranks > 1 ? ranks : ctx.jobs, options.version);
    store->put_iteration(ctx.run_id,
                         {1, "preliminary", it.model_hash, project_file.string(), "{}", "the project as given"});
  }

  const auto record = [&](StageRun stage) {
    if (store)
      store->put_stage(ctx.run_id,
                       {stage.stage, stage.iteration, stage.model_hash, stage.pass, stage.governing,
                        stage.tasks - stage.tasks_failed, stage.tasks_failed, stage.tasks_reused, stage.wall_s});
    result.solver_failures = result.solver_failures || stage.tasks_failed > 0 || !stage.failures.empty();
    ctx.log(fmt::format("{} stage, iteration {}: {} ({} tasks, {} from the store, {} failed, {:.1f} s){}", stage.stage,
                        stage.iteration, !stage.completed ? "NOT COMPLETED" : (stage.pass ? "PASS" : "FAIL"),
                        stage.tasks, stage.tasks_reused, stage.tasks_failed, stage.wall_s,
                        stage.governing.empty() ? "" : "; governing: " + stage.governing));
    if (stage_done) stage_done(stage);
    result.stages.push_back(std::move(stage));
  };

  try {
    bool go_on = true;
    for (const std::string& name : stages) {
      if (!go_on) break;
      if (name == "preliminary") {
        const Stage* settings = stage_settings(it.project->project, name);
        const int max_iterations = settings ? settings->max_iterations : Stage{}.max_iterations;
        // The iteration nearest to passing so far: a feedback iteration
        // that is not nearer ends the feedback, and the spiral goes on with it.
        struct Nearest {
          Iteration iteration;
          std::pair<int, double> distance;
          std::vector<std::string> riser_findings;
        };
        std::optional<Nearest> nearest;
        while (true) {
          StageRun stage = run_preliminary(ctx, it);
          const bool completed = stage.completed;
          const std::string reason = completed ? feedback_reason(stage_settings(it.project->project, name),
                                                                 *stage.preliminary, !result.feedback.empty())
                                               : "";
          const std::pair<int, double> distance =
              completed ? feedback_distance(*stage.preliminary) : std::pair<int, double>{0, 0.0};
          std::vector<std::string> risers =
              completed ? riser_findings(*stage.preliminary, it.number) : std::vector<std::string>{};
          record(std::move(stage));
          if (!completed) {
            go_on = false;
            break;
          }
          if (!reason.empty() && !options.feedback) {
            result.findings.push_back(
                fmt::format("iteration {} fails ({}); no feedback was asked for: the stages run the project as given",
                            it.number, reason));
            for (std::string& f : risers) result.findings.push_back(std::move(f));
            break;
          }
          if (reason.empty()) {
            for (std::string& f : risers) result.findings.push_back(std::move(f));
            break;
          }
          if (nearest && !(distance < nearest->distance)) {
            result.findings.push_back(fmt::format(
                "iteration {}: the optimizer's payouts did not bring the failing checks closer ({} failing, worst "
                "{:.3f}; iteration {}: {} failing, worst {:.3f}); the spiral goes on with iteration {}",
                it.number, distance.first, distance.second, nearest->iteration.number, nearest->distance.first,
                nearest->distance.second, nearest->iteration.number));
            it = std::move(nearest->iteration);
            for (std::string& f : nearest->riser_findings) result.findings.push_back(std::move(f));
            break;
          }
          nearest = Nearest{it, distance, risers};
          if (it.number >= max_iterations) {
            result.findings.push_back(
                fmt::format("iteration {} still fails ({}) after {} iteration(s), the stage's max_iterations",
                            it.number, reason, it.number));
            for (std::string& f : risers) result.findings.push_back(std::move(f));
            break;
          }
          FeedbackStep step;
          step.from_iteration = it.number;
          step.reason = reason;
          ctx.log(fmt::format("feedback after iteration {}: {}; running the pretension optimizer", it.number, reason));
          std::optional<Iteration> next = feedback(ctx, it, data_folder, step, result);
          if (next && store) {
            store->put_iteration(ctx.run_id, {next->number, "preliminary", next->model_hash,
                                              next->project_file.string(), payouts_json(step.payouts_m), reason});
          }
          result.feedback.push_back(std::move(step));
          if (!next) {
            for (std::string& f : risers) result.findings.push_back(std::move(f));
            break;
          }
          it = std::move(*next);
        }
      } else if (name == "intermediate") {
        StageRun stage = run_intermediate(ctx, it);
        go_on = stage.completed;
        record(std::move(stage));
      } else {
        // The ranking of the intermediate stage selects the critical cases;
        // without that stage in the project it is run here (from the store).
        const StageRun* ranking = nullptr;
        for (const StageRun& s : result.stages)
          if (s.stage == "intermediate" && s.iteration == it.number && s.intermediate) ranking = &s;
        std::optional<StageRun> own;
        if (!ranking) {
          own = run_intermediate(ctx, it);
          if (!own->completed) {
            record(std::move(*own));
            go_on = false;
            break;
          }
          ranking = &*own;
        }
        const IntermediateStageResults intermediate = *ranking->intermediate;
        record(run_advanced(ctx, it, intermediate));
        if (const StageRun& advanced = result.stages.back(); advanced.advanced)
          for (std::string& f : advanced_riser_findings(*advanced.advanced, it.number))
            result.findings.push_back(std::move(f));
      }
    }
    result.completed = go_on && !result.stages.empty() && result.stages.back().completed;
    result.pass = result.completed;
    for (const StageRun& s : result.stages)
      if (s.iteration == it.number) result.pass = result.pass && s.pass;
    if (store) store->finish_run(ctx.run_id, result.pass ? "pass" : (result.completed ? "fail" : "incomplete"));
  } catch (...) {
    if (store) store->finish_run(ctx.run_id, "error");
    throw;
  }
  return result;
}

}  // namespace spiral::design
