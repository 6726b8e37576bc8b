#include "design/analysis/static_case.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "design/project/request_error.hpp"
#include "design/model/environment_loads.hpp"
#include "design/model/mooring_model.hpp"
#include "design/criteria/riser_checks.hpp"
#include "engine/analysis/fe_static_line.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/analysis/static_equilibrium.hpp"
#include "engine/common/stopwatch.hpp"
#include "engine/common/table_range_error.hpp"
#include "engine/common/dof_names.hpp"

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
using engine::kDofNames;

OffsetSummary summarize_offset(const engine::Vector6d& offset, double depth_m) {
  OffsetSummary s;
  s.horizontal_m = std::hypot(offset(0), offset(1));
  s.horizontal_pct_depth = 100.0 * s.horizontal_m / depth_m;
  // Below a millimetre the direction is round-off: report 0.
  s.direction_deg = s.horizontal_m > 1e-3 ? std::atan2(offset(1), offset(0)) * kRadToDeg : 0.0;
  if (s.direction_deg < 0.0) s.direction_deg += 360.0;
  s.heave_m = offset(2);
  s.roll_deg = offset(3) * kRadToDeg;
  s.pitch_deg = offset(4) * kRadToDeg;
  s.yaw_deg = offset(5) * kRadToDeg;
  return s;
}

/// Undamped modes of M ẍ + K x = 0. K is symmetrised: its antisymmetric part
/// (seabed friction, a net moment on the turning arms) does no work over a
/// cycle of small oscillation to first order and is below 2 % here.
std::vector<NaturalMode> natural_modes(const engine::Matrix6d& stiffness, const engine::Matrix6d& mass) {
  const engine::Matrix6d k = 0.5 * (stiffness + stiffness.transpose());
  const Eigen::GeneralizedSelfAdjointEigenSolver<engine::Matrix6d> solver(k, mass);
  std::vector<NaturalMode> modes;
  if (solver.info() != Eigen::Success) return modes;
  for (int i = 0; i < 6; ++i) {
    const double omega_squared = solver.eigenvalues()(i);
    if (!(omega_squared > 0.0)) continue;  // no restoring in this mode: no period
    // The dominant DOF by kinetic-energy share: |x_j| sqrt(M_jj).
    const engine::Vector6d shape = solver.eigenvectors().col(i).cwiseAbs().cwiseProduct(mass.diagonal().cwiseSqrt());
    Eigen::Index dominant = 0;
    shape.maxCoeff(&dominant);
    modes.push_back({2.0 * std::numbers::pi / std::sqrt(omega_squared), kDofNames[dominant]});
  }
  std::sort(modes.begin(), modes.end(),
            [](const NaturalMode& a, const NaturalMode& b) { return a.period_s < b.period_s; });
  return modes;
}

}  // namespace

StaticCaseResult run_static_case(const ValidatedProject& validated, const StaticCaseRequest& request,
                                 RestSolutionCache* cache) {
  return run_static_case(validated, build_case_model(validated.project, request.load_case), request, cache);
}

