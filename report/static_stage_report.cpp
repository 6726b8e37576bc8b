// The preliminary stage's report: one function per section, in report order.
// Past ~600 lines because the stage has that many sections (pretensions,
// cases, restoring curves, code check, riser criteria, SOZ, storm, verdict);
// the shared pieces (SOZ, storm, scenes) are already in their own files.
#include "report/static_stage_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <cmath>
#include <numbers>

#include "report/color_map.hpp"
#include "report/plot.hpp"
#include "report/render3d.hpp"
#include "report/stage_scene.hpp"
#include "report/table_cells.hpp"
#include "report/soz_section.hpp"
#include "report/dynamics_section.hpp"

namespace spiral::report {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kN = 1e-3;  // N -> kN

std::string case_label(const design::StaticCaseResult& c) {
  return c.damaged_line ? fmt::format("{} (damaged: {})", c.case_name, *c.damaged_line) : c.case_name;
}

Figure view_figure(const design::Project& project, const design::StaticStageResults& r, std::size_t case_index,
                   ViewKind kind, const StaticStageReportOptions& options) {
  const design::StaticCaseResult& result = r.cases[case_index];
  const Scene scene = stage_scene(project, result, r.strengths, r.checks[case_index].safety_factor, r.hull_panels_b);
  ViewOptions view;
  view.width = options.view_width;
  view.height = options.view_height;
  const char* kind_name = kind == ViewKind::iso         ? "iso"
                          : kind == ViewKind::plan      ? "plan"
                          : kind == ViewKind::elevation ? "elevation"
                                                        : "hull";
  const char* kind_title = kind == ViewKind::iso         ? "Overview"
                           : kind == ViewKind::plan      ? "Plan view"
                           : kind == ViewKind::elevation ? "Elevation (looking +y)"
                                                         : "Hull close-up";
  view.title = fmt::format("{} — {}", kind_title, result.case_name);
  Figure f;
  f.id = fmt::format("view-{}-{}", slug(result.case_name), kind_name);
  f.aspect = static_cast<double>(view.width) / view.height;
  f.image = render_view(scene, frame_view(scene, kind, f.aspect), view);
  f.caption = fmt::format(
      "{}, case {}: hull at its static equilibrium (offset {:.2f} m towards {:.1f}°), mooring "
      "lines coloured by "
      "code utilization T·SF/MBL along the line (SF {:.2f}), risers (thin) as solved by FE "
      "statics in the same case, on the same scale by their own utilization (von Mises over the "
      "steel wall with the condition's design factor; curvature × minimum bending radius for "
      "flexible pipes). Line "
      "thickness is exaggerated for visibility.",
      kind_title, case_label(result), result.offset_summary.horizontal_m, result.offset_summary.direction_deg,
      r.checks[case_index].safety_factor);
  return f;
}

}  // namespace

