#include "design/stages/intermediate_stage.hpp"
#include "design/criteria/riser_checks.hpp"

#include <algorithm>

#include "engine/common/parallel_for.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

const char* to_string(RankingMeasure measure) {
  switch (measure) {
    case RankingMeasure::tension:
      return "tension";
    case RankingMeasure::offset:
      return "offset";
    case RankingMeasure::riser:
      return "riser";
  }
  return "?";
}

StageDynamics run_case_storm(const ValidatedProject& vp, const StaticStageResults& statics, std::size_t case_index,
                             RestSolutionCache* rest_solutions) {
  return run_stage_dynamics(vp, statics.cases[case_index], AnalysisLevel::semi_coupled_enhanced,
                            statics.soz ? &*statics.soz : nullptr, "every case of the matrix", rest_solutions);
}

std::size_t intermediate_critical_cases(const Project& project) {
  for (const Stage& s : project.stages)
    if (s.name == "intermediate" && s.critical_cases) return static_cast<std::size_t>(*s.critical_cases);
  return kCriticalCases;
}

IntermediateStageResults reduce_intermediate_stage(StaticStageResults statics, std::vector<CaseStorm> storms,
                                                   std::size_t critical_per_measure) {
  IntermediateStageResults out;
  out.critical_per_measure = critical_per_measure;
  out.statics = std::move(statics);
  out.statics.stage = "intermediate";
  out.ranked.resize(storms.size());
  for (std::size_t i = 0; i < storms.size(); ++i) {
    RankedCase& c = out.ranked[i];
    c.case_index = storms[i].case_index;
    c.storm = std::move(storms[i].storm);
    c.tension_utilization = c.storm.tension_utilization;
    c.offset_ratio = c.storm.extreme_offset ? c.storm.extreme_offset->ratio : 0.0;
    for (const RiserStaticsRow& r : out.statics.cases[c.case_index].risers) {
      if (r.utilization > c.riser_utilization) {
        c.riser_utilization = r.utilization;
        c.riser = r.name;
        c.riser_criterion = r.governing_criterion;
      }
    }
    c.score = c.tension_utilization, c.governing_measure = RankingMeasure::tension;
    if (c.offset_ratio > c.score) c.score = c.offset_ratio, c.governing_measure = RankingMeasure::offset;
    if (c.riser_utilization > c.score) c.score = c.riser_utilization, c.governing_measure = RankingMeasure::riser;
    // The static checks of the case (code, offset limit, risers, SOZ) count too.
    c.pass = c.score <= 1.0 && out.statics.checks[c.case_index].pass;
    out.pass = out.pass && c.pass;
  }
  // Most severe first; ties keep the project order (stable).
  std::stable_sort(out.ranked.begin(), out.ranked.end(),
                   [](const RankedCase& a, const RankedCase& b) { return a.score > b.score; });
  for (std::size_t i = 0; i < out.ranked.size(); ++i) {
    out.ranked[i].rank = static_cast<int>(i) + 1;
    out.ranked[i].critical = !out.ranked[i].pass;
  }
  // The N most severe by each measure (a case that is severe in offset but
  // not in tension still gets its coupled verification).
  for (const auto measure :
       {&RankedCase::tension_utilization, &RankedCase::offset_ratio, &RankedCase::riser_utilization}) {
    std::vector<RankedCase*> order;
    for (RankedCase& c : out.ranked) order.push_back(&c);
    std::stable_sort(order.begin(), order.end(),
                     [measure](const RankedCase* a, const RankedCase* b) { return a->*measure > b->*measure; });
    for (std::size_t k = 0; k < std::min(critical_per_measure, order.size()); ++k)
      if (order[k]->*measure > 0.0) order[k]->critical = true;
  }
  return out;
}

IntermediateStageResults run_intermediate_stage(const ValidatedProject& vp) {
  engine::Stopwatch start;
  StaticStageOptions options;
  options.dynamics = false;  // every case gets its storm below
  StaticStageResults statics = run_static_stage(vp, options);
  const std::size_t n = statics.cases.size() - 1;  // load cases, after still water
  std::vector<CaseStorm> storms(n);
  const int threads = engine::worker_count(static_cast<int>(n));
  engine::Stopwatch storms_start;
  RestSolutionCache rest_solutions;  // the storms' S-C static cases sharing an environment
  engine::parallel_for(static_cast<int>(n), threads, [&](int i) {
    CaseStorm& s = storms[static_cast<std::size_t>(i)];
    s.case_index = static_cast<std::size_t>(i) + 1;
    s.storm = run_case_storm(vp, statics, s.case_index, &rest_solutions);
  });
  const double storms_wall_s = storms_start.seconds();
  IntermediateStageResults out =
      reduce_intermediate_stage(std::move(statics), std::move(storms), intermediate_critical_cases(vp.project));
  out.threads = threads;
  out.storms_wall_s = storms_wall_s;
  out.wall_time_s = start.seconds();
  return out;
}

}  // namespace spiral::design
