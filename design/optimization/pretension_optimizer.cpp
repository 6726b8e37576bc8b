#include "design/optimization/pretension_optimizer.hpp"

#include <fmt/format.h>
#include <nlopt.hpp>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>

#include "design/model/mooring_model.hpp"
#include "design/optimization/pretension_problem.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

// A constraint within this of its limit (or a variable within this fraction
// of its bound range) at the optimum is active for the multipliers.
constexpr double kActive = 1e-4;

nlopt::algorithm nlopt_algorithm(OptimizationAlgorithm a) {
  switch (a) {
    case OptimizationAlgorithm::slsqp:
      return nlopt::LD_SLSQP;
    case OptimizationAlgorithm::ccsaq:
      return nlopt::LD_CCSAQ;
    case OptimizationAlgorithm::cobyla:
      return nlopt::LN_COBYLA;
  }
  return nlopt::LD_SLSQP;
}

const char* describe(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS:
      return "success";
    case nlopt::STOPVAL_REACHED:
      return "stop value reached";
    case nlopt::FTOL_REACHED:
      return "objective change below tolerance";
    case nlopt::XTOL_REACHED:
      return "payout change below tolerance";
    case nlopt::MAXEVAL_REACHED:
      return "evaluation cap reached";
    case nlopt::MAXTIME_REACHED:
      return "time cap reached";
    default:
      return "stopped";
  }
}

double worst_of(const std::vector<Measure>& constraints, const ConstraintValue** which) {
  double worst = -std::numeric_limits<double>::infinity();
  for (const Measure& c : constraints) {
    if (c.value.value > worst) {
      worst = c.value.value;
      if (which) *which = &c.value;
    }
  }
  return worst;
}

/// The NLopt callbacks over one problem: x = payouts / scale (and the slack s
/// for a minimax objective). Physics is evaluated once per point and cached.
class Run {
 public:
  /// `clock`: the run's (history times); `first_evaluation`: the number of the first evaluation.
  /// `progress`: the request's hook, called after each evaluation (may be empty).
  Run(PretensionProblem& problem, bool gradients, const engine::Stopwatch& clock, int first_evaluation,
      const std::function<void(double)>& progress)
      : progress_(progress),
        clock_(clock),
        first_evaluation_(first_evaluation),
        problem_(problem),
        gradients_(gradients),
        minimax_(problem.settings().objective != OptimizationObjective::min_total_payout) {
    const auto n = static_cast<Eigen::Index>(problem.groups().size());
    scale_.resize(n);
    for (Eigen::Index g = 0; g < n; ++g) {
      const GroupVariable& v = problem.groups()[static_cast<std::size_t>(g)];
      scale_(g) = std::max({std::abs(v.min_m), std::abs(v.max_m), 1e-6});
    }
  }

  bool minimax() const { return minimax_; }
  Eigen::Index groups() const { return scale_.size(); }
  const Eigen::VectorXd& scale() const { return scale_; }
  double slack_scale = 1.0;

  Eigen::VectorXd payouts_of(const double* x) const {
    return Eigen::Map<const Eigen::VectorXd>(x, groups()).cwiseProduct(scale_);
  }

  /// The evaluation at x (cached), recording the history and the best points.
  const ProblemEvaluation& at(const double* x, bool need_gradient) {
    const Eigen::VectorXd payouts = payouts_of(x);
    if (cached_ && payouts == cached_payouts_ && (!need_gradient || cached_has_gradient_)) return cache_;
    cache_ = problem_.evaluate(payouts, need_gradient);
    cached_ = true;
    cached_payouts_ = payouts;
    cached_has_gradient_ = need_gradient;
    record(payouts);
    if (progress_) {
      const int evaluations = first_evaluation_ + static_cast<int>(history.size()) - 1;
      progress_(std::min(1.0, evaluations / static_cast<double>(problem_.settings().max_evaluations)));
    }
    return cache_;
  }

  double objective(unsigned n, const double* x, double* grad) {
    if (failed()) return 0.0;
    try {
      if (minimax_) {
        if (grad) {
          std::fill(grad, grad + n, 0.0);
          grad[n - 1] = 1.0;
        }
        return x[n - 1];
      }
      const Eigen::VectorXd p = payouts_of(x);
      const double eps = 0.1 * problem_.settings().payout_tolerance_m;
      if (grad) {
        for (Eigen::Index g = 0; g < groups(); ++g) grad[g] = p(g) / std::sqrt(p(g) * p(g) + eps * eps) * scale_(g);
      }
      return ((p.array().square() + eps * eps).sqrt() - eps).sum();
    } catch (...) {
      fail();
      return 0.0;
    }
  }

