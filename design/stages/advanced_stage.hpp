#pragma once
// The advanced stage (DESIGN.md §2): fully coupled time-domain verification
// of the critical load cases, the final criteria check and the coupled-vs-S-C
// trade-off of DESIGN.md §1.
//
// 1. The intermediate stage (run_intermediate_stage): every load case's
//    enhanced S-C 3-h storm, the ranking and the critical cases.
// 2. Per critical case, from the stage's static equilibrium of the case
//    (DynamicAnalysisRequest::statics) and on one seed and duration
//    (stages[].duration of the advanced stage, default 3 h):
//      coupled      hull + every mooring line and riser as dynamic FE lines
//                   in one system (coupled_analysis.hpp);
//      sc-enhanced  the same case and sea, its quasi-static fairlead tensions
//                   (the S-C answer the coupled run verifies).
//    Both are summarized as level_comparison.hpp does (mean, std, max, MPM,
//    % against coupled, wall clock, speed-up).
// 3. Final criteria, from the coupled run:
//      tension  every mooring line's MPM fairlead tension with the code's
//               dynamic factor (dynamic_tension_check, stage_dynamics.hpp);
//      offset   the MPM horizontal offset against the platform SOZ (when
//               the project has risers) and against the offset limit
//               (criteria.max_offset_pct_depth);
//      risers   the MPM top tension against max_top_tension where the
//               riser's criteria give one; the other riser criteria as the
//               stage's static equilibrium of the case checked them.
// A coupled run that fails (engine::SolverError) keeps its message in its
// case, the other cases still run, and the stage cannot pass: an unverified
// critical case is not a verified one. Two critical cases that are the same
// analysis under two names (a matrix case and a case the project names) are
// run once; the second shares the first's runs and says so.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "design/stages/intermediate_stage.hpp"
#include "design/analysis/level_comparison.hpp"
#include "design/stages/stage_dynamics.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {

/// Default duration of the verification runs: a 3-h storm, the duration the
/// MPM extremes and the codes' dynamic factors refer to.
inline constexpr double kAdvancedStageDuration_s = 10800.0;

/// One mooring line's final tension check (coupled FE fairlead tension).
struct FinalLineCheck {
  std::string line;
  double mean_N = 0.0, max_N = 0.0;
  double mpm_N = 0.0;       ///< Gumbel MPM of the 3-h maximum, or the sample maximum
  bool mpm_fitted = false;  ///< false: mpm_N is the sample maximum
  double mbl_N = 0.0;       ///< fairlead segment
  double dynamic_factor = 0.0;
  double utilization = 0.0;
  bool pass = true;
};

/// One riser's top tension from the coupled run against its max_top_tension.
struct FinalRiserCheck {
  std::string riser;
  double mean_N = 0.0, max_N = 0.0, mpm_N = 0.0;
  std::optional<double> limit_N;  ///< absent: the riser's criteria give no maximum top tension
  double utilization = 0.0;       ///< mpm / limit (0 without a limit)
  bool pass = true;
};

struct CriticalCaseVerification {
  int rank = 0;  ///< in the intermediate ranking
  std::string case_name;
  LineIntegrity integrity = LineIntegrity::intact;
  double intermediate_score = 0.0;
  RankingMeasure intermediate_governing = RankingMeasure::tension;
  /// sc-enhanced, its tension channel on the coupled run's most loaded line;
  /// absent when it failed.
  std::optional<StageDynamics> sc;
  std::optional<StageDynamics> coupled;  ///< absent when the coupled run failed
  /// The two levels side by side: sc-enhanced then coupled (a failed level
  /// carries its error and no channels).
  LevelComparison comparison;
  std::optional<std::string> error;  ///< the coupled (or S-C) solver failure

