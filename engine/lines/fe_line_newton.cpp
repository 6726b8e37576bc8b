// Newton–Raphson driver of the FE line statics and its continuations
// (current, axial stiffness, touchdown node). See fe_line_newton.hpp.

#include "engine/lines/fe_line_newton.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

namespace spiral::engine::fe_detail {
namespace {

constexpr double kShortStep = 0.05;
constexpr int kWatchdogSteps = 2;
constexpr double kSevereStepLimit = 0.1;
constexpr double kFirstAxialCap = 10.0;  // × the largest tension
constexpr int kMaxShortSteps = 4;
// A kept Jacobian is refreshed when a chord step reduces the residual norm
// by less than this factor (linear convergence slower than halving costs
// more residual evaluations than a fresh factorisation saves).
constexpr double kChordContraction = 0.5;
// After convergence by chord steps, polish to this fraction of the tolerance
// while chord steps still contract (they stop at round-off): about where a
// Newton step would have landed.
constexpr double kChordPolish = 1e-3;

}  // namespace

/// Newton–Raphson with backtracking line search. With give_up_when_crawling,
/// returns unconverged after kMaxShortSteps consecutive steps shorter than
/// kShortStep of the Newton step: the linear step of a large rotation (a line
/// swung by a cross current) stretches the line spuriously, the line search
/// cuts it to a sliver, and Newton would crawl — the caller then continues the
/// load in smaller increments instead.
///
/// Modified Newton (chord steps; Kelley, "Iterative Methods for Linear and
/// Nonlinear Equations", SIAM 1995, §5.4 and the Shamanskii method §5.4.3):
/// while t holds a factorised Jacobian — of an earlier iterate or of the
/// solve warm-started from — and chord steps are allowed (t.chord_steps), a
/// full step with it is taken if it reduces the residual norm by
/// kChordContraction or better; otherwise (or if the step would exceed the
/// step limits) a fresh Jacobian is assembled and factorised at the current
/// iterate for a full Newton step with line search. Assembly and factorisation are most of the
/// cost of an iteration, a chord step costs one residual and one
/// back-substitution; the converged state is held to the same tolerance.
NewtonOutcome newton(const Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q, Tangent& t,
                     bool give_up_when_crawling) {
  NewtonOutcome out;
  int short_steps = 0;
  Eigen::VectorXd g(p.n_dofs), g_trial(p.n_dofs), q_trial(p.n_dofs), dq(p.n_dofs);
  if (t.factor().size() != p.n_dofs) t.valid = false;
  // Step limits: nodes move at most a tenth of the line length, slopes change
  // by at most 0.5 per step (keeps |r'| away from 0, where the strain measure
  // and the tangent are undefined).
  auto step_limit = [&p](const Eigen::VectorXd& d) {
    double limit = 1.0;
    for (std::size_t n = 0; n < static_cast<std::size_t>(p.n_nodes); ++n) {
      const double dr = d.segment<3>(p.r_dof[n]).norm();
      const double dt = std::max(d.segment<3>(p.t_in[n]).norm(), d.segment<3>(p.t_out[n]).norm());
      limit = std::min(limit, 0.1 * p.line_length_m / std::max(dr, 1e-300));
      limit = std::min(limit, 0.5 / std::max(dt, 1e-300));
    }
    return limit;
  };
  auto newton_rhs = [&p](const Eigen::VectorXd& residual, Eigen::VectorXd& d) {
    d = -residual;
    for (int i = 0; i < p.n_dofs; ++i) {
      if (is_fixed(p, i)) d[i] = 0.0;
    }
  };
  t.converged_q.resize(0);
  if (!assemble(p, q, g, nullptr)) return out;
  // Iteration limits count Newton steps (fresh Jacobians) and chord steps
  // apart: o.max_iterations each (chord steps are cheap, and each one taken
  // halves the residual norm at least, so they cannot cycle).
  int it = 0, chord_steps = 0;
  bool try_chord = t.chord_steps && t.valid;  // not after a damped Newton step: its chord step would be too long too
  bool polishing = false;                     // the last step was a chord step
  for (;; ++it) {
    out.scale_N = std::max(p.load_scale_N, max_axial_force(p, q));
    out.residual_N = residual_norm(p, g);
    out.iterations = it + chord_steps;
    const double tolerance_N = std::max(o.relative_force_tolerance * out.scale_N, p.round_off_floor_N);
    if (out.residual_N <= tolerance_N) {
      out.converged = true;
      t.converged_q = q;
      t.converged_residual = g;
      // A Newton step lands far below the tolerance (quadratic convergence),
      // a chord step just below it: polish with more chord steps while they
      // contract, so that the state is as exact as a full Newton iteration
      // leaves it (stages and touchdown-node moves that follow depend on it).
      if (!polishing || !o.polish_chord_steps || out.residual_N <= kChordPolish * tolerance_N) return out;
    }
    if (it + chord_steps >= o.max_iterations) return out;
    const double m0 = merit(p, g);
    if (t.valid && try_chord && chord_steps < o.max_iterations) {
      polishing = true;
      // Chord step with the kept factorisation.
      newton_rhs(g, dq);
      t.factor().solve_in_place(dq);
      if (dq.allFinite() && step_limit(dq) >= 1.0) {
        q_trial = q + dq;
        if (assemble(p, q_trial, g_trial, nullptr) && merit(p, g_trial) <= kChordContraction * kChordContraction * m0) {
          q.swap(q_trial);
          g.swap(g_trial);
          short_steps = 0;
          ++chord_steps;
          --it;  // not a Newton iteration
          continue;
        }
      }
      polishing = false;
    }
    if (out.converged) return out;  // polished as far as chord steps go
    BandMatrix& jac = t.own();
    if (!assemble(p, q, g, &jac)) return out;
    ++t.evaluations;
    for (int i = 0; i < p.n_dofs; ++i) {
      if (is_fixed(p, i)) jac.set_identity_row(i);
    }
    newton_rhs(g, dq);
    if (!jac.factorize(Pivoting::diagonal_while_definite)) return out;
    t.valid = true;
    jac.solve_in_place(dq);
    if (!dq.allFinite()) return out;
    double limit = step_limit(dq);
    if (limit < kSevereStepLimit && p.load.current != nullptr && !p.load.current->empty() &&
        p.load.current_factor > 0.0) {
      // A near-singular tangent: the drag's dependence on the line's
      // orientation (a follower-load stiffness, not symmetric) can cancel the
      // small swing stiffness that gravity gives a hanging line, so the
      // Newton step explodes. Far from equilibrium, step with the drag held
      // as a dead load instead (structure + gravity + seabed tangent); the
      // full tangent returns, with quadratic convergence, once steps are sane.
      BandMatrix jac_dead;
      Eigen::VectorXd g_dead(p.n_dofs), dq_dead(p.n_dofs);
      if (assemble(p, q, g_dead, &jac_dead, false)) {
        ++t.evaluations;
        for (int i = 0; i < p.n_dofs; ++i) {
          if (is_fixed(p, i)) jac_dead.set_identity_row(i);
        }
        newton_rhs(g, dq_dead);
        if (jac_dead.factorize(Pivoting::diagonal_while_definite)) {
          jac_dead.solve_in_place(dq_dead);
          if (dq_dead.allFinite() && step_limit(dq_dead) > limit) {
            dq = dq_dead;
            limit = step_limit(dq);
            jac = std::move(jac_dead);
          }
        }
      }
    }
    // Step acceptance: the full step if it descends (Armijo on the scaled
    // residual); else a watchdog (Chamberlain et al., Math. Prog. Study 16,
    // 1982): up to kWatchdogSteps more full Newton steps, kept if the residual
    // has come below the starting one by then — the full step of a large
    // rotation leaves a spurious axial strain (≈ θ²/2 times EA) that makes
    // the residual jump although the step is right, and the next Newton step
    // removes it; else back to the starting point and backtracking (halving).
    double alpha = limit;
    bool accepted = false;
    q_trial = q + limit * dq;
    const bool full_ok = assemble(p, q_trial, g_trial, nullptr);
    if (full_ok && merit(p, g_trial) <= (1.0 - 1e-4 * limit) * m0) {
      accepted = true;
    } else if (full_ok && limit == 1.0) {
      Eigen::VectorXd q_w = q_trial, g_w(p.n_dofs), dq_w(p.n_dofs);
      BandMatrix jac_w;
      for (int k = 0; k < kWatchdogSteps && !accepted; ++k) {
        if (!assemble(p, q_w, g_w, &jac_w)) break;
        ++t.evaluations;
        for (int i = 0; i < p.n_dofs; ++i) {
          if (is_fixed(p, i)) jac_w.set_identity_row(i);
        }
        newton_rhs(g_w, dq_w);
        if (!jac_w.factorize(Pivoting::diagonal_while_definite)) break;
        jac_w.solve_in_place(dq_w);
        if (!dq_w.allFinite()) break;
        q_w += dq_w;
        ++it;  // a Newton iteration spent
        if (assemble(p, q_w, g_w, nullptr) && merit(p, g_w) <= (1.0 - 1e-4) * m0) {
          q_trial = q_w;
          g_trial = g_w;
          accepted = true;
        }
      }
    }
    for (int ls = 0; !accepted && ls < 30; ++ls, alpha *= 0.5) {
      q_trial = q + alpha * dq;
      if (!assemble(p, q_trial, g_trial, nullptr)) continue;
      if (merit(p, g_trial) <= (1.0 - 1e-4 * alpha) * m0) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      // No descent: at round-off level this is convergence in all but name;
      // otherwise report the failure to the caller.
      out.converged = out.residual_N <= 1e3 * o.relative_force_tolerance * out.scale_N;
      return out;
    }
    q.swap(q_trial);
    g.swap(g_trial);
    short_steps = alpha < kShortStep ? short_steps + 1 : 0;
    try_chord = t.chord_steps && alpha == 1.0;
    if (give_up_when_crawling && short_steps >= kMaxShortSteps) {
      out.residual_N = residual_norm(p, g);
      return out;
    }
  }
}

/// Swing predictor of a cold start under current: turns the suspended part
/// of the line rigidly about its chord — from the last node resting on the
/// seabed (or end A) to end B — to the angle where the loads have no moment
/// about that chord, and returns the turned state (q unchanged and false if
/// no such angle is found within ±kMaxSwingAngle).
/// Why: a cable under a uniform load hangs in the plane of the load and its
/// chord, so a current mostly swings the line's plane about the chord; the
/// linear Newton step of that rotation stretches the line by ≈ θ²/2 (see
/// solve_with_current_steps), whereas a rigid rotation keeps every strain and
/// curvature. The angle solves G(θ) = g(q_θ) · ∂q_θ/∂θ = 0, the generalised
/// force along the rotation (internal forces do no work in a rigid rotation:
/// G is the moment of the weight, drag and contact loads about the chord),
/// by a march in kSwingAngleStep to a sign change, then Illinois regula falsi.
static bool swing_into_current(const Problem& p, Eigen::VectorXd& q) {
  constexpr double kSwingAngleStep = 0.1;        // rad; the march that brackets the root
  constexpr double kMaxSwingAngle = 1.5;         // rad; a line swung further is left to the continuations
  constexpr double kSwingAngleTolerance = 1e-3;  // rad; Newton removes the rest
  constexpr int kMaxRegulaFalsiSteps = 30;
  // Pivot: the last node on the seabed (the laid part stays where it lies).
  int pivot = 0;
  if (p.load.seabed_stiffness_N_per_m2 > 0.0) {
    const double on_seabed_m = p.load.seabed_z_m + 1e-6 * p.line_length_m;
    for (int i = 0; i + 1 < p.n_nodes; ++i) {
      if (q[p.r_dof[static_cast<std::size_t>(i)] + 2] <= on_seabed_m) pivot = i;
    }
  }
  if (pivot + 2 >= p.n_nodes) return false;
  const Eigen::Vector3d c = q.segment<3>(p.r_dof[static_cast<std::size_t>(pivot)]);
  const Eigen::Vector3d chord = q.segment<3>(p.r_dof.back()) - c;
  if (chord.norm() < 1e-6 * p.line_length_m) return false;
  const Eigen::Vector3d u = chord.normalized();
  const Eigen::VectorXd q0 = q;
  Eigen::VectorXd g(p.n_dofs);
  auto turn = [&](double theta) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, u).toRotationMatrix();
    for (std::size_t i = static_cast<std::size_t>(pivot) + 1; i + 1 < static_cast<std::size_t>(p.n_nodes); ++i) {
      q.segment<3>(p.r_dof[i]) = c + R * (q0.segment<3>(p.r_dof[i]) - c);
      q.segment<3>(p.t_in[i]) = R * q0.segment<3>(p.t_in[i]);
      q.segment<3>(p.t_out[i]) = R * q0.segment<3>(p.t_out[i]);
    }
  };
  auto moment = [&](double theta, double& G) {
    turn(theta);
    if (!assemble(p, q, g, nullptr)) return false;
    G = 0.0;
    for (std::size_t i = static_cast<std::size_t>(pivot) + 1; i + 1 < static_cast<std::size_t>(p.n_nodes); ++i) {
      G += g.segment<3>(p.r_dof[i]).dot(u.cross(q.segment<3>(p.r_dof[i]) - c));
      G += g.segment<3>(p.t_in[i]).dot(u.cross(q.segment<3>(p.t_in[i])));
      if (p.t_out[i] != p.t_in[i]) G += g.segment<3>(p.t_out[i]).dot(u.cross(q.segment<3>(p.t_out[i])));
    }
    return std::isfinite(G);
  };
  auto give_up = [&] {
    q = q0;
    return false;
  };
  double G0 = 0.0;
  if (!moment(0.0, G0) || G0 == 0.0) return give_up();
  // Angles along the direction the moment turns the line; G(lo) has G0's sign.
  const double dir = G0 > 0.0 ? 1.0 : -1.0;
  double lo = 0.0, G_lo = G0, hi = NAN, G_hi = NAN;
  for (int k = 1; k * kSwingAngleStep <= kMaxSwingAngle + 1e-12; ++k) {
    const double theta = k * kSwingAngleStep;
    double G = 0.0;
    if (!moment(dir * theta, G)) return give_up();
    if ((G > 0.0) != (G0 > 0.0)) {
      hi = theta;
      G_hi = G;
      break;
    }
    lo = theta;
    G_lo = G;
  }
  if (std::isnan(hi)) return give_up();
  int side = 0;  // Illinois: halve the retained end's value when it is kept twice
  for (int k = 0; k < kMaxRegulaFalsiSteps && hi - lo > kSwingAngleTolerance; ++k) {
    const double theta = (lo * G_hi - hi * G_lo) / (G_hi - G_lo);
    double G = 0.0;
    if (!moment(dir * theta, G)) return give_up();
    if ((G > 0.0) == (G0 > 0.0)) {
      lo = theta;
      G_lo = G;
      if (side == -1) G_hi *= 0.5;
      side = -1;
    } else {
      hi = theta;
      G_hi = G;
      if (side == 1) G_lo *= 0.5;
      side = 1;
    }
  }
  turn(dir * 0.5 * (lo + hi));
  return true;
}

