// Multi-segment elastic catenary solver: input checks, Newton on (H, V_F) with
// the analytic Jacobian and a backtracking line search, a bracketing fallback,
// and the error messages. Span kernels: catenary_spans.{hpp,cpp}; H = 0
// configurations: catenary_vertical.cpp; profile: catenary_profile.cpp.

#include "engine/lines/catenary.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/lines/catenary_spans.hpp"

namespace spiral::engine {

namespace detail = catenary_detail;
using detail::Infeasibility;
using detail::LineView;
using detail::SpanEvaluation;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

[[noreturn]] void fail(const std::string& message) { throw SolverError("catenary: " + message); }

LineView check_inputs(const CatenaryLine& line, const CatenaryGeometry& g, const CatenaryOptions& o) {
  if (!(!line.segments.empty())) fail("segments: at least one segment is required");
  const std::size_t n = line.segments.size();
  LineView view;
  view.line = &line;
  for (std::size_t i = 0; i < n; ++i) {
    const CatenarySegment& s = line.segments[i];
    if (!(std::isfinite(s.length_m) && s.length_m > 0.0))
      fail(fmt::format("segments[{}].length_m: must be > 0, got {} m", i, s.length_m));
    if (!(std::isfinite(s.weight_N_per_m)))
      fail(fmt::format("segments[{}].weight_N_per_m: must be finite, got {} N/m", i, s.weight_N_per_m));
    if (!(std::isfinite(s.EA_N) && s.EA_N > 0.0))
      fail(fmt::format("segments[{}].EA_N: must be > 0, got {} N", i, s.EA_N));
    view.total_weight_N += s.weight_N_per_m * s.length_m;
    view.total_length_m += s.length_m;
  }
  if (!(line.joint_load_N.empty() || line.joint_load_N.size() == n - 1))
    fail(fmt::format("joint_load_N: must be empty or have {} entries (one per joint), got {}", n - 1,
                     line.joint_load_N.size()));
  for (std::size_t i = 0; i < line.joint_load_N.size(); ++i) {
    if (!(std::isfinite(line.joint_load_N[i])))
      fail(fmt::format("joint_load_N[{}]: must be finite, got {} N", i, line.joint_load_N[i]));
    view.total_weight_N += line.joint_load_N[i];
  }
  if (!(std::isfinite(line.seabed_friction) && line.seabed_friction >= 0.0))
    fail(fmt::format("seabed_friction: must be >= 0, got {}", line.seabed_friction));
  if (!(std::isfinite(g.horizontal_span_m) && g.horizontal_span_m >= 0.0))
    fail(fmt::format("horizontal_span_m: must be >= 0, got {} m", g.horizontal_span_m));
  if (!(std::isfinite(g.vertical_span_m)))
    fail(fmt::format("vertical_span_m: must be finite, got {} m", g.vertical_span_m));
  if (!(std::isfinite(g.anchor_height_above_seabed_m) && g.anchor_height_above_seabed_m >= 0.0))
    fail(fmt::format("anchor_height_above_seabed_m: must be >= 0, got {} m", g.anchor_height_above_seabed_m));
  if (!(std::isfinite(o.tolerance_m) && o.tolerance_m > 0.0))
    fail(fmt::format("options.tolerance_m: must be > 0, got {} m", o.tolerance_m));
  if (!(o.max_iterations > 0)) fail(fmt::format("options.max_iterations: must be > 0, got {}", o.max_iterations));
  if (!(std::isfinite(o.max_strain) && o.max_strain > 0.0))
    fail(fmt::format("options.max_strain: must be > 0, got {}", o.max_strain));
  if (!(o.profile_points_per_segment >= 0))
    fail(fmt::format("options.profile_points_per_segment: must be >= 0, got {}", o.profile_points_per_segment));
  view.anchor_on_seabed = g.anchor_height_above_seabed_m == 0.0;
  if (!(!view.anchor_on_seabed || g.vertical_span_m > 0.0))
    fail(
        fmt::format("vertical_span_m: the fairlead must be above the seabed when the anchor "
                    "lies on it, got {} m",
                    g.vertical_span_m));
  const double chord_m = std::hypot(g.horizontal_span_m, g.vertical_span_m);
  if (chord_m >= view.total_length_m * (1.0 + o.max_strain)) {
    throw SolverError(
        fmt::format("catenary: line too short for its span: chord {:.3f} m, unstretched length {:.3f} m, "
                    "needs mean strain {:.2f} % (limit options.max_strain = {:.2f} %)",
                    chord_m, view.total_length_m, 100.0 * (chord_m / view.total_length_m - 1.0), 100.0 * o.max_strain));
  }
  return view;
}

std::string infeasibility_text(const CatenaryLine& line, Infeasibility why, int index) {
  switch (why) {
    case Infeasibility::buoyant_segment_on_seabed:
      return fmt::format(
          "segments[{}] is buoyant (weight {} N/m) but would have to lie on the seabed; a buoyant "
          "segment on the seabed cannot be represented by this catenary model (use a "
          "finite-element "
          "line, or lift the anchor off the seabed)",
          index, line.segments[index].weight_N_per_m);
    case Infeasibility::buoy_on_seabed:
      return fmt::format(
          "the buoy at joint_load_N[{}] ({} N) would have to lie on the seabed; a buoyant "
          "element on the seabed cannot be represented by this catenary model",
          index, line.joint_load_N[index]);
    case Infeasibility::no_suspended_part:
      return "no suspended part: the whole line would lie on the seabed";
    case Infeasibility::none:
      break;
  }
  return {};
}

// ---------------------------------------------------------------------------
// Newton on (H, V_F).

struct Iterate {
  double H = 0.0, V = 0.0;
  SpanEvaluation e;
  double rx = 0.0, rz = 0.0;
  double norm() const { return std::hypot(rx, rz); }
};

struct Attempt {
  bool converged = false;
  Iterate it;
  int iterations = 0;
  Infeasibility infeasible = Infeasibility::none;
  int infeasible_index = -1;
};

Iterate evaluate(const LineView& view, const CatenaryGeometry& g, double H, double V) {
  Iterate it;
  it.H = H;
  it.V = V;
  it.e = detail::evaluate_spans(view, H, V);
  it.rx = it.e.x_m - g.horizontal_span_m;
  it.rz = it.e.z_m - g.vertical_span_m;
  return it;
}

bool usable(const Iterate& it) {
  return it.e.infeasible == Infeasibility::none && std::isfinite(it.rx) && std::isfinite(it.rz);
}

bool closed(const Iterate& it, double tol) { return std::abs(it.rx) <= tol && std::abs(it.rz) <= tol; }

/// Newton on (H, V_F) with the analytic Jacobian and a backtracking (Armijo)
/// line search on the closure norm.
Attempt newton(const LineView& view, const CatenaryGeometry& g, double H0, double V0, double tol, int max_iterations) {
  constexpr double kCollapsedH = 1e-12;  // H below this fraction of the vertical forces
  constexpr double kMinFraction = 0.05;  // H may fall to 5 % of its value in one step
  constexpr double kArmijo = 1e-4;
  constexpr int kMaxHalvings = 40;
  Attempt a;
  a.it = evaluate(view, g, H0, V0);
  if (!usable(a.it)) {
    a.infeasible = a.it.e.infeasible;
    a.infeasible_index = a.it.e.infeasible_index;
    return a;
  }
  for (a.iterations = 0; a.iterations < max_iterations; ++a.iterations) {
    const Iterate& cur = a.it;
    if (closed(cur, tol)) {
      a.converged = true;
      return a;
    }
    // H collapsing towards 0: the answer is an H = 0 configuration (slack
    // vertical) or none; stop instead of spending the iteration budget.
    if (cur.H < kCollapsedH * (std::abs(cur.V) + std::abs(view.total_weight_N))) return a;
    // Newton step from the 2x2 Jacobian d(x, z)/d(H, V_F).
    const double j00 = cur.e.jacobian(0, 0), j01 = cur.e.jacobian(0, 1);
    const double j10 = cur.e.jacobian(1, 0), j11 = cur.e.jacobian(1, 1);
    const double det = j00 * j11 - j01 * j10;
    if (!std::isfinite(det) || det == 0.0) return a;
    const double dH = -(j11 * cur.rx - j01 * cur.rz) / det;
    const double dV = -(-j10 * cur.rx + j00 * cur.rz) / det;
    // Keep H > 0: along the Newton direction while H stays above a fraction of
    // its value (H and V scale together on a nearly straight line); beyond it,
    // clamp H alone so the V step is not lost (kinks such as a clump lifting off).
    const double r0 = cur.norm();
    double alpha = 1.0;
    bool accepted = false;
    for (int h = 0; h < kMaxHalvings; ++h, alpha *= 0.5) {
      const double H_trial = std::max(cur.H + alpha * dH, kMinFraction * cur.H);
      Iterate trial = evaluate(view, g, H_trial, cur.V + alpha * dV);
      if (!usable(trial)) {
        a.infeasible = trial.e.infeasible;
        a.infeasible_index = trial.e.infeasible_index;
        continue;
      }
      if (trial.norm() <= (1.0 - kArmijo * alpha) * r0 || closed(trial, tol)) {
        a.it = trial;
        accepted = true;
        break;
      }
    }
    if (!accepted) return a;
  }
  a.converged = closed(a.it, tol);
  return a;
}

// ---------------------------------------------------------------------------
// Fallback: eliminate V_F by a bracketed 1-D solve of the vertical closure,
// then a bracketed 1-D solve of the horizontal closure in ln H. Slower but
// globally convergent for the monotone spans of a catenary.

/// V_F closing z at fixed H; z is increasing in V_F. Infeasible points lie at low V_F.
bool solve_V_at_H(const LineView& view, const CatenaryGeometry& g, double H, double& V, double tol, Iterate& out,
                  int& evaluations, Attempt& record) {
  const double step0 = std::max({std::abs(view.total_weight_N), H, 1.0});
  auto f_at = [&](double v, Iterate& it) {
    ++evaluations;
    it = evaluate(view, g, H, v);
    if (it.e.infeasible != Infeasibility::none) {
      record.infeasible = it.e.infeasible;
      record.infeasible_index = it.e.infeasible_index;
    }
    return usable(it) ? it.rz : -std::numeric_limits<double>::infinity();
  };
  Iterate it;
  double f = f_at(V, it);
  double lo, hi;
  if (f > 0.0) {
    hi = V;
    lo = V;
    double step = step0;
    double flo = f;
    for (int k = 0; k < 200 && flo > 0.0; ++k, step *= 2.0) {
      lo = hi - step;
      flo = f_at(lo, it);
      if (flo > 0.0) hi = lo;
    }
    if (flo > 0.0) return false;
  } else {
    lo = V;
    hi = V;
    double step = step0;
    double fhi = f;
    for (int k = 0; k < 200 && fhi <= 0.0; ++k, step *= 2.0) {
      hi = lo + step;
      fhi = f_at(hi, it);
      if (fhi <= 0.0) lo = hi;
    }
    if (fhi <= 0.0) return false;
  }
  double v = 0.5 * (lo + hi);
  for (int k = 0; k < 300; ++k) {
    const double fv = f_at(v, it);
    if (std::isfinite(fv) && std::abs(fv) <= 0.1 * tol) break;
    (fv > 0.0 ? hi : lo) = v;
    double next = std::isfinite(fv) && it.e.jacobian(1, 1) > 0.0 ? v - fv / it.e.jacobian(1, 1) : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 4.0 * kEps * std::max(std::abs(lo), std::abs(hi))) break;
    v = next;
  }
  if (!usable(it)) return false;
  V = it.V;
  out = it;
  return true;
}

