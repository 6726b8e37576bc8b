#include "design/optimization/scenario_model.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "design/criteria/mooring_checks.hpp"
#include "design/model/environment_loads.hpp"
#include "design/model/riser_model.hpp"
#include "engine/analysis/fe_static_line.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/analysis/linearized_line.hpp"
#include "engine/analysis/static_line.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/common/rigid_body.hpp"
#include "engine/lines/catenary_payout.hpp"

namespace spiral::design {

std::string Scenario::label() const {
  if (!damaged_line || !removed_by_study) return case_name;
  return fmt::format("{} without {}", case_name, *damaged_line);
}

namespace {

// Within this of the pose where the line array's stiffness was computed,
// the hull's Newton tangent keeps it (EquilibriumOptions).
constexpr double kStiffnessReuseDistance_m = 0.1;
// Within this of where an FE riser's end-B stiffness was last computed (by
// itself or by the scenario it adopted its state from), an equilibrium
// without gradients takes that stiffness for its Newton tangent
// (FeStaticLine::set_stiffness_reuse_distance): a damaged scenario starts
// 0.2-1 m from its cluster neighbour, and a riser's stiffness changes over
// metres.
constexpr double kRiserStiffnessReuseDistance_m = 1.0;

/// A mooring line of the scenario and how to rebuild it at a payout.
struct PaidLine {
  std::size_t project_index = 0;
  int group = -1;  ///< index into the groups, or −1 (not a variable)
  double anchor_height_m = 0.0;
  std::optional<engine::CatenaryLine> catenary;  ///< at zero payout; none for an FE line
  double installed_payout_m = 0.0;
};

/// Where along a line its utilization is set.
struct GoverningPoint {
  double utilization = 0.0;
  std::string segment_type;
  std::size_t point = 0;  ///< index into the catenary profile
};

}  // namespace

struct ScenarioModel::Impl {
  const Project& project;
  const HullModel& hull;
  const std::vector<PayoutGroup>& groups;
  std::vector<LineTypeProperties> types;
  engine::ExternalLoad environment_load;
  std::optional<engine::CurrentProfile> current;
  LineArrayModel array;
  std::vector<PaidLine> paid;  ///< one per mooring line of `array`
  double safety_factor = 1.0;
  engine::Vector6d last_offset = engine::Vector6d::Zero();
  std::optional<engine::HullPose> last_pose;
  /// Where predict() put the next evaluation's start.
  std::optional<engine::Vector6d> predicted;
  /// The full lines while their linearizations stand in (by array index).
  std::vector<std::unique_ptr<engine::StaticLine>> stashed;
  /// The FE lines' solves stop at their tolerance (1e-10 of the force
  /// scale): the constraints need no more, and polishing a chord-converged
  /// state to 1e-3 of it took 2,068 of the every-line optimization's 16,800
  /// residual assemblies (most of them a last chord step that no longer
  /// contracts). The payouts move by 4e-8 m.
  static engine::FeStaticsOptions screening_options() {
    engine::FeStaticsOptions o;
    o.polish_chord_steps = false;
    return o;
  }
  const engine::FeStaticsOptions fe_statics = screening_options();

