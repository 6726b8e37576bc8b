#include "report/optimization_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "report/plot.hpp"
#include "report/table_cells.hpp"

namespace spiral::report {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

/// Offsets of the scenarios (intact or damaged) as markers.
Series offsets(const std::vector<design::ScenarioSummary>& scenarios, bool damaged, bool after) {
  Series s;
  s.label = fmt::format("{} {}", damaged ? "damaged" : "intact", after ? "after" : "before");
  s.line_width = 0.0;
  s.markers = true;
  s.marker = damaged ? Marker::triangle : Marker::circle;
  s.color = after ? (damaged ? Rgb{0.84, 0.15, 0.16} : Rgb{0.12, 0.47, 0.71}) : Rgb{0.6, 0.6, 0.6};
  for (const design::ScenarioSummary& c : scenarios) {
    if (c.damaged_line.has_value() != damaged) continue;
    s.x.push_back(c.offset_m * std::cos(c.direction_deg * kDegToRad));
    s.y.push_back(c.offset_m * std::sin(c.direction_deg * kDegToRad));
  }
  return s;
}

Figure plan_figure(const design::Project& p, const design::OptimizationResult& r) {
  Plot plot;
  plot.title = "Static offsets against the platform SOZ, before and after";
  plot.x_label = "Hull offset x (m)";
  plot.y_label = "Hull offset y (m)";
  plot.equal_aspect = true;
  plot.legend_columns = 1;
  for (std::size_t k = 0; k < r.zones.size(); ++k) {
    Series zone = polar_polygon(r.zones[k].directions_deg, r.zones[k].allowable_m);
    zone.label = "SOZ " + r.zones[k].name;
    zone.color = palette(k + 2);
    plot.series.push_back(std::move(zone));
  }
  for (const bool damaged : {false, true}) {
    for (const bool after : {false, true}) {
      Series s = offsets(after ? r.after : r.before, damaged, after);
      if (!s.x.empty()) plot.series.push_back(std::move(s));
    }
  }
  if (p.criteria.max_offset_pct_depth) {
    plot.circles.push_back(
        {0.0, 0.0, *p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m, "offset limit", {0.3, 0.3, 0.3}, true});
  }
  return Figure{"optimization-plan",
                "Every scenario's static offset before (grey) and after (colour) against the "
                "zone it is checked against and the offset limit.",
                1.0, std::nullopt, [plot](cairo_t* cr, double w, double h) { draw_plot(cr, plot, w, h); }};
}

Figure history_figure(const design::OptimizationResult& r) {
  Plot plot;
  plot.title = "Iteration history";
  plot.x_label = "Evaluation";
  plot.y_label = "Objective (" + r.objective_unit + ")";
  Series feasible{"feasible", {}, {}, {0.12, 0.47, 0.71}, 0.0, false, true, false, Marker::circle};
  Series infeasible{"infeasible", {}, {}, {0.84, 0.15, 0.16}, 0.0, false, true, false, Marker::triangle};
  for (const design::OptimizationHistoryRow& h : r.history) {
    if (!std::isfinite(h.objective)) continue;
    Series& s = h.feasible ? feasible : infeasible;
    s.x.push_back(h.evaluation);
    s.y.push_back(h.objective);
  }
  for (Series* s : {&feasible, &infeasible})
    if (!s->x.empty()) plot.series.push_back(*s);
  return Figure{"optimization-history", "Objective at every evaluation (inner evaluations on linearized risers).", 1.8,
                std::nullopt, [plot](cairo_t* cr, double w, double h) { draw_plot(cr, plot, w, h); }};
}

Figure sweep_figure(const design::PretensionSweep& sweep) {
  Plot plot;
  plot.title = "Pretension study: " + sweep.name;
  plot.x_label = "Mean pretension at rest (kN)";
  plot.y_label = "Ratio (-)";
  Series soz_i{"max offset / SOZ, intact", {}, {}, {0.12, 0.47, 0.71}};
  Series soz_d{"max offset / SOZ, damaged", {}, {}, {0.84, 0.15, 0.16}};
  Series util_i{"max utilization, intact", {}, {}, {0.12, 0.47, 0.71}, 1.3, true};
  Series util_d{"max utilization, damaged", {}, {}, {0.84, 0.15, 0.16}, 1.3, true};
  for (const design::PretensionStudyPoint& pt : sweep.points) {
    const double x = pt.pretension_N / 1e3;
    if (pt.max_soz_ratio_intact) soz_i.x.push_back(x), soz_i.y.push_back(*pt.max_soz_ratio_intact);
    if (pt.max_soz_ratio_damaged) soz_d.x.push_back(x), soz_d.y.push_back(*pt.max_soz_ratio_damaged);
    util_i.x.push_back(x), util_i.y.push_back(pt.max_utilization_intact);
    if (pt.max_utilization_damaged > 0.0) util_d.x.push_back(x), util_d.y.push_back(pt.max_utilization_damaged);
  }
  for (Series* s : {&soz_i, &soz_d, &util_i, &util_d})
    if (!s->x.empty()) plot.series.push_back(*s);
  for (const design::PretensionStudyPoint& pt : sweep.points) {
    if (pt.feasible) plot.x_lines.emplace_back(pt.pretension_N / 1e3, "");
  }
  return Figure{"study-" + slug(sweep.name),
                "Largest offset / SOZ and utilization against the pretension; dashed verticals: feasible points.", 1.6,
                std::nullopt, [plot](cairo_t* cr, double w, double h) { draw_plot(cr, plot, w, h); }};
}

Table installation_table(const design::OptimizationResult& r) {
  Table t{"payouts",
          "Installation table: payout of each line (top segment at the fairlead; + pays out)",
          {"Line", "Group", "Payout (m)", "Top segment before (m)", "after (m)", "Pretension before (kN)", "after (kN)",
           "after (% MBL)"},
          {}};
  for (const design::LinePayout& l : r.lines) {
    t.rows.push_back({text(l.name), text(l.group), num(l.payout_m, 3), num(l.top_segment_before_m, 3),
                      num(l.top_segment_after_m, 3), num(l.pretension_before_N, 1, 1e-3),
                      num(l.pretension_after_N, 1, 1e-3), num(100.0 * l.pretension_after_N / l.top_segment_mbl_N, 1)});
  }
  return t;
}

Table scenario_table(const design::OptimizationResult& r) {
  Table t{"scenarios",
          "Scenarios before and after: static offset, SOZ in its direction and the worst line utilization (code "
          "factor included)",
          {"Scenario", "Offset before (m)", "after (m)", "SOZ (m)", "Ratio before", "after", "Utilization before",
           "after", "Worst line"},
          {}};
  for (std::size_t i = 0; i < r.before.size() && i < r.after.size(); ++i) {
    const design::ScenarioSummary& b = r.before[i];
    const design::ScenarioSummary& a = r.after[i];
    const auto optional = [](const std::optional<double>& v) { return v ? num(*v, 3) : text("–"); };
    TableCell ratio = optional(a.soz_ratio);
    if (a.soz_ratio) ratio.status = *a.soz_ratio <= 1.0 ? CellStatus::pass : CellStatus::fail;
    TableCell utilization = num(a.worst_utilization, 3);
    utilization.status = a.worst_utilization <= 1.0 ? CellStatus::pass : CellStatus::fail;
    t.rows.push_back({text(b.scenario), num(b.offset_m, 2), num(a.offset_m, 2),
                      a.soz_allowable_m ? num(*a.soz_allowable_m, 1) : text("–"), optional(b.soz_ratio), ratio,
                      num(b.worst_utilization, 3), utilization, text(a.worst_line)});
  }
  return t;
}

}  // namespace