/// Continuation on the current velocity factor λ (drag ∝ λ²) from the state
/// converged at λ = 0: steps grow by half after a success, halve after a
/// failure. Leaves current_factor at 1.
static NewtonOutcome current_continuation(Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q, Tangent& t,
                                          Counters& counters) {
  p.load.current_factor = 0.0;
  NewtonOutcome last = newton(p, o, q, t);
  counters.iterations += last.iterations;
  ++counters.load_steps;
  double lambda = 0.0, step = 0.25;
  int halvings = 0;
  while (last.converged && lambda < 1.0) {
    const Eigen::VectorXd q_prev = q;
    p.load.current_factor = std::min(1.0, lambda + step);
    last = newton(p, o, q, t, true);
    counters.iterations += last.iterations;
    ++counters.load_steps;
    if (last.converged) {
      lambda = p.load.current_factor;
      step *= 1.5;
    } else if (halvings < o.max_load_step_halvings) {
      q = q_prev;
      step *= 0.5;
      ++halvings;
      last.converged = true;  // retry with the smaller step
    }
  }
  p.load.current_factor = 1.0;
  return last;
}

/// Newton at the full current — with steps.swing_predictor, first from the
/// state swung into the current (swing_into_current) —; if it crawls or
/// fails, and steps.continuations:
/// (1) current continuation with EA capped at kFirstAxialCap × the largest
///     tension, then the cap raised ×10 per stage to the model's EA at full
///     current. Why: a current swings the line through a large angle θ, and
///     Newton's linear step for a rotation stretches the elements by ≈ θ²/2;
///     with EA ≫ T that spurious strain dominates the residual and the line
///     search cuts the step to ≈ √(2T/EA)/θ of itself (0.01 rad per step for a
///     flexible riser). With EA ≈ 10 T a step can turn the line by ≈ 0.5 rad;
///     raising EA afterwards changes the shape only by the stretch.
/// (2) if that fails, current continuation with the model's EA.
NewtonOutcome solve_with_current_steps(Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q, Tangent& t,
                                       Counters& counters, CurrentSteps steps) {
  const bool has_current = p.load.current != nullptr && !p.load.current->empty();
  const Eigen::VectorXd q_start = q;
  p.load.current_factor = 1.0;
  const double T_start = max_axial_force(p, q_start);
  const double T_ref = T_start > 0.0 ? T_start : p.load_scale_N;
  const double EA_max = *std::max_element(p.EA_true_N.begin(), p.EA_true_N.end());
  FeStaticsOptions loose = o;
  loose.relative_force_tolerance = std::max(o.relative_force_tolerance, 1e-6);
  auto count = [&counters](const NewtonOutcome& outcome) {
    counters.iterations += outcome.iterations;
    ++counters.load_steps;
    return outcome;
  };
  // From a state converged with EA capped at kFirstAxialCap × T_ref: the cap
  // raised ×10 per stage to the model's EA.
  auto restore_axial_stiffness = [&](NewtonOutcome last) {
    for (double cap = 10.0 * kFirstAxialCap * T_ref; last.converged; cap *= 10.0) {
      const bool final_stage = cap >= EA_max;
      cap_axial_stiffness(p, final_stage ? INFINITY : cap);
      last = count(newton(p, final_stage ? o : loose, q, t, true));
      if (final_stage) break;
    }
    cap_axial_stiffness(p, INFINITY);
    return last;
  };
  NewtonOutcome last;
  if (has_current && steps.swing_predictor && swing_into_current(p, q)) {
    // The swung start usually converges directly (with a larger budget than
    // a direct attempt: it starts with the bending and contact residuals of
    // the turn); else the unswung start and the continuations below.
    FeStaticsOptions swung_options = o;
    swung_options.max_iterations = std::max(o.max_iterations, kSwungAttemptIterations);
    last = count(newton(p, swung_options, q, t, true));
    if (last.converged) return last;
    q = q_start;
  }
  if (steps.direct || !has_current) {
    last = count(newton(p, o, q, t, has_current));
    if (last.converged || !has_current || !steps.continuations) return last;
    q = q_start;
  }
  if (!steps.continuations) return last;

  cap_axial_stiffness(p, kFirstAxialCap * T_ref);
  last = restore_axial_stiffness(current_continuation(p, loose, q, t, counters));
  if (last.converged) return last;

  q = q_start;
  return current_continuation(p, o, q, t, counters);
}