  Impl(const Project& p, const HullModel& h, const std::vector<PayoutGroup>& g, const Scenario& scenario,
       engine::ExternalLoad load)
      : project(p), hull(h), groups(g), types(resolve_line_types(p)), environment_load(std::move(load)) {
    const LoadCase& load_case = *std::find_if(p.load_cases.begin(), p.load_cases.end(),
                                              [&](const LoadCase& c) { return c.name == scenario.case_name; });
    const Environment& environment = environment_of(p, load_case);
    if (!environment_load) environment_load = mean_environment_load(p, environment).load;
    current = current_profile_of(environment);
    LineArrayOptions options;
    options.excluded_line = scenario.damaged_line.value_or("");
    options.current = current;
    options.fe_statics = fe_statics;
    array = build_line_array(p, options);
    safety_factor = mooring_safety_factor(p.criteria.mooring, scenario.damaged_line.has_value());
    for (const MooringLineDesign& design : array.designs) {
      PaidLine line;
      for (std::size_t i = 0; i < p.mooring.lines.size(); ++i)
        if (p.mooring.lines[i].name == design.name) line.project_index = i;
      for (std::size_t k = 0; k < g.size(); ++k) {
        if (std::find(g[k].lines.begin(), g[k].lines.end(), line.project_index) != g[k].lines.end())
          line.group = static_cast<int>(k);
      }
      const MooringLine& source = p.mooring.lines[line.project_index];
      line.anchor_height_m = std::max(0.0, source.anchor_g.z() + p.site.depth_m);
      if (source.model == LineModel::catenary) line.catenary = catenary_of(p, source, types);
      paid.push_back(std::move(line));
    }
  }

  bool has_expensive_lines() const {
    return std::any_of(array.lines.begin() + static_cast<std::ptrdiff_t>(paid.size()), array.lines.end(),
                       [](const auto& line) { return line->expensive(); });
  }

  /// Solves the risers (the expensive lines) with their stiffness at `pose`,
  /// on the cores the caller leaves free; `label` names the scenario in a
  /// failure.
  void solve_expensive_lines(const engine::HullPose& pose, const std::string& label) {
    const auto first = static_cast<std::ptrdiff_t>(paid.size());
    const int count = static_cast<int>(array.lines.size() - paid.size());
    try {
      engine::parallel_for(count, engine::worker_count(count), [&](int i) {
        engine::StaticLine& line = *array.lines[static_cast<std::size_t>(first + i)];
        if (line.expensive()) line.solve(pose.point_g(line.attachment_b()));
      });
    } catch (const engine::SolverError& error) {
      throw engine::SolverError(fmt::format("{}: {}", label, error.what()), error.diagnostics());
    }
  }

  bool all_catenary() const {
    return std::all_of(paid.begin(), paid.end(), [](const PaidLine& l) { return l.catenary.has_value(); });
  }

  /// Rebuilds the mooring lines whose payout changed.
  void install(const Eigen::VectorXd& payouts_m) {
    for (std::size_t k = 0; k < paid.size(); ++k) {
      PaidLine& line = paid[k];
      const double payout = line.group >= 0 ? payouts_m(line.group) : 0.0;
      if (payout == line.installed_payout_m) continue;
      const MooringLine& source = project.mooring.lines[line.project_index];
      if (line.catenary) {
        array.lines[k] = std::make_unique<engine::CatenaryStaticLine>(source.name, source.anchor_g, source.fairlead_b,
                                                                      line.anchor_height_m,
                                                                      engine::with_payout(*line.catenary, payout));
      } else {
        MooringLine paid_out = source;
        paid_out.segments.back().length_m += payout;
        const engine::FeLineModel fe = fe_line_model(project, paid_out, types);
        array.lines[k] = std::make_unique<engine::FeStaticLine>(
            source.name, source.anchor_g, source.fairlead_b, fe,
            fe_environment(project, current, fe.sections.front().hydro_diameter_m), fe_statics);
      }
      line.installed_payout_m = payout;
    }
  }