Section model_summary_section(const design::ValidatedProject& vp, const std::string& code) {
  const design::Project& p = vp.project;
  Section s{"Model summary", {}, true};
  KeyValues kv;
  kv.items.reserve(16);  // also keeps GCC 12's -Warray-bounds false positive on the first emplace away
  kv.items.emplace_back("Water depth", fmt::format("{:g} m", p.site.depth_m));
  kv.items.emplace_back("Water density, gravity",
                        fmt::format("{:g} kg/m³, {:g} m/s²", p.site.water_density_kg_per_m3, p.site.gravity_m_per_s2));
  kv.items.emplace_back("Seabed friction (axial, lateral)",
                        fmt::format("{:g}, {:g}", p.site.seabed.friction_axial, p.site.seabed.friction_lateral));
  kv.items.emplace_back("Hull mass", fmt::format("{:.0f} t", p.hull.mass_kg / 1000.0));
  if (p.hull.displaced_volume_m3)
    kv.items.emplace_back("Displaced volume", fmt::format("{:.0f} m³", *p.hull.displaced_volume_m3));
  kv.items.emplace_back("Hull reference point",
                        fmt::format("({:g}, {:g}, {:g}) m", p.hull.reference_point_g.x(), p.hull.reference_point_g.y(),
                                    p.hull.reference_point_g.z()));
  kv.items.emplace_back("Hull geometry",
                        p.hull.geometry ? fmt::format("{} columns, {} pontoons/braces", p.hull.geometry->columns.size(),
                                                      p.hull.geometry->pontoons.size())
                                        : std::string("none given (drawn as a box)"));
  if (p.hull.geometry && p.hull.geometry->panel_mesh) {
    kv.items.emplace_back("Hull panel mesh", fmt::format("{} (drawn as the hull in the 3D views)",
                                                         p.hull.geometry->panel_mesh->filename().string()));
  }
  kv.items.emplace_back("Mooring", fmt::format("{} lines, {} risers", p.mooring.lines.size(), p.risers.size()));
  kv.items.emplace_back("Mooring code", fmt::format("{}: SF intact {:.2f}, damaged {:.2f} (quasi-static)", code,
                                                    design::mooring_safety_factor(p.criteria.mooring, false),
                                                    design::mooring_safety_factor(p.criteria.mooring, true)));
  if (p.criteria.max_offset_pct_depth) {
    kv.items.emplace_back("Offset limit", fmt::format("{:g} % of depth = {:.1f} m", *p.criteria.max_offset_pct_depth,
                                                      *p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m));
  }
  if (const auto& length = p.global_analysis.element_length_m) {
    kv.items.emplace_back("Global-analysis mesh",
                          fmt::format("{:g} m elements on every line in the coupled runs and dynamic tensions (statics "
                                      "and riser checks on each line's own mesh)",
                                      *length));
  }
  s.blocks.emplace_back(kv);

  Table types{"line-types",
              "Line types (resolved properties; formulas in docs/line-types.md).",
              {"Type", "Kind", "D nom (mm)", "Mass (kg/m)", "Wet weight (N/m)", "EA (MN)", "MBL (kN)"},
              {}};
  for (const auto& t : vp.line_types) {
    types.rows.push_back({text(t.name), text(design::to_string(t.kind)), num(t.nominal_diameter_m, 0, 1000.0),
                          num(t.mass_per_length_kg_per_m, 1), num(t.submerged_weight_N_per_m, 0),
                          num(t.axial_stiffness_N, 0, 1e-6), num(t.breaking_load_N, 0, kN)});
  }
  s.blocks.emplace_back(types);

  Table lines{"mooring-lines",
              "Mooring lines: anchor (global) and fairlead (hull body frame), segments anchor to fairlead.",
              {"Line", "Anchor x (m)", "Anchor y (m)", "Anchor z (m)", "Fairlead x (m)", "Fairlead y (m)",
               "Fairlead z (m)", "Length (m)", "Segments"},
              {}};
  for (const auto& l : p.mooring.lines) {
    double length = 0;
    std::string segs;
    for (const auto& seg : l.segments) {
      length += seg.length_m;
      segs += (segs.empty() ? "" : " + ") + fmt::format("{} {:g}", seg.type, seg.length_m);
    }
    lines.rows.push_back({text(l.name), num(l.anchor_g.x(), 1), num(l.anchor_g.y(), 1), num(l.anchor_g.z(), 1),
                          num(l.fairlead_b.x(), 2), num(l.fairlead_b.y(), 2), num(l.fairlead_b.z(), 2), num(length, 1),
                          text(segs)});
  }
  s.blocks.emplace_back(lines);

  if (!p.risers.empty()) {
    Table risers{"risers",
                 "Risers.",
                 {"Riser", "Kind", "Azimuth (°)", "Top angle (°)", "Length (m)", "OD (mm)", "Hang-off z (m)"},
                 {}};
    for (const auto& rr : p.risers) {
      double length = 0;
      for (const auto& sec : rr.sections) length += sec.length_m;
      risers.rows.push_back({text(rr.name), text(design::to_string(rr.kind)), num(rr.azimuth_rad * kRadToDeg, 1),
                             num(rr.top_angle_rad * kRadToDeg, 1), num(length, 0),
                             num(rr.sections.empty() ? 0.0 : rr.sections.front().outer_diameter_m, 1, 1000.0),
                             num(rr.hang_off_b.z(), 1)});
    }
    s.blocks.emplace_back(risers);
  }
  return s;
}