Attempt bracketing_fallback(const LineView& view, const CatenaryGeometry& g, double H0, double V0, double tol,
                            int max_iterations) {
  Attempt a;
  double V = V0;
  int evaluations = 0;
  // g(u) = x(e^u, V(e^u)) - XF, increasing in u.
  auto g_at = [&](double u, Iterate& it) {
    if (!solve_V_at_H(view, g, std::exp(u), V, tol, it, evaluations, a)) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    return it.rx;
  };
  Iterate it;
  double u = std::log(H0);
  double gu = g_at(u, it);
  if (!std::isfinite(gu)) {
    a.iterations = evaluations;
    return a;
  }
  double lo = u, hi = u, glo = gu, ghi = gu;
  double step = 1.0;
  const int expansions = std::min(12, max_iterations);
  for (int k = 0; k < expansions && glo > 0.0; ++k, step *= 2.0) {
    hi = lo;
    ghi = glo;
    lo -= step;
    glo = g_at(lo, it);
    if (!std::isfinite(glo)) break;
  }
  step = 1.0;
  for (int k = 0; k < expansions && ghi < 0.0; ++k, step *= 2.0) {
    lo = hi;
    glo = ghi;
    hi += step;
    ghi = g_at(hi, it);
    if (!std::isfinite(ghi)) break;
  }
  if (!(glo <= 0.0 && ghi >= 0.0)) {
    a.iterations = evaluations;
    return a;
  }
  // Illinois regula falsi on u.
  int side = 0;
  for (int k = 0; k < max_iterations; ++k) {
    double m = (lo * ghi - hi * glo) / (ghi - glo);
    if (!(m > lo && m < hi)) m = 0.5 * (lo + hi);
    const double gm = g_at(m, it);
    if (!std::isfinite(gm)) break;
    if (closed(it, tol) || hi - lo <= 4.0 * kEps * std::max(1.0, std::abs(m))) break;
    if (gm > 0.0) {
      hi = m;
      ghi = gm;
      if (side == 1) glo *= 0.5;
      side = 1;
    } else {
      lo = m;
      glo = gm;
      if (side == -1) ghi *= 0.5;
      side = -1;
    }
  }
  a.it = it;
  a.iterations = evaluations;
  a.converged = usable(it) && closed(it, tol);
  return a;
}

