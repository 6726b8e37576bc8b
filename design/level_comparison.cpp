#include "design/level_comparison.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "engine/numerics/statistics.hpp"

namespace spiral::design {
namespace {

ChannelSummary summarize(const std::string& name, const std::string& unit,
                         const std::vector<double>& x, double dt_s) {
  ChannelSummary c;
  c.name = name;
  c.unit = unit;
  const engine::ChannelMoments m = engine::channel_moments(x);
  c.mean = m.mean;
  c.std_dev = m.std_dev;
  c.maximum = m.maximum;
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

double total_wall_s(const DynamicAnalysisResult& r) {
  return r.equilibrium_wall_s + r.reduction_wall_s + r.forcing_wall_s + r.dynamics_wall_s +
         r.wave_frequency_wall_s + r.tensions_wall_s;
}

}  // namespace

double percent_difference(double level, double coupled) {
  return std::abs(coupled) > 0.0 ? 100.0 * (level - coupled) / std::abs(coupled) : 0.0;
}

LevelSummary summarize_level(const DynamicAnalysisResult& result) {
  LevelSummary s;
  s.level = result.level;
  s.wall_s = total_wall_s(result);
  s.line_dynamics_wall_s = result.line_dynamics_wall_s;
  s.channels = summarize_channels(result);
  s.notes = result.notes;
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
    c.levels.push_back(summarize_level(result));
  }
  return c;
}

nlohmann::json comparison_to_json(const LevelComparison& c) {
  nlohmann::json j;
  j["format"] = "spiral.level_comparison";
  j["format_version"] = 1;
  j["load_case"] = c.case_name;
  j["seed"] = c.seed;
  j["duration_s"] = c.duration_s;
  const LevelSummary* coupled = find_level(c, AnalysisLevel::coupled);
  nlohmann::json levels;
  for (const LevelSummary& l : c.levels) {
    nlohmann::json lj;
    if (l.error) {
      lj["error"] = *l.error;
      levels[to_string(l.level)] = lj;
      continue;
    }
    lj["wall_s"] = l.wall_s;
    lj["line_dynamics_wall_s"] = l.line_dynamics_wall_s;
    lj["real_time_factor"] = l.wall_s > 0.0 ? c.duration_s / l.wall_s : 0.0;
    if (coupled != nullptr && l.wall_s > 0.0) {
      lj["speedup_vs_coupled"] = coupled->wall_s / l.wall_s;
      if (l.level != AnalysisLevel::coupled)
        lj["speedup_with_line_dynamics_vs_coupled"] =
            coupled->wall_s / (l.wall_s + l.line_dynamics_wall_s);
    }
    if (const ChannelSummary* o = find_channel(l, "offset_m")) {
      lj["max_offset_m"] = o->maximum;
      lj["mpm_offset_m"] = o->mpm;
    }
    nlohmann::json channels;
    for (const ChannelSummary& ch : l.channels) {
      nlohmann::json cj = {{"unit", ch.unit},       {"mean", ch.mean}, {"std", ch.std_dev},
                           {"max", ch.maximum},     {"mpm", ch.mpm},   {"mpm_fitted", ch.mpm_fitted}};
      const ChannelSummary* ref = coupled != nullptr ? find_channel(*coupled, ch.name) : nullptr;
      if (ref == nullptr && coupled != nullptr && ch.name.rfind("qs_", 0) == 0)
        ref = find_channel(*coupled, ch.name.substr(3));  // quasi-static against coupled tension
      if (ref != nullptr && l.level != AnalysisLevel::coupled) {
        cj["diff_pct_vs_coupled"] = {{"mean", percent_difference(ch.mean, ref->mean)},
                                     {"std", percent_difference(ch.std_dev, ref->std_dev)},
                                     {"max", percent_difference(ch.maximum, ref->maximum)},
                                     {"mpm", percent_difference(ch.mpm, ref->mpm)}};
      }
      channels[ch.name] = cj;
    }
    lj["channels"] = channels;
    if (l.coupled_solver) {
      lj["solver"] = {{"steps", l.coupled_solver->steps},
                      {"residual_evaluations", l.coupled_solver->residual_evaluations},
                      {"jacobian_evaluations", l.coupled_solver->newton_matrix_setups},
                      {"error_test_failures", l.coupled_solver->error_test_failures}};
    }
    lj["notes"] = l.notes;
    levels[to_string(l.level)] = lj;
  }
  j["levels"] = levels;
  return j;
}

std::string comparison_table(const LevelComparison& c) {
  const LevelSummary* coupled = find_level(c, AnalysisLevel::coupled);
  std::string out = fmt::format("{:<24}", "channel (max / MPM)");
  for (const LevelSummary& l : c.levels) out += fmt::format(" | {:>24}", to_string(l.level));
  out += "\n";
  auto row = [&](const std::string& name, double scale, const char* unit) {
    std::string line = fmt::format("{:<24}", name + " [" + unit + "]");
    for (const LevelSummary& l : c.levels) {
      const ChannelSummary* ch = find_channel(l, name);
      std::string ref_name = name.rfind("qs_", 0) == 0 ? name.substr(3) : name;
      const ChannelSummary* ref = coupled != nullptr ? find_channel(*coupled, ref_name) : nullptr;
      if (ch == nullptr) {
        line += fmt::format(" | {:>24}", "-");
      } else if (ref != nullptr && l.level != AnalysisLevel::coupled) {
        line += fmt::format(" | {:>9.4g} {:>7.4g} {:>+5.0f}%", ch->maximum * scale, ch->mpm * scale,
                            percent_difference(ch->mpm, ref->mpm));
      } else {
        line += fmt::format(" | {:>9.4g} {:>7.4g}      ", ch->maximum * scale, ch->mpm * scale);
      }
    }
    out += line + "\n";
  };
  row("offset_m", 1.0, "m");
  row("surge_m", 1.0, "m");
  row("sway_m", 1.0, "m");
  row("yaw_deg", 1.0, "deg");
  // The mooring lines, dynamic then quasi-static (kN).
  if (coupled != nullptr) {
    for (const ChannelSummary& ch : c.levels.front().channels) {
      if (ch.name.rfind("tension_", 0) == 0) row(ch.name, 1e-3, "kN");
    }
    for (const ChannelSummary& ch : c.levels.front().channels) {
      if (ch.name.rfind("qs_tension_", 0) == 0) row(ch.name, 1e-3, "kN");
    }
  }
  std::string cost = fmt::format("{:<24}", "wall-clock [s]");
  std::string speed = fmt::format("{:<24}", "speed-up vs coupled");
  for (const LevelSummary& l : c.levels) {
    cost += fmt::format(" | {:>24}", l.level == AnalysisLevel::coupled
                                         ? fmt::format("{:.3g}", l.wall_s)
                                         : fmt::format("{:.3g} (+{:.3g} FE)", l.wall_s,
                                                       l.line_dynamics_wall_s));
    speed += fmt::format(" | {:>24}", coupled != nullptr && l.wall_s > 0.0
                                          ? fmt::format("{:.1f}x", coupled->wall_s / l.wall_s)
                                          : std::string("-"));
  }
  out += cost + "\n" + speed + "\n";
  for (const LevelSummary& l : c.levels) {
    if (l.error) out += fmt::format("{} failed: {}\n", to_string(l.level), *l.error);
  }
  return out;
}

}  // namespace spiral::design