  void constraints(unsigned m, double* result, unsigned n, const double* x, double* grad) {
    if (failed()) {
      std::fill(result, result + m, 0.0);
      return;
    }
    try {
      const ProblemEvaluation& e = at(x, grad != nullptr && gradients_);
      std::size_t row = 0;
      const auto put = [&](const Measure& c, double value, double factor, double slack_derivative) {
        result[row] = value;
        if (grad) {
          for (Eigen::Index g = 0; g < groups(); ++g)
            grad[row * n + static_cast<std::size_t>(g)] = factor * c.gradient(g) * scale_(g);
          if (minimax_) grad[row * n + n - 1] = slack_derivative;
        }
        ++row;
      };
      for (const Measure& c : e.constraints) put(c, c.value.value + kDesignMargin, 1.0, 0.0);
      if (minimax_) {
        // (measure − s) / s_scale ≤ 0, s = x_s s_scale.
        const double s = x[n - 1] * slack_scale;
        for (const Measure& c : e.objective_measures)
          put(c, (c.value.value - s) / slack_scale, 1.0 / slack_scale, -1.0);
      }
    } catch (...) {
      fail();
      std::fill(result, result + m, 0.0);
    }
  }

  void set_optimizer(nlopt::opt* opt) { opt_ = opt; }
  void rethrow_failure() const {
    if (error_) std::rethrow_exception(error_);
  }

  std::vector<OptimizationHistoryRow> history;
  std::optional<Eigen::VectorXd> best_feasible;
  double best_objective = std::numeric_limits<double>::infinity();
  Eigen::VectorXd least_infeasible;
  double least_violation = std::numeric_limits<double>::infinity();

 private:
  const std::function<void(double)>& progress_;
  const engine::Stopwatch& clock_;
  int first_evaluation_;
  PretensionProblem& problem_;
  bool gradients_;
  bool minimax_;
  Eigen::VectorXd scale_;
  nlopt::opt* opt_ = nullptr;
  std::exception_ptr error_;
  bool cached_ = false;
  bool cached_has_gradient_ = false;
  Eigen::VectorXd cached_payouts_;
  ProblemEvaluation cache_;

  bool failed() const { return error_ != nullptr; }
  void fail() {
    error_ = std::current_exception();
    if (opt_) opt_->force_stop();
  }

  void record(const Eigen::VectorXd& payouts) {
    OptimizationHistoryRow row;
    row.evaluation = first_evaluation_ + static_cast<int>(history.size());
    row.objective = problem_.objective_of(cache_, payouts);
    const ConstraintValue* worst = nullptr;
    row.worst_constraint = worst_of(cache_.constraints, &worst);
    if (worst) row.worst_constraint_name = worst->describe();
    row.feasible = row.worst_constraint <= kConstraintTolerance;
    row.wall_s = clock_.seconds();
    row.payouts_m.assign(payouts.data(), payouts.data() + payouts.size());
    if (row.feasible && row.objective < best_objective) {
      best_objective = row.objective;
      best_feasible = payouts;
    }
    if (row.worst_constraint < least_violation) {
      least_violation = row.worst_constraint;
      least_infeasible = payouts;
    }
    history.push_back(std::move(row));
  }
};

double objective_callback(unsigned n, const double* x, double* grad, void* data) {
  return static_cast<Run*>(data)->objective(n, x, grad);
}

void constraint_callback(unsigned m, double* result, unsigned n, const double* x, double* grad, void* data) {
  static_cast<Run*>(data)->constraints(m, result, n, x, grad);
}

/// Pretensions at rest (hull at its reference position, still water, intact)
/// before and after, from each line's catenary.
std::vector<LinePayout> line_payouts(const ValidatedProject& validated, const std::vector<GroupVariable>& groups,
                                     const Eigen::VectorXd& payouts) {
  const Project& project = validated.project;
  const std::vector<LineTypeProperties>& types = validated.line_types;
  std::vector<LinePayout> out;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (const std::string& name : groups[g].lines) {
      const MooringLine& line = mooring_line(project, name);
      LinePayout row;
      row.name = name;
      row.group = groups[g].name;
      row.payout_m = payouts(static_cast<Eigen::Index>(g));
      row.length_before_m = total_length_m(line);
      row.length_after_m = row.length_before_m + row.payout_m;
      row.top_segment_before_m = line.segments.back().length_m;
      row.top_segment_after_m = row.top_segment_before_m + row.payout_m;
      row.top_segment_mbl_N = find_type(types, line.segments.back().type).breaking_load_N;
      row.pretension_before_N = pretension_at_rest_N(project, line, types);
      row.pretension_after_N = pretension_at_rest_N(project, line, types, row.payout_m);
      out.push_back(std::move(row));
    }
  }
  return out;
}

