#pragma once
// Target-pretension mode (`optimization.target_pretension`): the payout of
// every line of a group that gives it the group's target fairlead tension
// with the hull at its rest position in still water — pretension as the
// industry defines it (hull fixed). What OrcaFlex's line setup wizard does,
// here per line by the bracketed Newton of engine/lines/catenary_payout.hpp,
// which either reaches the target or says why not: never a silent miss.
// Lines are solved as their multi-segment catenary (an FE line's static
// shape in still water is that catenary to its discretization).

#include <string>
#include <vector>

#include "design/optimization/pretension_optimizer.hpp"

namespace spiral::design {

struct TargetPretensionRow {
  std::string line;
  std::string group;
  double target_N = 0.0;
  double pretension_before_N = 0.0;
  double payout_m = 0.0;  ///< top-segment length change
  double pretension_after_N = 0.0;
  double top_segment_after_m = 0.0;
  int iterations = 0;
};

struct TargetPretensionResult {
  std::string project;
  std::vector<TargetPretensionRow> lines;
  double wall_s = 0.0;
};

/// Throws InputError when the project gives no targets, engine::SolverError
/// naming the line when a target is outside what the group's bounds reach.
TargetPretensionResult solve_target_pretensions(const Project& project);

}  // namespace spiral::design
