#include "design/stages/advanced_stage.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "design/project/request_error.hpp"
#include "engine/common/solver_error.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

std::string verification_selection(const RankedCase& ranked) {
  return fmt::format("critical case #{} of the intermediate ranking", ranked.rank);
}

/// What of a verification is `ranked`'s own in `stage`: its name, rank,
/// intermediate score and static riser check.
void name_as(CriticalCaseVerification& v, const IntermediateStageResults& stage, const RankedCase& ranked) {
  const StaticCaseResult& statics = stage.statics.cases[ranked.case_index];
  v.rank = ranked.rank;
  v.case_name = statics.case_name;
  v.integrity = statics.integrity;
  v.intermediate_score = ranked.score;
  v.intermediate_governing = ranked.governing_measure;
  // The riser criteria the coupled run does not give (stress, angles, …)
  // stand as the stage's static equilibrium of the case checked them.
  v.static_risers_pass = stage.statics.checks[ranked.case_index].risers_pass;
  v.static_riser_utilization = ranked.riser_utilization;
  v.static_riser = ranked.riser;
  v.static_riser_criterion = ranked.riser_criterion;
  v.comparison.case_name = statics.case_name;
}

/// The verification of `ranked` from `verified`, that of a case with the
/// same analysis inputs: the runs and checks are the same, the name, rank,
/// intermediate score and selection are `ranked`'s, and `shared_with` names
/// the case that ran.
CriticalCaseVerification shared_verification(CriticalCaseVerification verified, const IntermediateStageResults& stage,
                                             const RankedCase& ranked) {
  CriticalCaseVerification v = std::move(verified);
  v.shared_with = v.case_name;
  name_as(v, stage, ranked);
  for (std::optional<StageDynamics>* level : {&v.sc, &v.coupled}) {
    if (!level->has_value()) continue;
    (*level)->case_name = v.case_name;
    (*level)->selection = verification_selection(ranked);
  }
  v.wall_s = 0.0;
  return v;
}

/// The output step of every stage storm (stage_dynamics.cpp): 0.5 s.
constexpr double kOutputStep_s = 0.5;
/// One seed for both levels, so that they see the same sea.
constexpr std::uint64_t kSeed = 1;

/// The final checks of one case from its coupled level summary: every
/// mooring line's tension and every riser's top tension are its channels
/// tension_<name>_N (the coupled FE lines, summarize_channels).
void final_checks(const ValidatedProject& vp, const LevelSummary& coupled, CriticalCaseVerification& v) {
  const Project& p = vp.project;
  const bool damaged = v.integrity == LineIntegrity::damaged;
  for (const MooringLine& line : p.mooring.lines) {
    const ChannelSummary* c = find_channel(coupled, "tension_" + line.name + "_N");
    if (c == nullptr) continue;  // the damaged line is not in the coupled system
    FinalLineCheck check;
    check.line = line.name;
    check.mean_N = c->moments.mean;
    check.max_N = c->moments.maximum;
    check.mpm_N = c->mpm;
    check.mpm_fitted = c->mpm_fitted;
    check.mbl_N = fairlead_segment_mbl(vp, line.name);
    const DynamicTensionCheck d =
        dynamic_tension_check(p.criteria.mooring, damaged, c->moments.mean, c->mpm, check.mbl_N);
    check.dynamic_factor = d.factor;
    check.utilization = d.utilization;
    check.pass = d.utilization <= 1.0;
    v.lines.push_back(check);
  }
  // The offset limit takes the extreme-offset rule's MPM of |d(t)| (soz.hpp), like the SOZ check.
  if (v.coupled) {
    const auto o = std::find_if(v.coupled->channels.begin(), v.coupled->channels.end(),
                                [](const StormChannel& c) { return c.name == "offset"; });
    if (o != v.coupled->channels.end())
      v.mpm_offset_m = horizontal_offset_mpm(o->values, v.coupled->output_step_s).offset_m;
  } else if (const ChannelSummary* o = find_channel(coupled, "offset_m")) {
    v.mpm_offset_m = o->mpm;
  }
  if (p.criteria.max_offset_pct_depth) {
    v.offset_limit_m = *p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m;
    v.offset_limit_pass = v.mpm_offset_m <= *v.offset_limit_m;
  }
  if (v.coupled) v.soz_offset = v.coupled->extreme_offset;
  for (const Riser& riser : p.risers) {
    const ChannelSummary* c = find_channel(coupled, "tension_" + riser.name + "_N");
    if (c == nullptr) continue;
    FinalRiserCheck check;
    check.riser = riser.name;
    check.mean_N = c->moments.mean;
    check.max_N = c->moments.maximum;
    check.mpm_N = c->mpm;
    check.limit_N = riser_criteria(p.criteria, riser).max_top_tension_N;
    if (check.limit_N) {
      check.utilization = check.mpm_N / *check.limit_N;
      check.pass = check.utilization <= 1.0;
    }
    v.risers.push_back(check);
  }
  v.pass = std::all_of(v.lines.begin(), v.lines.end(), [](const FinalLineCheck& c) { return c.pass; }) &&
           std::all_of(v.risers.begin(), v.risers.end(), [](const FinalRiserCheck& c) { return c.pass; }) &&
           v.offset_limit_pass && (!v.soz_offset || v.soz_offset->passes) && v.static_risers_pass;
}

}  // namespace

