#include "report/soz_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "report/plot.hpp"
#include "report/table_cells.hpp"

namespace spiral::report {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr Rgb kIntactColor{0.12, 0.47, 0.71};
constexpr Rgb kDamagedColor{0.84, 0.15, 0.16};
constexpr Rgb kExtremeColor{0.58, 0.40, 0.74};

/// Governing criterion of the grid direction nearest to `deg`.
const std::string& criterion_near(const design::SozResult& z, const design::RiserSoz& r, double deg) {
  const double step = z.options.step_deg;
  const double x = std::fmod(std::fmod(deg, 360.0) + 360.0, 360.0) / step;
  return r.directions[static_cast<std::size_t>(std::lround(x)) % r.directions.size()].governing_criterion;
}

std::string model_text(const design::SozResult& z) {
  return fmt::format(
      "{} model, {:g}° direction step, tolerance {:g} m, search limit {:g} % of depth "
      "({:.0f} m)",
      design::to_string(z.options.model), z.options.step_deg, z.options.tolerance_m, z.options.search_limit_pct_depth,
      z.options.search_limit_pct_depth / 100.0 * z.depth_m);
}

Figure plan_figure(const design::SozResult& z, const std::vector<design::OffsetCheck>& extremes,
                   std::optional<double> offset_limit_m) {
  Plot plot;
  plot.title = "Riser safe operational zones (plan view)";
  plot.x_label = "Hull offset x (m)";
  plot.y_label = "Hull offset y (m)";
  plot.equal_aspect = true;
  plot.legend_columns = 1;
  // The risers that set part of the platform zone get a colour and a key;
  // the others are drawn light grey under one key (12 keys would hide the zone).
  std::size_t coloured = 0;
  bool other_keyed = false;
  for (const auto& riser : z.risers) {
    std::vector<double> a;
    for (const auto& d : riser.directions) a.push_back(d.allowable_offset_m);
    Series s = polar_polygon(z.directions_deg, a);
    // Where every riser reaches the search limit the "governing" riser is just the first one.
    bool governs = false;
    for (std::size_t k = 0; k < z.platform.governing_riser.size(); ++k)
      governs = governs ||
                (z.platform.governing_riser[k] == riser.name && z.platform.governing_criterion[k] != "search_limit");
    if (governs) {
      s.label = riser.name + " (governs)";
      s.color = palette(coloured++);
      s.line_width = 0.9;
    } else {
      s.label = other_keyed ? "" : "other risers";
      other_keyed = true;
      s.color = {0.72, 0.72, 0.75};
      s.line_width = 0.6;
    }
    plot.series.push_back(std::move(s));
  }
  Series platform = polar_polygon(z.directions_deg, z.platform.allowable_offset_m);
  platform.label = "platform SOZ (intersection)";
  platform.color = {0.05, 0.05, 0.08};
  platform.line_width = 2.6;
  plot.series.push_back(std::move(platform));
  Series intact, damaged;
  intact.label = "static offset, intact";
  damaged.label = "static offset, damaged";
  for (Series* s : {&intact, &damaged}) s->line_width = 0, s->markers = true;
  intact.color = kIntactColor;
  damaged.color = kDamagedColor, damaged.marker = Marker::triangle;
  for (std::size_t i = 0; i < z.offset_checks.size(); ++i) {
    const design::OffsetCheck& c = z.offset_checks[i];
    Series& s = c.integrity == design::LineIntegrity::damaged ? damaged : intact;
    const double x = c.offset_m * std::cos(c.direction_deg * kDegToRad),
                 y = c.offset_m * std::sin(c.direction_deg * kDegToRad);
    s.x.push_back(x);
    s.y.push_back(y);
    plot.labels.push_back({x, y, std::to_string(i + 1)});
  }
  for (Series* s : {&intact, &damaged})
    if (!s->x.empty()) plot.series.push_back(*s);
  if (!extremes.empty()) {
    Series s;
    s.label = "MPM offset (3-h S-C storm)";
    s.line_width = 0, s.markers = true, s.marker = Marker::diamond, s.color = kExtremeColor;
    for (const design::OffsetCheck& e : extremes) {
      s.x.push_back(e.offset_m * std::cos(e.direction_deg * kDegToRad));
      s.y.push_back(e.offset_m * std::sin(e.direction_deg * kDegToRad));
      // Numbered like the static offsets of the same case.
      for (std::size_t i = 0; i < z.offset_checks.size(); ++i)
        if (z.offset_checks[i].case_name == e.case_name)
          plot.labels.push_back({s.x.back(), s.y.back(), std::to_string(i + 1)});
    }
    plot.series.push_back(std::move(s));
  }
  if (offset_limit_m) {
    plot.circles.push_back(
        {0, 0, *offset_limit_m, fmt::format("offset limit {:.0f} m", *offset_limit_m), {0.5, 0.5, 0.5}, true});
  }
  std::string key;
  for (std::size_t i = 0; i < z.offset_checks.size(); ++i)
    key += fmt::format("{}{} {}", i ? "; " : "", i + 1, z.offset_checks[i].case_name);
  Figure f{"soz-plan",
           fmt::format("Allowable hull offset per direction of every riser (thin) and of the platform "
                       "(bold: the intersection), still water, {}; a zone drawn at the search limit "
                       "found no failure within it. Markers: static offsets of the load cases ({}), "
                       "circles intact, triangles damaged{}.",
                       model_text(z), key, extremes.empty() ? "" : ", diamonds the MPM offsets of the S-C storms"),
           1.2, std::nullopt, nullptr};
  f.draw = [plot](cairo_t* cr, double w, double h) { draw_plot(cr, plot, w, h); };
  return f;
}

}  // namespace

