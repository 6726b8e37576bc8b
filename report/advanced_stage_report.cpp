#include "report/advanced_stage_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/dynamics_section.hpp"
#include "report/plot.hpp"
#include "report/soz_section.hpp"
#include "report/table_cells.hpp"

namespace spiral::report {

namespace {

constexpr double kN = 1e-3;  // N -> kN
/// The two levels' colours in every comparison plot: S-C blue, coupled orange.
constexpr std::size_t kScColor = 0, kCoupledColor = 1;

std::string duration_text(double s) {
  return s >= 3600.0 ? fmt::format("{:.0f} s ({:.3g} h)", s, s / 3600.0) : fmt::format("{:.0f} s", s);
}

Section critical_cases_section(const design::AdvancedStageResults& r) {
  Section s{"Critical cases", {}, true};
  const auto& in = r.intermediate;
  s.blocks.emplace_back(Paragraph{fmt::format(
      "The intermediate stage ranked the {} load cases by their enhanced S-C 3-h storms ({} storms in {:.1f} s "
      "wall clock on {} threads); its critical cases — the top {} by each measure and every failing case — are "
      "verified here "
      "fully coupled: hull 6-DOF and every mooring line and riser as a dynamic FE line in one time-domain "
      "system, {} at a {:g} s output step, seed {}, from the stage's static equilibrium of the case. The "
      "sc-enhanced analysis of the same case and sea runs beside it for the comparison.",
      in.ranked.size(), in.ranked.size(), in.storms_wall_s, in.threads, in.critical_per_measure,
      duration_text(r.duration_s), r.output_step_s, r.seed)});
  Table t{"critical-cases",
          "Critical cases: their intermediate score (S-C) and the outcome of the coupled verification.",
          {"Rank", "Case", "Condition", "S-C score", "Governs (S-C)", "Coupled run", "Wall (s)", "Final check"},
          {}};
  for (const auto& c : r.cases) {
    t.rows.push_back({num(c.rank, 0), text(c.case_name), text(design::to_string(c.integrity)),
                      num(c.intermediate_score, 3), text(design::to_string(c.intermediate_governing)),
                      text(!c.shared_with.empty() ? "as " + c.shared_with
                           : c.coupled            ? "finished"
                                                  : "FAILED"),
                      c.shared_with.empty() ? num(c.wall_s, 2) : text("–"), verdict(c.pass)});
  }
  s.blocks.emplace_back(t);
  for (const auto& c : r.cases)
    if (!c.shared_with.empty())
      s.blocks.emplace_back(Paragraph{fmt::format(
          "Case {} is the same analysis as {} (the same sea, wind and current, line integrity, design condition "
          "and seed): it was run once, and its results and checks below are those of {}.",
          c.case_name, c.shared_with, c.shared_with)});
  for (const auto& c : r.cases)
    if (c.error) s.blocks.emplace_back(Paragraph{fmt::format("Case {} — solver failure: {}", c.case_name, *c.error)});
  return s;
}

Section final_check_section(const design::AdvancedStageResults& r, const std::string& code) {
  Section s{"Final criteria check (coupled)", {}, true};
  s.blocks.emplace_back(Paragraph{fmt::format(
      "Every check below uses the coupled run of the case. Tension: {} with every mooring line's MPM fairlead "
      "tension (Gumbel fit, most probable 3-h maximum; the sample maximum where the record is too short for the "
      "fit) against its fairlead segment's MBL with the code's dynamic factor. Offset: the most probable 3-h "
      "maximum of the horizontal offset (Weibull fit to the record's peaks) against the offset limit and, with "
      "risers, the most probable 3-h maximum of offset / SOZ allowable in the offset's direction against 1 (the "
      "SOZ column shows it as an offset in the direction where the record comes closest to the zone). Risers: the MPM "
      "top tension against the riser's maximum top tension where its "
      "criteria give one; the other riser criteria as the static equilibrium of the case checked them.",
      code)});
  Table lines{"final-tension",
              "Mooring lines: coupled fairlead tension and the dynamic code check.",
              {"Case", "Line", "Mean (kN)", "Max (kN)", "MPM (kN)", "MBL (kN)", "Factor", "Utilization", "Check"},
              {}};
  for (const auto& c : r.cases) {
    for (const auto& l : c.lines) {
      lines.rows.push_back({text(c.case_name), text(l.line), num(l.mean_N, 1, kN), num(l.max_N, 1, kN),
                            num(l.mpm_N, 1, kN), num(l.mbl_N, 0, kN), num(l.dynamic_factor, 2), num(l.utilization, 3),
                            verdict(l.pass)});
    }
  }
  s.blocks.emplace_back(lines);
  Table offsets{
      "final-offset",
      "Offsets: coupled MPM horizontal offset against the offset limit and the platform SOZ.",
      {"Case", "MPM offset (m)", "Limit (m)", "Offset/limit", "SOZ allowable (m)", "Offset/SOZ", "Riser", "Check"},
      {}};
  for (const auto& c : r.cases) {
    if (!c.coupled) continue;
    const bool pass = c.offset_limit_pass && (!c.soz_offset || c.soz_offset->passes);
    offsets.rows.push_back(
        {text(c.case_name), num(c.mpm_offset_m, 2), c.offset_limit_m ? num(*c.offset_limit_m, 2) : text("–"),
         c.offset_limit_m && *c.offset_limit_m > 0 ? num(c.mpm_offset_m / *c.offset_limit_m, 3) : text("–"),
         c.soz_offset ? num(c.soz_offset->allowable_m, 2) : text("–"),
         c.soz_offset ? num(c.soz_offset->ratio, 3) : text("–"),
         text(c.soz_offset ? c.soz_offset->governing_riser : "–"), verdict(pass)});
  }
  s.blocks.emplace_back(offsets);
  bool risers = false;
  for (const auto& c : r.cases) risers = risers || !c.risers.empty();
  if (risers) {
    Table t{"final-risers",
            "Risers: coupled top tension against the maximum top tension; static: the riser criteria at the "
            "case's static equilibrium.",
            {"Case", "Riser", "Mean (kN)", "Max (kN)", "MPM (kN)", "Limit (kN)", "Utilization", "Static", "Check"},
            {}};
    for (const auto& c : r.cases) {
      for (const auto& rc : c.risers) {
        t.rows.push_back({text(c.case_name), text(rc.riser), num(rc.mean_N, 1, kN), num(rc.max_N, 1, kN),
                          num(rc.mpm_N, 1, kN), rc.limit_N ? num(*rc.limit_N, 0, kN) : text("–"),
                          rc.limit_N ? num(rc.utilization, 3) : text("–"), verdict(c.static_risers_pass),
                          verdict(rc.pass && c.static_risers_pass)});
      }
    }
    s.blocks.emplace_back(t);
  }
  return s;
}

/// One quantity at both levels: the S-C channel `sc_name` against the coupled `coupled_name`.
void comparison_rows(Table& t, const design::LevelComparison& cmp, const std::string& label, const std::string& sc_name,
                     const std::string& coupled_name, double scale, int decimals) {
  const design::LevelSummary& sc = cmp.levels.front();
  const design::LevelSummary& coupled = cmp.levels.back();
  const design::ChannelSummary* ref = design::find_channel(coupled, coupled_name);
  for (const design::LevelSummary* level : {&sc, &coupled}) {
    const design::ChannelSummary* c = design::find_channel(*level, level == &sc ? sc_name : coupled_name);
    if (c == nullptr) {
      t.rows.push_back({text(label), text(design::to_string(level->level)), text("–"), text("–"), text("–"), text("–"),
                        text("–"), text("–"), text("–"), text("–")});
      continue;
    }
    auto diff = [&](double v, double r) {
      return level != &coupled && ref ? num(design::percent_difference(v, r), 1) : text("–");
    };
    t.rows.push_back({text(label), text(design::to_string(level->level)), num(c->moments.mean, decimals, scale),
                      num(c->moments.std_dev, decimals, scale), num(c->moments.maximum, decimals, scale),
                      num(c->mpm, decimals, scale), diff(c->moments.mean, ref ? ref->moments.mean : 0.0),
                      diff(c->moments.std_dev, ref ? ref->moments.std_dev : 0.0),
                      diff(c->moments.maximum, ref ? ref->moments.maximum : 0.0), diff(c->mpm, ref ? ref->mpm : 0.0)});
  }
}

/// Length of the zoomed window of the level plots: a few slow-drift cycles
/// and tens of wave cycles, where the two levels' records can be told apart.
constexpr double kZoomWindow_s = 300.0;

/// The zoom window: centred on the largest coupled tension (else the S-C
/// one), the instant the final tension check is about, within the record.
std::pair<double, double> zoom_window(const design::CriticalCaseVerification& c) {
  const auto& d = c.coupled ? c.coupled : c.sc;
  if (!d || d->times_s.empty()) return {0.0, kZoomWindow_s};
  const std::vector<double>& t = d->times_s;
  double at = t.front();
  if (const design::StormChannel* tension = d->tension(); tension && !tension->values.empty()) {
    const auto& v = tension->values;
    at = t[static_cast<std::size_t>(std::max_element(v.begin(), v.end()) - v.begin())];
  }
  const double half = 0.5 * std::min(kZoomWindow_s, t.back() - t.front());
  const double lo = std::clamp(at - half, t.front(), t.back() - 2.0 * half);
  return {lo, lo + 2.0 * half};
}

/// Surge, offset and the most loaded line's tension at both levels: the
/// whole record (min/max envelope) beside the zoom window (every sample).
Figure overlay_figure(const design::CriticalCaseVerification& c, const std::string& id) {
  const auto [zoom_lo, zoom_hi] = zoom_window(c);
  std::vector<Plot> plots;
  enum class Shown { surge, offset, tension };
  for (const Shown shown : {Shown::surge, Shown::offset, Shown::tension}) {
    Plot whole, zoom;
    const design::StormChannel* any = nullptr;
    for (const auto* d : {&c.sc, &c.coupled}) {
      if (!*d) continue;
      const design::StormChannel* found = shown == Shown::tension  ? (*d)->tension()
                                          : shown == Shown::offset ? (*d)->channel("offset")
                                                                   : (*d)->channel("surge");
      if (!found) continue;
      const design::StormChannel& ch = *found;
      const double scale = ch.unit == "N" ? kN : 1.0;
      Series s = time_envelope((*d)->times_s, ch.values, scale);
      s.label = design::to_string((*d)->level);
      if (ch.unit == "N")
        s.label += (*d)->tension_source == design::TensionSource::coupled ? " (FE line)" : " (quasi-static)";
      s.color = palette(d == &c.sc ? kScColor : kCoupledColor);
      s.line_width = 0.6;
      Series z;
      z.label = s.label;
      z.color = s.color;
      z.line_width = 0.9;
      for (std::size_t i = 0; i < (*d)->times_s.size() && i < ch.values.size(); ++i) {
        if ((*d)->times_s[i] < zoom_lo || (*d)->times_s[i] > zoom_hi) continue;
        z.x.push_back((*d)->times_s[i]);
        z.y.push_back(ch.values[i] * scale);
      }
      whole.series.push_back(std::move(s));
      zoom.series.push_back(std::move(z));
      any = &ch;
    }
    if (any == nullptr) continue;
    const std::string unit = any->unit == "N" ? "kN" : any->unit;
    whole.title = any->name;
    zoom.title = fmt::format("{}, {:.0f}–{:.0f} s", any->name, zoom_lo, zoom_hi);
    for (Plot* p : {&whole, &zoom}) {
      p->x_label = "Time (s)";
      p->y_label = fmt::format("{} ({})", any->name, unit);
    }
    whole.legend = false;  // the key is in the zoom panel and the caption
    zoom.legend_columns = 1;
    zoom.x_range = std::pair{zoom_lo, zoom_hi};
    plots.push_back(std::move(whole));
    plots.push_back(std::move(zoom));
  }
  const std::size_t samples = c.coupled ? c.coupled->times_s.size() : c.sc ? c.sc->times_s.size() : 1;
  const double step = c.coupled ? c.coupled->output_step_s : c.sc ? c.sc->output_step_s : 0.5;
  return plot_panels(
      id + "-levels",
      fmt::format("Case {}: surge, horizontal offset and the fairlead tension of the coupled run's most loaded "
                  "line, sc-enhanced (blue; quasi-static catenary tension) and coupled (orange; FE line top "
                  "tension) on the same sea. Left: the whole record, each plotted point pair the min and max of "
                  "{:g} s; right: every sample of the {:.0f} s around the largest coupled tension.",
                  c.case_name, step * static_cast<double>(envelope_bin_samples(samples)), zoom_hi - zoom_lo),
      1.1, std::move(plots), 2);
}

Section case_section(const design::CriticalCaseVerification& c) {
  Section s{fmt::format("Critical case #{}: {} — coupled vs S-C", c.rank, c.case_name), {}, true};
  const std::string id = "case-" + slug(c.case_name);
  const design::LevelSummary& sc = c.comparison.levels.front();
  const design::LevelSummary& coupled = c.comparison.levels.back();
  if (c.error) s.blocks.emplace_back(Paragraph{"Solver failure: " + *c.error + "."});
  const std::string line = c.coupled ? c.coupled->most_loaded_line : std::string();
  Table t{id + "-comparison",
          fmt::format("Case {}: sc-enhanced against coupled, {} on seed {}. MPM: most probable 3-h maximum "
                      "(Gumbel; the sample maximum where the record is too short for the fit). Δ: 100 (S-C − coupled) "
                      "/ |coupled|. The S-C tension is the quasi-static "
                      "catenary at the S-C fairlead motion, the coupled one the FE line's top tension.",
                      c.case_name, duration_text(c.comparison.duration_s), c.comparison.seed),
          {"Quantity", "Level", "Mean", "Std", "Max", "MPM", "Δ mean (%)", "Δ std (%)", "Δ max (%)", "Δ MPM (%)"},
          {}};
  comparison_rows(t, c.comparison, "offset (m)", "offset_m", "offset_m", 1.0, 3);
  comparison_rows(t, c.comparison, "surge (m)", "surge_m", "surge_m", 1.0, 3);
  if (!line.empty())
    comparison_rows(t, c.comparison, "tension " + line + " (kN)", "qs_tension_" + line + "_N", "tension_" + line + "_N",
                    kN, 1);
  s.blocks.emplace_back(t);

  Table cost{id + "-cost",
             "Cost of each level: its own analysis (the stage's static equilibrium is reused by both), real-time "
             "factor (simulated / wall-clock time) and speed-up against the coupled run.",
             {"Level", "Wall clock (s)", "Real-time factor", "Speed-up vs coupled", "Integrator steps"},
             {}};
  for (const design::LevelSummary* l : {&sc, &coupled}) {
    const auto* d = l == &sc ? &c.sc : &c.coupled;
    if (l->error || !*d) {
      cost.rows.push_back({text(design::to_string(l->level)), text("failed"), text("–"), text("–"), text("–")});
      continue;
    }
    cost.rows.push_back({text(design::to_string(l->level)), num(l->wall_s, 3),
                         l->wall_s > 0 ? num(c.comparison.duration_s / l->wall_s, 1) : text("–"),
                         !coupled.error && l->wall_s > 0 ? num(coupled.wall_s / l->wall_s, 1) : text("–"),
                         num((*d)->solver_steps, 0)});
  }
  s.blocks.emplace_back(cost);
  if (c.sc || c.coupled) s.blocks.emplace_back(overlay_figure(c, id));
  if (c.coupled) {
    s.blocks.emplace_back(Paragraph{
        fmt::format("The coupled storm of case {}: motions, spectra and statistics ({} integrator steps, {:.2f} s wall "
                    "clock).",
                    c.case_name, c.coupled->solver_steps, c.coupled->wall_s)});
    for (Block& b : storm_blocks(*c.coupled, id + "-coupled")) s.blocks.push_back(std::move(b));
    for (const std::string& note : c.coupled->notes) s.blocks.emplace_back(note_paragraph(note));
  }
  return s;
}

}  // namespace

ReportDocument advanced_stage_report(const design::ValidatedProject& vp, const design::AdvancedStageResults& r,
                                     const ReportInfo& info) {
  const design::Project& p = vp.project;
  const auto& statics = r.intermediate.statics;
  ReportDocument doc =
      stage_document(p, info, "advanced", statics.code,
                     fmt::format("{:.3f} s (intermediate ranking {:.3f} s, coupled and S-C verification {:.3f} s)",
                                 r.wall_time_s, r.intermediate.wall_time_s, r.verification_wall_s),
                     statics.soz ? &*statics.soz : nullptr);
  doc.title.title = "Advanced stage report";
  doc.title.subtitle = "Fully coupled verification of the critical cases";
  doc.title.facts.emplace_back(
      "Critical cases", fmt::format("{} of {} (intermediate ranking: top {} by each measure and every failing case)",
                                    r.cases.size(), r.intermediate.ranked.size(), r.intermediate.critical_per_measure));
  doc.title.facts.emplace_back("Verification runs", fmt::format("coupled and sc-enhanced, {} each, seed {}",
                                                                duration_text(r.duration_s), r.seed));
  doc.title.pass = r.pass;
  // FAIL names what was not verified (failed runs) and what failed (the
  // verified cases' governing check); PASS names the governing check.
  int failing = 0;
  for (const auto& c : r.cases) failing += c.pass || !c.coupled ? 0 : 1;
  const std::size_t verified = r.cases.size() - r.failed_cases.size();
  std::vector<std::string> parts;
  if (!r.failed_cases.empty()) {
    std::string names;
    for (const auto& n : r.failed_cases) names += (names.empty() ? "" : ", ") + n;
    parts.push_back(fmt::format("coupled run failed for {} of {} critical cases: {}", r.failed_cases.size(),
                                r.cases.size(), names));
  }
  if (failing > 0) parts.push_back(fmt::format("{} of {} verified cases fail the final criteria", failing, verified));
  if (!r.governing.empty()) parts.push_back("governing: " + r.governing);
  std::string reasons;
  for (const auto& p_ : parts) reasons += (reasons.empty() ? "" : "; ") + p_;
  doc.title.verdict = r.pass ? fmt::format(
                                   "PASS — all {} critical cases verified fully coupled pass the final "
                                   "criteria; governing: {}",
                                   r.cases.size(), r.governing)
                             : "FAIL — " + reasons;
  doc.sections.push_back(model_summary_section(vp, statics.code));
  doc.sections.push_back(load_cases_section(p));
  doc.sections.push_back(critical_cases_section(r));
  doc.sections.push_back(final_check_section(r, statics.code));
  if (statics.soz) {
    std::vector<design::OffsetCheck> extremes;
    for (const auto& c : r.cases)
      if (c.soz_offset) extremes.push_back(*c.soz_offset);
    std::optional<double> limit;
    if (p.criteria.max_offset_pct_depth) limit = *p.criteria.max_offset_pct_depth / 100.0 * p.site.depth_m;
    doc.sections.push_back(soz_section(*statics.soz, extremes, limit));
  }
  for (const auto& c : r.cases) doc.sections.push_back(case_section(c));
  return doc;
}

}  // namespace spiral::report