  GoverningPoint governing_point(std::size_t k, const std::vector<engine::LineProfilePoint>& profile) const {
    GoverningPoint out;
    const MooringLineDesign& design = array.designs[k];
    for (std::size_t p = 0; p < profile.size(); ++p) {
      const auto segment = static_cast<std::size_t>(profile[p].segment);
      if (segment >= design.segment_types.size()) continue;
      const double u = safety_factor * profile[p].tension_N / design.segment_types[segment].breaking_load_N;
      if (u >= out.utilization) out = {u, design.segment_types[segment].name, p};
    }
    return out;
  }
};

ScenarioModel::ScenarioModel(const Project& project, const HullModel& hull, const std::vector<PayoutGroup>& groups,
                             Scenario scenario, engine::ExternalLoad environment_load)
    : impl_(std::make_unique<Impl>(project, hull, groups, scenario, std::move(environment_load))),
      scenario_(std::move(scenario)) {}
ScenarioModel::ScenarioModel(ScenarioModel&&) noexcept = default;
ScenarioModel::~ScenarioModel() = default;

ScenarioResponse ScenarioModel::evaluate(const Eigen::VectorXd& payouts_m, bool with_gradient) {
  Impl& m = *impl_;
  if (with_gradient && !m.all_catenary()) return evaluate_by_differences(payouts_m);
  m.install(payouts_m);
  if (!m.last_pose && !m.predicted && m.has_expensive_lines()) {
    // Cold: the FE lines solved once where the hull starts (with their
    // stiffness), so that the predictor below takes the hull across its
    // tens of metres of offset on them linearized; the hull's Newton from
    // rest with the full risers re-solved every riser at each of its 3-4
    // poses on the way.
    const engine::HullPose rest = engine::pose_from_offset(m.hull.statics.reference_point_at_rest_g, m.last_offset);
    m.solve_expensive_lines(rest, scenario_.label());
    m.last_pose = rest;
  }
  engine::Vector6d start = m.last_offset;
  if (m.predicted) {
    start = *m.predicted;
  } else if (const auto predicted = predicted_offset(payouts_m)) {
    start = *predicted;
  }
  m.predicted.reset();
  // Exact riser stiffness where the gradients use it (at the solution),
  // and outside the equilibrium (state(), complete_expensive_lines).
  const auto riser_stiffness_reuse = [&](double distance_m) {
    for (std::size_t k = m.paid.size(); k < m.array.lines.size(); ++k)
      if (auto* fe = dynamic_cast<engine::FeStaticLine*>(m.array.lines[k].get()))
        fe->set_stiffness_reuse_distance(distance_m);
  };
  riser_stiffness_reuse(with_gradient ? 0.0 : kRiserStiffnessReuseDistance_m);
  engine::EquilibriumResult eq;
  try {
    // The K at the solution serves the analytic gradient only (catenaries
    // alone); the FE risers then skip a factorisation each. The closing
    // Newton steps (centimetres from the predicted start) keep the tangent
    // of the step before: a riser's stiffness changes over metres.
    eq = engine::solve_static_equilibrium(
        m.hull.statics, m.array.lines, m.environment_load, start,
        {.stiffness_at_solution = with_gradient, .stiffness_reuse_distance_m = kStiffnessReuseDistance_m});
  } catch (const engine::SolverError& error) {
    riser_stiffness_reuse(0.0);
    throw engine::SolverError(fmt::format("{}: {}", scenario_.label(), error.what()), error.diagnostics());
  }
  riser_stiffness_reuse(0.0);
  m.last_offset = eq.offset;
  m.last_pose = eq.pose;
  ScenarioResponse out;
  out.offset = eq.offset;
  out.equilibrium_iterations = eq.iterations;

  const auto group_count = static_cast<Eigen::Index>(m.groups.size());
  Eigen::Matrix<double, 6, Eigen::Dynamic> dq;
  if (with_gradient) {
    // ∂F/∂ΔL per group, from each catenary's payout tangent at the solution.
    Eigen::Matrix<double, 6, Eigen::Dynamic> rhs = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, group_count);
    for (std::size_t k = 0; k < m.paid.size(); ++k) {
      if (m.paid[k].group < 0) continue;
      const auto& line = static_cast<const engine::CatenaryStaticLine&>(*m.array.lines[k]);
      const Eigen::Vector2d s = engine::catenary_payout_sensitivity(line.line(), line.last_solution());
      const Eigen::Vector3d df = -s.x() * line.last_direction_g() - s.y() * Eigen::Vector3d::UnitZ();
      const Eigen::Vector3d arm = eq.pose.rotation * line.attachment_b();
      rhs.col(m.paid[k].group).head<3>() += df;
      rhs.col(m.paid[k].group).tail<3>() += arm.cross(df);
    }
    // dq/dΔL in the equilibrium's unknowns (offset with roll, pitch, yaw),
    // then as translations and small global rotations.
    const engine::Matrix6d k_total =
        engine::equilibrium_tangent(m.hull.statics, eq.lines.stiffness, m.environment_load, eq.offset);
    const Eigen::Matrix<double, 6, Eigen::Dynamic> d_offset = k_total.partialPivLu().solve(rhs);
    out.d_horizontal_offset = d_offset.topRows<2>();
    dq = engine::offset_increment_to_global(eq.offset) * d_offset;
  }

