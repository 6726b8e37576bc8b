#include "report/terminal/optimization_tables.hpp"

#include <fmt/format.h>

#include <optional>

namespace spiral::report {

namespace {

std::string cell(const std::optional<double>& v) { return v ? fmt::format("{:.4f}", *v) : ""; }

std::string scenario_rows(const std::vector<design::ScenarioSummary>& before,
                          const std::vector<design::ScenarioSummary>& after) {
  std::string out = fmt::format("{:<44} {:>9} {:>9} {:>8} {:>8} {:>8} {:>8}  {}\n", "scenario", "offset m", "-> after",
                                "SOZ m", "ratio", "-> after", "util", "-> after (line)");
  for (std::size_t i = 0; i < before.size() && i < after.size(); ++i) {
    const design::ScenarioSummary& b = before[i];
    const design::ScenarioSummary& a = after[i];
    out += fmt::format("{:<44} {:>9.2f} {:>9.2f} {:>8} {:>8} {:>8} {:>8.3f}  {:.3f} ({})\n", b.scenario, b.offset_m,
                       a.offset_m, a.soz_allowable_m ? fmt::format("{:.1f}", *a.soz_allowable_m) : "-",
                       b.soz_ratio ? fmt::format("{:.3f}", *b.soz_ratio) : "-",
                       a.soz_ratio ? fmt::format("{:.3f}", *a.soz_ratio) : "-", b.worst_utilization,
                       a.worst_utilization, a.worst_line);
  }
  return out;
}

}  // namespace

std::string optimization_table(const design::OptimizationResult& r) {
  std::string out =
      fmt::format("Pretension optimization of {}: {} ({}, {} level), {} scenarios, {} evaluations, {:.2f} s\n",
                  r.project, design::to_string(r.objective), design::to_string(r.algorithm),
                  r.dynamic ? "sc-enhanced" : "static", r.scenarios.size(), r.evaluations, r.wall_s);
  out += fmt::format("objective ({}): {:.6g} -> {:.6g}; {}; stop: {}\n\n", r.objective_unit, r.objective_start,
                     r.objective_best, design::to_string(r.status), r.stop_reason);
  out += fmt::format("{:>5} {:>14} {:>12}  {}\n", "eval", "objective", "worst g", "worst constraint");
  for (const design::OptimizationHistoryRow& h : r.history) {
    out += fmt::format("{:>5} {:>14.6g} {:>12.3e}  {}{}\n", h.evaluation, h.objective, h.worst_constraint,
                       h.worst_constraint_name, h.feasible ? "" : "  (infeasible)");
  }
  out += fmt::format("\n{:<12} {:<10} {:>10} {:>12} {:>12} {:>14} {:>14} {:>8}\n", "line", "group", "payout m",
                     "top seg m", "-> after m", "pretension kN", "-> after kN", "% MBL");
  for (const design::LinePayout& l : r.lines) {
    out += fmt::format("{:<12} {:<10} {:>10.3f} {:>12.3f} {:>12.3f} {:>14.1f} {:>14.1f} {:>8.1f}\n", l.name, l.group,
                       l.payout_m, l.top_segment_before_m, l.top_segment_after_m, l.pretension_before_N / 1e3,
                       l.pretension_after_N / 1e3, 100.0 * l.pretension_after_N / l.top_segment_mbl_N);
  }
  out += "\n" + scenario_rows(r.before, r.after);
  if (r.dynamic) {
    out += fmt::format("\n{:<44} {:>12} {:>12} {:>12} {:>12}  {}\n", "storm extremes (3-h MPM)", "offset m", "-> after",
                       "ratio", "-> after", "dyn. util after (line)");
    for (std::size_t i = 0; i < r.before.size() && i < r.after.size(); ++i) {
      const design::ScenarioSummary& b = r.before[i];
      const design::ScenarioSummary& a = r.after[i];
      const auto value = [](const std::optional<double>& v) { return v ? fmt::format("{:.3f}", *v) : "-"; };
      out += fmt::format("{:<44} {:>12} {:>12} {:>12} {:>12}  {} ({})\n", b.scenario, value(b.mpm_offset_m),
                         value(a.mpm_offset_m), value(b.mpm_soz_ratio), value(a.mpm_soz_ratio),
                         value(a.worst_dynamic_utilization), a.worst_dynamic_line);
    }
  }
  if (!r.active.empty()) {
    out += "\nactive at the optimum (multiplier: objective gained per unit relaxation)\n";
    for (const design::ActiveConstraint& a : r.active) out += fmt::format("  {:<70} {:>12.4g}\n", a.name, a.multiplier);
  }
  if (r.most_violated) {
    out +=
        fmt::format("\nINFEASIBLE: most violated: {} by {:.4g}\n", r.most_violated->describe(), r.most_violated->value);
  }
  for (const std::string& f : r.findings) out += "finding: " + f + "\n";
  for (const std::string& n : r.notes) out += "note: " + n + "\n";
  return out;
}

std::string target_pretension_table(const design::TargetPretensionResult& r) {
  std::string out = fmt::format("Target pretensions of {} (hull at rest, still water): {} lines, {:.3f} s\n", r.project,
                                r.lines.size(), r.wall_s);
  out += fmt::format("{:<12} {:<10} {:>12} {:>12} {:>10} {:>12} {:>12}\n", "line", "group", "target kN", "before kN",
                     "payout m", "reached kN", "top seg m");
  for (const design::TargetPretensionRow& l : r.lines) {
    out += fmt::format("{:<12} {:<10} {:>12.1f} {:>12.1f} {:>10.3f} {:>12.3f} {:>12.3f}\n", l.line, l.group,
                       l.target_N / 1e3, l.pretension_before_N / 1e3, l.payout_m, l.pretension_after_N / 1e3,
                       l.top_segment_after_m);
  }
  return out;
}

std::string pretension_study_table(const design::PretensionStudyResult& r) {
  std::string out = fmt::format("Pretension study of {}: {} scenarios, {} evaluations, {:.2f} s\n", r.project,
                                r.scenarios.size(), r.evaluations, r.wall_s);
  for (const design::PretensionSweep& s : r.sweeps) {
    out += fmt::format("\nsweep {} ({} lines); feasible band: {}\n", s.name, s.lines.size(),
                       s.feasible_m ? fmt::format("{:.3f} to {:.3f} m", s.feasible_m->first, s.feasible_m->second)
                                    : std::string("none"));
    out += fmt::format("{:>10} {:>14} {:>10} {:>10} {:>10} {:>10} {:>10}  {}\n", "payout m", "pretension kN",
                       "offset m", "SOZ int", "SOZ dam", "util int", "util dam", "");
    for (const design::PretensionStudyPoint& p : s.points) {
      out += fmt::format("{:>10.3f} {:>14.1f} {:>10.2f} {:>10} {:>10} {:>10.3f} {:>10.3f}  {}\n", p.payout_m,
                         p.pretension_N / 1e3, p.max_offset_m, cell(p.max_soz_ratio_intact),
                         cell(p.max_soz_ratio_damaged), p.max_utilization_intact, p.max_utilization_damaged,
                         p.feasible ? "feasible" : "x " + p.worst_constraint_name);
    }
  }
  if (r.optimum_payouts_m) {
    out += fmt::format("\noptimizer ({}): payouts", r.optimum_status);
    for (const double p : *r.optimum_payouts_m) out += fmt::format(" {:+.3f}", p);
    out += " m\n";
  }
  for (const std::string& n : r.notes) out += "note: " + n + "\n";
  return out;
}

}  // namespace spiral::report
