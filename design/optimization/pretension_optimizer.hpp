#pragma once
// Mooring pretension optimization (DESIGN.md §8): the payout of each line
// group, within its bounds, that meets every constraint of every scenario —
// the load cases, intact and damaged, with the payouts of the intact design
// (a broken line does not re-tension the others) — and best meets the
// objective.
//
// Constraints, per scenario, written g ≤ 0:
//   every line's quasi-static utilization (code factor of the scenario's
//   integrity) − 1; the static offset over the platform SOZ radius in the
//   offset's own direction − 1 (SmoothZone, the zone of the case's current and
//   design condition, from the first stage's SOZ settings); the offset over
//   the project's offset limit − 1; optionally the laid length below
//   `min_laid_length` and the fairlead tension below `min_tension`.
// Objectives: the minimax ones (largest SOZ ratio, largest utilization,
// largest offset) with a slack variable s — minimize s subject to
// measure_j − s ≤ 0 — which keeps every function smooth; the least winching
// Σ|ΔL| smoothed as Σ (√(ΔL² + ε²) − ε), ε a tenth of the payout tolerance.
//
// NLopt (S. G. Johnson, The NLopt nonlinear-optimization package): SLSQP
// (Kraft 1988) by default and CCSAQ (Svanberg 2002) with the analytic
// gradients of scenario_model.hpp, COBYLA (Powell 1994) without. Variables
// scaled by their bound. Stops when a step moves no payout by more than a
// thousandth of the payout tolerance (SLSQP's line search takes short steps
// on its way: stopping at the tolerance itself ended runs metres from the
// optimum), on a relative objective change of 1e-8, or at the evaluation cap. Every evaluation is recorded; the best
// feasible point is kept and verified with the full models. A solver
// failure inside an evaluation stops the run with the scenario named (no
// penalty value is invented). When no evaluated point is feasible the result
// says so, with the most violated constraint.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "design/optimization/scenario_model.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {

/// The storms of the dynamic level (dynamic_level.hpp).
struct DynamicLevelOptions {
  double duration_s = 10800.0;  ///< of each storm, > 0; the MPMs refer to 3 h whatever the duration
  std::uint64_t seed = 1;
};

/// What the command line may override of the project's `optimization`.
struct OptimizationRequest {
  std::optional<OptimizationObjective> objective;
  std::optional<OptimizationAlgorithm> algorithm;
  std::vector<std::string> cases;  ///< empty: the project's (or every load case)
  std::optional<DamagedConditions> damaged;
  std::optional<int> max_evaluations;
  int threads = 0;  ///< scenarios evaluated in parallel; 0: all cores
  /// The dynamic level (enhanced S-C storms, COBYLA); none: the static level.
  std::optional<DynamicLevelOptions> dynamic;
  /// Called after each evaluation with the evaluations so far over the
  /// evaluation cap (0..1; a run usually stops well before its cap), on the
  /// calling thread. May throw to stop the run: the exception leaves
  /// optimize_pretension. May be empty.
  std::function<void(double)> progress;
};

/// One design variable.
struct GroupVariable {
  std::string name;
  std::vector<std::string> lines;
  double min_m = 0.0;
  double max_m = 0.0;
};

/// A constraint at a design point, g ≤ 0 (dimensionless: ratios − 1).
struct ConstraintValue {
  std::string scenario;
  std::string kind;     ///< utilization | soz | offset_limit | min_laid_length | min_tension
  std::string subject;  ///< the line, or the governing riser of the zone there
  double value = 0.0;
  std::string describe() const;
};

/// A platform zone the scenarios are checked against, as the optimizer sees
/// it (the smooth zone, sampled for plots and the document).
struct ZoneOutline {
  std::string name;  ///< as in soz.hpp's zones ("<environment>/<condition>") or "still-water"
  std::vector<double> directions_deg;
  std::vector<double> allowable_m;
};

