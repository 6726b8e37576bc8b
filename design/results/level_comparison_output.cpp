#include "design/results/level_comparison_output.hpp"

#include <cmath>

#include "design/results/dynamic_analysis_output.hpp"

namespace spiral::design {

nlohmann::json comparison_to_json(const LevelComparison& c) {
  nlohmann::json j;
  j["format"] = "spiral.level_comparison";
  j["format_version"] = 1;
  j["load_case"] = c.case_name;
  j["seed"] = c.seed;
  j["duration_s"] = c.duration_s;
  j["sc_enhanced_line_reduction"] = c.line_reduction == LineReduction::dynamic ? "dynamic" : "quasi-static";
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
      lj["max_offset_m"] = o->moments.maximum;
      lj["mpm_offset_m"] = o->mpm;
    }
    nlohmann::json channels;
    for (const ChannelSummary& ch : l.channels) {
      nlohmann::json cj = {{"unit", ch.unit},           {"mean", ch.moments.mean}, {"std", ch.moments.std_dev},
                           {"max", ch.moments.maximum}, {"mpm", ch.mpm},           {"mpm_fitted", ch.mpm_fitted}};
      const ChannelSummary* ref = coupled != nullptr ? find_channel(*coupled, ch.name) : nullptr;
      if (ref == nullptr && coupled != nullptr && ch.name.rfind("qs_", 0) == 0)
        ref = find_channel(*coupled, ch.name.substr(3));  // quasi-static against coupled tension
      if (ref != nullptr && l.level != AnalysisLevel::coupled) {
        cj["diff_pct_vs_coupled"] = {{"mean", percent_difference(ch.moments.mean, ref->moments.mean)},
                                     {"std", percent_difference(ch.moments.std_dev, ref->moments.std_dev)},
                                     {"max", percent_difference(ch.moments.maximum, ref->moments.maximum)},
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
    if (!l.low_frequency_damping.empty())
      lj["low_frequency_damping"] = low_frequency_damping_to_json(l.low_frequency_damping);
    lj["notes"] = l.notes;
    levels[to_string(l.level)] = lj;
  }
  j["levels"] = levels;
  return j;
}

}  // namespace spiral::design