  std::vector<FinalLineCheck> lines;      ///< every intact mooring line (coupled)
  std::optional<OffsetCheck> soz_offset;  ///< MPM offset vs the platform SOZ (with risers)
  double mpm_offset_m = 0.0;              ///< coupled: 3-h MPM of |d(t)| by the extreme-offset rule (soz.hpp)
  std::optional<double> offset_limit_m;   ///< criteria.max_offset_pct_depth · depth
  bool offset_limit_pass = true;
  std::vector<FinalRiserCheck> risers;
  /// The case's static riser criteria (stage statics): what the coupled
  /// run's top tensions do not cover (stress, angles, compression); the
  /// largest utilization, its riser and criterion (none without risers).
  bool static_risers_pass = true;
  double static_riser_utilization = 0.0;
  std::string static_riser, static_riser_criterion;
  bool pass = false;    ///< the coupled run finished and every check passes
  double wall_s = 0.0;  ///< 0 for a case that shares another's runs
  /// The critical case whose runs and checks this one shares: the same
  /// analysis under another name (same_analysis_inputs); empty when the
  /// case ran its own.
  std::string shared_with;
};

struct AdvancedStageResults {
  IntermediateStageResults intermediate;  ///< the ranking that chose the cases
  double duration_s = kAdvancedStageDuration_s;
  double output_step_s = 0.5;
  std::uint64_t seed = 1;
  std::vector<CriticalCaseVerification> cases;  ///< rank order
  int failed_runs = 0;                          ///< cases whose coupled run failed
  std::vector<std::string> failed_cases;        ///< their names, rank order
  bool pass = true;
  /// The governing check of the verified cases: the failing check of largest
  /// utilization, or the largest utilization when all pass ("" when no case
  /// was verified).
  std::string governing;
  double verification_wall_s = 0.0;  ///< the coupled and S-C runs
  double wall_time_s = 0.0;
};

struct AdvancedStageOptions {
  /// Overrides the project's stages[advanced].duration (s, > 0).
  std::optional<double> duration_s;
  /// The coupled integrator's work limit per output step
  /// (DynamicAnalysisRequest's), and per case name where it differs: a case
  /// given a limit it cannot meet stops with a solver failure, recorded.
  long coupled_max_steps_between_outputs = 500000;
  std::map<std::string, long> coupled_max_steps_by_case;
};

/// The advanced stage's duration: stages[advanced].duration, else 3 h.
double advanced_stage_duration(const Project& project);

/// The verification request of the advanced stage's critical cases: duration
/// (options, else stages[advanced].duration, else 3 h), output step, one seed
/// for both levels so that they see the same sea.
DynamicAnalysisRequest advanced_stage_request(const Project& project, const AdvancedStageOptions& options = {});

/// The coupled work limit of one case (AdvancedStageOptions).
long coupled_max_steps(const AdvancedStageOptions& options, const std::string& case_name);

/// One critical case of `stage` verified: the coupled run and the enhanced
/// S-C run on the same sea (`base`, its load case and statics set here), the
/// final checks. Solver failures are recorded in the result, not thrown.
CriticalCaseVerification verify_critical_case(const ValidatedProject& project, const IntermediateStageResults& stage,
                                              const RankedCase& ranked, DynamicAnalysisRequest base,
                                              long coupled_max_steps);

/// The first critical case ranked before `ranked` that is the same analysis
/// (same_analysis_inputs and the same coupled work limit), verified once for
/// both; null when there is none.
const RankedCase* earlier_identical_case(const Project& project, const IntermediateStageResults& stage,
                                         const RankedCase& ranked, const AdvancedStageOptions& options);

/// The critical cases of `stage` in rank order from the verifications of the
/// cases that ran (`verified`): a case that is an earlier case's analysis
/// (earlier_identical_case) takes that verification under its own name and
/// rank, `shared_with` naming the case that ran; a case whose verification
/// is missing (its task failed) is left out.
std::vector<CriticalCaseVerification> critical_case_verifications(
    const Project& project, const IntermediateStageResults& stage, const AdvancedStageOptions& options,
    const std::vector<CriticalCaseVerification>& verified);

/// The stage from the ranking and the verified cases (rank order).
AdvancedStageResults reduce_advanced_stage(IntermediateStageResults intermediate, const DynamicAnalysisRequest& base,
                                           std::vector<CriticalCaseVerification> cases);

/// Throws as run_intermediate_stage; solver failures of the verification
/// runs are recorded per case (CriticalCaseVerification::error), not thrown.
AdvancedStageResults run_advanced_stage(const ValidatedProject& project, const AdvancedStageOptions& options = {});

}  // namespace spiral::design
