#include "design/stages/static_stage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "design/model/mooring_model.hpp"
#include "design/criteria/riser_checks.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/common/solver_error.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

CaseCheck check_case(const Project& project, const StaticCaseResult& result) {
  CaseCheck check;
  check.case_name = result.case_name;
  check.integrity = result.integrity;
  check.safety_factor = mooring_safety_factor(project.criteria.mooring, result.integrity == LineIntegrity::damaged);
  double worst = -1.0;
  for (std::size_t i = 0; i < result.lines.size(); ++i) {
    const LineStaticsRow& row = result.lines[i];
    LineCodeCheck line;
    line.line = row.name;
    line.max_tension_N = row.max_tension_N;
    line.utilization_mbl = row.utilization;
    line.safety_factor = check.safety_factor;
    line.utilization = row.utilization * check.safety_factor;
    line.pass = line.utilization <= 1.0;
    check.lines_pass = check.lines_pass && line.pass;
    if (line.utilization > worst) {
      worst = line.utilization;
      check.governing_line = static_cast<int>(i);
    }
    check.lines.push_back(line);
  }
  check.offset_m = result.offset_summary.horizontal_m;
  if (project.criteria.max_offset_pct_depth) {
    check.offset_limit_m = *project.criteria.max_offset_pct_depth / 100.0 * project.site.depth_m;
    check.offset_pass = check.offset_m <= *check.offset_limit_m;
  }
  for (const RiserStaticsRow& riser : result.risers) check.risers_pass = check.risers_pass && riser.passes;
  check.pass = check.lines_pass && check.offset_pass && check.risers_pass;
  return check;
}

RestoringCurve restoring_curve(LineArrayModel& model, double direction_deg, double depth_m) {
  RestoringCurve curve;
  curve.direction_deg = direction_deg;
  const Eigen::Vector2d d(std::cos(direction_deg * kDegToRad), std::sin(direction_deg * kDegToRad));
  const double max_offset_m = kRestoringMaxOffsetFractionOfDepth * depth_m;
  for (int i = 0; i <= kRestoringSteps; ++i) {
    const double s = max_offset_m * i / kRestoringSteps;
    engine::Vector6d offset = engine::Vector6d::Zero();
    offset.head<2>() = s * d;
    try {
      const engine::LineArrayResponse response =
          engine::evaluate_line_array(model.lines, engine::pose_from_offset(model.reference_point_g, offset));
      curve.offset_m.push_back(s);
      curve.force_N.push_back(-response.force.head<2>().dot(d));
    } catch (const engine::SolverError& error) {
      // A line that cannot reach at this offset ends the sweep; the curve up
      // to here is still valid and the report says where and why it stopped.
      curve.stopped = error.what();
      break;
    }
  }
  return curve;
}

/// Still-water zones of every riser with the stage's model and step: no
/// current, no mean heave or rotations, the normal design condition (the
/// strictest design factor), as `spiral soz` without --case.
SozResult stage_soz(const Project& project, const StageSoz& settings) {
  SozOptions options;
  options.step_deg = settings.step_deg;
  options.model = settings.model == StageSozModel::fe ? SozModel::fe : SozModel::catenary;
  options.offset_check = false;  // the stage holds its static cases already
  std::vector<RiserDesign> designs;
  for (const Riser& riser : project.risers) designs.push_back(riser_design(project, riser));
  return compute_soz(project, designs, SozConditions{}, options);
}

/// Keeps the failing check of largest utilization (or the largest overall
/// while nothing fails).
void consider(GoverningCheck& governing, bool& any, GoverningCheck candidate) {
  const bool better = !any || (governing.pass && !candidate.pass) ||
                      (governing.pass == candidate.pass && candidate.utilization > governing.utilization);
  if (better) governing = std::move(candidate);
  any = true;
}

GoverningCheck governing_check(const StaticStageResults& r) {
  GoverningCheck g;
  bool any = false;
  for (std::size_t i = 0; i < r.checks.size(); ++i) {
    const CaseCheck& c = r.checks[i];
    if (c.governing_line >= 0) {
      const LineCodeCheck& l = c.lines[static_cast<std::size_t>(c.governing_line)];
      consider(g, any, {c.case_name, "mooring code", l.line, "T·SF/MBL", l.utilization, l.pass});
    }
    if (c.offset_limit_m) {
      consider(g, any,
               {c.case_name, "offset limit", "", "offset/limit", c.offset_m / *c.offset_limit_m, c.offset_pass});
    }
    for (const RiserStaticsRow& riser : r.cases[i].risers) {
      consider(g, any,
               {c.case_name, "riser criteria", riser.name, riser.governing_criterion, riser.utilization, riser.passes});
    }
    if (c.soz) {
      consider(
          g, any,
          {c.case_name, "riser SOZ", c.soz->governing_riser, "static offset/allowable", c.soz->ratio, c.soz->passes});
    }
  }
  if (r.dynamics && !r.dynamics->most_loaded_line.empty()) {
    const StageDynamics& d = *r.dynamics;
    consider(g, any,
             {d.case_name, "dynamic tension", d.most_loaded_line, "MPM tension·SF/MBL", d.tension_utilization,
              d.tension_pass});
    if (d.extreme_offset) {
      consider(g, any,
               {d.case_name, "extreme offset (SOZ)", d.extreme_offset->governing_riser, "MPM offset/allowable",
                d.extreme_offset->ratio, d.extreme_offset->passes});
    }
  }
  return g;
}

}  // namespace

StageSoz preliminary_soz_settings(const Project& project) {
  for (const Stage& stage : project.stages)
    if (stage.name == "preliminary") return stage.soz;
  return StageSoz{};
}

