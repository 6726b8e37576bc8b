#include "design/results/dynamic_analysis_output.hpp"

#include "engine/numerics/free_decay.hpp"
#include "engine/common/dof_names.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <utility>

namespace spiral::design {
namespace {

using engine::kDofNames;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

/// Output unit of a DOF: m for translations, deg for rotations (SI inside).
double dof_scale(int dof) { return dof < 3 ? 1.0 : kRadToDeg; }
const char* dof_unit(int dof) { return dof < 3 ? "m" : "deg"; }

/// The tension channels of a result, one name per quantity in every output
/// (analyze, compare, the advanced stage): `tension_<line>_N` is a dynamic FE
/// line's top tension (the coupled run's, or under the prescribed motion of
/// --line-dynamics; mooring lines, then risers), `qs_tension_<line>_N` the
/// quasi-static catenary at the instantaneous fairlead (no current on the line).
std::vector<std::pair<std::string, const std::vector<double>*>> tension_channels(const DynamicAnalysisResult& r) {
  std::vector<std::pair<std::string, const std::vector<double>*>> out;
  for (const auto& t : r.tensions) out.emplace_back("qs_tension_" + t.line + "_N", &t.tension_N);
  for (const auto& t : r.dynamic_tensions) out.emplace_back("tension_" + t.line + "_N", &t.tension_N);
  return out;
}

std::vector<double> row_of(const Eigen::Matrix<double, 6, Eigen::Dynamic>& m, int dof) {
  std::vector<double> out(static_cast<std::size_t>(m.cols()));
  for (Eigen::Index k = 0; k < m.cols(); ++k) out[static_cast<std::size_t>(k)] = m(dof, k) * dof_scale(dof);
  return out;
}

nlohmann::json matrix_json(const engine::Matrix6d& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < 6; ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

std::vector<TimeSeriesColumn> dynamic_time_series_columns(const DynamicAnalysisResult& r) {
  std::vector<TimeSeriesColumn> columns;
  columns.push_back({"time_s", std::vector<double>(r.times_s.data(), r.times_s.data() + r.times_s.size()), "{:.3f}"});
  const std::pair<const Eigen::Matrix<double, 6, Eigen::Dynamic>*, const char*> motions[] = {
      {&r.total, ""}, {&r.low_frequency, "_lf"}, {&r.wave_frequency, "_wf"}};
  for (const auto& [m, suffix] : motions) {
    for (int d = 0; d < 6; ++d)
      columns.push_back({fmt::format("{}{}_{}", kDofNames[d], suffix, dof_unit(d)), row_of(*m, d), "{:.6g}"});
  }
  for (const auto& [name, values] : tension_channels(r)) columns.push_back({name, *values, "{:.7g}"});
  for (const auto& t : r.tensions) {
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> values(t.fairlead_g_m.size());
      for (std::size_t k = 0; k < values.size(); ++k) values[k] = t.fairlead_g_m[k](axis);
      columns.push_back({fmt::format("fairlead_{}_{}_m", t.line, "xyz"[axis]), std::move(values), "{:.4f}"});
    }
  }
  return columns;
}

std::string dynamic_time_series_csv(const DynamicAnalysisResult& r) {
  return time_series_csv(dynamic_time_series_columns(r));
}

nlohmann::json dynamic_analysis_to_json(const DynamicAnalysisResult& r, const std::string& project_name) {
  nlohmann::json j;
  j["format"] = "spiral.dynamic_analysis";
  j["format_version"] = 1;
  j["project"] = project_name;
  j["load_case"] = r.case_name;
  j["environment"] = r.environment;
  j["level"] = to_string(r.level);
  j["seed"] = r.seed;
  const double dt = r.times_s.size() > 1 ? r.times_s(1) - r.times_s(0) : 0.0;
  j["duration_s"] = r.times_s.size() > 0 ? r.times_s(r.times_s.size() - 1) : 0.0;
  j["output_step_s"] = dt;
  j["tolerance_scale"] = r.tolerance_scale;
  j["line_element_length_m"] =
      r.line_element_length_m ? nlohmann::json(*r.line_element_length_m) : nlohmann::json(nullptr);
  if (r.decay) {
    // A free decay: what was asked, and the half cycles of every displaced
    // degree of freedom's low-frequency motion about the static equilibrium
    // after the release, down to 1 % of the displacement (m; angles in deg,
    // as every output).
    nlohmann::json displacement, half_cycles;
    for (int d = 0; d < 6; ++d) {
      const std::string name = fmt::format("{}_{}", kDofNames[d], dof_unit(d));
      const double asked = r.decay->displacement(d);
      displacement[name] = asked * dof_scale(d);
      if (asked == 0.0 || r.times_s.size() < 3) continue;
      const Eigen::VectorXd motion = r.low_frequency.row(d).transpose();
      nlohmann::json cycles = nlohmann::json::array();
      for (const engine::DecayHalfCycle& c : engine::free_decay_half_cycles(
               std::span<const double>(r.times_s.data(), static_cast<std::size_t>(r.times_s.size())),
               std::span<const double>(motion.data(), static_cast<std::size_t>(motion.size())), r.static_offset(d),
               r.decay->release_s, 0.01 * std::abs(asked))) {
        cycles.push_back({{"start_s", c.start_s},
                          {"amplitude", c.amplitude * dof_scale(d)},
                          {"period_s", c.period_s},
                          {"damping_ratio", c.damping_ratio}});
      }
      half_cycles[name] = std::move(cycles);
    }
    j["decay"] = {{"release_s", r.decay->release_s}, {"displacement", displacement}, {"half_cycles", half_cycles}};
  }
  j["wave_frequency_motions"] = r.wave_frequency_computed;
  nlohmann::json offset;
  for (int d = 0; d < 6; ++d)
    offset[fmt::format("{}_{}", kDofNames[d], dof_unit(d))] = r.static_offset(d) * dof_scale(d);
  j["static_offset"] = offset;
  nlohmann::json drift = nlohmann::json::array();
  for (int d = 0; d < 6; ++d) drift.push_back(r.mean_slow_drift_force(d));
  j["mean_slow_drift_force_N"] = drift;
  if (!r.low_frequency_damping.empty())
    j["low_frequency_damping"] = low_frequency_damping_to_json(r.low_frequency_damping);
  if (r.line_added_mass) j["line_added_mass"] = matrix_json(*r.line_added_mass);
  if (r.line_damping) j["line_damping"] = matrix_json(*r.line_damping);
  if (r.line_reduction) j["line_reduction"] = *r.line_reduction == LineReduction::dynamic ? "dynamic" : "quasi-static";
  if (!r.line_relaxations.empty()) {
    nlohmann::json relaxations = nlohmann::json::array();
    for (const engine::LineRelaxation& x : r.line_relaxations)
      relaxations.push_back({{"time_constant_s", x.time_constant_s}, {"stiffness", matrix_json(x.stiffness)}});
    j["line_relaxations"] = std::move(relaxations);
  }
  nlohmann::json channels = nlohmann::json::array();
  if (r.times_s.size() >= 2) {
    for (int d = 0; d < 6; ++d) {
      channels.push_back(
          channel_json(fmt::format("{}_{}", kDofNames[d], dof_unit(d)), dof_unit(d), row_of(r.total, d), dt));
    }
    for (int d = 0; d < 6; ++d) {
      channels.push_back(channel_json(fmt::format("{}_lf_{}", kDofNames[d], dof_unit(d)), dof_unit(d),
                                      row_of(r.low_frequency, d), dt));
    }
    for (const auto& [name, values] : tension_channels(r)) channels.push_back(channel_json(name, "N", *values, dt));
  }
  j["channels"] = channels;
  j["timing_s"] = {{"equilibrium", r.timing.equilibrium_s},
                   {"reduction", r.timing.reduction_s},
                   {"forcing", r.timing.forcing_s},
                   {"dynamics", r.timing.dynamics_s},
                   {"wave_frequency", r.timing.wave_frequency_s},
                   {"tensions", r.timing.tensions_s},
                   {"line_dynamics", r.timing.line_dynamics_s},
                   {"total", r.timing.total_s()}};
  j["solver"] = {{"steps", r.solver.steps},
                 {"rhs_evaluations", r.solver.rhs_evaluations},
                 {"jacobian_evaluations", r.solver.jacobian_evaluations},
                 {"error_test_failures", r.solver.error_test_failures},
                 {"nonlinear_convergence_failures", r.solver.nonlinear_convergence_failures},
                 {"last_step_s", r.solver.last_step_s}};
  nlohmann::json line_solvers = nlohmann::json::array();
  for (const auto& t : r.dynamic_tensions) {
    line_solvers.push_back({{"line", t.line},
                            {"wall_s", t.wall_s},
                            {"steps", t.solver.steps},
                            {"residual_evaluations", t.solver.residual_evaluations},
                            {"jacobian_evaluations", t.solver.newton_matrix_setups},
                            {"error_test_failures", t.solver.error_test_failures},
                            {"nonlinear_convergence_failures", t.solver.nonlinear_convergence_failures}});
  }
  if (r.coupled_solver) {
    const engine::IdaStatistics& s = *r.coupled_solver;
    j["coupled_solver"] = {{"integrator", "IDA (BDF, order <= 2), hull + lines in one system"},
                           {"lines", r.coupled_lines},
                           {"states", r.coupled_state_size},
                           {"steps", s.steps},
                           {"residual_evaluations", s.residual_evaluations},
                           {"jacobian_evaluations", s.newton_matrix_setups},
                           {"partial_jacobian_updates", s.newton_matrix_updates},
                           {"nonlinear_iterations", s.nonlinear_iterations},
                           {"error_test_failures", s.error_test_failures},
                           {"nonlinear_convergence_failures", s.nonlinear_convergence_failures},
                           {"newton_restarts", s.newton_restarts},
                           {"last_step_s", s.last_step_s}};
  } else if (!r.dynamic_tensions.empty()) {
    j["line_dynamics_solver"] = line_solvers;
  }
  j["notes"] = r.notes;
  return j;
}

nlohmann::json low_frequency_damping_to_json(const std::vector<engine::DofDamping>& oscillators) {
  // SI, rotations per radian (a ratio and a period need no unit of angle).
  nlohmann::json out = nlohmann::json::object();
  for (const engine::DofDamping& d : oscillators) {
    const bool angle = d.dof >= 3;
    out[kDofNames[static_cast<std::size_t>(d.dof)]] = {
        {"natural_period_s", d.natural_period_s},
        {"damping_ratio", d.damping_ratio},
        {angle ? "mass_kg_m2" : "mass_kg", d.mass},
        {angle ? "stiffness_N_m_per_rad" : "stiffness_N_per_m", d.stiffness},
        {angle ? "damping_N_m_s_per_rad" : "damping_N_s_per_m", d.damping}};
  }
  return out;
}

}  // namespace spiral::design
