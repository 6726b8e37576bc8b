#include "design/stages/stage_dynamics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/common/rigid_body.hpp"
#include "engine/common/stopwatch.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
/// The stage's storm: a 3-h sea state (the MPM's target duration) at the
/// output step of `spiral analyze`, seed 1 (reproducible).
constexpr double kStormDuration_s = 10800.0;
constexpr double kStormOutputStep_s = 0.5;

std::vector<double> row(const Eigen::Matrix<double, 6, Eigen::Dynamic>& m, int dof, double scale) {
  std::vector<double> out(static_cast<std::size_t>(m.cols()));
  for (Eigen::Index k = 0; k < m.cols(); ++k) out[static_cast<std::size_t>(k)] = m(dof, k) * scale;
  return out;
}

/// Vertical displacement of a body point from its rest height at each column
/// of `total` (hull offsets about the reference point): heave plus the
/// exact rotation's vertical component of the point's lever arm, the motion
/// a riser's top sees (WF heave and pitch drive its tension range and the
/// compression at its touchdown).
std::vector<double> vertical_displacement(const Eigen::Matrix<double, 6, Eigen::Dynamic>& total,
                                          const Eigen::Vector3d& point_b) {
  std::vector<double> out(static_cast<std::size_t>(total.cols()));
  for (Eigen::Index k = 0; k < total.cols(); ++k) {
    const engine::Vector6d offset = total.col(k);
    out[static_cast<std::size_t>(k)] =
        engine::body_point_to_global(Eigen::Vector3d::Zero(), offset, point_b).z() - point_b.z();
  }
  return out;
}

}  // namespace

const StormChannel* StageDynamics::channel(std::string_view name) const {
  for (const StormChannel& c : channels)
    if (c.name == name) return &c;
  return nullptr;
}

const StormChannel* StageDynamics::tension() const {
  return most_loaded_line.empty() ? nullptr : channel("tension " + most_loaded_line);
}

StormChannel summarize_storm_channel(std::string name, std::string unit, std::vector<double> values, double dt_s) {
  StormChannel c;
  c.name = std::move(name);
  c.unit = std::move(unit);
  c.statistics.moments = engine::channel_moments(values);
  const engine::ChannelMoments m = c.statistics.moments;
  if (m.std_dev <= 1e-12 * std::max(1.0, std::abs(m.mean))) {
    c.extremes_note = "constant channel";
  } else {
    try {
      c.statistics = engine::analyze_channel(values, dt_s, engine::welch_segment_length(values.size()));
      engine::Spectrum& spectrum = c.statistics.spectrum;
      const Eigen::Index bins = engine::spectrum_last_significant_bin(spectrum) + 1;
      spectrum.frequency_rad_s.conservativeResize(bins);
      spectrum.density.conservativeResize(bins);
    } catch (const std::invalid_argument& e) {
      // Too short a record for the fits: the moments stand, the reason is shown.
      c.extremes_note = e.what();
    }
  }
  c.values = std::move(values);
  return c;
}

int case_seed(const Project& project, const std::string& case_name) {
  for (const LoadCase& c : project.load_cases)
    if (c.name == case_name) return c.seed;
  return 1;
}

StageDynamics run_stage_dynamics(const ValidatedProject& vp, const StaticCaseResult& statics, AnalysisLevel level,
                                 const SozResult* zone, std::string selection, RestSolutionCache* rest_solutions) {
  engine::Stopwatch start;
  DynamicAnalysisRequest request;
  request.load_case = statics.case_name;
  request.level = level;
  request.duration_s = kStormDuration_s;
  request.output_step_s = kStormOutputStep_s;
  request.seed = case_seed(vp.project, statics.case_name);
  request.statics = &statics;
  request.rest_solutions = rest_solutions;
  const DynamicAnalysisResult r = run_dynamic_analysis(vp, request);
  StageDynamics out = summarize_stage_dynamics(vp, statics, request, r, zone, std::move(selection));
  out.wall_s = start.seconds();
  return out;
}