  for (std::size_t k = 0; k < m.paid.size(); ++k) {
    engine::StaticLine& line = *m.array.lines[k];
    const Eigen::Vector3d arm = eq.pose.rotation * line.attachment_b();
    // One profile point per segment end: a segment's largest tension is at
    // one of its ends (statics_study.cpp).
    const engine::LineState state = line.state(eq.pose.reference_point_g + arm, 1);
    LineResponse r;
    r.name = m.array.designs[k].name;
    r.fairlead_tension_N = state.top.force_g.norm();
    r.laid_length_m = state.laid_length_m;
    const GoverningPoint governing = m.governing_point(k, state.profile);
    r.utilization = governing.utilization;
    r.governing_segment_type = governing.segment_type;
    if (with_gradient) {
      const auto& catenary = static_cast<const engine::CatenaryStaticLine&>(line);
      const engine::CatenarySolution& sol = catenary.last_solution();
      const engine::CatenarySegment& top = catenary.line().segments.back();
      const Eigen::Vector3d& e = catenary.last_direction_g();
      // Fairlead displacement per group, then the in-plane spans.
      const Eigen::Matrix<double, 3, Eigen::Dynamic> dp = engine::point_jacobian(arm) * dq;
      Eigen::Matrix<double, 2, Eigen::Dynamic> dspan(2, group_count);
      dspan.row(0) = e.transpose() * dp;
      dspan.row(1) = dp.row(2);
      Eigen::Matrix<double, 2, Eigen::Dynamic> dhv = sol.tangent_stiffness * dspan;
      Eigen::VectorXd own = Eigen::VectorXd::Zero(group_count);  // ∂/∂ΔL of this line's own payout
      if (m.paid[k].group >= 0) {
        own(m.paid[k].group) = 1.0;
        dhv += engine::catenary_payout_sensitivity(catenary.line(), sol) * own.transpose();
      }
      const double h = sol.fairlead_horizontal_N, v = sol.fairlead_vertical_N;
      const Eigen::VectorXd dH = dhv.row(0).transpose(), dV = dhv.row(1).transpose();
      r.d_fairlead_tension_N = (h * dH + v * dV) / sol.fairlead_tension_N;
      // The governing point: T² = H² + V_p², V_p = V_F − (weight above it);
      // below the fairlead the added top length adds w_top ΔL above it.
      const engine::CatenaryProfilePoint& point = sol.profile[governing.point];
      const bool at_fairlead = governing.point + 1 == sol.profile.size();
      const MooringLineDesign& design = m.array.designs[k];
      const double mbl = design.segment_types[static_cast<std::size_t>(point.segment)].breaking_load_N;
      Eigen::VectorXd dT_point;
      if (point.on_seabed || point.tension_N <= 0.0) {
        dT_point = dH;
      } else {
        const Eigen::VectorXd dVp = at_fairlead ? dV : Eigen::VectorXd(dV - top.weight_N_per_m * own);
        dT_point = (point.horizontal_N * dH + point.vertical_N * dVp) / point.tension_N;
      }
      r.d_utilization = m.safety_factor / mbl * dT_point;
      // Laid length: the suspended part weighs V_F; the added top length
      // takes w_top ΔL of it, the touchdown point moves by the rest over the
      // weight per metre of the segment it lies in.
      r.d_laid_length_m = Eigen::VectorXd::Zero(group_count);
      if (sol.regime == engine::CatenaryRegime::touchdown && sol.laid_length_m > 0.0) {
        double arc = 0.0;
        const engine::CatenarySegment* at_touchdown = &catenary.line().segments.back();
        for (const engine::CatenarySegment& s : catenary.line().segments) {
          arc += s.length_m;
          if (arc >= sol.laid_length_m) {
            at_touchdown = &s;
            break;
          }
        }
        if (at_touchdown->weight_N_per_m > 0.0)
          r.d_laid_length_m = -(dV - top.weight_N_per_m * own) / at_touchdown->weight_N_per_m;
      }
    }
    out.lines.push_back(std::move(r));
  }
  return out;
}

