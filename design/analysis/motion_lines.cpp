#include "design/analysis/motion_lines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "design/analysis/dynamic_analysis.hpp"
#include "design/criteria/mooring_checks.hpp"
#include "design/model/environment_loads.hpp"
#include "design/model/riser_model.hpp"
#include "design/project/request_error.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/common/stopwatch.hpp"
#include "engine/numerics/sampled_trajectory.hpp"

namespace spiral::design {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

/// The hull offset history as a C² spline of its translations and its
/// rotation angles (the angles are small: interpolating them is what the
/// fairlead spline does to the positions they make).
class OffsetSpline {
 public:
  OffsetSpline(const std::vector<double>& times_s, const Eigen::Matrix<double, 6, Eigen::Dynamic>& motion) {
    std::vector<Eigen::Vector3d> translation, rotation;
    for (Eigen::Index k = 0; k < motion.cols(); ++k) {
      translation.emplace_back(motion.col(k).head<3>());
      rotation.emplace_back(motion.col(k).tail<3>());
    }
    translation_ = std::make_unique<engine::SampledTrajectory>(times_s, std::move(translation));
    rotation_ = std::make_unique<engine::SampledTrajectory>(times_s, std::move(rotation));
  }
  engine::Vector6d at(double t_s) const {
    engine::Vector6d q;
    q << translation_->at(t_s).position_m, rotation_->at(t_s).position_m;
    return q;
  }

 private:
  std::unique_ptr<engine::SampledTrajectory> translation_, rotation_;
};

/// A dynamic riser state as the static post-processing reads it.
engine::FeStaticsResult as_solution(const engine::FeLineDynamicSnapshot& state) {
  engine::FeStaticsResult s;
  s.node_arc_length_m = state.node_arc_length_m;
  s.node_position_m = state.node_position_m;
  s.node_tension_N = state.node_tension_N;
  s.node_curvature_per_m = state.node_curvature_per_m;
  s.node_bending_moment_Nm = state.node_bending_moment_Nm;
  s.end_A_force_N = state.end_A_force_N;
  s.end_B_force_N = state.end_B_force_N;
  s.touchdown = state.touchdown;
  return s;
}

void check_request(const Project& project, const MotionLinesRequest& r) {
  const std::size_t n = r.motion_times_s.size();
  if (n < 2 || static_cast<std::size_t>(r.motion.cols()) != n || !r.motion.allFinite())
    throw request_error(project, "motion", fmt::format("needs >= 2 finite samples with a time each, got {}", n));
  for (std::size_t k = 1; k < n; ++k) {
    if (!(r.motion_times_s[k] > r.motion_times_s[k - 1]))
      throw request_error(
          project, "motion",
          fmt::format("times must increase, got {} s after {} s", r.motion_times_s[k], r.motion_times_s[k - 1]));
  }
  const double span_s = r.motion_times_s.back() - r.motion_times_s.front();
  if (!(r.output_step_s > 0.0) || !(r.output_step_s <= span_s))
    throw request_error(
        project, "output_step_s",
        fmt::format("must be > 0 s and at most the motion's span of {} s, got {} s", span_s, r.output_step_s));
  if (!(r.ramp_s >= 0.0) || !(r.ramp_s < span_s))
    throw request_error(
        project, "ramp_s",
        fmt::format("must be >= 0 s and shorter than the motion's span of {} s, got {} s", span_s, r.ramp_s));
  if (!(r.tolerance_scale > 0.0))
    throw request_error(project, "tolerance_scale", fmt::format("must be > 0, got {}", r.tolerance_scale));
}

}  // namespace

