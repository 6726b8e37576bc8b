// FE static equilibrium of one line: the entry point (stages of the solve)
// and the post-processing of the converged state. Formulation and
// conventions: fe_line_statics.hpp; element: ancf_cable_element.hpp; problem
// and assembly: fe_line_problem; Newton and continuations: fe_line_newton.

#include "engine/lines/fe_line_statics.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "engine/lines/fe_line_newton.hpp"
#include "engine/lines/fe_line_problem.hpp"

namespace spiral::engine {
namespace {

using namespace fe_detail;

/// Static condensation of the assembled Jacobian onto end B's position DOFs,
/// K = J_bb − J_bf J_ff⁻¹ J_fb: d(end-B force)/d(end-B position) with every
/// free DOF re-equilibrated. Leaves `jac` factorised with the prescribed rows
/// as identity rows (a warm start's tangent); empty if J_ff is singular.
std::optional<Eigen::Matrix3d> condense_on_end_B(const Problem& p, BandMatrix& jac) {
  const int b0 = p.r_dof.back();
  Eigen::Matrix<double, 3, Eigen::Dynamic> rows_b(3, p.n_dofs);
  rows_b.setZero();
  Eigen::MatrixXd cols_b = Eigen::MatrixXd::Zero(p.n_dofs, 3);
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < p.n_dofs; ++j) {
      if (jac.in_band(b0 + k, j)) rows_b(k, j) = jac.at(b0 + k, j);
      if (jac.in_band(j, b0 + k) && !is_fixed(p, j)) cols_b(j, k) = jac.at(j, b0 + k);
    }
  }
  for (int i = 0; i < p.n_dofs; ++i) {
    if (is_fixed(p, i)) jac.set_identity_row(i);
  }
  const Eigen::Matrix3d k_bb = rows_b.middleCols<3>(b0);
  if (!jac.factorize(Pivoting::diagonal_while_definite)) return std::nullopt;
  jac.solve_columns_in_place(cols_b);
  return Eigen::Matrix3d(k_bb - rows_b * cols_b);
}

FeStaticsResult post_process(const Problem& p, const FeStaticsOptions& o, const Eigen::VectorXd& q, Tangent& t) {
  FeStaticsResult r;
  const int nn = p.n_nodes;
  r.state = q;
  r.node_arc_length_m = p.mesh.s;
  Eigen::VectorXd g(p.n_dofs);
  auto tangent = std::make_shared<FeLineTangent>();
  BandMatrix& jac = tangent->lu;
  if (!o.compute_end_B_stiffness && t.converged_q.size() == q.size() && t.converged_q == q) {
    g = t.converged_residual;  // the Newton solve's last assembly
  } else {
    assemble(p, q, g, o.compute_end_B_stiffness ? &jac : nullptr);
  }
  r.node_position_m.resize(static_cast<std::size_t>(nn));
  r.node_tension_N.resize(static_cast<std::size_t>(nn));
  r.node_force_residual_N.resize(static_cast<std::size_t>(nn));
  for (std::size_t i = 0; i < static_cast<std::size_t>(nn); ++i) {
    r.node_position_m[i] = q.segment<3>(p.r_dof[i]);
    r.node_force_residual_N[i] = g.segment<3>(p.r_dof[i]);
    // Mean of the two sides' EA (|r'| − 1) (equal up to the discretisation;
    // at a hinge joint each side has its own EA and slope).
    double sum = 0.0;
    int cnt = 0;
    if (i > 0) sum += p.elements[i - 1].EA_N * (q.segment<3>(p.t_in[i]).norm() - 1.0), ++cnt;
    if (i + 1 < static_cast<std::size_t>(nn))
      sum += p.elements[i].EA_N * (q.segment<3>(p.t_out[i]).norm() - 1.0), ++cnt;
    r.node_tension_N[i] = sum / cnt;
  }
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    const double L = p.elements[e].length_m;
    r.element_tension_N.push_back(p.elements[e].EA_N * (slope(ancf::shape_at(0.5, L), gather(p, q, e)).norm() - 1.0));
  }
  NodeBending bending = node_bending(p, q);
  r.node_curvature_per_m = std::move(bending.curvature_per_m);
  r.node_bending_moment_Nm = std::move(bending.moment_Nm);
  r.end_A_force_N = r.node_force_residual_N.front();
  r.end_B_force_N = r.node_force_residual_N.back();
  // End tensions: axial components of the end reactions (more accurate than
  // the strain of the free end slope, which converges more slowly).
  r.node_tension_N.front() = r.end_A_force_N.dot(q.segment<3>(p.t_out.front()).normalized());
  r.node_tension_N.back() = -r.end_B_force_N.dot(q.segment<3>(p.t_in.back()).normalized());
  r.touchdown = find_touchdown(p, q);

  if (o.compute_end_B_stiffness) {
    ++t.evaluations;
    if (auto k = condense_on_end_B(p, jac)) {
      r.end_B_stiffness_N_per_m = *k;
      r.has_end_B_stiffness = true;
      r.tangent = std::move(tangent);  // at the converged state
    }
  } else if (t.valid && t.borrowed) {
    r.tangent = t.borrowed;  // chord steps only: the warm start's, shared
  } else if (t.valid) {
    tangent->lu = std::move(t.lu);  // of an iterate near the converged state
    r.tangent = std::move(tangent);
  }
  return r;
}