Section load_cases_section(const design::Project& p) {
  Section s{"Load cases", {}, true};
  s.blocks.emplace_back(
      Paragraph{"Headings are directions of propagation, degrees counter-clockwise from global +x. "
                "Current: surface speed of the profile."});
  Table t{"load-cases",
          "Load cases and their environments.",
          {"Case", "Environment", "Damaged line", "Riser condition", "Hs (m)", "Tp (s)", "Wave dir (°)", "Wind (m/s)",
           "Wind dir (°)", "Current (m/s)", "Current dir (°)"},
          {}};
  for (const auto& lc : p.load_cases) {
    const design::Environment* env = nullptr;
    for (const auto& e : p.environments)
      if (e.name == lc.environment) env = &e;
    auto opt = [](bool has, double v, int d) { return has ? num(v, d) : text("–"); };
    const bool w = env && env->waves, wi = env && env->wind, c = env && env->current && !env->current->profile.empty();
    t.rows.push_back({text(lc.name), text(lc.environment), text(lc.damaged_line.value_or("–")),
                      text(design::to_string(lc.condition)), opt(w, w ? env->waves->hs_m : 0, 1),
                      opt(w, w ? env->waves->tp_s : 0, 1), opt(w, w ? env->waves->heading_rad * kRadToDeg : 0, 0),
                      opt(wi, wi ? env->wind->speed_m_per_s : 0, 1),
                      opt(wi, wi ? env->wind->heading_rad * kRadToDeg : 0, 0),
                      opt(c, c ? env->current->profile.front().speed_m_per_s : 0, 2),
                      opt(c, c ? env->current->heading_rad * kRadToDeg : 0, 0)});
  }
  s.blocks.emplace_back(t);
  return s;
}