std::optional<engine::Vector6d> ScenarioModel::predicted_offset(const Eigen::VectorXd& payouts_m) {
  Impl& m = *impl_;
  if (!m.last_pose || !m.stashed.empty() || !m.has_expensive_lines()) return std::nullopt;
  // Predictor: the equilibrium first with the FE risers linearized where
  // they were last solved (microseconds), then the full one from there.
  // The hull's Newton iterations that follow the mooring's nonlinearity
  // over a payout change (a damaged hull moves tens of metres) then cost
  // no riser solves; the full solve only corrects the risers' second-order
  // force error: one solve at the predicted pose and one or two small
  // Newton steps, instead of a riser solve at every step of the way.
  m.install(payouts_m);
  try {
    linearize_expensive_lines();
  } catch (const engine::SolverError& error) {
    throw engine::SolverError(fmt::format("{}: {}", scenario_.label(), error.what()), error.diagnostics());
  }
  std::optional<engine::Vector6d> out;
  try {
    out = engine::solve_static_equilibrium(m.hull.statics, m.array.lines, m.environment_load, m.last_offset,
                                           {.stiffness_at_solution = false})
              .offset;
  } catch (const engine::SolverError&) {
    // The linear risers' equilibrium is only a starting point: without
    // one, the full solve starts where the last one ended.
  }
  restore_expensive_lines();
  return out;
}

std::optional<engine::HullPose> ScenarioModel::predict(const Eigen::VectorXd& payouts_m) {
  Impl& m = *impl_;
  m.predicted = predicted_offset(payouts_m);
  if (!m.predicted) return std::nullopt;
  return engine::pose_from_offset(m.hull.statics.reference_point_at_rest_g, *m.predicted);
}

std::vector<Eigen::Vector3d> ScenarioModel::riser_tops_g(const engine::HullPose& pose) const {
  const Impl& m = *impl_;
  std::vector<Eigen::Vector3d> out;
  for (std::size_t k = m.paid.size(); k < m.array.lines.size(); ++k)
    if (m.array.lines[k]->expensive()) out.push_back(pose.point_g(m.array.lines[k]->attachment_b()));
  return out;
}

std::vector<Eigen::Vector3d> ScenarioModel::solved_riser_tops_g() const {
  const Impl& m = *impl_;
  std::vector<Eigen::Vector3d> out;
  for (std::size_t k = m.paid.size(); k < m.array.lines.size(); ++k) {
    if (!m.array.lines[k]->expensive()) continue;
    const auto* line = dynamic_cast<const engine::FeStaticLine*>(m.array.lines[k].get());
    if (!line || !line->last_result()) return {};
    out.push_back(line->last_attachment_g());
  }
  return out;
}

void ScenarioModel::start_risers_from(const ScenarioModel& source) {
  Impl& m = *impl_;
  const Impl& from = *source.impl_;
  // The risers follow the mooring lines in both arrays, in project order.
  const std::size_t risers = m.array.lines.size() - m.paid.size();
  if (risers != from.array.lines.size() - from.paid.size())
    throw std::logic_error("ScenarioModel::start_risers_from: the scenarios have different risers");
  for (std::size_t j = 0; j < risers; ++j) {
    auto* line = dynamic_cast<engine::FeStaticLine*>(m.array.lines[m.paid.size() + j].get());
    const auto* solved = dynamic_cast<const engine::FeStaticLine*>(from.array.lines[from.paid.size() + j].get());
    if (!line || !solved || !solved->last_result()) continue;
    line->adopt(*solved);
  }
}

