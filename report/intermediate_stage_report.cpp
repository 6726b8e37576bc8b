#include "report/intermediate_stage_report.hpp"

#include <fmt/format.h>

#include "report/color_map.hpp"
#include "report/dynamics_section.hpp"
#include "report/plot.hpp"
#include "report/soz_section.hpp"
#include "report/table_cells.hpp"

namespace spiral::report {

namespace {

constexpr double kN = 1e-3;  // N -> kN

const design::StaticCaseResult& case_of(const design::IntermediateStageResults& r, const design::RankedCase& c) {
  return r.statics.cases[c.case_index];
}

Section ranking_section(const design::IntermediateStageResults& r) {
  Section s{"Ranking of the load cases", {}, true};
  s.blocks.emplace_back(Paragraph{
      fmt::format("Every load case analysed at the sc-enhanced level for 3 h (seed 1) from its coupled static "
                  "equilibrium; {} storms in {:.1f} s wall clock on {} threads. Measures (≤ 1 passes): tension — MPM "
                  "fairlead tension of the most loaded line with the {} dynamic factor against the fairlead segment's "
                  "MBL; offset — MPM horizontal offset against the still-water platform SOZ in its direction; riser — "
                  "largest riser utilization at the case's static equilibrium (FE risers with its current; riser "
                  "dynamics are not analysed at this level). The score is the largest measure; the critical cases "
                  "(the top {} by each measure and every failing case) go to the advanced stage.",
                  r.ranked.size(), r.storms_wall_s, r.threads, r.statics.code, r.critical_per_measure)});
  Table t{"ranking",
          "Load cases ranked by score (most severe first).",
          {"Rank", "Case", "Condition", "Tension util.", "Line", "Offset/SOZ", "Riser util.", "Riser", "Score",
           "Governs", "Critical", "Check"},
          {}};
  for (const auto& c : r.ranked) {
    const auto& sc = case_of(r, c);
    t.rows.push_back({num(c.rank, 0), text(sc.case_name), text(design::to_string(sc.integrity)),
                      num(c.tension_utilization, 3), text(c.storm.most_loaded_line), num(c.offset_ratio, 3),
                      num(c.riser_utilization, 3), text(c.riser.empty() ? "–" : c.riser + " " + c.riser_criterion),
                      num(c.score, 3), text(design::to_string(c.governing_measure)), text(c.critical ? "yes" : "no"),
                      verdict(c.pass)});
  }
  s.blocks.emplace_back(t);

  BarChart chart;
  chart.title = "Score per load case";
  chart.y_label = "Score (–)";
  chart.limit = 1.0;
  chart.limit_label = "limit 1.0";
  for (const auto& c : r.ranked)
    chart.bars.push_back({fmt::format("#{}", c.rank), c.score, utilization_color(c.score),
                          fmt::format("{:.2f} {}", c.score, design::to_string(c.governing_measure))});
  std::string key;
  for (const auto& c : r.ranked)
    key += fmt::format("{}#{} {}", key.empty() ? "" : "; ", c.rank, case_of(r, c).case_name);
  Figure f{"ranking-scores", "Score of each load case by rank (" + key + ").", 2.0, std::nullopt, nullptr};
  f.draw = [chart](cairo_t* cr, double w, double h) { draw_bar_chart(cr, chart, w, h); };
  s.blocks.emplace_back(f);

  Table stats{"storm-summary",
              "Storm statistics per case: the most loaded line's fairlead tension and the horizontal offset.",
              {"Case", "Line", "T mean (kN)", "T std (kN)", "T max (kN)", "T MPM (kN)", "Offset mean (m)",
               "Offset max (m)", "Offset MPM (m)", "Wall (s)"},
              {}};
  for (const auto& c : r.ranked) {
    const auto& d = c.storm;
    const design::StormChannel* o = d.channel("offset");
    const design::StormChannel* tt = d.tension();
    if (!o) continue;
    const auto tension = [&](auto value) { return tt ? num(value(*tt), 1, kN) : text("–"); };
    stats.rows.push_back({text(d.case_name), text(tt ? d.most_loaded_line : "–"),
                          tension([](const auto& c) { return c.moments().mean; }),
                          tension([](const auto& c) { return c.moments().std_dev; }),
                          tension([](const auto& c) { return c.moments().maximum; }),
                          tension([](const auto& c) { return c.mpm_max().value_or(c.moments().maximum); }),
                          num(o->moments().mean, 2), num(o->moments().maximum, 2),
                          num(o->mpm_max().value_or(o->moments().maximum), 2), num(d.wall_s, 2)});
  }
  s.blocks.emplace_back(stats);
  return s;
}

}  // namespace

ReportDocument intermediate_stage_report(const design::ValidatedProject& vp, const design::IntermediateStageResults& r,
                                         const ReportInfo& info) {
  const design::Project& p = vp.project;
  ReportDocument doc = stage_document(p, info, "intermediate", r.statics.code,
                                      fmt::format("{:.3f} s (storms {:.3f} s)", r.wall_time_s, r.storms_wall_s),
                                      r.statics.soz ? &*r.statics.soz : nullptr);
  doc.title.title = "Intermediate stage report";
  doc.title.subtitle = "Enhanced S-C dynamics of the load-case matrix and ranking";
  int failed = 0, critical = 0;
  for (const auto& c : r.ranked) {
    critical += c.critical ? 1 : 0;
    failed += c.pass ? 0 : 1;
  }
  doc.title.facts.emplace_back("Critical cases",
                               fmt::format("{} of {} (top {} by each measure and every failing case; see the ranking)",
                                           critical, r.ranked.size(), r.critical_per_measure));
  doc.title.pass = r.pass;
  const design::RankedCase* top = r.ranked.empty() ? nullptr : &r.ranked.front();
  const std::string governing = top ? fmt::format("{} ({} {:.3f})", case_of(r, *top).case_name,
                                                  design::to_string(top->governing_measure), top->score)
                                    : "–";
  doc.title.verdict =
      r.pass ? fmt::format(
                   "PASS — all {} load cases pass the dynamic tension, extreme offset and riser measures "
                   "and the static checks; most severe: {}",
                   r.ranked.size(), governing)
             : fmt::format("FAIL — {} of {} load cases fail; most severe: {}", failed, r.ranked.size(), governing);
  doc.sections.push_back(model_summary_section(vp, r.statics.code));
  doc.sections.push_back(load_cases_section(p));
  doc.sections.push_back(ranking_section(r));
  if (r.statics.soz) {
    std::vector<design::OffsetCheck> extremes;
    for (const auto& c : r.ranked)
      if (c.storm.extreme_offset) extremes.push_back(*c.storm.extreme_offset);
    std::optional<double> limit;
    if (p.criteria.max_offset_pct_depth) limit = *p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m;
    doc.sections.push_back(soz_section(*r.statics.soz, extremes, limit));
  }
  for (const auto& c : r.ranked) {
    if (!c.critical) continue;
    Section s{fmt::format("Critical case #{}: {}", c.rank, c.storm.case_name), {}, true};
    s.blocks.emplace_back(
        Paragraph{fmt::format("Score {:.3f} ({}); {} storm, {:.2f} s wall clock, {} integrator steps.", c.score,
                              design::to_string(c.governing_measure), design::to_string(c.storm.level), c.storm.wall_s,
                              c.storm.solver_steps)});
    for (Block& b : storm_blocks(c.storm, "storm-" + slug(c.storm.case_name))) s.blocks.push_back(std::move(b));
    for (const std::string& note : c.storm.notes) s.blocks.emplace_back(note_paragraph(note));
    doc.sections.push_back(std::move(s));
  }
  return doc;
}

}  // namespace spiral::report
