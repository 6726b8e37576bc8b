// Project loader, section optimization (project_loader_sections.hpp).

#include "design/project/project_loader_sections.hpp"

namespace spiral::design::loader_detail {
namespace {

const EnumTable<OptimizationObjective> kObjectives = {
    {"max_soz_margin", OptimizationObjective::max_soz_margin},
    {"min_max_utilization", OptimizationObjective::min_max_utilization},
    {"min_total_payout", OptimizationObjective::min_total_payout},
    {"min_max_offset", OptimizationObjective::min_max_offset}};
const EnumTable<OptimizationAlgorithm> kAlgorithms = {{"slsqp", OptimizationAlgorithm::slsqp},
                                                      {"ccsaq", OptimizationAlgorithm::ccsaq},
                                                      {"cobyla", OptimizationAlgorithm::cobyla}};
const EnumTable<DamagedConditions> kDamagedConditions = {{"load_cases", DamagedConditions::load_cases},
                                                         {"every_line", DamagedConditions::every_line}};

}  // namespace

Optimization read_optimization(MapReader& r) {
  Optimization o;
  r.list("groups", kOptional,
         [&](const YAML::Node& item, const std::string& path) { read_name(r.context(), item, path, o.groups); });
  r.list_of_maps("bounds", kOptional, [&](MapReader& b) {
    PayoutBound bound;
    assign(bound.group, b.text("group", kRequired));
    assign(bound.min_m, b.number("min", "m", kRequired));
    assign(bound.max_m, b.number("max", "m", kRequired));
    o.bounds.push_back(bound);
  });
  assign(o.payout_limit_pct, r.number("payout_limit_pct", "%", kOptional));
  assign(o.objective, r.enumeration("objective", kObjectives, kOptional));
  assign(o.algorithm, r.enumeration("algorithm", kAlgorithms, kOptional));
  r.list("cases", kOptional,
         [&](const YAML::Node& item, const std::string& path) { read_name(r.context(), item, path, o.cases); });
  assign(o.damaged, r.enumeration("damaged", kDamagedConditions, kOptional));
  o.min_laid_length_m = r.number("min_laid_length", "m", kOptional);
  o.min_tension_N = r.number("min_tension", "N", kOptional);
  assign(o.payout_tolerance_m, r.number("payout_tolerance", "m", kOptional));
  assign(o.max_evaluations, r.integer("max_evaluations", kOptional));
  r.list_of_maps("target_pretension", kOptional, [&](MapReader& t) {
    PretensionTarget target;
    assign(target.group, t.text("group", kRequired));
    assign(target.tension_N, t.number("tension", "N", kRequired));
    o.target_pretension.push_back(target);
  });
  return o;
}

}  // namespace spiral::design::loader_detail
