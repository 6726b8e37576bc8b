#include "report/dynamics_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/plot.hpp"
#include "report/table_cells.hpp"

namespace spiral::report {

namespace {

/// A plotted time series keeps at most this many min/max pairs: 21 600
/// samples of a 3-h record are far more than the page resolves, and the
/// min/max envelope per bin keeps every peak that a full plot would show.
constexpr std::size_t kEnvelopeBins = 1500;
/// Fraction of a spectrum's variance that decides its frequency axis.
constexpr double kShownVarianceFraction = 0.999;

/// Display scale of a channel: tensions in kN, the rest as stored.
double display_scale(const design::StormChannel& c) { return c.unit == "N" ? 1e-3 : 1.0; }
std::string display_unit(const design::StormChannel& c) { return c.unit == "N" ? "kN" : c.unit; }

Plot time_plot(const design::StageDynamics& d, const design::StormChannel& c, std::size_t color) {
  Plot p;
  p.title = c.name;
  p.x_label = "Time (s)";
  p.y_label = fmt::format("{} ({})", c.name, display_unit(c));
  Series s = time_envelope(d.times_s, c.values, display_scale(c));
  s.label = fmt::format("{} {}", design::to_string(d.level), c.name);
  s.color = palette(color);
  p.series.push_back(std::move(s));
  const double k = display_scale(c);
  Series mean{"mean",
              {d.times_s.front(), d.times_s.back()},
              {c.moments().mean * k, c.moments().mean * k},
              {0.2, 0.2, 0.2},
              0.8,
              true,
              false,
              false};
  p.series.push_back(mean);
  if (const std::optional<double> mpm = c.mpm_max()) {
    p.series.push_back({"MPM max (3 h)",
                        {d.times_s.front(), d.times_s.back()},
                        {*mpm * k, *mpm * k},
                        {0.84, 0.15, 0.16},
                        0.8,
                        true,
                        false,
                        false});
  }
  p.x_range = std::pair{d.times_s.front(), d.times_s.back()};
  p.legend = false;  // one key for all panels, in the caption: the legend would hide the record
  return p;
}

Plot spectrum_plot(const design::StormChannel& c, std::size_t color) {
  Plot p;
  p.title = fmt::format("{} spectrum", c.name);
  p.x_label = "Angular frequency ω (rad/s)";
  const double k = display_scale(c);
  p.y_label = fmt::format("S(ω) ({}²·s/rad)", display_unit(c));
  const engine::Spectrum& spectrum = c.statistics.spectrum;
  const std::vector<double> frequency(spectrum.frequency_rad_s.data(),
                                      spectrum.frequency_rad_s.data() + spectrum.frequency_rad_s.size());
  const std::vector<double> density(spectrum.density.data(), spectrum.density.data() + spectrum.density.size());
  Series s;
  s.x = frequency;
  for (const double v : density) s.y.push_back(v * k * k);
  s.label = c.statistics.spectral_peak_period_s > 0
                ? fmt::format("Welch, {} segments; Tp {:.1f} s", spectrum.segments, c.statistics.spectral_peak_period_s)
                : "Welch";
  s.color = palette(color);
  s.line_width = 1.1;
  p.series.push_back(std::move(s));
  double ymax = 0;
  for (const double v : p.series.front().y) ymax = std::max(ymax, v);
  p.y_range = std::pair{0.0, ymax > 0 ? ymax * 1.1 : 1.0};
  // Frequency axis to twice the frequency below which 99.9 % of the variance
  // lies: slow-drift spectra sit far below the record's last significant bin.
  double total = 0, cumulative = 0;
  for (const double v : density) total += v;
  for (std::size_t i = 0; i < density.size(); ++i) {
    cumulative += density[i];
    if (cumulative >= kShownVarianceFraction * total) {
      p.x_range = std::pair{0.0, std::min(frequency.back(), 2.0 * frequency[i])};
      break;
    }
  }
  return p;
}

TableCell opt(const std::optional<double>& v, int decimals, double scale) {
  return v ? num(*v, decimals, scale) : text("–");
}

}  // namespace

std::size_t envelope_bin_samples(std::size_t samples) {
  return std::max<std::size_t>(1, (samples + kEnvelopeBins - 1) / kEnvelopeBins);
}

Series time_envelope(const std::vector<double>& t, const std::vector<double>& v, double scale) {
  Series s;
  const std::size_t n = std::min(t.size(), v.size());
  const std::size_t per = envelope_bin_samples(n);
  for (std::size_t b = 0; b < n; b += per) {
    const std::size_t e = std::min(n, b + per);
    const auto [lo, hi] =
        std::minmax_element(v.begin() + static_cast<std::ptrdiff_t>(b), v.begin() + static_cast<std::ptrdiff_t>(e));
    // In time order within the bin, so the polyline does not fold back.
    const bool lo_first = lo < hi;
    const auto first = lo_first ? lo : hi, second = lo_first ? hi : lo;
    s.x.push_back(t[static_cast<std::size_t>(first - v.begin())]);
    s.y.push_back(*first * scale);
    if (per > 1) {
      s.x.push_back(t[static_cast<std::size_t>(second - v.begin())]);
      s.y.push_back(*second * scale);
    }
  }
  s.line_width = 0.5;
  return s;
}

Figure plot_panels(std::string id, std::string caption, double aspect, std::vector<Plot> plots, int cols) {
  Figure f{std::move(id), std::move(caption), aspect, std::nullopt, nullptr};
  f.draw = [plots = std::move(plots), cols](cairo_t* cr, double w, double h) {
    const int rows =
        static_cast<int>((plots.size() + static_cast<std::size_t>(cols) - 1) / static_cast<std::size_t>(cols));
    const double pw = w / cols, ph = h / std::max(1, rows);
    for (std::size_t i = 0; i < plots.size(); ++i) {
      cairo_save(cr);
      cairo_translate(cr, pw * static_cast<double>(i % static_cast<std::size_t>(cols)),
                      ph * static_cast<double>(i / static_cast<std::size_t>(cols)));
      draw_plot(cr, plots[i], pw - 6, ph - 6);
      cairo_restore(cr);
    }
  };
  return f;
}

std::vector<Block> storm_blocks(const design::StageDynamics& d, const std::string& id) {
  std::vector<Block> out;
  std::vector<Plot> motion, spectra;
  for (const char* name : {"surge", "sway", "yaw", "offset"}) {
    if (const design::StormChannel* c = d.channel(name)) {
      motion.push_back(time_plot(d, *c, motion.size()));
      spectra.push_back(spectrum_plot(*c, spectra.size()));
    }
  }
  out.emplace_back(plot_panels(
      id + "-motions",
      fmt::format("Hull motions of the reference point in case {} ({}, {:.0f} s, seed {}): surge, sway, yaw "
                  "and the horizontal offset √(x² + y²) from the rest position; dashed: the mean (grey) and the "
                  "MPM of the 3-h maximum (red, Gumbel). Each plotted point pair is the min and max of {} s.",
                  d.case_name, design::to_string(d.level), d.duration_s, d.seed,
                  d.output_step_s * static_cast<double>(envelope_bin_samples(d.times_s.size()))),
      1.25, std::move(motion), 2));
  out.emplace_back(plot_panels(id + "-spectra",
                               "One-sided Welch spectra of the same channels (Hann window, 50 % overlap), up to "
                               "the frequency beyond which less than 1e-6 of the variance lies.",
                               1.3, std::move(spectra), 2));
  // Heave, roll, pitch and the hang-off's vertical motion: what the
  // wave-frequency response drives (each spectrum shows its wave peak).
  std::vector<Plot> vertical, vertical_spectra;
  const design::StormChannel* hang_off = nullptr;
  for (const design::StormChannel& c : d.channels) {
    const bool shown =
        c.name == "heave" || c.name == "roll" || c.name == "pitch" || c.name.starts_with(design::kHangOffHeavePrefix);
    if (!shown) continue;
    if (c.name.starts_with(design::kHangOffHeavePrefix)) hang_off = &c;
    vertical.push_back(time_plot(d, c, vertical.size()));
    vertical_spectra.push_back(spectrum_plot(c, vertical_spectra.size()));
  }
  if (!vertical.empty()) {
    out.emplace_back(plot_panels(
        id + "-vertical",
        fmt::format("Heave, roll and pitch of the reference point{} in case {} ({}), as above.",
                    hang_off ? fmt::format(", and the vertical motion of the riser hang-off that moves most ({})",
                                           hang_off->name.substr(design::kHangOffHeavePrefix.size()))
                             : std::string(),
                    d.case_name, design::to_string(d.level)),
        1.25, std::move(vertical), 2));
    out.emplace_back(plot_panels(id + "-vertical-spectra",
                                 "One-sided Welch spectra of heave, roll, pitch and the hang-off's vertical motion: "
                                 "the wave-frequency band, and the hull's own resonances beside it (a semi's "
                                 "heave, roll and pitch periods lie above the waves').",
                                 1.3, std::move(vertical_spectra), 2));
  }
  if (const design::StormChannel* tension = d.tension()) {
    const design::StormChannel& t = *tension;
    Plot series = time_plot(d, t, 4);  // not red: the MPM line is
    const bool coupled = d.tension_source == design::TensionSource::coupled;
    series.title = fmt::format("{} fairlead tension, {}", coupled ? "Coupled" : "Quasi-static", d.most_loaded_line);
    Plot spectrum = spectrum_plot(t, 4);
    out.emplace_back(plot_panels(
        id + "-tension",
        fmt::format("{} fairlead tension of the most loaded line, {} ({}), and its spectrum.",
                    coupled ? "Coupled" : "Quasi-static", d.most_loaded_line,
                    coupled ? "the dynamic FE line's top tension, integrated with the hull"
                            : "elastic catenary at the instantaneous fairlead position at every output step"),
        1.25, {series, spectrum}, 1));
  }
  Table stats{id + "-statistics",
              fmt::format("Statistics of the storm, case {} ({}); MPM: most probable 3-h extreme, Gumbel fit "
                          "to 10 segment maxima (Weibull fit to the upper half of the peaks for comparison).",
                          d.case_name, design::to_string(d.level)),
              {"Channel", "Unit", "Mean", "Std", "Min", "Max", "MPM max", "MPM max Weibull", "MPM min", "Tp (s)"},
              {}};
  for (const auto& c : d.channels) {
    const double k = display_scale(c);
    const int dec = c.unit == "N" ? 1 : 3;
    stats.rows.push_back(
        {text(c.name), text(display_unit(c)), num(c.moments().mean, dec, k), num(c.moments().std_dev, dec, k),
         num(c.moments().minimum, dec, k), num(c.moments().maximum, dec, k), opt(c.mpm_max(), dec, k),
         opt(c.mpm_max_weibull(), dec, k), opt(c.mpm_min(), dec, k),
         c.statistics.spectral_peak_period_s > 0 ? num(c.statistics.spectral_peak_period_s, 1) : text("–")});
  }
  out.emplace_back(stats);
  return out;
}

Section dynamics_section(const design::StageDynamics& d, const std::string& code) {
  Section s{"Dynamics: S-C storm", {}, true};
  s.blocks.emplace_back(Paragraph{fmt::format(
      "Time-domain analysis at the {} level of case {} ({}{}), chosen as {}: {:.0f} s (3 h) at a {:g} s output "
      "step, seed {}, integrated from the stage's static equilibrium of the case. Wall-clock cost {:.2f} s "
      "(line reduction and damping {:.2f} s, forcing {:.2f} s, hull dynamics {:.2f} s, {} steps, fairlead "
      "tensions {:.2f} s; the static equilibrium was reused from the static cases).",
      design::to_string(d.level), d.case_name, design::to_string(d.integrity),
      d.damaged_line ? fmt::format(", {} removed", *d.damaged_line) : std::string(), d.selection, d.duration_s,
      d.output_step_s, d.seed, d.wall_s, d.timing.reduction_s, d.timing.forcing_s,
      d.timing.dynamics_s + d.timing.wave_frequency_s, d.solver_steps, d.timing.tensions_s)});
  for (Block& b : storm_blocks(d, "storm")) s.blocks.push_back(std::move(b));
  Table checks{"storm-checks",
               fmt::format("Dynamic checks of the storm. Tension: {} with the MPM fairlead tension against the "
                           "fairlead segment's MBL (dynamic factor {:.2f}). Offset: the most probable 3-h "
                           "maximum of offset / SOZ allowable in the offset's direction (Weibull fit to the "
                           "record's peaks), shown as an offset where the record comes closest to the zone.",
                           code, d.dynamic_safety_factor),
               {"Check", "Item", "Value", "Limit", "Utilization", "Result"},
               {}};
  if (const design::StormChannel* tension = d.tension()) {
    const auto& t = *tension;
    checks.rows.push_back({text("dynamic tension"), text(d.most_loaded_line),
                           text(fmt::format("MPM {:.1f} kN", t.mpm_max().value_or(t.moments().maximum) * 1e-3)),
                           text(fmt::format("MBL {:.0f} kN", d.fairlead_mbl_N * 1e-3)), num(d.tension_utilization, 3),
                           verdict(d.tension_pass)});
  }
  if (d.extreme_offset) {
    const auto& e = *d.extreme_offset;
    checks.rows.push_back({text("extreme offset (SOZ)"), text(e.governing_riser),
                           text(fmt::format("{:.1f} m towards {:.0f}°", e.offset_m, e.direction_deg)),
                           text(fmt::format("{:.1f} m", e.allowable_m)), num(e.ratio, 3), verdict(e.passes)});
  }
  s.blocks.emplace_back(checks);
  for (const std::string& note : d.notes) s.blocks.emplace_back(note_paragraph(note));
  return s;
}

}  // namespace spiral::report
