#include "design/optimization/pretension_problem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "design/model/environment_loads.hpp"
#include "design/optimization/dynamic_level.hpp"
#include "design/project/request_error.hpp"
#include "design/optimization/warm_start_plan.hpp"
#include "design/soz/soz.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Below this horizontal offset (m) its direction is round-off: the ratio's
// gradient is taken as zero there (the ratio itself is ~0).
constexpr double kNoOffset_m = 1e-9;

const LoadCase& load_case_named(const Project& project, const std::string& name) {
  return *std::find_if(project.load_cases.begin(), project.load_cases.end(),
                       [&](const LoadCase& c) { return c.name == name; });
}

Optimization settings_of(const Project& project, const OptimizationRequest& request) {
  Optimization s = project.optimization.value_or(Optimization{});
  if (request.objective) s.objective = *request.objective;
  if (request.algorithm) s.algorithm = *request.algorithm;
  if (!request.cases.empty()) s.cases = request.cases;
  if (request.damaged) s.damaged = *request.damaged;
  if (request.max_evaluations) s.max_evaluations = *request.max_evaluations;
  if (request.dynamic) s.algorithm = OptimizationAlgorithm::cobyla;  // storms give no gradients
  return s;
}

void check_request(const Project& project, const OptimizationRequest& request) {
  std::vector<InputIssue> issues;
  const auto add = [&](const std::string& argument, const std::string& message, const std::string& problem) {
    const InputError error = request_error(project, argument, message, problem);
    issues.insert(issues.end(), error.issues().begin(), error.issues().end());
  };
  for (const std::string& name : request.cases) {
    if (std::none_of(project.load_cases.begin(), project.load_cases.end(),
                     [&](const LoadCase& c) { return c.name == name; })) {
      add("cases", fmt::format("no load case named \"{}\"", name), "load_case_defined");
    }
  }
  if (request.max_evaluations && *request.max_evaluations < 1)
    add("max_evaluations", fmt::format("must be >= 1, got {}", *request.max_evaluations), "max_evaluations_positive");
  if (request.objective == OptimizationObjective::max_soz_margin && project.risers.empty()) {
    add("objective", "max_soz_margin needs risers (their safe operational zone); the project has none",
        "objective_needs_risers");
  }
  if (request.dynamic && !(request.dynamic->duration_s > 0.0))
    add("duration_s", fmt::format("must be > 0 s, got {} s", request.dynamic->duration_s), "duration_positive");
  if (!issues.empty()) throw InputError(std::move(issues));
}

}  // namespace

std::vector<GroupVariable> group_variables(const Project& project) {
  const Optimization settings = project.optimization.value_or(Optimization{});
  std::vector<GroupVariable> out;
  for (const PayoutGroup& g : payout_groups(project)) {
    GroupVariable v;
    v.name = g.name;
    double shortest = std::numeric_limits<double>::infinity();
    for (const std::size_t i : g.lines) {
      v.lines.push_back(project.mooring.lines[i].name);
      shortest = std::min(shortest, total_length_m(project.mooring.lines[i]));
    }
    const auto bound = std::find_if(settings.bounds.begin(), settings.bounds.end(),
                                    [&](const PayoutBound& b) { return b.group == g.name; });
    if (bound != settings.bounds.end()) {
      v.min_m = bound->min_m;
      v.max_m = bound->max_m;
    } else {
      v.max_m = 0.01 * settings.payout_limit_pct * shortest;
      v.min_m = -v.max_m;
    }
    out.push_back(std::move(v));
  }
  return out;
}

