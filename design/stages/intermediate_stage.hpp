#pragma once
// The intermediate stage (DESIGN.md §2): the enhanced S-C dynamic analysis of
// the full load-case matrix (every load case as the project lists it: its
// headings, environments, intact or one line damaged), then the ranking of
// the cases and the selection of the critical ones for the advanced stage.
//
// Per case: the static part of the preliminary stage (run_static_stage: the
// coupled static equilibria with FE risers, the code check, the still-water
// SOZ) and a 3-h enhanced S-C storm from that equilibrium
// (stage_dynamics.hpp). Ranking measures, each ≤ 1 passes:
//   tension   MPM fairlead tension of the most loaded line with the code's
//             dynamic factor (stage_dynamics.hpp);
//   offset    MPM horizontal offset / platform SOZ in its direction;
//   riser     the largest riser utilization of the case's static
//             equilibrium (FE risers with the case's current; the risers'
//             dynamic response is not analysed at this level).
// A case's score is the largest of the three; cases are ranked by score, and
// the critical ones are the N most severe by each measure (N =
// stages[intermediate].critical_cases, default kCriticalCases) plus every
// failing case.
// Storms run in parallel over the cases (each owns its state).

#include <string>
#include <vector>

#include "design/stages/stage_dynamics.hpp"
#include "design/stages/static_stage.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {

/// How many top-ranked cases by each measure go to the advanced stage
/// (failing cases go too), unless stages[intermediate].critical_cases says.
inline constexpr std::size_t kCriticalCases = 3;

/// The ranking measures (the file comment).
enum class RankingMeasure { tension, offset, riser };

const char* to_string(RankingMeasure measure);  ///< "tension" | "offset" | "riser"

struct RankedCase {
  std::size_t case_index = 0;  ///< into IntermediateStageResults::statics.cases (0 is still water)
  StageDynamics storm;
  double tension_utilization = 0.0;
  double offset_ratio = 0.0;  ///< 0 without risers (no zone)
  double riser_utilization = 0.0;
  std::string riser;            ///< the riser that sets riser_utilization
  std::string riser_criterion;  ///< its governing criterion
  double score = 0.0;
  RankingMeasure governing_measure = RankingMeasure::tension;  ///< the measure that sets the score
  bool pass = true;
  bool critical = false;
  int rank = 0;  ///< 1 = most severe
};

struct IntermediateStageResults {
  std::size_t critical_per_measure = kCriticalCases;  ///< N of the selection (file comment)
  StaticStageResults statics;                         ///< static cases, code check and SOZ (no storm)
  std::vector<RankedCase> ranked;                     ///< most severe first
  bool pass = true;                                   ///< every case passes every measure
  int threads = 1;
  double storms_wall_s = 0.0;  ///< all storms, wall clock
  double wall_time_s = 0.0;
};

/// The storm of the load case `case_index` of `statics.cases` (≥ 1), from
/// its static equilibrium, against the still-water zone; `rest_solutions`
/// shared by the stage's storms (may be null). Throws as run_dynamic_analysis.
StageDynamics run_case_storm(const ValidatedProject& project, const StaticStageResults& statics, std::size_t case_index,
                             RestSolutionCache* rest_solutions = nullptr);

/// One load case's storm: `case_index` into the stage's statics.cases (≥ 1).
struct CaseStorm {
  std::size_t case_index = 0;
  StageDynamics storm;
};

/// The ranking from the stage's statics (run with StaticStageOptions::dynamics
/// false) and the storms of its load cases. A case without a storm (its run
/// failed) is not ranked; the caller says why in statics.notes.
IntermediateStageResults reduce_intermediate_stage(StaticStageResults statics, std::vector<CaseStorm> storms,
                                                   std::size_t critical_per_measure = kCriticalCases);

/// stages[intermediate].critical_cases, else kCriticalCases.
std::size_t intermediate_critical_cases(const Project& project);

/// Throws as run_static_stage and run_dynamic_analysis (the message names the case).
IntermediateStageResults run_intermediate_stage(const ValidatedProject& project);

}  // namespace spiral::design
