#include "design/analysis/level_comparison.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "engine/numerics/statistics.hpp"

namespace spiral::design {
namespace {

ChannelSummary summarize(const std::string& name, const std::string& unit, const std::vector<double>& x, double dt_s) {
  ChannelSummary c;
  c.name = name;
  c.unit = unit;
  c.moments = engine::channel_moments(x);
  const engine::ChannelMoments& m = c.moments;
  c.mpm = m.maximum;
  if (m.std_dev > 1e-12 * std::max(1.0, std::abs(m.mean))) {
    try {
      c.mpm = engine::most_probable_maximum(x, dt_s).mpm_gumbel;
      c.mpm_fitted = std::isfinite(c.mpm);
      if (!c.mpm_fitted) c.mpm = m.maximum;
    } catch (const std::exception&) {
      c.mpm = m.maximum;  // too few cycles for the fit: the sample maximum
    }
  }
  return c;
}

}  // namespace

const ChannelSummary* find_channel(const LevelSummary& level, const std::string& name) {
  for (const ChannelSummary& c : level.channels) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

const LevelSummary* find_level(const LevelComparison& c, AnalysisLevel level) {
  for (const LevelSummary& l : c.levels) {
    if (l.level == level && !l.error) return &l;
  }
  return nullptr;
}

double percent_difference(double level, double coupled) {
  return std::abs(coupled) > 0.0 ? 100.0 * (level - coupled) / std::abs(coupled) : 0.0;
}

LevelSummary summarize_level(const DynamicAnalysisResult& result) {
  LevelSummary s;
  s.level = result.level;
  s.wall_s = result.timing.level_s();
  s.line_dynamics_wall_s = result.timing.line_dynamics_s;
  s.channels = summarize_channels(result);
  s.notes = result.notes;
  s.low_frequency_damping = result.low_frequency_damping;
  s.coupled_solver = result.coupled_solver;
  return s;
}

std::vector<ChannelSummary> summarize_channels(const DynamicAnalysisResult& r) {
  std::vector<ChannelSummary> out;
  if (r.times_s.size() < 2) return out;
  const double dt = r.times_s(1) - r.times_s(0);
  const auto n = static_cast<std::size_t>(r.total.cols());
  std::vector<double> offset(n), surge(n), sway(n), heave(n), yaw(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto col = r.total.col(static_cast<Eigen::Index>(k));
    offset[k] = std::hypot(col(0), col(1));
    surge[k] = col(0);
    sway[k] = col(1);
    heave[k] = col(2);
    yaw[k] = col(5) * 180.0 / std::numbers::pi;
  }
  out.push_back(summarize("offset_m", "m", offset, dt));
  out.push_back(summarize("surge_m", "m", surge, dt));
  out.push_back(summarize("sway_m", "m", sway, dt));
  out.push_back(summarize("heave_m", "m", heave, dt));
  out.push_back(summarize("yaw_deg", "deg", yaw, dt));
  for (const LineDynamicsSeries& t : r.dynamic_tensions)
    out.push_back(summarize("tension_" + t.line + "_N", "N", t.tension_N, dt));
  for (const TensionSeries& t : r.tensions)
    out.push_back(summarize("qs_tension_" + t.line + "_N", "N", t.tension_N, dt));
  return out;
}

LevelComparison compare_levels(const ValidatedProject& project, const ComparisonRequest& request) {
  LevelComparison c;
  c.case_name = request.load_case;
  c.seed = request.seed;
  c.duration_s = request.duration_s;
  c.line_reduction = request.line_reduction;
  for (AnalysisLevel level : {AnalysisLevel::uncoupled, AnalysisLevel::semi_coupled,
                              AnalysisLevel::semi_coupled_enhanced, AnalysisLevel::coupled}) {
    DynamicAnalysisRequest r;
    r.load_case = request.load_case;
    r.level = level;
    r.duration_s = request.duration_s;
    r.output_step_s = request.output_step_s;
    r.seed = request.seed;
    r.line_dynamics = level != AnalysisLevel::coupled;
    r.coupled_max_steps_between_outputs = request.coupled_max_steps_between_outputs;
    r.line_reduction = request.line_reduction;
    r.detailed_line_mesh = request.detailed_line_mesh;
    if (request.progress) {
      const std::string name = to_string(level);
      r.progress = [p = request.progress, name](double f) { p(name, f); };
    }
    LevelSummary s;
    s.level = level;
    DynamicAnalysisResult result;
    try {
      result = run_dynamic_analysis(project, r);
    } catch (const engine::SolverError& e) {
      s.error = e.what();
      c.levels.push_back(std::move(s));
      continue;
    }
    if (result.line_reduction) c.line_reduction = *result.line_reduction;  // as applied: see DynamicModel
    c.levels.push_back(summarize_level(result));
  }
  return c;
}

}  // namespace spiral::design