namespace {

Figure profile_figure(const design::StaticsResult& pre, const design::StaticStageResults& r, const design::Project& p) {
  Plot plot;
  plot.title = "Line profiles at zero offset";
  plot.x_label = "Horizontal distance from the hull reference point (m)";
  plot.y_label = "Elevation z (m)";
  const auto& still_water_risers = r.cases.front().risers;
  for (const auto& riser : still_water_risers) {
    Series s;
    for (const auto& q : riser.profile) {
      s.x.push_back((q.position_g - p.hull.reference_point_g).head<2>().norm());
      s.y.push_back(q.position_g.z());
    }
    s.color = {0.62, 0.62, 0.66};
    s.line_width = 0.7;
    s.label = &riser == &still_water_risers.front() ? "risers (FE statics)" : "";
    plot.series.push_back(std::move(s));
  }
  for (std::size_t i = 0; i < pre.lines.size(); ++i) {
    Series s;
    s.label = pre.lines[i].name;
    for (const auto& q : pre.lines[i].profile) {
      s.x.push_back((q.position_g - p.hull.reference_point_g).head<2>().norm());
      s.y.push_back(q.position_g.z());
    }
    s.color = palette(i);
    s.line_width = 0.9;
    plot.series.push_back(std::move(s));
  }
  Series seabed;
  seabed.x = {0.0, 0.0};
  seabed.y = {-p.site.depth_m, -p.site.depth_m};
  for (const auto& s : plot.series)
    seabed.x[1] = std::max(seabed.x[1], s.x.empty() ? 0.0 : *std::max_element(s.x.begin(), s.x.end()));
  seabed.color = {0.55, 0.45, 0.3};
  seabed.line_width = 1.6;
  seabed.label = "seabed";
  plot.series.push_back(seabed);
  plot.legend_columns = 3;
  Figure f{"profiles-zero-offset",
           "Elevation of every mooring line at zero offset (pretension), each in its own "
           "vertical plane, against the horizontal distance from the hull reference point; risers "
           "as solved by FE statics in still water.",
           1.45, std::nullopt, nullptr};
  f.draw = [plot](cairo_t* cr, double w, double h) { draw_plot(cr, plot, w, h); };
  return f;
}

Figure tension_figure(const design::StaticStageResults& r, const design::Project& p) {
  const auto& check = r.checks[static_cast<std::size_t>(r.worst_case)];
  const auto& result = r.cases[static_cast<std::size_t>(r.worst_case)];
  const auto& row = result.lines[static_cast<std::size_t>(std::max(0, check.governing_line))];
  const design::LineStrength* strength = nullptr;
  for (const auto& s : r.strengths)
    if (s.name == row.name) strength = &s;
  Plot plot;
  plot.title = fmt::format("Effective tension along {} — {}", row.name, result.case_name);
  plot.x_label = "Unstretched arc length from the anchor (m)";
  plot.y_label = "Tension (kN)";
  Series t{"tension", {}, {}, {0.12, 0.47, 0.71}, 1.5, false, false, false};
  Series allow{
      fmt::format("allowable MBL/SF (SF {:.2f})", check.safety_factor), {}, {}, kFailColor, 1.0, true, false, false};
  int last_segment = -1;
  for (const auto& q : row.profile) {
    t.x.push_back(q.arc_length_m);
    t.y.push_back(q.tension_N * kN);
    if (strength && q.segment < static_cast<int>(strength->segment_mbl_N.size())) {
      const double a = strength->segment_mbl_N[static_cast<std::size_t>(q.segment)] / check.safety_factor * kN;
      if (q.segment != last_segment && !allow.x.empty()) {
        allow.x.push_back(q.arc_length_m);
        allow.y.push_back(allow.y.back());
      }
      allow.x.push_back(q.arc_length_m);
      allow.y.push_back(a);
      last_segment = q.segment;
    }
  }
  plot.series = {t, allow};
  double ymax = 0;
  for (const double v : allow.y) ymax = std::max(ymax, v);
  for (const double v : t.y) ymax = std::max(ymax, v);
  plot.y_range = std::pair{0.0, ymax * 1.08};
  (void)p;
  Figure f{"tension-most-loaded-line",
           fmt::format("Effective tension along the most utilized line, {}, in the governing case {} (code "
                       "utilization {:.3f}), with the allowable tension of each segment's line type.",
                       row.name, case_label(result),
                       check.lines[static_cast<std::size_t>(std::max(0, check.governing_line))].utilization),
           1.8, std::nullopt, nullptr};
  f.draw = [plot](cairo_t* cr, double w, double h) { draw_plot(cr, plot, w, h); };
  return f;
}

Figure restoring_figure(const design::StaticStageResults& r, const design::Project& p) {
  Plot plot;
  plot.title = "Restoring force of the line array";
  plot.x_label = "Horizontal offset of the hull (m)";
  plot.y_label = "Restoring force (kN)";
  std::size_t i = 0;
  for (const auto& c : r.restoring) {
    Series s;
    s.label = fmt::format("offset towards {:g}°", c.direction_deg);
    s.x = c.offset_m;
    for (const double f : c.force_N) s.y.push_back(f * kN);
    s.color = palette(i++);
    s.markers = true;
    s.line_width = 1.4;
    plot.series.push_back(std::move(s));
  }
  if (p.criteria.max_offset_pct_depth) {
    plot.x_lines.emplace_back(*p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m, "offset limit");
  }
  plot.legend_left = true;
  Figure f{"restoring-curves",
           fmt::format("Horizontal restoring force of the mooring lines against a pure horizontal "
                       "offset of the hull "
                       "(no heave or rotation), 0 to {:g} % of the water depth in {} steps.",
                       design::kRestoringMaxOffsetFractionOfDepth * 100, design::kRestoringSteps),
           1.8, std::nullopt, nullptr};
  f.draw = [plot](cairo_t* cr, double w, double h) { draw_plot(cr, plot, w, h); };
  return f;
}

Figure utilization_figure(const design::StaticStageResults& r) {
  BarChart chart;
  chart.title = "Largest code utilization per line over all cases";
  chart.y_label = "Utilization T·SF/MBL (–)";
  chart.limit = 1.0;
  chart.limit_label = "limit 1.0";
  for (std::size_t l = 0; l < r.strengths.size(); ++l) {
    const std::string& name = r.strengths[l].name;
    double worst = 0;
    for (const auto& check : r.checks)
      for (const auto& line : check.lines)
        if (line.line == name) worst = std::max(worst, line.utilization);
    chart.bars.push_back({name, worst, utilization_color(worst), fmt::format("{:.2f}", worst)});
  }
  Figure f{"utilization-per-line",
           "Largest code utilization of each mooring line over still water and every load "
           "case (colours as in the 3D views; above 1 fails).",
           2.0, std::nullopt, nullptr};
  f.draw = [chart](cairo_t* cr, double w, double h) { draw_bar_chart(cr, chart, w, h); };
  return f;
}

Figure offsets_figure(const design::StaticStageResults& r, const design::Project& p) {
  Plot plot;
  plot.title = "Static offsets of the hull (plan view)";
  plot.x_label = "x offset (m)";
  plot.y_label = "y offset (m)";
  plot.equal_aspect = true;
  Series pts;
  pts.label = "equilibrium offset";
  pts.line_width = 0;
  pts.markers = true;
  // Cases are numbered; cases whose offsets coincide on the plot share one label.
  double extent = 1.0;
  for (const auto& c : r.cases) extent = std::max(extent, c.offset.head<2>().norm());
  if (p.criteria.max_offset_pct_depth)
    extent = std::max(extent, *p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m);
  // A label per point is unreadable beyond a few dozen cases (a load-case
  // matrix of hundreds): then only the largest offsets are numbered, and the
  // offsets table holds every case.
  constexpr std::size_t kAllLabelled = 24, kLargestLabelled = 8;
  std::vector<std::size_t> labelled(r.cases.size());
  std::iota(labelled.begin(), labelled.end(), std::size_t{0});
  const bool every_case = r.cases.size() <= kAllLabelled;
  if (!every_case) {
    std::stable_sort(labelled.begin(), labelled.end(), [&](std::size_t a, std::size_t b) {
      return r.cases[a].offset.head<2>().norm() > r.cases[b].offset.head<2>().norm();
    });
    labelled.resize(kLargestLabelled);
    std::sort(labelled.begin(), labelled.end());
  }
  for (const auto& c : r.cases) {
    pts.x.push_back(c.offset.x());
    pts.y.push_back(c.offset.y());
  }
  std::vector<std::pair<Eigen::Vector2d, std::string>> groups;
  std::string key;
  for (const std::size_t i : labelled) {
    const Eigen::Vector2d xy = r.cases[i].offset.head<2>();
    key += fmt::format("{}{} {}", key.empty() ? "" : "; ", i + 1, r.cases[i].case_name);
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const auto& g) { return (g.first - xy).norm() < 0.03 * extent; });
    if (it == groups.end())
      groups.emplace_back(xy, std::to_string(i + 1));
    else
      it->second += fmt::format(",{}", i + 1);
  }
  if (!every_case)
    key = fmt::format("the {} largest offsets of the {} cases are numbered (every case is in the offsets table): {}",
                      kLargestLabelled, r.cases.size(), key);
  for (const auto& [xy, label] : groups) plot.labels.push_back({xy.x(), xy.y(), label});
  plot.series.push_back(pts);
  if (p.criteria.max_offset_pct_depth) {
    const double limit = *p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m;
    plot.circles.push_back({0, 0, limit, fmt::format("offset limit {:.0f} m", limit), kFailColor, true});
  }
  Figure f{"offsets-plan",
           "Horizontal static offset of the hull reference point in each case, with the allowable "
           "offset circle (criteria.max_offset_pct_depth). Cases: " +
               key + ".",
           1.25, std::nullopt, nullptr};
  f.draw = [plot](cairo_t* cr, double w, double h) { draw_plot(cr, plot, w, h); };
  return f;
}