PretensionProblem::PretensionProblem(const ValidatedProject& validated, const OptimizationRequest& request)
    : project_(validated.project), settings_(settings_of(validated.project, request)) {
  check_request(project_, request);
  payout_groups_ = payout_groups(project_);
  groups_ = group_variables(project_);
  for (const std::string& skipped : skipped_overlapping_groups(project_)) {
    notes_.push_back(fmt::format("group {} shares lines with an earlier group: not a variable", skipped));
  }

  std::vector<std::string> case_names = settings_.cases;
  if (case_names.empty())
    for (const LoadCase& c : project_.load_cases) case_names.push_back(c.name);
  for (const std::string& name : case_names) {
    const LoadCase& lc = load_case_named(project_, name);
    scenarios_.push_back({lc.name, lc.damaged_line, lc.condition});
    if (settings_.damaged == DamagedConditions::every_line && !lc.damaged_line) {
      for (const MooringLine& line : project_.mooring.lines)
        scenarios_.push_back({lc.name, line.name, lc.condition, true});
    }
  }
  threads_ = request.threads > 0 ? request.threads : engine::worker_count(static_cast<int>(scenarios_.size()));

  zones_.resize(scenarios_.size());
  if (!project_.risers.empty()) {
    engine::Stopwatch start;
    const Stage& stage = project_.stages.empty() ? Stage{} : project_.stages.front();
    SozOptions options;
    options.model = stage.soz.model == StageSozModel::fe ? SozModel::fe : SozModel::catenary;
    options.step_deg = stage.soz.step_deg;
    options.threads = request.threads;
    options.zones_only = true;  // the scenarios below are the cases' equilibria
    const SozResult soz = run_soz(validated, options);
    zone_wall_s_ = start.seconds();
    // The zone each case is checked against: its own (current, condition),
    // or the still-water zone.
    std::map<std::string, const SozZone*> zone_of_case;
    for (const SozZone& z : soz.zones)
      for (const std::string& c : z.cases) zone_of_case[c] = &z;
    std::map<const void*, ZoneOfScenario> built;
    for (std::size_t s = 0; s < scenarios_.size(); ++s) {
      const auto it = zone_of_case.find(scenarios_[s].case_name);
      const std::vector<RiserSoz>& risers = it != zone_of_case.end() ? it->second->risers : soz.risers;
      const PlatformSoz& platform = it != zone_of_case.end() ? it->second->platform : soz.platform;
      const std::string zone_name = it != zone_of_case.end() ? it->second->name : "still-water";
      const void* key = &risers;
      if (!built.count(key)) {
        ZoneOfScenario z;
        z.name = zone_name;
        z.directions_deg = soz.directions_deg;
        z.governing_riser = platform.governing_riser;
        bool empty = false;
        for (const RiserSoz& r : risers) {
          if (!r.fails_at_zero_offset) continue;
          empty = true;
          findings_.push_back(fmt::format(
              "riser {} fails {} already at zero offset (utilization {:.3f}) in zone {}: no pretension can bring "
              "the cases checked against that zone inside it; their SOZ constraint is left out (a riser design "
              "finding)",
              r.name, r.zero_offset_governing_criterion, r.zero_offset_utilization, zone_name));
        }
        if (!empty) {
          const std::vector<double>& directions = soz.directions_deg;
          std::vector<std::vector<double>> allowable;
          for (const RiserSoz& r : risers) {
            std::vector<double> a;
            for (const SozDirection& d : r.directions) a.push_back(d.allowable_offset_m);
            allowable.push_back(std::move(a));
          }
          auto smooth = std::make_shared<SmoothZone>([&](double deg) {
            double least = std::numeric_limits<double>::infinity();
            for (const std::vector<double>& a : allowable)
              least = std::min(least, polygon_allowable(directions, a, deg));
            return least;
          });
          zone_conservatism_m_ = std::max(zone_conservatism_m_, smooth->conservatism_m());
          z.zone = std::move(smooth);
        }
        built[key] = std::move(z);
      }
      zones_[s] = built[key];
    }
    notes_.push_back(fmt::format(
        "SOZ: {} model at {:g} deg (the first stage's settings), each case against the zone of its current and "
        "design condition; smoothed for the gradients and lowered by at most {:.3f} m to stay inside it",
        to_string(options.model), options.step_deg, zone_conservatism_m_));
    if (options.model == SozModel::catenary) {
      notes_.push_back("the catenary SOZ screening model carries no current (stages[0].soz.model: fe for the FE zone)");
    }
  }
  if (settings_.objective == OptimizationObjective::max_soz_margin &&
      std::any_of(zones_.begin(), zones_.end(), [](const ZoneOfScenario& z) { return !z.zone; })) {
    // A margin to a zone that some scenario has not: the largest offset is
    // the measure every scenario has.
    settings_.objective = OptimizationObjective::min_max_offset;
    notes_.push_back(project_.risers.empty()
                         ? "no risers, so no SOZ: the objective is min_max_offset instead of max_soz_margin"
                         : "a zone is missing (see findings): the objective is min_max_offset instead of "
                           "max_soz_margin");
  }
  if (std::any_of(project_.mooring.lines.begin(), project_.mooring.lines.end(),
                  [](const MooringLine& l) { return l.model == LineModel::catenary; }) &&
      std::any_of(project_.environments.begin(), project_.environments.end(),
                  [](const Environment& e) { return e.current.has_value(); })) {
    notes_.push_back("mooring lines with model: catenary carry no current drag in the equilibria (risers do)");
  }
  hull_ = build_hull_model(project_);
  build_models();
  if (request.dynamic) {
    dynamic_ = std::make_unique<DynamicLevel>(validated, *request.dynamic, threads_);
    notes_.push_back(fmt::format(
        "dynamic level: the constraints on each scenario's enhanced S-C storm ({:g} s, seed {}): Weibull 3-h MPM of "
        "offset / SOZ, MPM offset against the limit, each line's dynamic check on its mean and Gumbel MPM tension",
        request.dynamic->duration_s, request.dynamic->seed));
  }
}

