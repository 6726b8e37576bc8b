#include "design/results/motion_lines_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "design/criteria/mooring_checks.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {
namespace {

constexpr const char* kDofColumns[6] = {"surge_m", "sway_m", "heave_m", "roll_deg", "pitch_deg", "yaw_deg"};
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
/// A straight pipe has an infinite bending radius; the channels carry this
/// instead so that their statistics stay finite.
constexpr double kStraightRadius_m = 1e9;

/// The values of `x` inside the statistics window.
std::vector<double> window(const MotionLinesResult& r, const std::vector<double>& x) {
  const auto first = static_cast<std::size_t>(
      std::lower_bound(r.times_s.begin(), r.times_s.end(), r.statistics_from_s - 1e-9) - r.times_s.begin());
  return {x.begin() + static_cast<std::ptrdiff_t>(std::min(first, x.size())), x.end()};
}

double output_step(const MotionLinesResult& r) { return r.times_s.size() > 1 ? r.times_s[1] - r.times_s[0] : 0.0; }

nlohmann::json windowed_channel(const MotionLinesResult& r, const std::string& name, const std::string& unit,
                                const std::vector<double>& x) {
  const std::vector<double> w = window(r, x);
  if (w.size() < 2) return {{"name", name}, {"unit", unit}, {"extremes_unavailable", "fewer than 2 samples"}};
  return channel_json(name, unit, w, output_step(r));
}

nlohmann::json solver_json(const engine::IdaStatistics& s, double wall_s) {
  return {{"wall_s", wall_s},
          {"steps", s.steps},
          {"residual_evaluations", s.residual_evaluations},
          {"jacobian_evaluations", s.newton_matrix_setups},
          {"error_test_failures", s.error_test_failures},
          {"nonlinear_convergence_failures", s.nonlinear_convergence_failures}};
}

std::vector<double> radii(const std::vector<double>& r) {
  std::vector<double> out(r.size());
  std::transform(r.begin(), r.end(), out.begin(), [](double x) { return std::min(x, kStraightRadius_m); });
  return out;
}

}  // namespace

std::vector<TimeSeriesColumn> motion_lines_columns(const MotionLinesResult& r) {
  std::vector<TimeSeriesColumn> columns;
  columns.push_back({"time_s", r.times_s, "{:.3f}"});
  for (int d = 0; d < 6; ++d) {
    std::vector<double> values(r.times_s.size());
    for (std::size_t k = 0; k < values.size(); ++k)
      values[k] = r.motion(d, static_cast<Eigen::Index>(k)) * (d < 3 ? 1.0 : kRadToDeg);
    columns.push_back({kDofColumns[d], std::move(values), "{:.6g}"});
  }
  for (const MooringLineMotionRecord& l : r.lines) {
    columns.push_back({fmt::format("fairlead_tension_{}_N", l.name), l.fairlead_tension_N, "{:.7g}"});
    columns.push_back({fmt::format("anchor_tension_{}_N", l.name), l.anchor_tension_N, "{:.7g}"});
    columns.push_back({fmt::format("anchor_uplift_{}_deg", l.name), l.anchor_uplift_deg, "{:.4f}"});
    columns.push_back({fmt::format("laid_length_{}_m", l.name), l.laid_length_m, "{:.3f}"});
  }
  for (const RiserMotionRecord& s : r.risers) {
    columns.push_back({fmt::format("top_tension_{}_N", s.name), s.top_tension_N, "{:.7g}"});
    columns.push_back({fmt::format("top_angle_{}_deg", s.name), s.top_angle_deg, "{:.4f}"});
    columns.push_back({fmt::format("flex_joint_rotation_{}_deg", s.name), s.flex_joint_rotation_deg, "{:.4f}"});
    columns.push_back({fmt::format("touchdown_distance_{}_m", s.name), s.touchdown_distance_m, "{:.3f}"});
    columns.push_back({fmt::format("min_effective_tension_{}_N", s.name), s.min_effective_tension_N, "{:.7g}"});
    columns.push_back({fmt::format("min_bending_radius_{}_m", s.name), radii(s.min_bending_radius_m), "{:.6g}"});
    if (!s.max_von_mises_utilization.empty())
      columns.push_back({fmt::format("von_mises_utilization_{}", s.name), s.max_von_mises_utilization, "{:.5f}"});
    columns.push_back({fmt::format("utilization_{}", s.name), s.utilization, "{:.5f}"});
  }
  return columns;
}

std::string motion_lines_csv(const MotionLinesResult& result) { return time_series_csv(motion_lines_columns(result)); }