/// Where the touchdown node should sit, given the lift-off point s_lift of
/// the current solution. A cable (EI = 0) on a penalty seabed of stiffness k
/// under tension T: on the bed T z'' = k (z − z_b) + w gives a boundary layer
/// ℓ = √(T/k); the suspended cubic leaves its node at z_b − w/k with zero
/// slope and curvature w/T, so it crosses z_b at √(2 w/(k κ)) = √2 ℓ beyond the
/// node: the node goes there. With bending (EI > 0) the beam-on-foundation
/// layer (4EI/k)^¼ (Hetényi 1946) and the TDP boundary layer √(EI/T) (Pesce et
/// al. 1998) are resolved by the mesh, not by this shift: the node goes to the
/// lift-off point. Tolerance: a tenth of the layer, at least 1e-4 element.
TouchdownTarget touchdown_node_target(const Problem& p, const Eigen::VectorXd& q, double s_lift) {
  const double k = p.load.seabed_stiffness_N_per_m2;
  std::size_t e = 0;
  while (e + 1 < p.elements.size() && p.mesh.s[e + 1] < s_lift) ++e;
  const auto& el = p.elements[e];
  const double stretch = q.segment<3>(p.t_out[e]).norm();
  const double T = std::max(0.0, el.EA_N * (stretch - 1.0));
  const double cable_layer = std::sqrt(T / k);
  if (el.EI_Nm2 > 0.0) {
    const double beam_layer = std::max(std::pow(4.0 * el.EI_Nm2 / k, 0.25), cable_layer);
    return {s_lift, 0.1 * beam_layer};
  }
  return {s_lift - std::sqrt(2.0) * cable_layer, 0.01 * cable_layer};
}