/// Multipliers of the active constraints and bounds at the optimum, from
/// ∇f + Σ λ_i ∇g_i = 0 in least squares (payout space, and the slack).
std::vector<ActiveConstraint> multipliers(const PretensionProblem& problem, const ProblemEvaluation& e,
                                          const Eigen::VectorXd& payouts, bool minimax, double objective) {
  const auto n = static_cast<Eigen::Index>(payouts.size());
  const Eigen::Index dim = n + (minimax ? 1 : 0);
  Eigen::VectorXd grad_f = Eigen::VectorXd::Zero(dim);
  if (minimax) {
    grad_f(n) = 1.0;
  } else {
    const double eps = 0.1 * problem.settings().payout_tolerance_m;
    grad_f.head(n) = payouts.array() / (payouts.array().square() + eps * eps).sqrt();
  }
  std::vector<ActiveConstraint> active;
  std::vector<Eigen::VectorXd> columns;
  for (const Measure& c : e.constraints) {
    if (c.value.value < -kActive || c.gradient.size() != n) continue;
    Eigen::VectorXd col = Eigen::VectorXd::Zero(dim);
    col.head(n) = c.gradient;
    columns.push_back(col);
    active.push_back({c.value.describe(), c.value.value, 0.0});
  }
  if (minimax) {
    for (const Measure& c : e.objective_measures) {
      if (c.value.value < objective - kActive * std::max(1.0, std::abs(objective)) || c.gradient.size() != n) continue;
      Eigen::VectorXd col = Eigen::VectorXd::Zero(dim);
      col.head(n) = c.gradient;
      col(n) = -1.0;
      columns.push_back(col);
      active.push_back({"objective measure: " + c.value.describe(), c.value.value - objective, 0.0});
    }
  }
  for (Eigen::Index g = 0; g < n; ++g) {
    const GroupVariable& v = problem.groups()[static_cast<std::size_t>(g)];
    const double range = v.max_m - v.min_m;
    for (const int side : {-1, 1}) {
      const double bound = side < 0 ? v.min_m : v.max_m;
      if (std::abs(payouts(g) - bound) > kActive * range) continue;
      Eigen::VectorXd col = Eigen::VectorXd::Zero(dim);
      col(g) = side;  // g = side (ΔL − bound) ≤ 0
      columns.push_back(col);
      active.push_back({fmt::format("bound: {} payout {} {:.3f} m", v.name, side < 0 ? ">=" : "<=", bound), 0.0, 0.0});
    }
  }
  if (columns.empty()) return active;
  Eigen::MatrixXd a(dim, static_cast<Eigen::Index>(columns.size()));
  for (std::size_t k = 0; k < columns.size(); ++k) a.col(static_cast<Eigen::Index>(k)) = columns[k];
  const Eigen::VectorXd lambda = a.colPivHouseholderQr().solve(-grad_f);
  for (std::size_t k = 0; k < active.size(); ++k) active[k].multiplier = lambda(static_cast<Eigen::Index>(k));
  return active;
}

/// One NLopt run from `start_payouts` on the problem as it stands (with its
/// risers full or linearized).
struct Pass {
  std::vector<OptimizationHistoryRow> history;
  std::optional<Eigen::VectorXd> best_feasible;
  Eigen::VectorXd least_infeasible;
  std::string stop_reason;
};