// ---------------------------------------------------------------------------
// Initial guesses.

struct Guess {
  double H, V;
};

/// MAP++/MoorPy initial guess (Peyrot & Goulois 1979, as in Jonkman 2007 eq. B-11):
/// lambda0 from (L^2 - ZF^2)/XF^2, H0 = |w XF/(2 lambda0)|, V0 = w/2 (ZF/tanh(lambda0) + L).
Guess map_guess(const LineView& view, const CatenaryGeometry& g) {
  const double L = view.total_length_m;
  const double XF = g.horizontal_span_m, ZF = g.vertical_span_m;
  double w = view.total_weight_N / L;
  if (std::abs(w) < 1e-12) w = 1e-12;
  double lambda0;
  if (L * L <= XF * XF + ZF * ZF) {
    lambda0 = 0.2;
  } else {
    lambda0 = std::sqrt(3.0 * ((L * L - ZF * ZF) / (XF * XF) - 1.0));
  }
  const double H = std::max(std::abs(w * XF / (2.0 * lambda0)), 1e-6 * std::abs(w) * L);
  const double V = 0.5 * w * (ZF / std::tanh(lambda0) + L);
  return {H, V};
}

/// Straight (taut) line guess: tension from the chord's strain over the
/// series axial stiffness, direction along the chord, half the weight at the fairlead.
Guess taut_guess(const LineView& view, const CatenaryGeometry& g) {
  const double XF = g.horizontal_span_m, ZF = g.vertical_span_m;
  const double chord = std::hypot(XF, ZF);
  double compliance = 0.0;  // m/N
  for (const CatenarySegment& s : view.line->segments) compliance += s.length_m / s.EA_N;
  const double stretch = std::max(chord - view.total_length_m, 1e-6 * view.total_length_m);
  const double T = stretch / compliance;
  return {std::max(T * XF / chord, 1e-6 * T), T * ZF / chord + 0.5 * view.total_weight_N};
}

