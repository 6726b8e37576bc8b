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

IntermediateStageResults run_intermediate_stage(const ValidatedProject& vp) {
  engine::Stopwatch start;
  IntermediateStageResults out;
  StaticStageOptions options;
  options.dynamics = false;  // every case gets its storm below
  out.statics = run_static_stage(vp, options);
  out.statics.stage = "intermediate";
  const std::size_t n = out.statics.cases.size() - 1;  // load cases, after still water
  out.ranked.resize(n);
  out.threads = engine::worker_count(static_cast<int>(n));
  engine::Stopwatch storms_start;
  const SozResult* zone = out.statics.soz ? &*out.statics.soz : nullptr;
  engine::parallel_for(static_cast<int>(n), out.threads, [&](int i) {
    RankedCase& c = out.ranked[static_cast<std::size_t>(i)];
    c.case_index = static_cast<std::size_t>(i) + 1;
    c.storm = run_stage_dynamics(vp, out.statics.cases[c.case_index], AnalysisLevel::semi_coupled_enhanced, zone,
                                 "every case of the matrix");
  });
  out.storms_wall_s = storms_start.seconds();

  for (RankedCase& c : out.ranked) {
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
    out.ranked[i].critical = i < kCriticalCases || !out.ranked[i].pass;
  }
  out.wall_time_s = start.seconds();
  return out;
}

}  // namespace spiral::design
