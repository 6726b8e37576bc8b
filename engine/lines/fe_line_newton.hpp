#pragma once
// Internal to the FE line statics: the Newton–Raphson driver (exact
// Jacobian kept while it contracts — modified Newton —, banded LU, Armijo backtracking with a watchdog) and the
// continuations around it — current velocity, axial-stiffness cap, and the
// touchdown node (r-adaptivity). Strategy and reasons: fe_line_statics.hpp.

#include <Eigen/Core>

#include "engine/lines/fe_line_problem.hpp"

namespace spiral::engine::fe_detail {

inline constexpr int kFinalSnapPasses = 10;          // touchdown node re-solves at the final stiffness
inline constexpr int kDirectAttemptIterations = 12;  // before falling back to seabed continuation
// Newton iterations allowed from the swung start of a cold solve under
// current (crawling still stops it early). Measured on the default scenario's
// 28 lines, 4 currents, 3 hull offsets: 24 leaves 1 of 336 cold solves to
// the continuations, 40 none; most converge in 5–20.
inline constexpr int kSwungAttemptIterations = 40;

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
  double residual_N = 0.0;
  double scale_N = 0.0;
};

/// Work counters of one solve (reported in FeStaticsResult).
struct Counters {
  int iterations = 0;
  int load_steps = 0;
  int remeshes = 0;
};

/// Newton–Raphson from q (updated in place). give_up_when_crawling: return
/// unconverged after a few very short steps (a continuation is the fallback).
/// t: the kept factorised Jacobian (modified Newton; see fe_line_newton.cpp),
/// updated in place.
NewtonOutcome newton(const Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q, Tangent& t,
                     bool give_up_when_crawling = false);
/// How solve_with_current_steps starts and what it falls back on.
struct CurrentSteps {
  /// Cold starts: first try Newton from the start swung into the current
  /// about its chord (a rigid rotation, see fe_line_newton.cpp).
  bool swing_predictor = false;
  /// Newton at the full current from the start (off: the caller just tried it).
  bool direct = true;
  /// Current / axial-stiffness continuations when Newton at the full current fails.
  bool continuations = true;
};
/// Newton at the full current, else current / axial-stiffness continuations.
NewtonOutcome solve_with_current_steps(Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q, Tangent& t,
                                       Counters& counters, CurrentSteps steps = {});
/// Touchdown node: move the nearest node onto the touchdown point and
/// re-solve until it stays (at most max_passes re-solves). `last`: the
/// outcome of the converged solve of q, returned if no node moves.
NewtonOutcome snap_touchdown(Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q, Tangent& t, Counters& counters,
                             int max_passes, NewtonOutcome last);
/// Where the touchdown node goes (and the tolerance), given the lift-off point.
struct TouchdownTarget {
  double arc_length_m = 0.0;
  double tolerance_m = 0.0;
};
TouchdownTarget touchdown_node_target(const Problem& p, const Eigen::VectorXd& q, double s_lift);

}  // namespace spiral::engine::fe_detail
