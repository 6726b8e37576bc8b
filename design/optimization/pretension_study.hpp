#pragma once
// The pretension study (`spiral study pretension`): the trade-off a mooring
// designer decides from. The payout of one group (or of every group
// together) is swept across its bounds; at each point every scenario's
// equilibrium gives the largest offset, offset / SOZ and line utilization,
// intact and damaged, and whether every constraint of the optimization holds
// (the feasible band). The optimizer's point can be marked on it.

#include <optional>
#include <string>
#include <vector>

#include "design/optimization/pretension_optimizer.hpp"

namespace spiral::design {

struct PretensionStudyRequest {
  OptimizationRequest problem;  ///< cases, damaged conditions, threads
  /// The groups swept one at a time (the others at zero payout); empty:
  /// every group together, all at the same payout.
  std::vector<std::string> groups;
  int points = 21;            ///< per sweep, >= 2, evenly spaced over the bounds
  bool with_optimum = false;  ///< also run the optimizer and mark its point
};

struct PretensionStudyPoint {
  double payout_m = 0.0;
  double pretension_N = 0.0;  ///< mean at rest over the swept lines
  double max_offset_m = 0.0;
  std::optional<double> max_soz_ratio_intact, max_soz_ratio_damaged;
  double max_utilization_intact = 0.0, max_utilization_damaged = 0.0;
  double worst_constraint = 0.0;  ///< largest g of the optimization's constraints
  std::string worst_constraint_name;
  bool feasible = false;
};

struct PretensionSweep {
  std::string name;  ///< the group, or "all"
  std::vector<std::string> lines;
  std::vector<PretensionStudyPoint> points;
  /// The feasible band [from, to] in payout (m), when there is one (the
  /// outermost feasible points; a gap inside it is reported in notes).
  std::optional<std::pair<double, double>> feasible_m;
};

struct PretensionStudyResult {
  std::string project;
  std::vector<std::string> scenarios;
  std::vector<PretensionSweep> sweeps;
  std::vector<std::string> notes;
  /// The optimizer's payouts per group (with_optimum), and its status.
  std::optional<std::vector<double>> optimum_payouts_m;
  std::string optimum_status;
  int evaluations = 0;
  double wall_s = 0.0;
};

/// Throws InputError for an unknown group or too few points, engine::SolverError
/// (scenario named) when an equilibrium cannot be solved.
PretensionStudyResult run_pretension_study(const ValidatedProject& project, const PretensionStudyRequest& request);

}  // namespace spiral::design