PretensionProblem::~PretensionProblem() = default;

void PretensionProblem::build_models() {
  models_.clear();
  models_.reserve(scenarios_.size());
  std::map<std::string, engine::ExternalLoad> environment_loads;
  for (std::size_t s = 0; s < scenarios_.size(); ++s) {
    const Environment& environment =
        design::environment_of(project_, load_case_named(project_, scenarios_[s].case_name));
    auto load = environment_loads.find(environment.name);
    if (load == environment_loads.end())
      load = environment_loads.emplace(environment.name, mean_environment_load(project_, environment).load).first;
    models_.emplace_back(project_, hull_, payout_groups_, scenarios_[s], load->second);
  }
  models_started_ = false;
}

std::string PretensionProblem::governing_riser(std::size_t s, double direction_rad) const {
  // The riser governing the zone at the grid direction nearest θ.
  const std::vector<double>& dirs = zones_[s].directions_deg;
  double deg = direction_rad * kRadToDeg;
  if (deg < 0.0) deg += 360.0;
  const double step = dirs.size() > 1 ? dirs[1] - dirs[0] : 360.0;
  const auto nearest = static_cast<std::size_t>(std::lround(deg / step)) % std::max<std::size_t>(dirs.size(), 1);
  return nearest < zones_[s].governing_riser.size() ? zones_[s].governing_riser[nearest] : "";
}

std::vector<ZoneOutline> PretensionProblem::zone_outlines() const {
  std::vector<ZoneOutline> out;
  std::vector<const SmoothZone*> seen;
  for (const ZoneOfScenario& z : zones_) {
    if (!z.zone || std::find(seen.begin(), seen.end(), z.zone.get()) != seen.end()) continue;
    seen.push_back(z.zone.get());
    ZoneOutline outline{z.name, {}, {}};
    for (int deg = 0; deg < 360; deg += 2) {
      outline.directions_deg.push_back(deg);
      outline.allowable_m.push_back(z.zone->allowable_m(deg / kRadToDeg));
    }
    out.push_back(std::move(outline));
  }
  return out;
}

bool PretensionProblem::has_expensive_lines() const {
  // Risers are FE lines; FE mooring lines are rebuilt with their payouts and
  // are never linearized.
  return !project_.risers.empty();
}

