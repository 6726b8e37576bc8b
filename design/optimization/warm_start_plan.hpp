#pragma once
// Which solved riser state each scenario's full equilibrium starts from.
//
// An FE riser solve costs with the distance its top moves from the warm
// start: a move of tens of metres takes 8–9 Newton or chord iterations and
// 2–3 fresh Jacobians, a move below a metre two chord steps on a borrowed
// factorisation (docs/decisions/pretension-optimization.md). The
// optimizer's scenarios of one environment share their risers (same
// models, same current) and sit close together: a case's 16 one-line-
// removed scenarios lie in four clusters (one per mooring cluster) whose
// members are 0.2–1 m apart, while a payout change moves every one of them
// by 20–25 m. So each scenario starts from the nearest solved state: its
// own last one, or that of a scenario of its environment already solved in
// this evaluation — one long move per cluster instead of one per scenario.
//
// The plan is built greedily (Prim's rule): of every scenario not yet
// planned and every state it may start from, the closest pair is planned
// next, and the scenario's predicted state joins the candidates. Distances
// are the largest over the risers of their tops' distance (predicted pose
// against the candidate's). A scenario whose donor was solved in this
// evaluation runs one wave after it; the scenarios of a wave are
// independent (they run in parallel).

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace spiral::design {

/// One scenario to be solved, as the plan sees it.
struct WarmStartNode {
  int environment = 0;  ///< scenarios of one environment share riser models
  /// Where its risers' tops will be (the predicted equilibrium), per riser.
  std::vector<Eigen::Vector3d> predicted_tops_g;
  /// Where its risers were last solved, per riser; empty: never solved (it
  /// must start from another scenario).
  std::vector<Eigen::Vector3d> own_tops_g;
};

struct WarmStart {
  /// The scenario (index into the nodes) whose state of this evaluation it
  /// starts from; none: its own last state.
  std::optional<int> donor;
  int wave = 0;  ///< 0 for its own state, the donor's wave + 1 otherwise
  double distance_m = 0.0;
};

/// The plan, one entry per node. Throws std::invalid_argument when a node
/// has neither its own state nor a scenario of its environment to start from,
/// or when nodes of one environment have different riser counts.
std::vector<WarmStart> plan_warm_starts(const std::vector<WarmStartNode>& nodes);

/// The nodes of each wave, in index order (wave 0 first).
std::vector<std::vector<int>> warm_start_waves(const std::vector<WarmStart>& plan);

}  // namespace spiral::design