Section pretension_section(const design::ValidatedProject& vp, const design::StaticStageResults& r,
                           const StaticStageReportOptions& options) {
  Section s{"Pretensions (zero offset)", {}, true};
  Table t{"pretensions",
          "Every line solved as a multi-segment elastic catenary with the hull at rest.",
          {"Line", "T fair (kN)", "H fair (kN)", "V fair (kN)", "Angle (°)", "T anchor (kN)", "Uplift (°)", "Laid (m)",
           "T/MBL (–)", "Regime"},
          {}};
  for (const auto& l : r.pretension.lines) {
    t.rows.push_back({text(l.name), num(l.fairlead_tension_N, 1, kN), num(l.fairlead_horizontal_N, 1, kN),
                      num(l.fairlead_vertical_N, 1, kN), num(l.fairlead_angle_deg, 2), num(l.anchor_tension_N, 1, kN),
                      num(l.anchor_uplift_angle_deg, 2), num(l.laid_length_m, 1), num(l.utilization, 3),
                      text(engine::to_string(l.regime))});
  }
  s.blocks.emplace_back(t);
  s.blocks.emplace_back(profile_figure(r.pretension, r, vp.project));
  for (const ViewKind kind : {ViewKind::iso, ViewKind::plan, ViewKind::elevation, ViewKind::hull_closeup}) {
    s.blocks.emplace_back(view_figure(vp.project, r, 0, kind, options));
  }
  return s;
}