Pass run_pass(PretensionProblem& problem, bool gradients, const Eigen::VectorXd& start_payouts,
              const engine::Stopwatch& clock, int first_evaluation, const std::function<void(double)>& progress) {
  Run run(problem, gradients, clock, first_evaluation, progress);
  const auto n_groups = static_cast<unsigned>(run.groups());
  const unsigned n = n_groups + (run.minimax() ? 1u : 0u);
  std::vector<double> x(n, 0.0);
  for (unsigned g = 0; g < n_groups; ++g) x[g] = start_payouts(g) / run.scale()(g);
  const ProblemEvaluation& at_start = run.at(x.data(), gradients);
  const std::size_t constraint_count =
      at_start.constraints.size() + (run.minimax() ? at_start.objective_measures.size() : 0);
  if (run.minimax()) {
    const double s0 = problem.objective_of(at_start, start_payouts);
    run.slack_scale = std::max(std::abs(s0), 1e-3);
    x[n - 1] = s0 / run.slack_scale;
  }

  nlopt::opt opt(nlopt_algorithm(problem.settings().algorithm), n);
  std::vector<double> lower(n), upper(n), xtol(n);
  for (unsigned g = 0; g < n_groups; ++g) {
    const GroupVariable& v = problem.groups()[g];
    lower[g] = v.min_m / run.scale()(g);
    upper[g] = v.max_m / run.scale()(g);
    xtol[g] = 1e-3 * problem.settings().payout_tolerance_m / run.scale()(g);
  }
  if (run.minimax()) {
    lower[n - 1] = -1e3;
    upper[n - 1] = 1e3;
    xtol[n - 1] = 1e-8;
  }
  opt.set_lower_bounds(lower);
  opt.set_upper_bounds(upper);
  opt.set_xtol_abs(xtol);
  opt.set_ftol_rel(1e-8);
  opt.set_maxeval(problem.settings().max_evaluations);
  opt.set_min_objective(objective_callback, &run);
  opt.add_inequality_mconstraint(constraint_callback, &run,
                                 std::vector<double>(constraint_count, kConstraintTolerance));
  run.set_optimizer(&opt);

  Pass pass;
  double f = 0.0;
  try {
    pass.stop_reason = describe(opt.optimize(x, f));
  } catch (const nlopt::forced_stop&) {
    run.rethrow_failure();  // an evaluation failed: its error, scenario named
    pass.stop_reason = "forced stop";
  } catch (const nlopt::roundoff_limited&) {
    pass.stop_reason = "round-off limited";
  } catch (const std::runtime_error& error) {
    run.rethrow_failure();
    pass.stop_reason = fmt::format("NLopt: {}", error.what());
  }
  run.rethrow_failure();
  pass.history = std::move(run.history);
  pass.best_feasible = run.best_feasible;
  pass.least_infeasible = run.least_infeasible;
  return pass;
}

}  // namespace

std::string ConstraintValue::describe() const {
  std::string what = kind;
  if (kind == "utilization") what = fmt::format("utilization of {}", subject);
  if (kind == "soz") what = subject.empty() ? "offset / SOZ" : fmt::format("offset / SOZ (riser {})", subject);
  if (kind == "offset_limit") what = "offset / offset limit";
  if (kind == "min_laid_length") what = fmt::format("laid length of {} below the minimum", subject);
  if (kind == "min_tension") what = fmt::format("tension of {} below the minimum", subject);
  return fmt::format("{}: {}", scenario, what);
}

const char* to_string(OptimizationStatus status) {
  return status == OptimizationStatus::infeasible ? "infeasible" : "optimal";
}