MotionLinesResult run_motion_lines(const ValidatedProject& validated, const MotionLinesRequest& request) {
  engine::Stopwatch start;
  const Project& project = validated.project;
  check_request(project, request);
  const LoadCase& load_case = find_load_case(project, request.load_case);
  const Environment& environment = environment_of(project, load_case);
  const std::string damaged = load_case.damaged_line.value_or("");
  for (const std::string& name : request.lines) {
    const bool line = std::any_of(project.mooring.lines.begin(), project.mooring.lines.end(),
                                  [&](const MooringLine& l) { return l.name == name; });
    const bool riser =
        std::any_of(project.risers.begin(), project.risers.end(), [&](const Riser& r) { return r.name == name; });
    if ((!line && !riser) || (line && name == damaged)) {
      std::vector<std::string> known;
      for (const MooringLine& l : project.mooring.lines)
        if (l.name != damaged) known.push_back(l.name);
      for (const Riser& r : project.risers) known.push_back(r.name);
      throw request_error(
          project, "lines",
          line ? fmt::format("line {} is the damaged line of case {}", name, load_case.name)
               : fmt::format("no mooring line or riser named \"{}\" (the case has: {})", name, fmt::join(known, ", ")));
    }
  }

  MotionLinesResult result;
  result.case_name = load_case.name;
  result.environment = environment.name;
  result.condition = load_case.condition;
  result.damaged_line = damaged;
  result.seed = request.seed.value_or(static_cast<std::uint64_t>(load_case.seed));
  result.ramp_s = request.ramp_s;
  result.notes = request.motion_notes;

  LineDynamicsInput input;
  input.damaged_line = damaged;
  input.current = current_profile_of(environment);
  input.static_offset = request.motion.col(0);
  input.t0_s = request.motion_times_s.front();
  input.dt_s = request.output_step_s;
  input.motion = request.motion;
  input.motion_times_s = request.motion_times_s;
  input.ramp_s = request.ramp_s;
  input.only = request.lines;
  input.tolerance_scale = request.tolerance_scale;
  const double span_s = request.motion_times_s.back() - request.motion_times_s.front();
  if (request.waves_on_lines && environment.waves) {
    // analyze realizes the sea over its duration from t = 0: the same span
    // and seed give the same components, so analyze's own motion meets the
    // waves that made it.
    input.sea =
        std::make_shared<const engine::WaveRealization>(realize_sea(project, *environment.waves, span_s, result.seed));
    result.waves_on_lines = true;
    result.notes.push_back(fmt::format(
        "waves on the lines: environment {}'s sea, seed {}, realized over the motion's {:g} s (the sea "
        "spiral analyze makes for this case, seed and duration); a motion from another program meets a sea of "
        "the same spectrum, not the phases of the waves that moved it",
        environment.name, result.seed, span_s));
  } else if (environment.waves) {
    result.notes.push_back("no waves on the lines (switched off): current and the hull motion only");
  }
  if (input.current) result.notes.push_back(fmt::format("current on the lines: environment {}", environment.name));
  if (!damaged.empty()) result.notes.push_back(fmt::format("line {} is damaged in case {}", damaged, load_case.name));
  result.times_s = line_dynamics_output_times(input);
  const std::size_t samples = result.times_s.size();
  result.statistics_from_s = input.t0_s + request.ramp_s;

  // The hull pose at each output time, as the ramp applies it.
  const OffsetSpline offsets(request.motion_times_s, request.motion);
  result.motion.resize(6, static_cast<Eigen::Index>(samples));
  std::vector<Eigen::Matrix3d> rotation(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    const engine::Vector6d q = offsets.at(result.times_s[k]);
    result.motion.col(static_cast<Eigen::Index>(k)) = q;
    const double r = engine::smooth_ramp(result.times_s[k] - input.t0_s, request.ramp_s).value;
    rotation[k] =
        engine::pose_from_offset(project.hull.reference_point_g, input.static_offset + r * (q - input.static_offset))
            .rotation;
  }

  // What each line records, by its index in the dynamics' result: the
  // selected intact mooring lines, then the selected risers.
  auto selected = [&](const std::string& name) {
    return request.lines.empty() || std::find(request.lines.begin(), request.lines.end(), name) != request.lines.end();
  };
  for (const MooringLine& l : project.mooring.lines) {
    if (l.name == damaged || !selected(l.name)) continue;
    MooringLineMotionRecord record;
    record.name = l.name;
    record.fairlead_tension_N.resize(samples);
    record.anchor_tension_N.resize(samples);
    record.anchor_uplift_deg.resize(samples);
    record.laid_length_m.resize(samples);
    record.fairlead_mbl_N = fairlead_segment_mbl(validated, l.name);
    result.lines.push_back(std::move(record));
  }
  std::vector<RiserDesign> designs;
  for (const Riser& r : project.risers) {
    if (!selected(r.name)) continue;
    designs.push_back(riser_design(project, r));
    RiserMotionRecord record;
    record.name = r.name;
    for (auto* channel :
         {&record.top_tension_N, &record.top_angle_deg, &record.flex_joint_rotation_deg, &record.touchdown_distance_m,
          &record.min_effective_tension_N, &record.min_bending_radius_m, &record.utilization})
      channel->resize(samples);
    result.risers.push_back(std::move(record));
  }
  const std::size_t line_count = result.lines.size();
  input.on_sample = [&](std::size_t index, std::size_t k, const engine::FeLineDynamicSnapshot& state) {
    if (request.progress && samples > 1) request.progress(static_cast<double>(k) / static_cast<double>(samples - 1));
    if (index < line_count) {
      MooringLineMotionRecord& record = result.lines[index];
      record.fairlead_tension_N[k] = state.end_B_force_N.norm();
      // The line's pull on its anchor points from the anchor into the line:
      // above the horizontal (> 0) it lifts the anchor, which a drag anchor
      // is not designed for (API RP 2SK: no uplift at the anchor in intact cases).
      const Eigen::Vector3d& pull = state.end_A_force_N;
      record.anchor_tension_N[k] = pull.norm();
      record.anchor_uplift_deg[k] = std::atan2(pull.z(), pull.head<2>().norm()) * kRadToDeg;
      record.laid_length_m[k] = state.touchdown ? state.touchdown->arc_length_m : 0.0;
      return;
    }
    const std::size_t r = index - line_count;
    RiserMotionRecord& record = result.risers[r];
    const RiserStaticsRow row =
        riser_statics_row(project, designs[r], as_solution(state), load_case.condition, rotation[k]);
    record.top_tension_N[k] = row.top_tension_N;
    record.top_angle_deg[k] = row.top_angle_deg;
    record.flex_joint_rotation_deg[k] = row.flex_joint_rotation_deg;
    record.touchdown_distance_m[k] = row.touchdown_distance_m;
    record.min_effective_tension_N[k] = row.min_effective_tension_N;
    record.min_bending_radius_m[k] = row.min_bending_radius_m;
    record.utilization[k] = row.utilization;
    if (row.max_von_mises_utilization) {
      if (record.max_von_mises_utilization.empty()) record.max_von_mises_utilization.resize(samples);
      record.max_von_mises_utilization[k] = *row.max_von_mises_utilization;
    }
    if (result.times_s[k] < result.statistics_from_s) return;
    if (record.extremes.empty()) {
      for (const RiserCriterionCheck& check : row.checks) record.extremes.push_back({check, result.times_s[k]});
      return;
    }
    for (std::size_t c = 0; c < row.checks.size() && c < record.extremes.size(); ++c) {
      const RiserCriterionCheck& now = row.checks[c];
      const RiserCriterionCheck& worst = record.extremes[c].worst;
      // A floor (minimum effective tension) has utilization 0 while it holds:
      // among equal utilizations the lower value is the worse.
      const bool floor = now.criterion.rfind("min_", 0) == 0;
      if (now.utilization > worst.utilization ||
          (floor && now.utilization == worst.utilization && now.value < worst.value))
        record.extremes[c] = {now, result.times_s[k]};
    }
  };

  const std::vector<LineDynamicsSeries> series = run_line_dynamics(project, input);
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (i < line_count) {
      result.lines[i].solver = series[i].solver;
      result.lines[i].wall_s = series[i].wall_s;
    } else {
      result.risers[i - line_count].solver = series[i].solver;
      result.risers[i - line_count].wall_s = series[i].wall_s;
    }
  }
  result.notes.push_back(
      fmt::format("the hull motion is built up from the first sample's pose over {:g} s; statistics from {:g} s",
                  request.ramp_s, result.statistics_from_s));
  result.wall_s = start.seconds();
  return result;
}

}  // namespace spiral::design