/// One scenario at a design point.
struct ScenarioSummary {
  std::string scenario;
  std::string zone;  ///< the ZoneOutline it is checked against; empty: none
  std::string case_name;
  std::optional<std::string> damaged_line;
  double offset_m = 0.0;
  double direction_deg = 0.0;
  std::optional<double> soz_allowable_m;  ///< the smooth zone in that direction
  std::optional<double> soz_ratio;
  std::optional<double> offset_limit_m;
  double worst_utilization = 0.0;
  std::string worst_line;
  double min_laid_length_m = 0.0;
  double min_fairlead_tension_N = 0.0;
  /// Dynamic level: 3-h MPM offset, its ratio to the zone (Weibull MPM of
  /// |d(t)| / A(θ(t))), and the worst dynamic code utilization and its line.
  std::optional<double> mpm_offset_m, mpm_soz_ratio, worst_dynamic_utilization;
  std::string worst_dynamic_line;
};

/// A line's length and pretension (hull at rest, still water, intact) before
/// and after.
struct LinePayout {
  std::string name;
  std::string group;
  double payout_m = 0.0;
  double length_before_m = 0.0;  ///< total unstretched
  double length_after_m = 0.0;
  double top_segment_before_m = 0.0;
  double top_segment_after_m = 0.0;
  double pretension_before_N = 0.0;
  double pretension_after_N = 0.0;
  double top_segment_mbl_N = 0.0;
};

struct OptimizationHistoryRow {
  int evaluation = 0;
  double objective = 0.0;
  double worst_constraint = 0.0;  ///< largest g (≤ 0: feasible)
  std::string worst_constraint_name;
  bool feasible = false;
  double wall_s = 0.0;  ///< since the start of the run
  std::vector<double> payouts_m;
};

/// An active constraint or bound at the optimum and its multiplier λ ≥ 0:
/// relaxing it by δ (its g by −δ) improves the objective by about λ δ
/// (the KKT system solved in least squares over the active set).
struct ActiveConstraint {
  std::string name;
  double value = 0.0;
  double multiplier = 0.0;
};

enum class OptimizationStatus { optimal, infeasible };

struct OptimizationResult {
  std::string project;
  OptimizationObjective objective = OptimizationObjective::max_soz_margin;
  OptimizationAlgorithm algorithm = OptimizationAlgorithm::slsqp;
  bool dynamic = false;  ///< the dynamic level (enhanced S-C storms)
  OptimizationStatus status = OptimizationStatus::optimal;
  std::string stop_reason;  ///< NLopt's result code as text
  std::vector<GroupVariable> groups;
  std::vector<std::string> scenarios;
  std::vector<double> payouts_m;  ///< best point, per group
  double objective_start = 0.0;
  double objective_best = 0.0;
  std::string objective_unit;  ///< of the two values above
  std::vector<ScenarioSummary> before, after;
  std::vector<LinePayout> lines;
  std::vector<OptimizationHistoryRow> history;
  std::vector<ActiveConstraint> active;
  std::vector<double> objective_gradient;        ///< d(objective)/d(payout) per group at the best point, 1/m
  std::optional<ConstraintValue> most_violated;  ///< infeasible: at the least infeasible point
  std::vector<std::string> findings;             ///< e.g. a riser without a zone: no pretension can help
  std::vector<std::string> notes;
  double zone_conservatism_m = 0.0;  ///< largest lowering of a smooth zone (smooth_zone.hpp)
  std::vector<ZoneOutline> zones;
  int evaluations = 0;
  double wall_s = 0.0;
  double zone_wall_s = 0.0;
};

const char* to_string(OptimizationStatus status);

/// The design variables of the project (payout_groups.hpp with the bounds).
std::vector<GroupVariable> group_variables(const Project& project);

/// Runs the optimization. Throws InputError for a bad request, engine::SolverError
/// (scenario named) when an evaluation cannot be solved.
OptimizationResult optimize_pretension(const ValidatedProject& project, const OptimizationRequest& request);

}  // namespace spiral::design