Section soz_section(const design::SozResult& z, const std::vector<design::OffsetCheck>& extremes,
                    std::optional<double> offset_limit_m) {
  Section s{"Riser safe operational zones", {}, true};
  s.blocks.emplace_back(
      Paragraph{fmt::format("For each riser, the largest horizontal hull offset per direction for which every riser "
                            "criterion holds (DESIGN.md §7), from riser statics with the hang-off displaced by the "
                            "offset: {}. Zones in still water (no current on the risers, no mean heave or rotations) "
                            "with the normal design condition; {} riser solves in {:.2f} s on {} threads. The platform "
                            "zone is their intersection; each load case's static offset is checked against it "
                            "(margin = allowable − offset, ratio = offset / allowable ≤ 1 passes).",
                            model_text(z), z.solves, z.zone_wall_s, z.threads)});
  if (z.options.model == design::SozModel::catenary) {
    s.blocks.emplace_back(
        Paragraph{"Screening model: the catenary carries no current and no bending stiffness (TDP curvature "
                  "from the boundary-layer estimate). The static-case riser checks above use FE risers with "
                  "each case's current; set stages[].soz.model: fe for the FE zones."});
  }
  s.blocks.emplace_back(plan_figure(z, extremes, offset_limit_m));

  Table groups{"soz-riser-directions",
               "Allowable offset of each riser at its near (towards its azimuth), far and cross "
               "positions, with the governing criterion there.",
               {"Riser", "Azimuth (°)", "At rest", "Near (m)", "Near crit.", "Far (m)", "Far crit.", "Cross +90° (m)",
                "Cross −90° (m)", "Cross crit."},
               {}};
  for (const auto& x : z.risers) {
    const std::string& cross = x.cross_left_m <= x.cross_right_m ? criterion_near(z, x, x.azimuth_deg + 90.0)
                                                                 : criterion_near(z, x, x.azimuth_deg - 90.0);
    groups.rows.push_back({text(x.name), num(x.azimuth_deg, 1),
                           text(fmt::format("{} {:.3f}", x.zero_offset_governing_criterion, x.zero_offset_utilization)),
                           num(x.near_m, 1), text(x.near_governing), num(x.far_m, 1), text(x.far_governing),
                           num(x.cross_left_m, 1), num(x.cross_right_m, 1), text(cross)});
  }
  s.blocks.emplace_back(groups);

  Table platform{"soz-platform",
                 "Platform zone per direction: the smallest allowable offset over the risers and the "
                 "riser and criterion that set it.",
                 {"Direction (°)", "Allowable (m)", "% depth", "Governing riser", "Criterion"},
                 {}};
  for (std::size_t k = 0; k < z.directions_deg.size(); ++k) {
    const double a = z.platform.allowable_offset_m[k];
    platform.rows.push_back({num(z.directions_deg[k], 0), num(a, 1), num(a / z.depth_m * 100.0, 2),
                             text(z.platform.governing_riser[k]), text(z.platform.governing_criterion[k])});
  }
  s.blocks.emplace_back(platform);

  Table check{"soz-offset-check",
              "Offset check against the platform zone: static (mean) offsets of every load case"
              " and the MPM offsets of the S-C storms where they ran.",
              {"Case", "Condition", "Kind", "Offset (m)", "Dir (°)", "Allowable (m)", "Margin (m)", "Ratio",
               "Governing riser", "Check"},
              {}};
  std::vector<design::OffsetCheck> rows = z.offset_checks;
  rows.insert(rows.end(), extremes.begin(), extremes.end());
  for (const auto& c : rows) {
    check.rows.push_back({text(c.case_name), text(design::to_string(c.integrity)), text(design::to_string(c.kind)),
                          num(c.offset_m, 2), num(c.direction_deg, 1), num(c.allowable_m, 1), num(c.margin_m, 1),
                          num(c.ratio, 3), text(c.governing_riser), verdict(c.passes)});
  }
  s.blocks.emplace_back(check);
  for (const std::string& note : z.notes) s.blocks.emplace_back(note_paragraph(note));
  return s;
}

}  // namespace spiral::report