nlohmann::json motion_lines_to_json(const MotionLinesResult& r, const ValidatedProject& vp,
                                    const std::string& motion_file) {
  const Project& project = vp.project;
  nlohmann::json j;
  j["format"] = "spiral.motion_lines";
  j["format_version"] = 1;
  j["project"] = project.name;
  j["motion_file"] = motion_file;
  j["load_case"] = r.case_name;
  j["environment"] = r.environment;
  j["condition"] = to_string(r.condition);
  j["damaged_line"] = r.damaged_line.empty() ? nlohmann::json() : nlohmann::json(r.damaged_line);
  j["seed"] = r.seed;
  j["waves_on_lines"] = r.waves_on_lines;
  j["start_s"] = r.times_s.empty() ? 0.0 : r.times_s.front();
  j["end_s"] = r.times_s.empty() ? 0.0 : r.times_s.back();
  j["output_step_s"] = output_step(r);
  j["ramp_s"] = r.ramp_s;
  j["statistics_from_s"] = r.statistics_from_s;
  const std::vector<double> first_window = window(r, r.times_s);
  const double window_s = first_window.size() > 1 ? first_window.back() - first_window.front() : 0.0;
  j["statistics_window_s"] = window_s;

  nlohmann::json motion = nlohmann::json::array();
  for (int d = 0; d < 6; ++d) {
    std::vector<double> values(r.times_s.size());
    for (std::size_t k = 0; k < values.size(); ++k)
      values[k] = r.motion(d, static_cast<Eigen::Index>(k)) * (d < 3 ? 1.0 : kRadToDeg);
    motion.push_back(windowed_channel(r, kDofColumns[d], d < 3 ? "m" : "deg", values));
  }
  j["motion"] = motion;

  bool all_pass = true;
  nlohmann::json lines = nlohmann::json::array();
  for (const MooringLineMotionRecord& l : r.lines) {
    nlohmann::json line;
    line["name"] = l.name;
    line["channels"] = {windowed_channel(r, "fairlead_tension_" + l.name + "_N", "N", l.fairlead_tension_N),
                        windowed_channel(r, "anchor_tension_" + l.name + "_N", "N", l.anchor_tension_N),
                        windowed_channel(r, "anchor_uplift_" + l.name + "_deg", "deg", l.anchor_uplift_deg),
                        windowed_channel(r, "laid_length_" + l.name + "_m", "m", l.laid_length_m)};
    const std::vector<double> t = window(r, l.fairlead_tension_N);
    if (t.size() >= 2) {
      const engine::ChannelMoments m = engine::channel_moments(t);
      double extreme = m.maximum;
      std::string basis = "record_maximum";
      if (window_s >= kMpmMinimumRecord_s) {
        try {
          extreme = engine::most_probable_maximum(t, output_step(r)).mpm_gumbel;
          basis = "mpm_3h_gumbel";
        } catch (const std::exception& e) {
          basis = fmt::format("record_maximum (no 3-h MPM: {})", e.what());
        }
      }
      const DynamicTensionCheck check =
          dynamic_tension_check(project.criteria.mooring, !r.damaged_line.empty(), m.mean, extreme, l.fairlead_mbl_N);
      line["dynamic_tension_check"] = {{"basis", basis},
                                       {"mean_N", m.mean},
                                       {"extreme_N", extreme},
                                       {"mbl_N", l.fairlead_mbl_N},
                                       {"factor", check.factor},
                                       {"utilization", check.utilization},
                                       {"passes", check.utilization <= 1.0}};
      all_pass = all_pass && check.utilization <= 1.0;
    }
    const std::vector<double> uplift = window(r, l.anchor_uplift_deg), laid = window(r, l.laid_length_m);
    if (!uplift.empty()) {
      line["max_anchor_uplift_deg"] = *std::max_element(uplift.begin(), uplift.end());
      line["min_laid_length_m"] = *std::min_element(laid.begin(), laid.end());
    }
    line["solver"] = solver_json(l.solver, l.wall_s);
    lines.push_back(std::move(line));
  }
  j["lines"] = lines;

  nlohmann::json risers = nlohmann::json::array();
  for (const RiserMotionRecord& s : r.risers) {
    nlohmann::json riser;
    riser["name"] = s.name;
    nlohmann::json channels = {
        windowed_channel(r, "top_tension_" + s.name + "_N", "N", s.top_tension_N),
        windowed_channel(r, "top_angle_" + s.name + "_deg", "deg", s.top_angle_deg),
        windowed_channel(r, "flex_joint_rotation_" + s.name + "_deg", "deg", s.flex_joint_rotation_deg),
        windowed_channel(r, "touchdown_distance_" + s.name + "_m", "m", s.touchdown_distance_m),
        windowed_channel(r, "min_effective_tension_" + s.name + "_N", "N", s.min_effective_tension_N),
        windowed_channel(r, "min_bending_radius_" + s.name + "_m", "m", radii(s.min_bending_radius_m))};
    if (!s.max_von_mises_utilization.empty())
      channels.push_back(windowed_channel(r, "von_mises_utilization_" + s.name, "-", s.max_von_mises_utilization));
    channels.push_back(windowed_channel(r, "utilization_" + s.name, "-", s.utilization));
    riser["channels"] = channels;
    nlohmann::json criteria = nlohmann::json::array();
    const RiserCriterionExtreme* governing = nullptr;
    for (const RiserCriterionExtreme& e : s.extremes) {
      criteria.push_back({{"criterion", e.worst.criterion},
                          {"value", e.worst.value},
                          {"limit", e.worst.limit},
                          {"unit", e.worst.unit},
                          {"utilization", e.worst.utilization},
                          {"passes", e.worst.passes},
                          {"time_s", e.time_s}});
      if (!governing || e.worst.utilization > governing->worst.utilization) governing = &e;
    }
    riser["criteria"] = criteria;
    if (governing) {
      riser["governing_criterion"] = governing->worst.criterion;
      riser["utilization"] = governing->worst.utilization;
      const bool passes = std::all_of(s.extremes.begin(), s.extremes.end(),
                                      [](const RiserCriterionExtreme& e) { return e.worst.passes; });
      riser["passes"] = passes;
      all_pass = all_pass && passes;
    }
    riser["solver"] = solver_json(s.solver, s.wall_s);
    risers.push_back(std::move(riser));
  }
  j["risers"] = risers;
  j["passes"] = all_pass;
  j["notes"] = r.notes;
  j["wall_s"] = r.wall_s;
  return j;
}

}  // namespace spiral::design
