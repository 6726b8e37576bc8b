#include "design/optimization/pretension_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "design/model/mooring_model.hpp"
#include "design/optimization/pretension_problem.hpp"
#include "design/project/request_error.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

/// Mean pretension at rest of `lines` paid out by `payout_m` (hull fixed, still water).
double mean_pretension_N(const ValidatedProject& validated, const std::vector<std::string>& lines, double payout_m) {
  const Project& project = validated.project;
  double sum = 0.0;
  for (const std::string& name : lines) {
    const MooringLine& line = mooring_line(project, name);
    sum += pretension_at_rest_N(project, line, validated.line_types, payout_m);
  }
  return lines.empty() ? 0.0 : sum / static_cast<double>(lines.size());
}

PretensionStudyPoint point_of(PretensionProblem& problem, const Eigen::VectorXd& payouts) {
  const ProblemEvaluation e = problem.evaluate(payouts, false);
  PretensionStudyPoint p;
  for (std::size_t s = 0; s < e.responses.size(); ++s) {
    const ScenarioSummary summary = problem.summarize(s, e);
    const bool damaged = summary.damaged_line.has_value();
    p.max_offset_m = std::max(p.max_offset_m, summary.offset_m);
    double& utilization = damaged ? p.max_utilization_damaged : p.max_utilization_intact;
    utilization = std::max(utilization, summary.worst_utilization);
    if (summary.soz_ratio) {
      std::optional<double>& ratio = damaged ? p.max_soz_ratio_damaged : p.max_soz_ratio_intact;
      ratio = std::max(ratio.value_or(0.0), *summary.soz_ratio);
    }
  }
  p.worst_constraint = -std::numeric_limits<double>::infinity();
  for (const Measure& c : e.constraints) {
    if (c.value.value > p.worst_constraint) {
      p.worst_constraint = c.value.value;
      p.worst_constraint_name = c.value.describe();
    }
  }
  p.feasible = p.worst_constraint <= kConstraintTolerance;
  return p;
}

}  // namespace

PretensionStudyResult run_pretension_study(const ValidatedProject& validated, const PretensionStudyRequest& request) {
  engine::Stopwatch start;
  if (request.points < 2) {
    throw request_error(validated.project, "points",
                        fmt::format("a sweep needs at least 2 points, got {}", request.points), "points_at_least_two");
  }
  PretensionProblem problem(validated, request.problem);
  const std::vector<GroupVariable>& groups = problem.groups();
  for (const std::string& name : request.groups) {
    if (std::none_of(groups.begin(), groups.end(), [&](const GroupVariable& g) { return g.name == name; })) {
      std::vector<std::string> names;
      for (const GroupVariable& g : groups) names.push_back(g.name);
      throw request_error(validated.project, "groups",
                          fmt::format("no optimization group \"{}\" (groups: {})", name, fmt::join(names, ", ")),
                          "group_defined");
    }
  }
  PretensionStudyResult result;
  result.project = validated.project.name;
  for (const Scenario& s : problem.scenarios()) result.scenarios.push_back(s.label());
  result.notes = problem.notes();
  for (const std::string& f : problem.findings()) result.notes.push_back("finding: " + f);

  const auto n = static_cast<Eigen::Index>(groups.size());
  // Sweeps: one per named group, or every group together over the
  // intersection of their bounds.
  struct Sweep {
    std::string name;
    Eigen::VectorXd direction;
    double from_m, to_m;
    std::vector<std::string> lines;
  };
  std::vector<Sweep> sweeps;
  if (request.groups.empty()) {
    Sweep all{"all",
              Eigen::VectorXd::Ones(n),
              -std::numeric_limits<double>::infinity(),
              std::numeric_limits<double>::infinity(),
              {}};
    for (const GroupVariable& g : groups) {
      all.from_m = std::max(all.from_m, g.min_m);
      all.to_m = std::min(all.to_m, g.max_m);
      all.lines.insert(all.lines.end(), g.lines.begin(), g.lines.end());
    }
    sweeps.push_back(std::move(all));
  } else {
    for (const std::string& name : request.groups) {
      const auto it =
          std::find_if(groups.begin(), groups.end(), [&](const GroupVariable& g) { return g.name == name; });
      Eigen::VectorXd direction = Eigen::VectorXd::Zero(n);
      direction(it - groups.begin()) = 1.0;
      sweeps.push_back({name, direction, it->min_m, it->max_m, it->lines});
    }
  }
  for (const Sweep& sweep : sweeps) {
    PretensionSweep out{sweep.name, sweep.lines, {}, std::nullopt};
    for (int k = 0; k < request.points; ++k) {
      const double payout = sweep.from_m + (sweep.to_m - sweep.from_m) * k / (request.points - 1);
      PretensionStudyPoint point = point_of(problem, payout * sweep.direction);
      point.payout_m = payout;
      point.pretension_N = mean_pretension_N(validated, sweep.lines, payout);
      ++result.evaluations;
      if (point.feasible) {
        if (!out.feasible_m) out.feasible_m = {payout, payout};
        out.feasible_m->second = payout;
      }
      out.points.push_back(std::move(point));
    }
    if (out.feasible_m) {
      for (const PretensionStudyPoint& p : out.points) {
        if (!p.feasible && p.payout_m > out.feasible_m->first && p.payout_m < out.feasible_m->second) {
          result.notes.push_back(fmt::format("sweep {}: infeasible at {:.3f} m inside the feasible band ({})",
                                             sweep.name, p.payout_m, p.worst_constraint_name));
        }
      }
    }
    result.sweeps.push_back(std::move(out));
  }
  if (request.with_optimum) {
    const OptimizationResult optimum = optimize_pretension(validated, request.problem);
    result.optimum_payouts_m = optimum.payouts_m;
    result.optimum_status = to_string(optimum.status);
    result.evaluations += optimum.evaluations;
  }
  result.wall_s = start.seconds();
  return result;
}

}  // namespace spiral::design