// ---------------------------------------------------------------------------

CatenarySolution from_iterate(const Iterate& it, int iterations) {
  CatenarySolution s;
  const SpanEvaluation& e = it.e;
  s.fairlead_horizontal_N = it.H;
  s.fairlead_vertical_N = it.V;
  s.fairlead_tension_N = std::hypot(it.H, it.V);
  s.anchor_horizontal_N = e.anchor_horizontal_N;
  s.anchor_vertical_N = e.anchor_vertical_N;
  s.anchor_tension_N = std::hypot(e.anchor_horizontal_N, e.anchor_vertical_N);
  s.laid_length_m = e.laid_length_m;
  s.touchdown_x_m = e.touchdown_x_m;
  s.regime = e.contact ? CatenaryRegime::touchdown : CatenaryRegime::suspended;
  // d(H, V)/d(XF, ZF) = [d(XF, ZF)/d(H, V)]^-1 (inverse function theorem).
  s.tangent_stiffness = e.jacobian.inverse();
  s.iterations = iterations;
  s.residual_m = it.norm();
  return s;
}

/// What the attempts so far achieved: the final answer, or the error message.
struct Progress {
  int iterations = 0;
  bool converged = false;
  bool have_best = false;
  Iterate best;                                    // converged iterate, else the smallest closure residual seen
  Infeasibility infeasible = Infeasibility::none;  // only the model limits (buoyant on seabed)
  int infeasible_index = -1;