StaticCaseResult run_static_case(const ValidatedProject& validated, const CaseModel& case_model,
                                 const StaticCaseRequest& request, RestSolutionCache* cache) {
  const Project& project = validated.project;
  StaticCaseResult result;
  result.case_name = "still-water";
  result.environment = "none";
  std::optional<std::string> damaged = request.damaged_line;
  if (request.load_case.has_value() != (case_model.load_case != nullptr) ||
      (request.load_case && *request.load_case != case_model.load_case->name)) {
    throw std::invalid_argument("run_static_case: the case model is not that of the requested load case");
  }
  if (const LoadCase* load_case = case_model.load_case) {
    result.case_name = load_case->name;
    result.environment = load_case->environment;
    if (!damaged) damaged = load_case->damaged_line;
  }
  if (damaged && std::none_of(project.mooring.lines.begin(), project.mooring.lines.end(),
                              [&](const MooringLine& l) { return l.name == *damaged; })) {
    std::string names;
    for (const MooringLine& l : project.mooring.lines) names += (names.empty() ? "" : ", ") + l.name;
    throw request_error(project, "damaged_line",
                        fmt::format("no mooring line named \"{}\" (defined: {})", *damaged, names));
  }
  result.damaged_line = damaged;
  result.integrity = damaged ? LineIntegrity::damaged : LineIntegrity::intact;

  engine::ExternalLoad environment_load;
  LineArrayOptions line_options;
  line_options.excluded_line = damaged.value_or("");
  if (case_model.environment) {
    MeanEnvironmentLoad mean = mean_environment_load(project, *case_model.environment, case_model.drift);
    environment_load = std::move(mean.load);
    result.notes = std::move(mean.notes);
    line_options.current = case_model.current;
    line_options.lines_carry_current = request.lines_carry_current;
    if (line_options.current) {
      const bool catenaries = std::any_of(
          project.mooring.lines.begin(), project.mooring.lines.end(),
          [&](const MooringLine& l) { return l.model == LineModel::catenary && l.name != line_options.excluded_line; });
      if (catenaries && request.lines_carry_current) {
        result.notes.push_back(
            "current on the mooring lines: every mooring line as an FE line with the current drag "
            "(the S-C static case), whatever its model");
      } else if (catenaries) {
        result.current_on_every_line = false;
        result.notes.push_back(
            "current on the mooring lines: lines with model: catenary carry no current drag (risers and "
            "model: fe lines do)");
      }
    }
  }
  result.lines_carry_current = request.lines_carry_current;
  const HullModel& hull = *case_model.hull;
  LineArrayModel lines = build_line_array(project, *case_model.line_types, line_options);
  if (case_model.load_case) result.design_condition = case_model.load_case->condition;

  engine::Stopwatch start;
  if (cache) {
    // The equilibrium's first evaluation is at the rest position: take the
    // FE lines solved there in an earlier case with this environment, solve
    // the others now (the equilibrium then finds them solved), keep them all.
    const engine::HullPose rest = engine::pose_from_offset(lines.reference_point_g, engine::Vector6d::Zero());
    std::vector<engine::FeStaticLine*> fe_lines;
    for (const auto& line : lines.lines) {
      auto* fe = dynamic_cast<engine::FeStaticLine*>(line.get());
      if (!fe) continue;
      fe_lines.push_back(fe);
      std::optional<engine::FeStaticsResult> solved;
      {
        const std::lock_guard lock(cache->mutex);
        const auto it = cache->solutions.find({result.environment, fe->name()});
        if (it != cache->solutions.end()) solved = it->second;
      }
      if (solved) fe->adopt(rest.point_g(fe->attachment_b()), std::move(*solved));
    }
    engine::evaluate_line_array(lines.lines, rest);
    const std::lock_guard lock(cache->mutex);
    for (engine::FeStaticLine* fe : fe_lines)
      cache->solutions.try_emplace({result.environment, fe->name()}, *fe->last_result());
  }
  const engine::EquilibriumResult equilibrium = [&] {
    try {
      return engine::solve_static_equilibrium(hull.statics, lines.lines, environment_load);
    } catch (const engine::TableRangeError& e) {
      // The hull's yaw at equilibrium turns the relative heading off the data
      // (e.g. a drift table of one heading and a damaged, yawing hull).
      heading_error(project, result.environment, "mean environmental loads at the hull's mean yaw", e);
    }
  }();
  result.equilibrium_wall_s = start.seconds();
  result.equilibrium_iterations = equilibrium.iterations;
  result.offset = equilibrium.offset;
  result.offset_summary = summarize_offset(equilibrium.offset, project.site.depth_m);
  result.hydrostatic_force = equilibrium.hydrostatic_force;
  result.environment_force = equilibrium.external_force;
  result.residual = equilibrium.residual;
  result.hydrostatic_stiffness = hull.statics.hydrostatic_stiffness;

  // The equilibrium's last evaluation is at the converged pose: its analytic
  // tangent is the line-array K there, no extra solve needed.
  start.restart();
  const engine::LineArrayResponse& array = equilibrium.lines;
  result.line_force = array.force;
  result.stiffness = array.stiffness;
  for (const auto& contribution : array.lines) {
    result.line_stiffness.push_back(contribution.stiffness);
    result.line_force_6dof.push_back(contribution.force);
  }
  result.stiffness_wall_s = start.seconds();
  if (request.finite_difference_check) {
    result.stiffness_finite_difference = engine::finite_difference_stiffness(lines.lines, equilibrium.pose);
    result.stiffness_check_relative_difference =
        (result.stiffness - *result.stiffness_finite_difference).norm() / result.stiffness_finite_difference->norm();
  }

  std::vector<engine::LineState> states;
  for (std::size_t i = 0; i < lines.designs.size(); ++i) {
    const auto& line = lines.lines[i];
    states.push_back(line->state(equilibrium.pose.point_g(line->attachment_b()), kResultProfilePointsPerSegment));
  }
  result.lines = line_statics_rows(lines, states);
  result.dynamic_stiffness = array.stiffness;
  for (std::size_t i = 0; i < lines.designs.size(); ++i) {
    const std::vector<LineTypeProperties>& types = lines.designs[i].segment_types;
    if (std::none_of(types.begin(), types.end(), has_dynamic_axial_stiffness)) continue;
    std::vector<int> point_segment;
    std::vector<double> point_tension;
    for (const engine::LineProfilePoint& point : states[i].profile) {
      point_segment.push_back(point.segment);
      point_tension.push_back(point.tension_N);
    }
    const engine::LineContribution& at = array.lines[i];
    const Eigen::Matrix3d k = lines.lines[i]->incremental_stiffness_g(
        at.attachment_g, incremental_axial_stiffness_N(types, point_segment, point_tension));
    result.dynamic_stiffness +=
        engine::attachment_stiffness_6x6(k, at.end.force_g, at.attachment_g - equilibrium.pose.reference_point_g) -
        at.stiffness;
    ++result.dynamic_stiffness_lines;
  }
  for (std::size_t r = 0; r < lines.risers.size(); ++r) {
    // The equilibrium left every riser solved at the final pose.
    const auto& riser = static_cast<const engine::FeStaticLine&>(*lines.lines[lines.designs.size() + r]);
    result.risers.push_back(riser_statics_row(project, lines.risers[r], *riser.last_result(), result.design_condition,
                                              equilibrium.pose.rotation));
  }

  // With a radiation file the modes use M + A(w_LF) (the hull's added mass at
  // the low frequency of the moored modes), with Morison members their strip
  // added mass; without either, M alone (flagged).
  result.added_mass_included = hull.radiation.has_value() || hull.morison.has_value();
  result.natural_modes = natural_modes(hull.statics.hydrostatic_stiffness + result.stiffness,
                                       hull.mass_matrix + hull.low_frequency_added_mass);
  result.dynamic_natural_modes = result.dynamic_stiffness_lines == 0
                                     ? result.natural_modes
                                     : natural_modes(hull.statics.hydrostatic_stiffness + result.dynamic_stiffness,
                                                     hull.mass_matrix + hull.low_frequency_added_mass);
  return result;
}

}  // namespace spiral::design