StageDynamics summarize_stage_dynamics(const ValidatedProject& vp, const StaticCaseResult& statics,
                                       const DynamicAnalysisRequest& request, const DynamicAnalysisResult& r,
                                       const SozResult* zone, std::string selection, const std::string& tension_line) {
  const AnalysisLevel level = r.level;
  StageDynamics out;
  out.case_name = r.case_name;
  out.integrity = statics.integrity;
  out.damaged_line = statics.damaged_line;
  out.selection = std::move(selection);
  out.level = level;
  out.duration_s = request.duration_s;
  out.output_step_s = request.output_step_s;
  out.seed = r.seed;
  out.times_s.assign(r.times_s.data(), r.times_s.data() + r.times_s.size());
  out.notes = r.notes;
  out.timing = r.timing;
  out.solver_steps = r.coupled_solver ? static_cast<int>(r.coupled_solver->steps) : static_cast<int>(r.solver.steps);
  const double dt = request.output_step_s;

  out.channels.push_back(summarize_storm_channel("surge", "m", row(r.total, 0, 1.0), dt));
  out.channels.push_back(summarize_storm_channel("sway", "m", row(r.total, 1, 1.0), dt));
  out.channels.push_back(summarize_storm_channel("yaw", "deg", row(r.total, 5, kRadToDeg), dt));
  std::vector<double> offset(static_cast<std::size_t>(r.total.cols()));
  for (Eigen::Index k = 0; k < r.total.cols(); ++k)
    offset[static_cast<std::size_t>(k)] = r.total.col(k).head<2>().norm();
  out.channels.push_back(summarize_storm_channel("offset", "m", std::move(offset), dt));

  // The tension records the stage checks: the coupled run's own FE line
  // tensions (its mooring lines; the risers follow them in dynamic_tensions),
  // else the quasi-static catenary tensions at the total motion.
  struct Record {
    const std::string* line;
    const std::vector<double>* tension_N;
  };
  std::vector<Record> records;
  if (level == AnalysisLevel::coupled) {
    out.tension_source = TensionSource::coupled;
    for (const LineDynamicsSeries& t : r.dynamic_tensions) {
      const bool mooring = std::any_of(vp.project.mooring.lines.begin(), vp.project.mooring.lines.end(),
                                       [&](const MooringLine& l) { return l.name == t.line; });
      if (mooring) records.push_back({&t.line, &t.tension_N});
    }
  } else {
    for (const TensionSeries& t : r.tensions) records.push_back({&t.line, &t.tension_N});
  }
  // The requested line, else the most loaded one (largest sampled tension).
  const Record* loaded = nullptr;
  double peak = -1.0;
  for (const Record& t : records) {
    const double m = t.tension_N->empty() ? 0.0 : *std::max_element(t.tension_N->begin(), t.tension_N->end());
    if (tension_line.empty() ? m > peak : *t.line == tension_line) peak = m, loaded = &t;
  }
  if (loaded) {
    out.most_loaded_line = *loaded->line;
    out.channels.push_back(summarize_storm_channel("tension " + *loaded->line, "N", *loaded->tension_N, dt));
    const StormChannel& t = out.channels.back();
    out.fairlead_mbl_N = fairlead_segment_mbl(vp, *loaded->line);
    const DynamicTensionCheck check =
        dynamic_tension_check(vp.project.criteria.mooring, statics.integrity == LineIntegrity::damaged,
                              t.moments().mean, t.mpm_max().value_or(t.moments().maximum), out.fairlead_mbl_N);
    out.dynamic_safety_factor = check.factor;
    out.tension_utilization = check.utilization;
    out.tension_pass = check.utilization <= 1.0;
  }

  out.channels.push_back(summarize_storm_channel("heave", "m", row(r.total, 2, 1.0), dt));
  out.channels.push_back(summarize_storm_channel("roll", "deg", row(r.total, 3, kRadToDeg), dt));
  out.channels.push_back(summarize_storm_channel("pitch", "deg", row(r.total, 4, kRadToDeg), dt));
  // The hang-off that moves most vertically: the riser whose top stroke and
  // touchdown compression the storm tests hardest.
  const Riser* moving = nullptr;
  std::vector<double> stroke;
  double largest_std = -1.0;
  for (const Riser& riser : vp.project.risers) {
    std::vector<double> z = vertical_displacement(r.total, riser.hang_off_b);
    const double s = engine::channel_moments(z).std_dev;
    if (s > largest_std) largest_std = s, moving = &riser, stroke = std::move(z);
  }
  if (moving)
    out.channels.push_back(
        summarize_storm_channel(std::string(kHangOffHeavePrefix) + moving->name, "m", std::move(stroke), dt));

  if (zone && !zone->risers.empty()) {
    StaticCaseResult extreme;  // names the case; the offset comes from the record
    extreme.case_name = out.case_name;
    extreme.integrity = out.integrity;
    extreme.damaged_line = out.damaged_line;
    std::string fit_note;
    OffsetCheck check = extreme_offset_check(*zone, extreme, r.total, r.times_s, "still-water", fit_note);
    if (!fit_note.empty())
      out.notes.push_back("extreme offset: the record's largest offset/allowable (no extreme-value fit: " + fit_note +
                          ")");
    check.extreme->seed = r.seed;  // the record's own sea, as soz --extreme records it
    out.extreme_offset = check;
  }
  return out;
}

}  // namespace spiral::design