  void record(const Attempt& a) {
    iterations += a.iterations;
    if (a.infeasible == Infeasibility::buoyant_segment_on_seabed || a.infeasible == Infeasibility::buoy_on_seabed) {
      infeasible = a.infeasible;
      infeasible_index = a.infeasible_index;
    }
    if (converged || !usable(a.it)) return;
    if (a.converged || !have_best || a.it.norm() < best.norm()) {
      best = a.it;
      have_best = true;
      converged = a.converged;
    }
  }
};

}  // namespace

CatenarySolution solve_catenary(const CatenaryLine& line, const CatenaryGeometry& geometry,
                                const CatenaryOptions& options, const std::optional<CatenaryGuess>& warm_start) {
  const LineView view = check_inputs(line, geometry, options);
  // Closure tolerance: the requested one, but never below the round-off floor of
  // summing spans of the line's size (a few ulps of the largest length involved).
  const double scale_m = view.total_length_m + geometry.horizontal_span_m + std::abs(geometry.vertical_span_m);
  const double tol = std::max(options.tolerance_m, 64.0 * kEps * scale_m);

  Progress progress;
  // Warm start first: it is usually 1-3 Newton steps from the answer.
  if (warm_start && std::isfinite(warm_start->horizontal_N) && std::isfinite(warm_start->vertical_N) &&
      warm_start->horizontal_N > 0.0) {
    progress.record(
        newton(view, geometry, warm_start->horizontal_N, warm_start->vertical_N, tol, options.max_iterations));
  }
  CatenarySolution solution;
  if (!progress.converged && detail::solve_vertical(view, geometry, tol, solution)) {
    solution.iterations += progress.iterations;
    if (options.profile_points_per_segment > 0) {
      fill_catenary_profile(line, geometry, options.profile_points_per_segment, solution);
    }
    return solution;
  }
  if (!progress.converged) {
    // Cold start from the better (smaller residual) of two standard guesses.
    const Guess candidates[] = {map_guess(view, geometry), taut_guess(view, geometry)};
    double best = std::numeric_limits<double>::infinity();
    Guess start = candidates[0];
    for (const Guess& c : candidates) {
      const Iterate it = evaluate(view, geometry, c.H, c.V);
      if (usable(it) && it.norm() < best) {
        best = it.norm();
        start = c;
      }
    }
    progress.record(newton(view, geometry, start.H, start.V, tol, options.max_iterations));
    if (!progress.converged) {
      // Newton stalled: bracketing fallback, then Newton to polish its answer.
      const Attempt fb = bracketing_fallback(view, geometry, start.H, start.V, tol, options.max_iterations);
      progress.record(fb);
      if (usable(fb.it) && !progress.converged) {
        progress.record(newton(view, geometry, fb.it.H, fb.it.V, tol, options.max_iterations));
      }
    }
  }
  if (!progress.converged) {
    const double residual = progress.have_best ? progress.best.norm() : std::numeric_limits<double>::infinity();
    const SolverDiagnostics diagnostics{progress.iterations, residual, "m"};
    if (progress.infeasible != Infeasibility::none) {
      throw SolverError("catenary: " + infeasibility_text(line, progress.infeasible, progress.infeasible_index),
                        diagnostics);
    }
    throw SolverError(fmt::format("catenary: no convergence after {} iterations, span closure residual {:.3e} m "
                                  "(tolerance {:.1e} m); XF = {} m, ZF = {} m, unstretched length {} m; check "
                                  "the line data, raise options.max_iterations or give a warm start",
                                  progress.iterations, residual, tol, geometry.horizontal_span_m,
                                  geometry.vertical_span_m, view.total_length_m),
                      diagnostics);
  }
  solution = from_iterate(progress.best, progress.iterations);
  if (!solution.tangent_stiffness.allFinite()) solution.tangent_stiffness.setZero();
  if (options.profile_points_per_segment > 0) {
    fill_catenary_profile(line, geometry, options.profile_points_per_segment, solution);
  }
  return solution;
}