/// Moves the interior node nearest to arc length s_new (not an end, not a
/// section joint) onto it, re-interpolating the state with the Hermite shape
/// functions. Returns false if no node moves (already there within 1e-4 of an
/// element or tolerance_m, or no movable node).
/// The interior node nearest to arc length s_new that may move there (not an
/// end, not a section joint, s_new strictly between its neighbours); −1 if none.
static int nearest_movable_node(const Problem& p, double s_new) {
  const auto& s = p.mesh.s;
  int best = -1;
  double dist = INFINITY;
  for (int i = 1; i + 1 < p.n_nodes; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    if (p.mesh.section[ui - 1] != p.mesh.section[ui]) continue;  // section joint
    if (s_new <= s[ui - 1] || s_new >= s[ui + 1]) continue;
    if (std::abs(s[ui] - s_new) < dist) {
      dist = std::abs(s[ui] - s_new);
      best = i;
    }
  }
  return best;
}

static bool move_node_to(Problem& p, Eigen::VectorXd& q, double s_new, double tolerance_m) {
  auto& s = p.mesh.s;
  const int best = nearest_movable_node(p, s_new);
  if (best < 0) return false;
  const double dist = std::abs(s[static_cast<std::size_t>(best)] - s_new);
  const auto ub = static_cast<std::size_t>(best);
  if (dist < std::max(tolerance_m, 1e-4 * std::min(s[ub] - s[ub - 1], s[ub + 1] - s[ub]))) return false;
  // The new node's state from the element that contains s_new.
  const std::size_t e = s_new < s[ub] ? ub - 1 : ub;
  const double L = s[e + 1] - s[e];
  const auto sh = ancf::shape_at((s_new - s[e]) / L, L);
  const ElementState qe = gather(p, q, e);
  q.segment<3>(p.r_dof[ub]) = position(sh, qe);
  q.segment<3>(p.t_in[ub]) = slope(sh, qe);  // not a joint: t_in == t_out
  s[ub] = s_new;
  update_lengths(p);
  return true;
}