CriticalCaseVerification verify_critical_case(const ValidatedProject& vp, const IntermediateStageResults& stage,
                                              const RankedCase& ranked, DynamicAnalysisRequest base,
                                              long coupled_max_steps) {
  engine::Stopwatch start;
  const StaticCaseResult& statics = stage.statics.cases[ranked.case_index];
  base.load_case = statics.case_name;
  base.statics = &statics;
  base.seed = static_cast<std::uint64_t>(case_seed(vp.project, statics.case_name));  // both levels, one sea
  const SozResult* zone = stage.statics.soz ? &*stage.statics.soz : nullptr;
  const std::string selection = verification_selection(ranked);
  CriticalCaseVerification v;
  name_as(v, stage, ranked);
  v.comparison.seed = base.seed;
  v.comparison.duration_s = base.duration_s;

  // Coupled first: the S-C tension channel follows its most loaded line, so
  // that the two levels' tensions compare the same line.
  DynamicAnalysisRequest coupled = base;
  coupled.level = AnalysisLevel::coupled;
  coupled.coupled_max_steps_between_outputs = coupled_max_steps;
  LevelSummary coupled_summary;
  coupled_summary.level = AnalysisLevel::coupled;
  engine::Stopwatch run_start;
  try {
    const DynamicAnalysisResult r = run_dynamic_analysis(vp, coupled);
    coupled_summary = summarize_level(r);
    v.coupled = summarize_stage_dynamics(vp, statics, coupled, r, zone, selection);
    v.coupled->wall_s = run_start.seconds();
  } catch (const engine::SolverError& e) {
    v.error = fmt::format("coupled: {}", e.what());
    coupled_summary.error = e.what();
  }

  DynamicAnalysisRequest sc = base;
  sc.level = AnalysisLevel::semi_coupled_enhanced;
  LevelSummary sc_summary;
  sc_summary.level = AnalysisLevel::semi_coupled_enhanced;
  run_start.restart();
  try {
    const DynamicAnalysisResult r = run_dynamic_analysis(vp, sc);
    sc_summary = summarize_level(r);
    v.sc = summarize_stage_dynamics(vp, statics, sc, r, zone, selection,
                                    v.coupled ? v.coupled->most_loaded_line : std::string());
    v.sc->wall_s = run_start.seconds();
  } catch (const engine::SolverError& e) {
    const std::string message = fmt::format("sc-enhanced: {}", e.what());
    v.error = v.error ? *v.error + "; " + message : message;
    sc_summary.error = e.what();
  }
  v.comparison.levels = {std::move(sc_summary), std::move(coupled_summary)};
  if (v.coupled) final_checks(vp, v.comparison.levels.back(), v);
  v.wall_s = start.seconds();
  return v;
}

namespace {

/// The failing check of largest utilization over the verified cases, else
/// the largest utilization.
std::string governing_of(const AdvancedStageResults& r) {
  struct Candidate {
    double utilization = -1.0;
    bool pass = true;
    std::string text;
  };
  Candidate worst;
  auto consider = [&](double u, bool pass, std::string text) {
    // A failing check outranks every passing one.
    const bool better = worst.pass && !pass ? true : (worst.pass == pass && u > worst.utilization);
    if (better) worst = {u, pass, std::move(text)};
  };
  for (const CriticalCaseVerification& c : r.cases) {
    for (const FinalLineCheck& l : c.lines)
      consider(l.utilization, l.pass, fmt::format("{}: dynamic tension {} {:.3f}", c.case_name, l.line, l.utilization));
    if (c.offset_limit_m && *c.offset_limit_m > 0.0)
      consider(c.mpm_offset_m / *c.offset_limit_m, c.offset_limit_pass,
               fmt::format("{}: MPM offset {:.2f} m / limit {:.2f} m", c.case_name, c.mpm_offset_m, *c.offset_limit_m));
    if (c.soz_offset)
      consider(c.soz_offset->ratio, c.soz_offset->passes,
               fmt::format("{}: MPM offset / SOZ {:.3f} ({})", c.case_name, c.soz_offset->ratio,
                           c.soz_offset->governing_riser));
    if (!c.static_riser.empty())
      consider(c.static_riser_utilization, c.static_risers_pass,
               fmt::format("{}: riser {} {} {:.3f} (static equilibrium)", c.case_name, c.static_riser,
                           c.static_riser_criterion, c.static_riser_utilization));
    for (const FinalRiserCheck& rc : c.risers)
      if (rc.limit_N)
        consider(rc.utilization, rc.pass,
                 fmt::format("{}: riser {} top tension {:.3f}", c.case_name, rc.riser, rc.utilization));
  }
  return worst.text;
}

}  // namespace