OptimizationResult optimize_pretension(const ValidatedProject& validated, const OptimizationRequest& request) {
  engine::Stopwatch start;
  PretensionProblem problem(validated, request);
  OptimizationResult result;
  result.project = validated.project.name;
  result.objective = problem.settings().objective;
  result.algorithm = problem.settings().algorithm;
  result.dynamic = problem.dynamic();
  result.groups = problem.groups();
  for (const Scenario& s : problem.scenarios()) result.scenarios.push_back(s.label());
  result.findings = problem.findings();
  result.notes = problem.notes();
  result.zone_conservatism_m = problem.zone_conservatism_m();
  result.zone_wall_s = problem.zone_wall_s();
  result.zones = problem.zone_outlines();
  result.objective_unit = problem.objective_unit();
  const bool gradients = result.algorithm != OptimizationAlgorithm::cobyla;

  // The starting design, the project as written, with the full models.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(problem.groups().size()));
  const ProblemEvaluation start_eval = problem.evaluate(zero, false);
  for (std::size_t s = 0; s < start_eval.responses.size(); ++s)
    result.before.push_back(problem.summarize(s, start_eval));
  result.objective_start = problem.objective_of(start_eval, zero);

  // Passes. Without risers: one NLopt run on the full models. With risers
  // (FE lines, milliseconds a solve, the mooring's catenaries microseconds):
  // each pass linearizes the risers about where the full model last left
  // them and optimizes on that; its best point is then solved with the full
  // risers. The pass is accepted when that holds every constraint; else the
  // next pass linearizes there and optimizes again (successive linearization:
  // the riser force error is second order in the hull's move between passes).
  // The dynamic level's constraints come from storms, not from the risers' statics.
  const bool linearize = problem.has_expensive_lines() && !problem.dynamic();
  constexpr int kMaxPasses = 4;
  Eigen::VectorXd from = zero;
  Eigen::VectorXd best = zero;
  bool feasible = false;
  std::optional<std::pair<Eigen::VectorXd, double>> kept;  // best point feasible with the full risers, its objective
  // The last pass's full evaluation, with the sensitivities: the final check
  // when its point is the one kept.
  std::optional<std::pair<Eigen::VectorXd, ProblemEvaluation>> last_full;
  for (int pass_number = 1; pass_number <= (linearize ? kMaxPasses : 1); ++pass_number) {
    if (linearize) problem.linearize_expensive_lines();
    Pass pass =
        run_pass(problem, gradients, from, start, static_cast<int>(result.history.size()) + 1, request.progress);
    if (linearize) problem.restore_expensive_lines();
    result.stop_reason = pass.stop_reason;
    const int evaluations = static_cast<int>(pass.history.size());
    for (OptimizationHistoryRow& row : pass.history) result.history.push_back(std::move(row));
    feasible = pass.best_feasible.has_value();
    best = feasible ? *pass.best_feasible : pass.least_infeasible;
    if (!linearize || !feasible) break;
    // Converged when the linearization point no longer moves by the payout tolerance.
    const bool last_pass =
        pass_number == kMaxPasses || (best - from).lpNorm<Eigen::Infinity>() <= problem.settings().payout_tolerance_m;
    const ProblemEvaluation full = problem.evaluate(best, last_pass);
    const ConstraintValue* worst_full = nullptr;
    const double violation = worst_of(full.constraints, &worst_full);
    const double objective = problem.objective_of(full, best);
    result.notes.push_back(fmt::format(
        "pass {}: risers linearized, {} evaluations; its best point with the full risers: objective {:.6g}, worst "
        "constraint {:.3e}{}",
        pass_number, evaluations, objective, violation, worst_full ? " (" + worst_full->describe() + ")" : ""));
    if (violation <= kConstraintTolerance && (!kept || objective < kept->second)) kept = {{best, objective}};
    if (last_pass) {
      last_full = {{best, full}};
      break;
    }
    from = best;  // the full models were last solved here: the next linearization is about this point
  }
  if (linearize && kept) {
    best = kept->first;
    feasible = true;
  } else if (linearize) {
    feasible = false;  // no pass's point held with the full risers
  }
  result.evaluations = static_cast<int>(result.history.size());
  result.payouts_m.assign(best.data(), best.data() + best.size());

  // Verify the kept point with the full models (risers restored: a new
  // equilibrium of every scenario), and take the sensitivities there — the
  // last pass's full evaluation when it was at that point.
  const ProblemEvaluation check =
      last_full && last_full->first == best ? std::move(last_full->second) : problem.evaluate(best, true);
  for (std::size_t s = 0; s < check.responses.size(); ++s) result.after.push_back(problem.summarize(s, check));
  result.objective_best = problem.objective_of(check, best);
  const ConstraintValue* worst = nullptr;
  const double violation = worst_of(check.constraints, &worst);
  result.status =
      feasible && violation <= kConstraintTolerance ? OptimizationStatus::optimal : OptimizationStatus::infeasible;
  if (result.status == OptimizationStatus::infeasible && worst) result.most_violated = *worst;
  if (!result.findings.empty()) result.status = OptimizationStatus::infeasible;
  const bool minimax = result.objective != OptimizationObjective::min_total_payout;
  result.active = multipliers(problem, check, best, minimax, result.objective_best);
  // The objective's gradient per group: of the largest measure (minimax) or
  // of the smoothed total payout.
  result.objective_gradient.assign(best.size(), 0.0);
  if (minimax) {
    const Measure* top = nullptr;
    for (const Measure& m : check.objective_measures)
      if (!top || m.value.value > top->value.value) top = &m;
    if (top && top->gradient.size() == best.size())
      result.objective_gradient.assign(top->gradient.data(), top->gradient.data() + top->gradient.size());
  } else {
    const double eps = 0.1 * problem.settings().payout_tolerance_m;
    for (Eigen::Index g = 0; g < best.size(); ++g)
      result.objective_gradient[static_cast<std::size_t>(g)] = best(g) / std::sqrt(best(g) * best(g) + eps * eps);
  }
  result.lines = line_payouts(validated, problem.groups(), best);
  result.wall_s = start.seconds();
  return result;
}

}  // namespace spiral::design
