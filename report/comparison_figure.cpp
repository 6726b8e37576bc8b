#include "report/comparison_figure.hpp"

#include <fmt/format.h>

#include <string>
#include <utility>
#include <vector>

#include "report/plot.hpp"

namespace spiral::report {

namespace {

using design::AnalysisLevel;
using design::ChannelSummary;
using design::LevelComparison;
using design::LevelSummary;

/// The dynamic tension channel with the largest MPM in `level`, or "".
std::string most_loaded_tension(const LevelSummary& level) {
  std::string name;
  double largest = -1.0;
  for (const ChannelSummary& c : level.channels) {
    if (!c.name.starts_with("tension_")) continue;
    if (c.mpm > largest) largest = c.mpm, name = c.name;
  }
  return name;
}

/// One panel: a bar per level that has `channel`, its value (× scale) with
/// the difference against the coupled level's above it.
BarChart statistic_chart(const LevelComparison& c, const std::string& channel, const std::string& title,
                         const std::string& y_label, double scale, bool std_dev) {
  const LevelSummary* coupled = design::find_level(c, AnalysisLevel::coupled);
  const ChannelSummary* reference = coupled ? design::find_channel(*coupled, channel) : nullptr;
  const auto value = [std_dev](const ChannelSummary& s) { return std_dev ? s.moments.std_dev : s.mpm; };
  BarChart chart;
  chart.title = title;
  chart.y_label = y_label;
  for (std::size_t i = 0; i < c.levels.size(); ++i) {
    const LevelSummary& l = c.levels[i];
    const ChannelSummary* s = design::find_channel(l, channel);
    if (!s) continue;
    std::string note;
    if (reference && l.level != AnalysisLevel::coupled)
      note = fmt::format("{:+.1f} %", design::percent_difference(value(*s), value(*reference)));
    else
      note = fmt::format("{:.3g}", value(*s) * scale);
    chart.bars.push_back({design::to_string(l.level), value(*s) * scale, palette(i), note});
  }
  return chart;
}

}  // namespace

Figure comparison_figure(const LevelComparison& c) {
  const LevelSummary* coupled = design::find_level(c, AnalysisLevel::coupled);
  std::string tension;
  if (coupled && !coupled->error) tension = most_loaded_tension(*coupled);
  for (std::size_t i = 0; tension.empty() && i < c.levels.size(); ++i) tension = most_loaded_tension(c.levels[i]);
  const std::string line =
      tension.empty() ? std::string() : tension.substr(8, tension.size() - 8 - 2);  // tension_<line>_N

  std::vector<BarChart> charts;
  charts.push_back(statistic_chart(c, "offset_m", "Offset, std", "Std (m)", 1.0, true));
  charts.push_back(statistic_chart(c, "offset_m", "Offset, 3-h MPM", "MPM (m)", 1.0, false));
  if (!tension.empty())
    charts.push_back(statistic_chart(c, tension, fmt::format("Tension {}, 3-h MPM", line), "MPM (kN)", 1e-3, false));
  BarChart cost;
  cost.title = "Wall clock (hull; FE lines apart)";
  cost.y_label = "Wall clock (s)";
  for (std::size_t i = 0; i < c.levels.size(); ++i) {
    const LevelSummary& l = c.levels[i];
    const std::string speed_up = coupled && l.wall_s > 0.0 && l.level != AnalysisLevel::coupled
                                     ? fmt::format("{:.0f}× faster", coupled->wall_s / l.wall_s)
                                     : fmt::format("{:.0f} s", l.wall_s);
    cost.bars.push_back({design::to_string(l.level), l.wall_s, palette(i), speed_up});
  }
  charts.push_back(std::move(cost));

  Figure f;
  f.id = "comparison";
  f.caption = fmt::format(
      "The levels on case {} (seed {}, {:.0f} s): offset std and 3-h MPM, the most loaded line's dynamic fairlead "
      "tension MPM (the non-coupled levels' from their motion prescribed to the same FE lines), each labelled with "
      "its difference against coupled, and each level's own wall clock with its speed-up.",
      c.case_name, c.seed, c.duration_s);
  f.aspect = 1.25;
  f.draw = [charts = std::move(charts)](cairo_t* cr, double w, double h) {
    const double pw = w / 2.0, ph = h / 2.0;
    for (std::size_t i = 0; i < charts.size(); ++i) {
      cairo_save(cr);
      cairo_translate(cr, static_cast<double>(i % 2) * pw + 3.0, static_cast<double>(i / 2) * ph + 3.0);
      draw_bar_chart(cr, charts[i], pw - 6.0, ph - 6.0);
      cairo_restore(cr);
    }
  };
  return f;
}

}  // namespace spiral::report
