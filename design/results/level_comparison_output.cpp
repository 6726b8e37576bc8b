#include "design/results/level_comparison_output.hpp"

#include <cmath>

#include <fmt/format.h>

namespace spiral::design {

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
        lj["speedup_with_line_dynamics_vs_coupled"] = coupled->wall_s / (l.wall_s + l.line_dynamics_wall_s);
    }
    if (const ChannelSummary* o = find_channel(l, "offset_m")) {
      lj["max_offset_m"] = o->maximum;
      lj["mpm_offset_m"] = o->mpm;
    }
    nlohmann::json channels;
    for (const ChannelSummary& ch : l.channels) {
      nlohmann::json cj = {{"unit", ch.unit},   {"mean", ch.mean}, {"std", ch.std_dev},
                           {"max", ch.maximum}, {"mpm", ch.mpm},   {"mpm_fitted", ch.mpm_fitted}};
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
                                         : fmt::format("{:.3g} (+{:.3g} FE)", l.wall_s, l.line_dynamics_wall_s));
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