void ScenarioModel::start_from(const ScenarioModel& source) {
  Impl& m = *impl_;
  const Impl& from = *source.impl_;
  if (!from.last_pose) throw std::logic_error("ScenarioModel::start_from: the source has not been evaluated");
  start_risers_from(source);
  m.last_offset = from.last_offset;
  m.last_pose = from.last_pose;
}

void ScenarioModel::complete_expensive_lines() {
  Impl& m = *impl_;
  if (!m.last_pose) throw std::logic_error("ScenarioModel::complete_expensive_lines: not evaluated");
  m.solve_expensive_lines(*m.last_pose, scenario_.label());
}

void ScenarioModel::linearize_expensive_lines() {
  Impl& m = *impl_;
  if (!m.last_pose) evaluate(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.groups.size())), false);
  m.stashed.resize(m.array.lines.size());
  for (std::size_t k = m.paid.size(); k < m.array.lines.size(); ++k) {
    std::unique_ptr<engine::StaticLine>& line = m.array.lines[k];
    if (m.stashed[k] || !line->expensive()) continue;
    // About where the line was last solved (the stored solution: no new
    // solve). The hull's last pose may be a linearized evaluation's.
    const auto* fe = dynamic_cast<const engine::FeStaticLine*>(line.get());
    const Eigen::Vector3d at =
        fe && fe->last_result() ? fe->last_attachment_g() : m.last_pose->point_g(line->attachment_b());
    const engine::LineEndResponse response = line->linearization(at);
    auto linear = std::make_unique<engine::LinearizedStaticLine>(line->name(), line->attachment_b(), at, response);
    m.stashed[k] = std::move(line);
    line = std::move(linear);
  }
}

void ScenarioModel::restore_expensive_lines() {
  Impl& m = *impl_;
  for (std::size_t k = 0; k < m.stashed.size(); ++k)
    if (m.stashed[k]) m.array.lines[k] = std::move(m.stashed[k]);
  m.stashed.clear();
}

ScenarioResponse ScenarioModel::evaluate_by_differences(const Eigen::VectorXd& payouts_m, double step_m) {
  ScenarioResponse out = evaluate(payouts_m, false);
  const Eigen::Index n = payouts_m.size();
  out.d_horizontal_offset.setZero(2, n);
  for (LineResponse& line : out.lines) {
    line.d_fairlead_tension_N.setZero(n);
    line.d_utilization.setZero(n);
    line.d_laid_length_m.setZero(n);
  }
  for (Eigen::Index g = 0; g < n; ++g) {
    Eigen::VectorXd plus = payouts_m, minus = payouts_m;
    plus(g) += step_m;
    minus(g) -= step_m;
    const ScenarioResponse a = evaluate(plus, false);
    const ScenarioResponse b = evaluate(minus, false);
    out.d_horizontal_offset.col(g) = (a.offset.head<2>() - b.offset.head<2>()) / (2.0 * step_m);
    for (std::size_t k = 0; k < out.lines.size(); ++k) {
      out.lines[k].d_fairlead_tension_N(g) =
          (a.lines[k].fairlead_tension_N - b.lines[k].fairlead_tension_N) / (2.0 * step_m);
      out.lines[k].d_utilization(g) = (a.lines[k].utilization - b.lines[k].utilization) / (2.0 * step_m);
      out.lines[k].d_laid_length_m(g) = (a.lines[k].laid_length_m - b.lines[k].laid_length_m) / (2.0 * step_m);
    }
  }
  // Leave the warm start at the centre point.
  evaluate(payouts_m, false);
  return out;
}

}  // namespace spiral::design