void PretensionProblem::linearize_expensive_lines() {
  for (ScenarioModel& m : models_) m.linearize_expensive_lines();
  linearized_ = true;
}

void PretensionProblem::restore_expensive_lines() {
  for (ScenarioModel& m : models_) m.restore_expensive_lines();
  linearized_ = false;
}

std::string PretensionProblem::objective_unit() const {
  switch (settings_.objective) {
    case OptimizationObjective::max_soz_margin:
      return "largest offset / SOZ";
    case OptimizationObjective::min_max_utilization:
      return "largest utilization";
    case OptimizationObjective::min_total_payout:
      return "total |payout| m";
    case OptimizationObjective::min_max_offset:
      return "largest offset % depth";
  }
  return "";
}

ProblemEvaluation PretensionProblem::evaluate(const Eigen::VectorXd& payouts_m, bool with_gradient) {
  ProblemEvaluation out;
  out.responses.resize(scenarios_.size());
  const auto evaluate_each = [&](const std::vector<std::size_t>& which) {
    engine::parallel_for(static_cast<int>(which.size()), threads_, [&](int k) {
      const std::size_t s = which[static_cast<std::size_t>(k)];
      out.responses[s] = models_[s].evaluate(payouts_m, with_gradient);
    });
  };
  // The first time, each scenario with a line removed starts at the
  // equilibrium of an intact scenario in the same environment (same risers,
  // same current; the study's own or the load-case matrix's intact case):
  // its FE risers then start warm instead of cold — a cold riser solve under
  // current goes through continuations and costs ten warm ones.
  std::vector<std::size_t> first, then;
  std::vector<std::size_t> intact_of(scenarios_.size(), scenarios_.size());
  for (std::size_t s = 0; s < scenarios_.size(); ++s) {
    if (!models_started_ && scenarios_[s].damaged_line) {
      for (std::size_t i = 0; i < scenarios_.size() && intact_of[s] == scenarios_.size(); ++i)
        if (!scenarios_[i].damaged_line && environment_of(i) == environment_of(s)) intact_of[s] = i;
    }
    (models_started_ || intact_of[s] < scenarios_.size() ? then : first).push_back(s);
  }
  evaluate_each(first);
  // The intact scenarios' riser stiffness once, for the damaged scenarios'
  // predictors (each would otherwise factorise every riser again).
  std::vector<std::size_t> sources;
  for (std::size_t s = 0; s < scenarios_.size(); ++s)
    if (intact_of[s] < scenarios_.size() && std::find(sources.begin(), sources.end(), intact_of[s]) == sources.end())
      sources.push_back(intact_of[s]);
  engine::parallel_for(static_cast<int>(sources.size()), threads_,
                       [&](int k) { models_[sources[static_cast<std::size_t>(k)]].complete_expensive_lines(); });
  for (std::size_t s = 0; s < scenarios_.size(); ++s)
    if (intact_of[s] < scenarios_.size()) models_[s].start_from(models_[intact_of[s]]);
  if (!has_expensive_lines() || linearized_ || !evaluate_in_waves(then, payouts_m, with_gradient, out))
    evaluate_each(then);
  models_started_ = true;
  for (std::size_t s = 0; s < scenarios_.size(); ++s) add_scenario_constraints(s, out.responses[s], with_gradient, out);
  if (dynamic_) dynamic_->apply(*this, payouts_m, out);
  return out;
}

const std::string& PretensionProblem::environment_of(std::size_t s) const {
  return load_case_named(project_, scenarios_[s].case_name).environment;
}

