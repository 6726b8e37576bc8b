#include "design/results/optimization_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace spiral::design {

namespace {

nlohmann::json optional_number(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

/// Infinity has no JSON form: written as null.
nlohmann::json finite(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

nlohmann::json scenario_json(const ScenarioSummary& s) {
  return {{"scenario", s.scenario},
          {"zone", s.zone},
          {"load_case", s.case_name},
          {"damaged_line", s.damaged_line ? nlohmann::json(*s.damaged_line) : nlohmann::json()},
          {"offset_m", s.offset_m},
          {"direction_deg", s.direction_deg},
          {"soz_allowable_m", optional_number(s.soz_allowable_m)},
          {"soz_margin_m", s.soz_allowable_m ? nlohmann::json(*s.soz_allowable_m - s.offset_m) : nlohmann::json()},
          {"soz_ratio", optional_number(s.soz_ratio)},
          {"offset_limit_m", optional_number(s.offset_limit_m)},
          {"worst_utilization", s.worst_utilization},
          {"worst_line", s.worst_line},
          {"min_laid_length_m", finite(s.min_laid_length_m)},
          {"min_fairlead_tension_N", finite(s.min_fairlead_tension_N)},
          {"mpm_offset_m", optional_number(s.mpm_offset_m)},
          {"mpm_soz_ratio", optional_number(s.mpm_soz_ratio)},
          {"worst_dynamic_utilization", optional_number(s.worst_dynamic_utilization)},
          {"worst_dynamic_line", s.worst_dynamic_line}};
}

}  // namespace

nlohmann::json optimization_to_json(const OptimizationResult& r) {
  nlohmann::json j;
  j["format"] = "spiral.optimization";
  j["format_version"] = 1;
  j["project"] = r.project;
  j["status"] = to_string(r.status);
  j["stop_reason"] = r.stop_reason;
  j["objective"] = {{"kind", to_string(r.objective)},
                    {"unit", r.objective_unit},
                    {"start", r.objective_start},
                    {"best", r.objective_best}};
  j["algorithm"] = to_string(r.algorithm);
  j["level"] = r.dynamic ? "sc-enhanced" : "static";
  nlohmann::json groups = nlohmann::json::array();
  for (std::size_t g = 0; g < r.groups.size(); ++g) {
    groups.push_back({{"name", r.groups[g].name},
                      {"lines", r.groups[g].lines},
                      {"min_m", r.groups[g].min_m},
                      {"max_m", r.groups[g].max_m},
                      {"payout_m", g < r.payouts_m.size() ? r.payouts_m[g] : 0.0},
                      {"objective_gradient_per_m", g < r.objective_gradient.size() ? r.objective_gradient[g] : 0.0}});
  }
  j["groups"] = groups;
  nlohmann::json lines = nlohmann::json::array();
  for (const LinePayout& l : r.lines) {
    lines.push_back({{"name", l.name},
                     {"group", l.group},
                     {"payout_m", l.payout_m},
                     {"length_before_m", l.length_before_m},
                     {"length_after_m", l.length_after_m},
                     {"top_segment_before_m", l.top_segment_before_m},
                     {"top_segment_after_m", l.top_segment_after_m},
                     {"pretension_before_N", l.pretension_before_N},
                     {"pretension_after_N", l.pretension_after_N},
                     {"pretension_after_pct_mbl", 100.0 * l.pretension_after_N / l.top_segment_mbl_N}});
  }
  j["lines"] = lines;
  nlohmann::json before = nlohmann::json::array(), after = nlohmann::json::array();
  for (const ScenarioSummary& s : r.before) before.push_back(scenario_json(s));
  for (const ScenarioSummary& s : r.after) after.push_back(scenario_json(s));
  j["scenarios"] = {{"before", before}, {"after", after}};
  nlohmann::json history = nlohmann::json::array();
  for (const OptimizationHistoryRow& h : r.history) {
    history.push_back({{"evaluation", h.evaluation},
                       {"objective", finite(h.objective)},
                       {"worst_constraint", finite(h.worst_constraint)},
                       {"worst_constraint_name", h.worst_constraint_name},
                       {"feasible", h.feasible},
                       {"wall_s", h.wall_s},
                       {"payouts_m", h.payouts_m}});
  }
  j["history"] = history;
  nlohmann::json active = nlohmann::json::array();
  for (const ActiveConstraint& a : r.active)
    active.push_back({{"name", a.name}, {"value", a.value}, {"multiplier", a.multiplier}});
  j["active_constraints"] = active;
  if (r.most_violated) {
    j["most_violated"] = {
        {"name", r.most_violated->describe()}, {"kind", r.most_violated->kind}, {"value", r.most_violated->value}};
  }
  j["findings"] = r.findings;
  j["notes"] = r.notes;
  j["zone_conservatism_m"] = r.zone_conservatism_m;
  nlohmann::json zones = nlohmann::json::array();
  for (const ZoneOutline& z : r.zones)
    zones.push_back({{"name", z.name}, {"directions_deg", z.directions_deg}, {"allowable_m", z.allowable_m}});
  j["zones"] = zones;
  j["evaluations"] = r.evaluations;
  j["wall_s"] = r.wall_s;
  j["zone_wall_s"] = r.zone_wall_s;
  return j;
}

nlohmann::json target_pretension_to_json(const TargetPretensionResult& r) {
  nlohmann::json lines = nlohmann::json::array();
  for (const TargetPretensionRow& l : r.lines) {
    lines.push_back({{"name", l.line},
                     {"group", l.group},
                     {"target_N", l.target_N},
                     {"pretension_before_N", l.pretension_before_N},
                     {"payout_m", l.payout_m},
                     {"pretension_after_N", l.pretension_after_N},
                     {"top_segment_after_m", l.top_segment_after_m},
                     {"iterations", l.iterations}});
  }
  return {{"format", "spiral.target_pretension"},
          {"format_version", 1},
          {"project", r.project},
          {"lines", lines},
          {"wall_s", r.wall_s}};
}

std::string optimized_project_header(const OptimizationResult& r, const std::string& source_file) {
  std::string h = fmt::format("Written by spiral optimize from {} ({}).\n", source_file, to_string(r.status));
  h += fmt::format("Objective {} ({}): {:.6g} -> {:.6g}; algorithm {}; {} scenarios; {} evaluations.\n",
                   to_string(r.objective), r.objective_unit, r.objective_start, r.objective_best,
                   to_string(r.algorithm), r.scenarios.size(), r.evaluations);
  h += "Payouts (top segment, + pays out):";
  for (std::size_t g = 0; g < r.groups.size() && g < r.payouts_m.size(); ++g)
    h += fmt::format(" {} {:+.3f} m;", r.groups[g].name, r.payouts_m[g]);
  h += "\nOnly the top segment lengths of the paid lines differ from the source file.\n";
  return h;
}

std::string target_pretension_header(const std::string& source_file) {
  std::string h = fmt::format("Written by spiral optimize --target-pretension from {}.\n", source_file);
  h += "Each line's top segment set so that its fairlead tension at rest (still water, hull fixed) meets its\n";
  h += "group's target; only those lengths differ from the source file.\n";
  return h;
}

}  // namespace spiral::design