Section results_section(const design::ValidatedProject& vp, const design::StaticStageResults& r,
                        const StaticStageReportOptions& options) {
  const design::Project& p = vp.project;
  Section s{"Static-case results and code check", {}, true};
  s.blocks.emplace_back(
      Paragraph{fmt::format("Coupled static equilibrium of hull and lines for still water and "
                            "every load case (intact, or with the "
                            "case's damaged line removed). Code check {}: a line passes when "
                            "T_max·SF ≤ MBL of its governing segment, "
                            "SF {:.2f} intact and {:.2f} damaged; the offset passes when within "
                            "the limit. Env. force is the horizontal "
                            "mean environmental force on the hull that the equilibrium included.",
                            r.code, design::mooring_safety_factor(p.criteria.mooring, false),
                            design::mooring_safety_factor(p.criteria.mooring, true))});
  Table off{"offsets",
            "Static offsets of the hull reference point and the offset check.",
            {"Case", "Condition", "Env. force (kN)", "Offset (m)", "% depth", "Dir (°)", "Heave (m)", "Roll (°)",
             "Pitch (°)", "Yaw (°)", "Limit (m)", "Offset"},
            {}};
  Table summary{"code-check-summary",
                "Mooring code check per case: the governing line.",
                {"Case", "Condition", "SF", "Governing line", "T max (kN)", "T/MBL", "Utilization", "Lines", "Case"},
                {}};
  for (std::size_t i = 0; i < r.cases.size(); ++i) {
    const auto& c = r.cases[i];
    const auto& k = r.checks[i];
    const auto& o = c.offset_summary;
    off.rows.push_back({text(c.case_name), text(design::to_string(c.integrity)),
                        num(c.environment_force.head<2>().norm(), 1, kN), num(o.horizontal_m, 2),
                        num(o.horizontal_pct_depth, 3), num(o.direction_deg, 1), num(o.heave_m, 3), num(o.roll_deg, 3),
                        num(o.pitch_deg, 3), num(o.yaw_deg, 3),
                        k.offset_limit_m ? num(*k.offset_limit_m, 1) : text("–"), verdict(k.offset_pass)});
    if (k.governing_line >= 0) {
      const auto& g = k.lines[static_cast<std::size_t>(k.governing_line)];
      summary.rows.push_back({text(c.case_name), text(design::to_string(c.integrity)), num(k.safety_factor, 2),
                              text(g.line), num(g.max_tension_N, 1, kN), num(g.utilization_mbl, 3),
                              num(g.utilization, 3), verdict(k.lines_pass), verdict(k.pass)});
    }
  }
  s.blocks.emplace_back(off);
  s.blocks.emplace_back(summary);
  s.blocks.emplace_back(utilization_figure(r));
  s.blocks.emplace_back(offsets_figure(r, p));
  s.blocks.emplace_back(tension_figure(r, p));
  for (std::size_t i = 0; i < r.cases.size(); ++i) {
    const auto& c = r.cases[i];
    const auto& k = r.checks[i];
    Table t{fmt::format("lines-{}", slug(c.case_name)),
            fmt::format("Line tensions and code check, case {} (SF {:.2f}).", case_label(c), k.safety_factor),
            {"Line", "Pretension (kN)", "T fair (kN)", "T max (kN)", "T/MBL", "Utilization", "Check"},
            {}};
    for (std::size_t l = 0; l < c.lines.size(); ++l) {
      double pre = 0;
      for (const auto& pl : r.pretension.lines)
        if (pl.name == c.lines[l].name) pre = pl.fairlead_tension_N;
      t.rows.push_back({text(c.lines[l].name), num(pre, 1, kN), num(c.lines[l].fairlead_tension_N, 1, kN),
                        num(k.lines[l].max_tension_N, 1, kN), num(k.lines[l].utilization_mbl, 3),
                        num(k.lines[l].utilization, 3), verdict(k.lines[l].pass)});
    }
    s.blocks.emplace_back(t);
  }
  const auto worst = static_cast<std::size_t>(r.worst_case);
  if (worst != 0) {
    for (const ViewKind kind : {ViewKind::iso, ViewKind::plan, ViewKind::elevation}) {
      s.blocks.emplace_back(view_figure(p, r, worst, kind, options));
    }
  } else {
    s.blocks.emplace_back(Paragraph{"The governing case is still water: its 3D views are in the pretension section."});
  }
  return s;
}

Section riser_section(const design::StaticStageResults& r) {
  Section s{"Riser static results", {}, true};
  s.blocks.emplace_back(
      Paragraph{"Every riser solved by FE statics (bending, current, seabed contact) in each case, at the "
                "hull's equilibrium, and checked against the riser criteria of the project: von Mises "
                "utilization with the design factor of the case's condition (API RP 2RD style), minimum "
                "effective tension (a floor: pass/fail), top tension, top angle, flex-joint rotation and "
                "minimum bending radius where given. Utilization ≤ 1 passes; the governing criterion is "
                "the one closest to its limit."});
  Table summary{"riser-summary",
                "Riser checks per case: the governing riser and whether every riser passes.",
                {"Case", "Condition", "Design condition", "Governing riser", "Criterion", "Utilization", "Risers"},
                {}};
  for (const auto& c : r.cases) {
    if (c.risers.empty()) continue;
    const auto worst = std::max_element(c.risers.begin(), c.risers.end(),
                                        [](const auto& a, const auto& b) { return a.utilization < b.utilization; });
    const bool all_pass = std::all_of(c.risers.begin(), c.risers.end(), [](const auto& x) { return x.passes; });
    summary.rows.push_back({text(c.case_name), text(design::to_string(c.integrity)),
                            text(design::to_string(c.design_condition)), text(worst->name),
                            text(worst->governing_criterion), num(worst->utilization, 3), verdict(all_pass)});
  }
  s.blocks.emplace_back(summary);
  for (const auto& c : r.cases) {
    if (c.risers.empty()) continue;
    Table t{fmt::format("risers-{}", slug(c.case_name)),
            fmt::format("Risers, case {} ({} condition).", case_label(c), design::to_string(c.design_condition)),
            {"Riser", "T top (kN)", "Top angle (°)", "TDP (m)", "Te min (kN)", "R min (m)", "von Mises", "Governing",
             "Utilization", "Check"},
            {}};
    for (const auto& x : c.risers) {
      t.rows.push_back({text(x.name), num(x.top_tension_N, 1, kN), num(x.top_angle_deg, 2),
                        num(x.touchdown_distance_m, 1), num(x.min_effective_tension_N, 1, kN),
                        num(x.min_bending_radius_m, 1),
                        x.max_von_mises_utilization ? num(*x.max_von_mises_utilization, 3) : text("–"),
                        text(x.governing_criterion), num(x.utilization, 3), verdict(x.passes)});
    }
    s.blocks.emplace_back(t);
  }
  return s;
}