double advanced_stage_duration(const Project& project) {
  for (const Stage& s : project.stages)
    if (s.name == "advanced" && s.duration_s) return *s.duration_s;
  return kAdvancedStageDuration_s;
}

DynamicAnalysisRequest advanced_stage_request(const Project& project, const AdvancedStageOptions& options) {
  DynamicAnalysisRequest base;
  base.duration_s = options.duration_s.value_or(advanced_stage_duration(project));
  base.output_step_s = std::min(kOutputStep_s, base.duration_s);
  base.seed = kSeed;
  return base;
}

long coupled_max_steps(const AdvancedStageOptions& options, const std::string& case_name) {
  const auto limit = options.coupled_max_steps_by_case.find(case_name);
  return limit != options.coupled_max_steps_by_case.end() ? limit->second : options.coupled_max_steps_between_outputs;
}

const RankedCase* earlier_identical_case(const Project& project, const IntermediateStageResults& stage,
                                         const RankedCase& ranked, const AdvancedStageOptions& options) {
  const auto load_case = [&](const RankedCase& r) -> const LoadCase& {
    return find_load_case(project, stage.statics.cases[r.case_index].case_name);
  };
  const LoadCase& own = load_case(ranked);
  for (const RankedCase& earlier : stage.ranked) {
    if (&earlier == &ranked) return nullptr;
    if (!earlier.critical) continue;
    const LoadCase& other = load_case(earlier);
    if (same_analysis_inputs(project, own, other) &&
        coupled_max_steps(options, own.name) == coupled_max_steps(options, other.name))
      return &earlier;
  }
  return nullptr;
}

std::vector<CriticalCaseVerification> critical_case_verifications(
    const Project& project, const IntermediateStageResults& stage, const AdvancedStageOptions& options,
    const std::vector<CriticalCaseVerification>& verified) {
  std::vector<CriticalCaseVerification> cases;
  for (const RankedCase& ranked : stage.ranked) {
    if (!ranked.critical) continue;
    const RankedCase* twin = earlier_identical_case(project, stage, ranked, options);
    const int rank = twin ? twin->rank : ranked.rank;
    const auto v = std::find_if(verified.begin(), verified.end(),
                                [&](const CriticalCaseVerification& c) { return c.rank == rank; });
    if (v == verified.end()) continue;  // its task failed: the caller says why
    cases.push_back(twin ? shared_verification(*v, stage, ranked) : *v);
  }
  return cases;
}

AdvancedStageResults reduce_advanced_stage(IntermediateStageResults intermediate, const DynamicAnalysisRequest& base,
                                           std::vector<CriticalCaseVerification> cases) {
  AdvancedStageResults out;
  out.intermediate = std::move(intermediate);
  out.intermediate.statics.stage = "advanced";
  out.duration_s = base.duration_s;
  out.output_step_s = base.output_step_s;
  out.seed = base.seed;
  out.cases = std::move(cases);
  for (const CriticalCaseVerification& c : out.cases) {
    if (!c.coupled) out.failed_cases.push_back(c.case_name);
    out.pass = out.pass && c.pass;
  }
  out.failed_runs = static_cast<int>(out.failed_cases.size());
  out.governing = governing_of(out);
  return out;
}

AdvancedStageResults run_advanced_stage(const ValidatedProject& vp, const AdvancedStageOptions& options) {
  engine::Stopwatch start;
  IntermediateStageResults intermediate = run_intermediate_stage(vp);
  const DynamicAnalysisRequest base = advanced_stage_request(vp.project, options);
  engine::Stopwatch runs_start;
  // One case at a time: the coupled run already spreads its lines over the
  // worker pool, and its memory is that of every FE line of the case.
  std::vector<CriticalCaseVerification> verified;
  for (const RankedCase& ranked : intermediate.ranked) {
    if (!ranked.critical || earlier_identical_case(vp.project, intermediate, ranked, options)) continue;
    const std::string& name = intermediate.statics.cases[ranked.case_index].case_name;
    verified.push_back(verify_critical_case(vp, intermediate, ranked, base, coupled_max_steps(options, name)));
  }
  std::vector<CriticalCaseVerification> cases =
      critical_case_verifications(vp.project, intermediate, options, verified);
  const double verification_wall_s = runs_start.seconds();
  AdvancedStageResults out = reduce_advanced_stage(std::move(intermediate), base, std::move(cases));
  out.verification_wall_s = verification_wall_s;
  out.wall_time_s = start.seconds();
  return out;
}

}  // namespace spiral::design