ReportDocument optimization_report(const design::ValidatedProject& vp, const design::OptimizationResult& r,
                                   const std::optional<design::PretensionStudyResult>& study, const ReportInfo& info) {
  const design::Project& p = vp.project;
  const std::string code = design::to_string(p.criteria.mooring.code);
  ReportDocument doc = stage_document(p, info, "optimization", code, fmt::format("{:.2f} s", r.wall_s), nullptr);
  doc.title.title = "Pretension optimization report";
  doc.title.subtitle = fmt::format("{} with {}, {} scenarios", design::to_string(r.objective),
                                   design::to_string(r.algorithm), r.scenarios.size());
  doc.title.pass = r.status == design::OptimizationStatus::optimal;
  doc.title.verdict =
      doc.title.pass
          ? fmt::format("OPTIMAL — {} {:.4g} -> {:.4g}; every line and offset constraint holds in every scenario",
                        r.objective_unit, r.objective_start, r.objective_best)
      : r.most_violated
          ? fmt::format("INFEASIBLE — most violated: {} by {:.4g}", r.most_violated->describe(), r.most_violated->value)
          : fmt::format("INFEASIBLE — {}", r.findings.empty() ? std::string("see the notes") : r.findings.front());
  doc.title.facts.emplace_back("Evaluations", fmt::format("{} ({})", r.evaluations, r.stop_reason));

  Section summary{"Optimization", {}, true};
  KeyValues kv;
  kv.items.emplace_back("Objective", fmt::format("{} ({}): {:.6g} -> {:.6g}", design::to_string(r.objective),
                                                 r.objective_unit, r.objective_start, r.objective_best));
  kv.items.emplace_back("Algorithm", fmt::format("NLopt {}", design::to_string(r.algorithm)));
  kv.items.emplace_back("Status", fmt::format("{} ({})", design::to_string(r.status), r.stop_reason));
  std::string payouts;
  for (std::size_t g = 0; g < r.groups.size() && g < r.payouts_m.size(); ++g)
    payouts += fmt::format("{}{} {:+.3f} m [{:.1f}, {:.1f}]", payouts.empty() ? "" : "; ", r.groups[g].name,
                           r.payouts_m[g], r.groups[g].min_m, r.groups[g].max_m);
  kv.items.emplace_back("Payouts [bounds]", payouts);
  kv.items.emplace_back("Wall time", fmt::format("{:.2f} s (SOZ {:.2f} s)", r.wall_s, r.zone_wall_s));
  summary.blocks.emplace_back(std::move(kv));
  for (const std::string& f : r.findings) summary.blocks.emplace_back(Paragraph{"Finding: " + f + "."});
  summary.blocks.emplace_back(plan_figure(p, r));
  summary.blocks.emplace_back(installation_table(r));
  doc.sections.push_back(std::move(summary));

  Section cases{"Scenarios before and after", {}, true};
  cases.blocks.emplace_back(scenario_table(r));
  Table active{"active-constraints",
               "Active constraints and bounds at the optimum: λ is the objective gained per unit relaxation",
               {"Constraint", "g", "λ"},
               {}};
  for (const design::ActiveConstraint& a : r.active)
    active.rows.push_back({text(a.name), num(a.value, 6), num(a.multiplier, 4)});
  cases.blocks.emplace_back(std::move(active));
  doc.sections.push_back(std::move(cases));

  Section history{"Iteration history", {}, true};
  history.blocks.emplace_back(history_figure(r));
  for (const std::string& n : r.notes) history.blocks.emplace_back(note_paragraph(n));
  doc.sections.push_back(std::move(history));

  if (study) {
    Section s{"Pretension study", {}, true};
    for (const design::PretensionSweep& sweep : study->sweeps) {
      s.blocks.emplace_back(sweep_figure(sweep));
      s.blocks.emplace_back(Paragraph{sweep.feasible_m
                                          ? fmt::format("Sweep {}: feasible from {:.3f} m to {:.3f} m of payout.",
                                                        sweep.name, sweep.feasible_m->first, sweep.feasible_m->second)
                                          : fmt::format("Sweep {}: no feasible point.", sweep.name)});
    }
    doc.sections.push_back(std::move(s));
  }
  return doc;
}

}  // namespace spiral::report