Section stiffness_section(const design::StaticStageResults& r, const design::Project& p) {
  Section s{"Stiffness and natural periods", {}, true};
  const auto& c = r.cases.front();
  const char* dof[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
  Table k{"stiffness-still-water",
          "6×6 line-array stiffness at the still-water equilibrium (analytic tangent). Units: kN/m "
          "(translation "
          "rows/columns), kN·m/rad and kN/rad (coupling), kN·m/rad (rotation).",
          {"", "surge", "sway", "heave", "roll", "pitch", "yaw"},
          {}};
  for (int i = 0; i < 6; ++i) {
    std::vector<TableCell> row{text(dof[i])};
    for (int j = 0; j < 6; ++j) {
      const double v = c.stiffness(i, j) * kN;
      row.push_back({std::abs(v) < 1e-6 ? std::string("0") : fmt::format("{:.4g}", v), v, CellStatus::none});
    }
    k.rows.push_back(std::move(row));
  }
  s.blocks.emplace_back(k);
  if (c.stiffness_check_relative_difference) {
    s.blocks.emplace_back(Paragraph{
        fmt::format("Cross-check by central finite differences of the line forces: ‖K − K_fd‖/‖K_fd‖ = {:.2e}.",
                    *c.stiffness_check_relative_difference)});
  }
  auto periods_table = [&](const char* id, const std::string& caption,
                           std::vector<design::NaturalMode> design::StaticCaseResult::*modes) {
    Table periods{id, caption, {"Case", "Mode 1", "Mode 2", "Mode 3", "Mode 4", "Mode 5", "Mode 6"}, {}};
    for (const auto& cs : r.cases) {
      const std::vector<design::NaturalMode>& list = cs.*modes;
      std::vector<TableCell> row{text(cs.case_name)};
      for (std::size_t m = 0; m < 6; ++m) {
        if (m < list.size()) {
          row.push_back(
              {fmt::format("{:.1f} {}", list[m].period_s, list[m].dominant_dof), list[m].period_s, CellStatus::none});
        } else {
          row.push_back(text("–"));
        }
      }
      periods.rows.push_back(std::move(row));
    }
    return periods;
  };
  s.blocks.emplace_back(
      periods_table("natural-periods",
                    fmt::format("Undamped natural periods of the moored hull (s) and their dominant DOF{}.",
                                c.added_mass_included ? ", added mass included" : ", without added mass"),
                    &design::StaticCaseResult::natural_modes));
  if (std::any_of(r.cases.begin(), r.cases.end(),
                  [](const design::StaticCaseResult& cs) { return cs.dynamic_stiffness_lines > 0; })) {
    s.blocks.emplace_back(periods_table(
        "natural-periods-dynamic",
        "The same with the polyester at its dynamic EA for the motions about each equilibrium (the "
        "static-dynamic convention of DNV-OS-E301 ch. 2 sec. 2 [2.4]): the periods the storms oscillate at.",
        &design::StaticCaseResult::dynamic_natural_modes));
  }
  s.blocks.emplace_back(restoring_figure(r, p));
  for (const auto& curve : r.restoring) {
    if (curve.stopped) {
      s.blocks.emplace_back(
          Paragraph{fmt::format("The sweep towards {:g}° stopped early: {}", curve.direction_deg, *curve.stopped)});
    }
  }
  return s;
}

}  // namespace

