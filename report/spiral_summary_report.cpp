#include "report/spiral_summary_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "report/table_cells.hpp"

namespace spiral::report {

namespace {

std::string stage_verdict(const design::StageRun& s) {
  if (!s.completed) return "NOT COMPLETED";
  return s.pass ? "PASS" : "FAIL";
}

Table stages_table(const design::SpiralRunResult& run) {
  Table t;
  t.id = "spiral-stages";
  t.caption =
      "Every stage of every iteration, in the order they ran. Tasks from the store were computed by an "
      "earlier stage or run on the same model and taken as they were.";
  t.headers = {"Stage", "Iteration", "Verdict", "Governing", "Tasks", "From store", "Failed", "Wall (s)"};
  for (const design::StageRun& s : run.stages) {
    TableCell verdict_cell = text(stage_verdict(s));
    verdict_cell.status = s.completed && s.pass ? CellStatus::pass : CellStatus::fail;
    t.rows.push_back({text(s.stage), num(s.iteration, 0), verdict_cell, text(s.governing.empty() ? "—" : s.governing),
                      num(s.tasks, 0), num(s.tasks_reused, 0), num(s.tasks_failed, 0), num(s.wall_s, 1)});
  }
  return t;
}

/// The preliminary checks of one iteration: the largest code utilization,
/// offset over the zone and offset over the limit (what the feedback acts on).
struct PreliminaryMeasures {
  double code = 0.0, soz = 0.0, limit = 0.0;
  bool has_soz = false, has_limit = false;
};

PreliminaryMeasures measures(const design::StaticStageResults& r) {
  PreliminaryMeasures m;
  for (const design::CaseCheck& c : r.checks) {
    if (c.governing_line >= 0)
      m.code = std::max(m.code, c.lines[static_cast<std::size_t>(c.governing_line)].utilization);
    if (c.soz) m.soz = std::max(m.soz, c.soz->ratio), m.has_soz = true;
    if (c.offset_limit_m && *c.offset_limit_m > 0.0)
      m.limit = std::max(m.limit, c.offset_m / *c.offset_limit_m), m.has_limit = true;
  }
  return m;
}

Table iterations_table(const design::SpiralRunResult& run) {
  Table t;
  t.id = "spiral-iterations";
  t.caption =
      "The preliminary stage of each iteration: its largest static code utilization (T·SF/MBL), offset "
      "over the platform SOZ in the offset's direction, and offset over the offset limit (≤ 1 passes).";
  t.headers = {"Iteration", "Model hash", "Max code utilization", "Max offset/SOZ", "Max offset/limit", "Verdict"};
  for (const design::StageRun& s : run.stages) {
    if (s.stage != "preliminary" || !s.preliminary) continue;
    const PreliminaryMeasures m = measures(*s.preliminary);
    t.rows.push_back({num(s.iteration, 0), text(s.model_hash), num(m.code, 3), m.has_soz ? num(m.soz, 3) : text("—"),
                      m.has_limit ? num(m.limit, 3) : text("—"), verdict(s.pass)});
  }
  return t;
}

std::vector<Block> feedback_blocks(const design::SpiralRunResult& run) {
  std::vector<Block> blocks;
  if (run.feedback.empty()) {
    blocks.push_back(
        Paragraph{"The preliminary stage's offset and tension checks needed no feedback: the "
                  "pretension optimizer did not run."});
    return blocks;
  }
  for (const design::FeedbackStep& f : run.feedback) {
    KeyValues kv;
    kv.items.push_back({"After iteration", std::to_string(f.from_iteration)});
    kv.items.push_back({"Why", f.reason});
    if (!f.error.empty()) kv.items.push_back({"Optimizer failure", f.error});
    if (f.optimization) {
      const design::OptimizationResult& o = *f.optimization;
      kv.items.push_back({"Optimizer", fmt::format("{} ({} evaluations, {:.1f} s)", design::to_string(o.status),
                                                   o.evaluations, o.wall_s)});
      kv.items.push_back(
          {"Objective", fmt::format("{:.4g} → {:.4g} {}", o.objective_start, o.objective_best, o.objective_unit)});
      if (o.most_violated) kv.items.push_back({"Most violated", o.most_violated->describe()});
    }
    kv.items.push_back({"Applied", f.applied ? fmt::format("yes: {}", f.project_file.string()) : "no"});
    blocks.push_back(kv);
    if (f.applied && f.optimization) {
      Table t;
      t.id = fmt::format("spiral-payouts-{}", f.from_iteration + 1);
      t.caption = fmt::format(
          "The payouts that made iteration {} (top segment lengthened; negative hauls in) and "
          "the pretensions at rest before and after.",
          f.from_iteration + 1);
      t.headers = {"Line", "Group", "Payout (m)", "Top segment (m)", "Pretension before (kN)", "Pretension after (kN)"};
      for (const design::LinePayout& l : f.optimization->lines) {
        t.rows.push_back({text(l.name), text(l.group), num(l.payout_m, 3), num(l.top_segment_after_m, 3),
                          num(l.pretension_before_N, 1, 1e-3), num(l.pretension_after_N, 1, 1e-3)});
      }
      blocks.push_back(t);
    }
  }
  return blocks;
}

Table provenance_table(const design::SpiralRunResult& run, const design::Project& project) {
  Table t;
  t.id = "spiral-provenance";
  t.caption =
      "Where each stage report's numbers come from: the iteration and model it ran on, and the analyses "
      "behind its checks (every task is a row of the results store, keyed by the model hash). Static cases: "
      "hull + catenary mooring + FE risers at equilibrium; storms: enhanced S-C, 3 h, each case's seed.";
  t.headers = {"Stage report", "Iteration", "Model hash", "Analyses"};
  std::set<std::string> seen;
  for (auto s = run.stages.rbegin(); s != run.stages.rend(); ++s) {
    if (!seen.insert(s->stage).second) continue;  // the report holds the stage's last iteration
    std::string analyses;
    if (s->stage == "preliminary")
      analyses = "static cases, still-water SOZ, S-C storm of the governing case";
    else if (s->stage == "intermediate")
      analyses = "static cases, S-C storm of every case";
    else
      analyses = fmt::format("coupled + S-C of the critical cases, {:.0f} s",
                             s->advanced ? s->advanced->duration_s : design::advanced_stage_duration(project));
    t.rows.insert(t.rows.begin(), {text(s->stage), num(s->iteration, 0), text(s->model_hash), text(analyses)});
  }
  return t;
}

}  // namespace

ReportDocument spiral_summary_report(const design::ValidatedProject& vp, const design::SpiralRunResult& run,
                                     const ReportInfo& info) {
  const design::Project& p = vp.project;
  ReportDocument doc;
  doc.title.title = "Design spiral summary";
  doc.title.subtitle = "Stages, iterations and feedback";
  doc.title.project = p.name;
  doc.title.description = p.description.value_or("");
  doc.title.facts = {{"Project file", info.project_file},
                     {"Model hash", info.model_hash},
                     {"Results store", run.store_file.string()},
                     {"Run", std::to_string(run.run_id)},
                     {"Date", info.date},
                     {"spiral", info.version}};
  doc.title.pass = run.pass;
  const design::StageRun* last = run.stages.empty() ? nullptr : &run.stages.back();
  if (!run.completed)
    doc.title.verdict = fmt::format("NOT COMPLETED: the {} stage could not finish", last ? last->stage : "first");
  else if (run.pass)
    doc.title.verdict = fmt::format("PASS: every stage of the final iteration ({}) passes", last ? last->iteration : 1);
  else
    doc.title.verdict = fmt::format("FAIL: {}", last && !last->governing.empty() ? last->governing : "see the stages");
  doc.running_header = fmt::format("{} — design spiral summary", p.name);
  doc.running_footer = fmt::format("spiral {} · model {}", info.version, info.model_hash);

  Section verdict_section{"Verdict and findings", {}, true};  // after the title page
  verdict_section.blocks.push_back(Paragraph{doc.title.verdict});
  if (run.findings.empty()) {
    verdict_section.blocks.push_back(Paragraph{"No findings beyond the stage verdicts."});
  } else {
    KeyValues kv;
    for (std::size_t i = 0; i < run.findings.size(); ++i)
      kv.items.push_back({fmt::format("Finding {}", i + 1), run.findings[i]});
    verdict_section.blocks.push_back(kv);
  }
  if (run.solver_failures)
    verdict_section.blocks.push_back(
        Paragraph{"A solver failed in at least one task (see Failed tasks): the "
                  "stage that owns it cannot pass."});
  doc.sections.push_back(std::move(verdict_section));

  Section stages{"Stages", {stages_table(run)}, false};
  doc.sections.push_back(std::move(stages));

  Section iterations{"Iterations and feedback", {iterations_table(run)}, true};
  for (Block& b : feedback_blocks(run)) iterations.blocks.push_back(std::move(b));
  doc.sections.push_back(std::move(iterations));

  Section failures{"Failed tasks", {}, false};
  Table t;
  t.id = "spiral-failures";
  t.caption = "Tasks whose solver failed, with its message (stored as failed: a resumed run does not repeat them).";
  t.headers = {"Stage", "Iteration", "Task and message"};
  for (const design::StageRun& s : run.stages)
    for (const std::string& f : s.failures) t.rows.push_back({text(s.stage), num(s.iteration, 0), text(f)});
  if (t.rows.empty())
    failures.blocks.push_back(Paragraph{"None."});
  else
    failures.blocks.push_back(std::move(t));
  doc.sections.push_back(std::move(failures));

  doc.sections.push_back(Section{"Where the numbers come from", {provenance_table(run, p)}, false});
  return doc;
}

}  // namespace spiral::report
