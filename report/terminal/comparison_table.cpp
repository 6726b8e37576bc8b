#include "report/terminal/comparison_table.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace spiral::report {

using namespace design;

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
        line += fmt::format(" | {:>9.4g} {:>7.4g} {:>+5.0f}%", ch->moments.maximum * scale, ch->mpm * scale,
                            percent_difference(ch->mpm, ref->mpm));
      } else {
        line += fmt::format(" | {:>9.4g} {:>7.4g}      ", ch->moments.maximum * scale, ch->mpm * scale);
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
  // How much of critical the slow surge is damped at each level (the
  // coupled level's lines are not reduced to a damping): the reason a level
  // without line damping overshoots.
  std::string damping = fmt::format("{:<24}", "surge LF damping [%]");
  for (const LevelSummary& l : c.levels) {
    const auto surge = std::find_if(l.low_frequency_damping.begin(), l.low_frequency_damping.end(),
                                    [](const engine::DofDamping& d) { return d.dof == 0; });
    damping += fmt::format(
        " | {:>24}", surge == l.low_frequency_damping.end() || surge->natural_period_s <= 0.0
                         ? std::string("-")
                         : fmt::format("{:.2f} at {:.0f} s", 100.0 * surge->damping_ratio, surge->natural_period_s));
  }
  out += damping + "\n";
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

}  // namespace spiral::report
