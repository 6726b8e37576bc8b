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

StaticStageResults run_static_stage(const ValidatedProject& validated, const StaticStageOptions& options) {
  engine::Stopwatch start;
  const Project& project = validated.project;
  StaticStageResults out;
  out.code = to_string(project.criteria.mooring.code);
  // Read first: a bad mesh file fails the stage before its analyses run.
  if (project.hull.geometry && project.hull.geometry->panel_mesh)
    out.hull_panels_b = engine::full_surface(engine::read_gdf(*project.hull.geometry->panel_mesh));

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

  // The analytic stiffness is cross-checked by finite differences once, in still water.
  StaticCaseRequest still_water;
  still_water.finite_difference_check = true;
  out.cases.push_back(run_static_case(validated, still_water));
  RestSolutionCache rest_solutions;  // cases sharing an environment (intact, damaged) solve its lines once
  for (const LoadCase& load_case : project.load_cases) {
    StaticCaseRequest request;
    request.load_case = load_case.name;
    out.cases.push_back(run_static_case(validated, request, &rest_solutions));
  }
  if (options.soz && !project.risers.empty()) out.soz = stage_soz(project, preliminary_soz_settings(project));
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

  for (const double direction_deg : {0.0, 90.0}) {
    out.restoring.push_back(restoring_curve(model, direction_deg, project.site.depth_m));
  }

  // The storm of the governing load case (still water governs only when the
  // environment adds little: then the first load case).
  if (options.dynamics && !project.load_cases.empty()) {
    if (project.hull.hydrodynamics) {
      const std::size_t index = out.worst_case > 0 ? static_cast<std::size_t>(out.worst_case) : 1;
      const std::string why =
          out.worst_case > 0
              ? fmt::format("the governing load case of the static code check (utilization {:.3f})", worst)
              : std::string("the first load case (still water governs the static code check)");
      out.dynamics = run_stage_dynamics(validated, out.cases[index], AnalysisLevel::semi_coupled_enhanced,
                                        out.soz ? &*out.soz : nullptr, why);
      out.pass = out.pass && out.dynamics->tension_pass &&
                 (!out.dynamics->extreme_offset || out.dynamics->extreme_offset->passes);
    } else {
      out.notes.push_back("no S-C storm: the project gives no hull.hydrodynamics for the hull's dynamics");
    }
  }
  out.governing = governing_check(out);
  out.wall_time_s = start.seconds();
  return out;
}

}  // namespace spiral::design