ReportDocument stage_document(const design::Project& p, const ReportInfo& info, const std::string& stage,
                              const std::string& code, const std::string& wall_time, const design::SozResult* soz) {
  ReportDocument doc;
  doc.title.project = p.name;
  doc.title.description = p.description.value_or("");
  doc.title.facts = {{"Project file", info.project_file},
                     {"Date", info.date},
                     {"spiral version", info.version},
                     {"Model hash", info.model_hash + " (FNV-1a 64 of the project file)"},
                     {"Stage", stage},
                     {"Mooring code", code},
                     {"Analysis wall time", wall_time}};
  if (soz) {
    doc.title.facts.emplace_back(
        "Riser SOZ",
        fmt::format("{} model, {:g}° step, still water", design::to_string(soz->options.model), soz->options.step_deg));
  }
  doc.running_header = fmt::format("spiral — {}", p.name);
  doc.running_footer =
      fmt::format("{} · model {} · spiral {} · {}", info.project_file, info.model_hash, info.version, info.date);
  return doc;
}

ReportDocument static_stage_report(const design::ValidatedProject& vp, const design::StaticStageResults& r,
                                   const ReportInfo& info, const StaticStageReportOptions& options) {
  const design::Project& p = vp.project;
  ReportDocument doc =
      stage_document(p, info, r.stage, r.code, fmt::format("{:.3f} s", r.wall_time_s), r.soz ? &*r.soz : nullptr);
  std::string stage = r.stage;
  if (!stage.empty()) stage[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(stage[0])));
  doc.title.title = stage + " stage report";
  doc.title.subtitle = r.dynamics ? "Static cases, mooring code check, riser SOZ, S-C storm"
                                  : "Static analyses: pretensions, static cases, mooring code check";
  if (r.dynamics) {
    doc.title.facts.emplace_back("S-C storm",
                                 fmt::format("{}, {} ({:.0f} s, {:.2f} s wall)", design::to_string(r.dynamics->level),
                                             r.dynamics->case_name, r.dynamics->duration_s, r.dynamics->wall_s));
  }
  for (const std::string& note : r.notes) doc.title.facts.emplace_back("Note", note);
  int failed = 0, failed_lines = 0, failed_offset = 0, failed_risers = 0, failed_soz = 0;
  for (const auto& c : r.checks) {
    failed += c.pass ? 0 : 1;
    failed_lines += c.lines_pass ? 0 : 1;
    failed_offset += c.offset_pass ? 0 : 1;
    failed_risers += c.risers_pass ? 0 : 1;
    failed_soz += c.soz_pass ? 0 : 1;
  }
  const design::GoverningCheck& g = r.governing;
  const std::string governing =
      fmt::format("{}{}{}, utilization {:.3f} in {}", g.check, g.item.empty() ? "" : " " + g.item,
                  g.criterion.empty() ? "" : " " + g.criterion, g.utilization, g.case_name);
  std::string storm;
  if (r.dynamics) {
    const bool storm_pass =
        r.dynamics->tension_pass && (!r.dynamics->extreme_offset || r.dynamics->extreme_offset->passes);
    storm = fmt::format("; S-C storm of {}: {}", r.dynamics->case_name, storm_pass ? "PASS" : "FAIL");
  }
  doc.title.pass = r.pass;
  doc.title.verdict = r.pass
                          ? fmt::format(
                                "PASS — all {} cases meet {}, the offset limit, the riser criteria{}{}; largest "
                                "utilization: {}",
                                r.checks.size(), r.code, r.soz ? " and the riser SOZ" : "", storm, governing)
                          : fmt::format(
                                "FAIL — {} of {} cases fail (mooring code: {}, offset limit: {}, riser criteria: "
                                "{}{}){}; governing failing check: {}",
                                failed, r.checks.size(), failed_lines, failed_offset, failed_risers,
                                r.soz ? fmt::format(", riser SOZ: {}", failed_soz) : std::string(), storm, governing);
  doc.sections.push_back(model_summary_section(vp, r.code));
  doc.sections.push_back(load_cases_section(p));
  doc.sections.push_back(pretension_section(vp, r, options));
  doc.sections.push_back(results_section(vp, r, options));
  if (!p.risers.empty()) doc.sections.push_back(riser_section(r));
  if (r.soz) {
    std::optional<double> limit;
    if (p.criteria.max_offset_pct_depth) limit = *p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m;
    std::vector<design::OffsetCheck> extremes;
    if (r.dynamics && r.dynamics->extreme_offset) extremes.push_back(*r.dynamics->extreme_offset);
    doc.sections.push_back(soz_section(*r.soz, extremes, limit));
  }
  if (r.dynamics) doc.sections.push_back(dynamics_section(*r.dynamics, r.code));
  doc.sections.push_back(stiffness_section(r, p));
  return doc;
}

}  // namespace spiral::report