/// Touchdown node: move the nearest interior node onto the touchdown point
/// and re-solve, until it stays put (touchdown_node_target). A cubic element
/// cannot follow "flat, then curved" inside itself; with a node there the
/// laid elements are straight and the suspended ones smooth, which restores
/// most of the element's accuracy (header numbers).
NewtonOutcome snap_touchdown(Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q, Tangent& t, Counters& counters,
                             int max_passes, NewtonOutcome last) {
  // The node position s solves s = target(s), a contraction with a factor near
  // 0.8 here: secant steps on f(s) = target(s) − s (Aitken) from the second
  // pass on, plain fixed-point steps when the secant is not usable.
  double s_prev = NAN, f_prev = NAN;
  for (int pass = 0; o.snap_node_to_touchdown && pass < max_passes; ++pass) {
    const auto td = find_touchdown(p, q);
    if (!td) break;
    const TouchdownTarget target = touchdown_node_target(p, q, td->arc_length_m);
    const int node = nearest_movable_node(p, target.arc_length_m);
    if (node < 0) break;
    const double s_node = p.mesh.s[static_cast<std::size_t>(node)];
    const double f = target.arc_length_m - s_node;
    double s_new = target.arc_length_m;
    if (std::isfinite(f_prev) && f != f_prev) {
      const double secant = s_node - f * (s_node - s_prev) / (f - f_prev);
      if (std::abs(secant - s_node) < 50.0 * std::abs(f)) s_new = secant;
    }
    s_prev = s_node;
    f_prev = f;
    if (std::abs(f) < target.tolerance_m) break;
    if (!move_node_to(p, q, s_new, 0.0)) break;
    ++counters.remeshes;
    last = solve_with_current_steps(p, o, q, t, counters);
    if (!last.converged) break;
  }
  return last;  // unmoved: the converged outcome it was given
}

}  // namespace spiral::engine::fe_detail
