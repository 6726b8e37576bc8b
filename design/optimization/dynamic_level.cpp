#include "design/optimization/dynamic_level.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "design/analysis/dynamic_analysis.hpp"
#include "design/criteria/mooring_checks.hpp"
#include "design/model/mooring_model.hpp"
#include "design/soz/soz.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {

namespace {

// A channel whose standard deviation is below this fraction of its mean is
// constant (no waves, no gusts): its extreme is its value (soz_check.cpp).
constexpr double kConstantChannel = 1e-12;

/// The Gumbel 3-h MPM of a tension channel (the stages' tension rule,
/// stage_dynamics.hpp), or its largest sample when it is constant or too
/// short to fit.
double gumbel_mpm(const std::vector<double>& x, double dt_s) {
  const engine::ChannelMoments m = engine::channel_moments(x);
  if (m.std_dev <= kConstantChannel * std::max(1.0, std::abs(m.mean))) return m.maximum;
  try {
    return engine::most_probable_maximum(x, dt_s).mpm_gumbel;
  } catch (const std::invalid_argument&) {
    return m.maximum;
  }
}

}  // namespace

DynamicLevel::DynamicLevel(const ValidatedProject& project, DynamicLevelOptions options, int threads)
    : project_(project), options_(options), threads_(std::max(1, threads)) {}

void DynamicLevel::apply(const PretensionProblem& problem, const Eigen::VectorXd& payouts_m,
                         ProblemEvaluation& evaluation) const {
  // The project with the payouts, and a load case for every line the study removes.
  ValidatedProject paid = project_;
  Project& p = paid.project;
  for (std::size_t g = 0; g < problem.groups().size(); ++g) {
    for (const std::string& name : problem.groups()[g].lines) {
      for (MooringLine& line : p.mooring.lines)
        if (line.name == name) line.segments.back().length_m += payouts_m(static_cast<Eigen::Index>(g));
    }
  }
  const std::vector<Scenario>& scenarios = problem.scenarios();
  std::vector<std::string> case_names;
  for (const Scenario& s : scenarios) {
    if (!s.removed_by_study) {
      case_names.push_back(s.case_name);
      continue;
    }
    const LoadCase& base = *std::find_if(p.load_cases.begin(), p.load_cases.end(),
                                         [&](const LoadCase& c) { return c.name == s.case_name; });
    p.load_cases.push_back({s.label(), base.environment, s.damaged_line, base.condition});
    case_names.push_back(s.label());
  }

  std::vector<DynamicAnalysisResult> runs(scenarios.size());
  engine::parallel_for(static_cast<int>(scenarios.size()), threads_, [&](int i) {
    DynamicAnalysisRequest request;
    request.load_case = case_names[static_cast<std::size_t>(i)];
    request.level = AnalysisLevel::semi_coupled_enhanced;
    request.duration_s = options_.duration_s;
    request.output_step_s = std::min(request.output_step_s, request.duration_s);
    request.seed = options_.seed;
    runs[static_cast<std::size_t>(i)] = run_dynamic_analysis(paid, request);
  });

  const std::vector<LineTypeProperties> types = resolve_line_types(p);
  const Optimization& settings = problem.settings();
  evaluation.constraints.clear();
  evaluation.objective_measures.clear();
  evaluation.dynamic.assign(scenarios.size(), {});
  for (std::size_t s = 0; s < scenarios.size(); ++s) {
    const DynamicAnalysisResult& run = runs[s];
    const std::string label = scenarios[s].label();
    const double dt = run.times_s.size() > 1 ? run.times_s(1) - run.times_s(0) : 1.0;
    DynamicScenarioMeasures& measures = evaluation.dynamic[s];
    // Offsets: |d(t)| and, against the zone, r(t) = |d(t)| / A(θ(t)).
    const SmoothZone* zone = problem.zone_of(s);
    std::vector<double> offset(static_cast<std::size_t>(run.total.cols())), ratio(offset.size());
    double worst_direction = 0.0, worst_ratio = -1.0;
    for (Eigen::Index k = 0; k < run.total.cols(); ++k) {
      const double d = std::hypot(run.total(0, k), run.total(1, k));
      const double theta = std::atan2(run.total(1, k), run.total(0, k));
      offset[static_cast<std::size_t>(k)] = d;
      if (zone) ratio[static_cast<std::size_t>(k)] = d / zone->allowable_m(theta);
      if (zone && ratio[static_cast<std::size_t>(k)] > worst_ratio) {
        worst_ratio = ratio[static_cast<std::size_t>(k)];
        worst_direction = theta;
      }
    }
    measures.mpm_offset_m = horizontal_offset_mpm(offset, dt).offset_m;
    if (zone) {
      // spiral's one extreme-offset rule (soz.hpp), on r(t) = |d| / A(θ).
      measures.mpm_soz_ratio = horizontal_offset_mpm(ratio, dt).offset_m;
      const std::string riser = problem.governing_riser(s, worst_direction);
      evaluation.constraints.push_back({{label, "soz", riser, *measures.mpm_soz_ratio - 1.0}, {}});
      if (settings.objective == OptimizationObjective::max_soz_margin)
        evaluation.objective_measures.push_back({{label, "soz", riser, *measures.mpm_soz_ratio}, {}});
    }
    if (p.criteria.max_offset_pct_depth) {
      const double limit = 0.01 * *p.criteria.max_offset_pct_depth * p.site.depth_m;
      evaluation.constraints.push_back({{label, "offset_limit", "", measures.mpm_offset_m / limit - 1.0}, {}});
    }
    if (settings.objective == OptimizationObjective::min_max_offset) {
      evaluation.objective_measures.push_back(
          {{label, "offset", "", 100.0 * measures.mpm_offset_m / p.site.depth_m}, {}});
    }
    // Tensions: each line's dynamic check on its mean and MPM.
    for (const TensionSeries& t : run.tensions) {
      const MooringLine& line = mooring_line(p, t.line);
      const double mbl = find_type(types, line.segments.back().type).breaking_load_N;
      const double mean = engine::channel_moments(t.tension_N).mean;
      const double utilization = dynamic_tension_check(p.criteria.mooring, scenarios[s].damaged_line.has_value(), mean,
                                                       gumbel_mpm(t.tension_N, dt), mbl)
                                     .utilization;
      evaluation.constraints.push_back({{label, "utilization", t.line, utilization - 1.0}, {}});
      if (settings.objective == OptimizationObjective::min_max_utilization)
        evaluation.objective_measures.push_back({{label, "utilization", t.line, utilization}, {}});
      if (utilization >= measures.worst_utilization) {
        measures.worst_utilization = utilization;
        measures.worst_line = t.line;
      }
    }
  }
}

}  // namespace spiral::design