bool PretensionProblem::evaluate_in_waves(const std::vector<std::size_t>& which, const Eigen::VectorXd& payouts_m,
                                          bool with_gradient, ProblemEvaluation& out) {
  // Each scenario's equilibrium predicted on linearized risers, then solved
  // in full starting its risers from the nearest solved state of its
  // environment (warm_start_plan.hpp).
  std::vector<WarmStartNode> nodes(which.size());
  engine::parallel_for(static_cast<int>(which.size()), threads_, [&](int k) {
    ScenarioModel& model = models_[which[static_cast<std::size_t>(k)]];
    WarmStartNode& node = nodes[static_cast<std::size_t>(k)];
    node.own_tops_g = model.solved_riser_tops_g();
    const std::optional<engine::HullPose> predicted = model.predict(payouts_m);
    // Without a prediction the full solve starts where the last one ended.
    node.predicted_tops_g = predicted ? model.riser_tops_g(*predicted) : node.own_tops_g;
  });
  std::vector<std::string> environments;
  for (std::size_t k = 0; k < which.size(); ++k) {
    const std::string& environment = environment_of(which[k]);
    auto it = std::find(environments.begin(), environments.end(), environment);
    if (it == environments.end()) it = environments.insert(environments.end(), environment);
    nodes[k].environment = static_cast<int>(it - environments.begin());
  }
  // A riser without a solution (its last solve failed): no plan, each
  // scenario starts from its own state.
  if (std::any_of(nodes.begin(), nodes.end(), [](const WarmStartNode& n) { return n.own_tops_g.empty(); }))
    return false;
  const std::vector<WarmStart> plan = plan_warm_starts(nodes);
  for (const std::vector<int>& wave : warm_start_waves(plan)) {
    engine::parallel_for(static_cast<int>(wave.size()), threads_, [&](int i) {
      const auto k = static_cast<std::size_t>(wave[static_cast<std::size_t>(i)]);
      const std::size_t s = which[k];
      if (plan[k].donor) models_[s].start_risers_from(models_[which[static_cast<std::size_t>(*plan[k].donor)]]);
      out.responses[s] = models_[s].evaluate(payouts_m, with_gradient);
    });
  }
  return true;
}

void PretensionProblem::add_scenario_constraints(std::size_t s, const ScenarioResponse& r, bool with_gradient,
                                                 ProblemEvaluation& out) const {
  const std::string label = scenarios_[s].label();
  const auto n = static_cast<Eigen::Index>(groups_.size());
  const auto gradient = [&](const Eigen::VectorXd& g) { return with_gradient ? g : Eigen::VectorXd(); };
  const bool minimax_utilization = settings_.objective == OptimizationObjective::min_max_utilization;
  for (const LineResponse& line : r.lines) {
    out.constraints.push_back(
        {{label, "utilization", line.name, line.utilization - 1.0}, gradient(line.d_utilization)});
    if (minimax_utilization)
      out.objective_measures.push_back(
          {{label, "utilization", line.name, line.utilization}, gradient(line.d_utilization)});
    if (settings_.min_laid_length_m) {
      const double scale = std::max(*settings_.min_laid_length_m, 1.0);
      out.constraints.push_back(
          {{label, "min_laid_length", line.name, (*settings_.min_laid_length_m - line.laid_length_m) / scale},
           gradient(-line.d_laid_length_m / scale)});
    }
    if (settings_.min_tension_N) {
      out.constraints.push_back(
          {{label, "min_tension", line.name, 1.0 - line.fairlead_tension_N / *settings_.min_tension_N},
           gradient(-line.d_fairlead_tension_N / *settings_.min_tension_N)});
    }
  }
  // Horizontal offset ρ and direction θ, with dρ and dθ per group.
  const double x = r.offset(0), y = r.offset(1);
  const double rho = std::hypot(x, y);
  const double theta = std::atan2(y, x);
  Eigen::VectorXd d_rho = Eigen::VectorXd::Zero(n), d_theta = Eigen::VectorXd::Zero(n);
  if (with_gradient && rho > kNoOffset_m) {
    d_rho = (x * r.d_horizontal_offset.row(0) + y * r.d_horizontal_offset.row(1)).transpose() / rho;
    d_theta = (x * r.d_horizontal_offset.row(1) - y * r.d_horizontal_offset.row(0)).transpose() / (rho * rho);
  }
  if (const auto& zone = zones_[s].zone) {
    const double allowable = zone->allowable_m(theta);
    const double ratio = allowable > 0.0 ? rho / allowable : std::numeric_limits<double>::infinity();
    const Eigen::VectorXd d_ratio =
        d_rho / allowable - rho * zone->slope_m_per_rad(theta) / (allowable * allowable) * d_theta;
    const std::string riser = governing_riser(s, theta);
    out.constraints.push_back({{label, "soz", riser, ratio - 1.0}, gradient(d_ratio)});
    if (settings_.objective == OptimizationObjective::max_soz_margin)
      out.objective_measures.push_back({{label, "soz", riser, ratio}, gradient(d_ratio)});
  }
  if (project_.criteria.max_offset_pct_depth) {
    const double limit = 0.01 * *project_.criteria.max_offset_pct_depth * project_.site.depth_m;
    out.constraints.push_back({{label, "offset_limit", "", rho / limit - 1.0}, gradient(d_rho / limit)});
  }
  if (settings_.objective == OptimizationObjective::min_max_offset) {
    const double per_pct = 100.0 / project_.site.depth_m;
    out.objective_measures.push_back({{label, "offset", "", rho * per_pct}, gradient(d_rho * per_pct)});
  }
}