/// The problem `solution` (a converged static solution of `model` in
/// `environment`) was solved on: its ends, mesh and node arc lengths.
Problem problem_of_solution(const FeLineModel& model, const FeEnvironment& environment,
                            const FeStaticsResult& solution) {
  if (solution.node_position_m.size() < 2) invalid("solution: not a static solution (no nodes)");
  const FeLineEnds ends{solution.node_position_m.front(), solution.node_position_m.back()};
  validate(model, environment, ends, FeStaticsOptions{});
  Problem p = make_problem(model, environment, ends);
  if (solution.state.size() != p.n_dofs)
    invalid(
        fmt::format("solution.state: needs {} entries (this model's mesh), got {}", p.n_dofs, solution.state.size()));
  set_node_arc_lengths(p, solution.node_arc_length_m);
  return p;
}

}  // namespace

std::vector<double> fe_line_mesh(const FeLineModel& model) {
  validate(model, FeEnvironment{}, FeLineEnds{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()}, {});
  return build_mesh(model).s;
}

FeStaticsResult solve_fe_line_statics(const FeLineModel& model, const FeEnvironment& environment,
                                      const FeLineEnds& ends, const FeStaticsOptions& options) {
  validate(model, environment, ends, options);
  Problem p = make_problem(model, environment, ends);
  Eigen::VectorXd q = initial_state(p, model, environment, ends, options);

  Counters counters;
  Tangent t;
  t.chord_steps = options.warm_start_state.has_value();
  if (options.warm_start_state && options.warm_start_tangent && options.warm_start_tangent->lu.size() == p.n_dofs) {
    t.borrowed = options.warm_start_tangent;
    t.valid = true;
  }
  NewtonOutcome last;
  const double k_target = environment.seabed_stiffness_N_per_m2;
  bool done = false;
  if (options.warm_start_state || (options.initial_shape && options.initial_shape_is_equilibrium)) {
    // No continuation from a warm state: they restart from zero current, and
    // the cold start below (swung into the current) is cheaper and surer.
    last = solve_with_current_steps(p, options, q, t, counters, {.continuations = false});
    if (last.converged) last = snap_touchdown(p, options, q, t, counters, kFinalSnapPasses, last);
    done = last.converged;
    if (!done) {
      t.valid = t.chord_steps = false;  // cold start
      p = make_problem(model, environment, ends);
      q = initial_state(p, model, environment, ends, FeStaticsOptions{});
    }
  }
  // The seabed continuation below starts at k_soft (penetration ≈ 1 % of an
  // element under the heaviest section's weight).
  double k_soft = k_target, h_min = INFINITY;
  if (k_target > 0.0) {
    double w_max = 0.0, h_max = 0.0;
    for (const auto& e : p.elements) {
      w_max = std::max(w_max, std::abs(e.weight_N_per_m));
      h_max = std::max(h_max, e.length_m);
      h_min = std::min(h_min, e.length_m);
    }
    k_soft = std::min(k_target, 100.0 * w_max / h_max);
  }
  // A cold start under current is swung into it once: in the direct attempt
  // when the seabed is at most one continuation stage (×10) stiffer than the
  // continuation's start, else in the continuation's soft first stage
  // (measured: an SCR on a 1e7 N/m² bed, 1600 × k_soft, crawls from the
  // swung start at full stiffness and converges at k_soft in 10 iterations).
  const bool swing_direct = k_target <= 10.0 * k_soft;
  if (!done && k_target > 0.0) {
    // Direct attempt at the final seabed stiffness from the default shape
    // (which already lies on the seabed where the catenary would): usually
    // converges; a bounded number of iterations and no current continuation
    // (against a stiff seabed it crawls where the seabed continuation below
    // converges), then the seabed continuation.
    const Eigen::VectorXd q0 = q;
    FeStaticsOptions direct = options;
    direct.max_iterations = std::min(options.max_iterations, kDirectAttemptIterations);
    Counters trial;
    last = solve_with_current_steps(p, direct, q, t, trial, {.swing_predictor = swing_direct, .continuations = false});
    if (last.converged) last = snap_touchdown(p, options, q, t, trial, kFinalSnapPasses, last);
    counters.iterations += trial.iterations;
    counters.load_steps += trial.load_steps;
    counters.remeshes += trial.remeshes;
    done = last.converged;
    if (!done) {
      t.valid = false;
      p = make_problem(model, environment, ends);
      q = q0;
    }
  }
  if (!done) {
    // Continuation on the seabed stiffness: start soft (k_soft), then ×10
    // per stage, intermediate stages to a loose tolerance. A stiff penalty
    // against a coarse cable mesh is a stiff, non-smooth system; each stage
    // starts inside the next one's convergence basin.
    double k = k_soft;
    FeStaticsOptions stage_options = options;
    stage_options.relative_force_tolerance = std::max(options.relative_force_tolerance, 1e-6);
    for (bool first_stage = true;; first_stage = false) {
      p.load.seabed_stiffness_N_per_m2 = k;
      const bool final_stage = k >= k_target;
      // The first stage repeats no attempt the direct one just made.
      const bool repeat = first_stage && final_stage && k_target > 0.0;
      last = solve_with_current_steps(p, final_stage ? options : stage_options, q, t, counters,
                                      {.swing_predictor = first_stage && !swing_direct, .direct = !repeat});
      if (!last.converged) break;
      if (final_stage) {
        last = snap_touchdown(p, options, q, t, counters, kFinalSnapPasses, last);
        break;
      }
      // One early move once the penalty layer fits inside an element, so the
      // final stage starts with the node near the touchdown point.
      const auto td = find_touchdown(p, q);
      if (td && touchdown_node_target(p, q, td->arc_length_m).tolerance_m < 0.01 * h_min) {
        last = snap_touchdown(p, stage_options, q, t, counters, 1, last);
        if (!last.converged) break;
      }
      k = std::min(k_target, 10.0 * k);
    }
  }
  if (!last.converged) {
    SolverDiagnostics d{counters.iterations, last.residual_N, "N"};
    // A line on the seabed from A that is longer than span + height has no
    // taut equilibrium on a frictionless seabed (it would have to fold).
    const Eigen::Vector3d AB = ends.end_B_m - ends.end_A_m;
    const double slack_length_m = std::hypot(AB.x(), AB.y()) + AB.z();
    const bool a_on_seabed = environment.seabed_stiffness_N_per_m2 > 0.0 &&
                             ends.end_A_m.z() <= environment.seabed_z_m + 1e-6 * p.line_length_m;
    const std::string slack = a_on_seabed && p.line_length_m >= slack_length_m
                                  ? fmt::format(
                                        " The line is slack: its length {:.2f} m is at least its horizontal span plus "
                                        "height, {:.2f} m, so it has no taut equilibrium on a frictionless seabed; "
                                        "shorten it or move the ends apart.",
                                        p.line_length_m, slack_length_m)
                                  : std::string();
    throw SolverError(
        fmt::format("FE line statics did not converge: {} Newton iterations, {} Newton solves (continuation "
                    "stages), force residual {:.4g} N against a tolerance of {:.4g} N.{} Try: check that the "
                    "end positions are reachable (line length vs. span, no slack or compressed line), "
                    "refine the mesh, give a better initial shape (catenary) or more iterations.",
                    counters.iterations, counters.load_steps, last.residual_N,
                    options.relative_force_tolerance * last.scale_N, slack),
        d);
  }
  FeStaticsResult r = post_process(p, options, q, t);
  r.iterations = counters.iterations;
  r.load_steps = counters.load_steps;
  r.touchdown_remeshes = counters.remeshes;
  r.jacobian_evaluations = t.evaluations;
  r.residual_N = last.residual_N;
  r.force_scale_N = last.scale_N;
  return r;
}