MooringOverview run_mooring_overview(const ValidatedProject& validated) {
  const Project& project = validated.project;
  MooringOverview out;
  LineArrayModel model = build_mooring_model(project);
  out.pretension = run_statics(model, engine::Vector6d::Zero());
  for (const MooringLineDesign& design : model.designs) {
    LineStrength strength;
    strength.name = design.name;
    for (const LineTypeProperties& type : design.segment_types) {
      strength.segment_mbl_N.push_back(type.breaking_load_N);
      strength.segment_types.push_back(type.name);
    }
    out.strengths.push_back(std::move(strength));
  }
  for (const double direction_deg : {0.0, 90.0}) {
    out.restoring.push_back(restoring_curve(model, direction_deg, project.site.depth_m));
  }
  return out;
}

StaticCaseResult run_stage_static_case(const ValidatedProject& validated, const std::optional<std::string>& load_case,
                                       RestSolutionCache* cache) {
  StaticCaseRequest request;
  request.load_case = load_case;
  request.finite_difference_check = !load_case.has_value();
  return run_static_case(validated, request, cache);
}

std::optional<SozResult> run_stage_soz(const ValidatedProject& validated) {
  const Project& project = validated.project;
  if (project.risers.empty()) return std::nullopt;
  return stage_soz(project, preliminary_soz_settings(project));
}

std::vector<engine::Panel> stage_hull_panels(const Project& project) {
  if (!project.hull.geometry || !project.hull.geometry->panel_mesh) return {};
  return engine::full_surface(engine::read_gdf(*project.hull.geometry->panel_mesh));
}

StaticStageResults reduce_static_stage(const ValidatedProject& validated, MooringOverview overview,
                                       std::vector<StaticCaseResult> cases, std::optional<SozResult> soz,
                                       std::vector<engine::Panel> hull_panels_b, const StaticStageOptions& options) {
  const Project& project = validated.project;
  StaticStageResults out;
  out.code = to_string(project.criteria.mooring.code);
  out.hull_panels_b = std::move(hull_panels_b);
  out.pretension = std::move(overview.pretension);
  out.strengths = std::move(overview.strengths);
  out.restoring = std::move(overview.restoring);
  out.cases = std::move(cases);
  out.soz = std::move(soz);
  double worst = -1.0;
  for (std::size_t i = 0; i < out.cases.size(); ++i) {
    out.checks.push_back(check_case(project, out.cases[i]));
    CaseCheck& check = out.checks.back();
    if (out.soz && i > 0) {  // still water sits at zero offset: inside any zone
      check.soz = check_offset(*out.soz, out.cases[i], "still-water");
      out.soz->offset_checks.push_back(*check.soz);
      check.soz_pass = check.soz->passes;
      check.pass = check.pass && check.soz_pass;
    }
    out.pass = out.pass && check.pass;
    if (check.governing_line >= 0 && check.lines[static_cast<std::size_t>(check.governing_line)].utilization > worst) {
      worst = check.lines[static_cast<std::size_t>(check.governing_line)].utilization;
      out.worst_case = static_cast<int>(i);
    }
  }
  if (options.dynamics && !project.load_cases.empty() && !project.hull.hydrodynamics)
    out.notes.push_back("no S-C storm: the project gives no hull.hydrodynamics for the hull's dynamics");
  out.governing = governing_check(out);
  return out;
}

std::optional<StormChoice> stage_storm_choice(const Project& project, const StaticStageResults& stage) {
  if (project.load_cases.empty() || !project.hull.hydrodynamics) return std::nullopt;
  // The governing load case of the code check; still water governs only when
  // the environment adds little: then the first load case.
  if (stage.worst_case > 0) {
    const CaseCheck& check = stage.checks[static_cast<std::size_t>(stage.worst_case)];
    const double worst = check.lines[static_cast<std::size_t>(check.governing_line)].utilization;
    return StormChoice{static_cast<std::size_t>(stage.worst_case),
                       fmt::format("the governing load case of the static code check (utilization {:.3f})", worst)};
  }
  return StormChoice{1, "the first load case (still water governs the static code check)"};
}

void add_stage_storm(StaticStageResults& stage, StageDynamics storm) {
  stage.dynamics = std::move(storm);
  stage.pass = stage.pass && stage.dynamics->tension_pass &&
               (!stage.dynamics->extreme_offset || stage.dynamics->extreme_offset->passes);
  stage.governing = governing_check(stage);
}

StaticStageResults run_static_stage(const ValidatedProject& validated, const StaticStageOptions& options) {
  engine::Stopwatch start;
  const Project& project = validated.project;
  // Read first: a bad mesh file fails the stage before its analyses run.
  std::vector<engine::Panel> panels = stage_hull_panels(project);
  MooringOverview overview = run_mooring_overview(validated);
  std::vector<StaticCaseResult> cases;
  cases.push_back(run_stage_static_case(validated, std::nullopt));
  RestSolutionCache rest_solutions;  // cases sharing an environment (intact, damaged) solve its lines once
  for (const LoadCase& load_case : project.load_cases)
    cases.push_back(run_stage_static_case(validated, load_case.name, &rest_solutions));
  std::optional<SozResult> soz = options.soz ? run_stage_soz(validated) : std::nullopt;
  StaticStageResults out =
      reduce_static_stage(validated, std::move(overview), std::move(cases), std::move(soz), std::move(panels), options);
  if (options.dynamics) {
    if (const std::optional<StormChoice> choice = stage_storm_choice(project, out)) {
      add_stage_storm(out,
                      run_stage_dynamics(validated, out.cases[choice->case_index], AnalysisLevel::semi_coupled_enhanced,
                                         out.soz ? &*out.soz : nullptr, choice->why));
    }
  }
  out.wall_time_s = start.seconds();
  return out;
}

}  // namespace spiral::design