double PretensionProblem::objective_of(const ProblemEvaluation& evaluation, const Eigen::VectorXd& payouts_m) const {
  if (settings_.objective == OptimizationObjective::min_total_payout) {
    const double eps = 0.1 * settings_.payout_tolerance_m;
    return ((payouts_m.array().square() + eps * eps).sqrt() - eps).sum();
  }
  double worst = -std::numeric_limits<double>::infinity();
  for (const Measure& m : evaluation.objective_measures) worst = std::max(worst, m.value.value);
  return worst;
}

ScenarioSummary PretensionProblem::summarize(std::size_t s, const ProblemEvaluation& evaluation) const {
  const ScenarioResponse& r = evaluation.responses[s];
  ScenarioSummary out;
  if (s < evaluation.dynamic.size()) {
    const DynamicScenarioMeasures& d = evaluation.dynamic[s];
    out.mpm_offset_m = d.mpm_offset_m;
    out.mpm_soz_ratio = d.mpm_soz_ratio;
    out.worst_dynamic_utilization = d.worst_utilization;
    out.worst_dynamic_line = d.worst_line;
  }
  out.scenario = scenarios_[s].label();
  out.case_name = scenarios_[s].case_name;
  out.damaged_line = scenarios_[s].damaged_line;
  out.offset_m = std::hypot(r.offset(0), r.offset(1));
  const double theta = std::atan2(r.offset(1), r.offset(0));
  out.direction_deg = out.offset_m > 1e-3 ? theta * kRadToDeg : 0.0;
  if (out.direction_deg < 0.0) out.direction_deg += 360.0;
  if (const auto& zone = zones_[s].zone) {
    out.zone = zones_[s].name;
    out.soz_allowable_m = zone->allowable_m(theta);
    out.soz_ratio = out.offset_m / *out.soz_allowable_m;
  }
  if (project_.criteria.max_offset_pct_depth)
    out.offset_limit_m = 0.01 * *project_.criteria.max_offset_pct_depth * project_.site.depth_m;
  out.min_laid_length_m = std::numeric_limits<double>::infinity();
  out.min_fairlead_tension_N = std::numeric_limits<double>::infinity();
  for (const LineResponse& line : r.lines) {
    if (line.utilization >= out.worst_utilization) {
      out.worst_utilization = line.utilization;
      out.worst_line = line.name;
    }
    out.min_laid_length_m = std::min(out.min_laid_length_m, line.laid_length_m);
    out.min_fairlead_tension_N = std::min(out.min_fairlead_tension_N, line.fairlead_tension_N);
  }
  return out;
}

}  // namespace spiral::design