FeStaticsResult with_end_B_stiffness(const FeLineModel& model, const FeEnvironment& environment,
                                     FeStaticsResult solution) {
  if (solution.has_end_B_stiffness) return solution;
  Problem p = problem_of_solution(model, environment, solution);
  auto tangent = std::make_shared<FeLineTangent>();
  Eigen::VectorXd g(p.n_dofs);
  assemble(p, solution.state, g, &tangent->lu);
  const std::optional<Eigen::Matrix3d> k = condense_on_end_B(p, tangent->lu);
  if (!k) throw SolverError("FE line statics: the tangent at the solution is singular (a section without stiffness?)");
  ++solution.jacobian_evaluations;
  solution.end_B_stiffness_N_per_m = *k;
  solution.has_end_B_stiffness = true;
  solution.tangent = std::move(tangent);
  return solution;
}

Eigen::Matrix3d fe_line_incremental_end_B_stiffness(const FeLineModel& model, const FeEnvironment& environment,
                                                    const FeStaticsResult& solution,
                                                    const std::vector<double>& incremental_EA_N) {
  if (incremental_EA_N.size() != model.sections.size()) {
    invalid(fmt::format("incremental_EA_N: needs one value per section ({}), got {}", model.sections.size(),
                        incremental_EA_N.size()));
  }
  for (std::size_t i = 0; i < incremental_EA_N.size(); ++i) {
    if (!(std::isfinite(incremental_EA_N[i]) && incremental_EA_N[i] > 0.0))
      invalid(fmt::format("incremental_EA_N[{}]: must be > 0 N, got {}", i, incremental_EA_N[i]));
  }
  Problem p = problem_of_solution(model, environment, solution);
  Eigen::VectorXd g(p.n_dofs);
  BandMatrix jac;
  assemble(p, solution.state, g, &jac);
  // The axial force N(ε) enters the element as −∫ S_k' N t ds; its tangent's
  // material part is dN/dε t tᵀ (ancf::strain_energy_hessian: EA t tᵀ plus
  // the geometric N/|r'| (I − t tᵀ)). With N = N_s + EA_inc (ε − ε_s) the
  // geometric part is unchanged at the state itself and the material part
  // gains (EA_inc − EA) t tᵀ at every Gauss point.
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    const double delta_EA = incremental_EA_N[static_cast<std::size_t>(p.mesh.section[e])] - p.elements[e].EA_N;
    if (delta_EA == 0.0) continue;
    const auto blocks = element_blocks(p, e);
    const ElementState qe = gather(p, solution.state, e);
    const double L = p.elements[e].length_m;
    for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp) {
      const ancf::ShapeAt sh = ancf::shape_at(ancf::kGaussXi[gp], L);
      const Eigen::Vector3d t = slope(sh, qe).normalized();
      const Eigen::Matrix3d k_point = (ancf::kGaussW[gp] * L * delta_EA) * (t * t.transpose());
      for (int k = 0; k < 4; ++k) {
        for (int j = 0; j < 4; ++j) {
          const double c = sh.dS[static_cast<std::size_t>(k)] * sh.dS[static_cast<std::size_t>(j)];
          for (int x = 0; x < 3; ++x)
            for (int y = 0; y < 3; ++y)
              jac.at(blocks[static_cast<std::size_t>(k)] + x, blocks[static_cast<std::size_t>(j)] + y) -=
                  c * k_point(x, y);
        }
      }
    }
  }
  const std::optional<Eigen::Matrix3d> k = condense_on_end_B(p, jac);
  if (!k) throw SolverError("FE line statics: the incremental tangent is singular (a section without stiffness?)");
  return *k;
}

}  // namespace spiral::engine