Eigen::Matrix2d catenary_incremental_tangent(const CatenaryLine& line, const CatenaryGeometry& geometry,
                                             const CatenarySolution& solution,
                                             const std::vector<double>& incremental_EA_N) {
  if (incremental_EA_N.size() != line.segments.size()) {
    throw std::invalid_argument(fmt::format("catenary_incremental_tangent: {} incremental EA for {} segments",
                                            incremental_EA_N.size(), line.segments.size()));
  }
  CatenaryLine incremental = line;
  for (std::size_t i = 0; i < incremental_EA_N.size(); ++i) {
    if (!(std::isfinite(incremental_EA_N[i]) && incremental_EA_N[i] > 0.0)) {
      throw std::invalid_argument(fmt::format(
          "catenary_incremental_tangent: incremental_EA_N[{}] must be > 0 N, got {}", i, incremental_EA_N[i]));
    }
    incremental.segments[i].EA_N = incremental_EA_N[i];
  }
  // The slack-vertical state has no (H, V) Jacobian to take (H = 0); its
  // tangent is the hanging part's, which the caller's static one already is.
  if (solution.regime == CatenaryRegime::slack_vertical || !(solution.fairlead_horizontal_N > 0.0))
    return solution.tangent_stiffness;
  const LineView view = check_inputs(incremental, geometry, CatenaryOptions{});
  const SpanEvaluation e = detail::evaluate_spans(view, solution.fairlead_horizontal_N, solution.fairlead_vertical_N);
  const Eigen::Matrix2d tangent = e.jacobian.inverse();
  return tangent.allFinite() ? tangent : solution.tangent_stiffness;
}

}  // namespace spiral::engine
