#include "design/analysis/coupled_analysis.hpp"

#include <fmt/format.h>

#include <cmath>

#include "design/project/request_error.hpp"
#include "design/model/environment_loads.hpp"
#include "design/analysis/line_dynamics.hpp"
#include "design/model/mooring_model.hpp"
#include "engine/analysis/coupled_dynamics.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/numerics/sampled_trajectory.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {
namespace {

/// Sample spacing of the wave-frequency motion the fairleads follow: the
/// natural cubic spline through samples 0.2 s apart reproduces a 5 s wave
/// component's motion to (ω Δt)⁴/384 ≈ 1e-5 of its amplitude.
constexpr double kWaveMotionSample_s = 0.2;

/// Under WF motion: at a full setup an element keeps its matrices until a
/// slope component moves by 1e-4 or a velocity (its nodes', the sea's at it)
/// by 0.05 m/s — measured to leave the default FPS's runs as they are, 14 %
/// faster with a setup at every step and 15 % with one every 8 on lc5
/// (engine::CoupledOptions::element_refresh_slope).
constexpr double kWaveFrequencyElementRefreshSlope = 1e-4;
constexpr double kWaveFrequencyElementRefreshVelocity_m_per_s = 0.05;

/// The RAO motion as a C² function of time with its rates, built up by the
/// quintic ramp (translations and rotations as two 3-vector splines).
engine::PrescribedHullMotionFn ramped_wave_motion(const Eigen::Matrix<double, 6, Eigen::Dynamic>& samples, double dt_s,
                                                  double ramp_s) {
  std::vector<Eigen::Vector3d> translation, rotation;
  for (Eigen::Index k = 0; k < samples.cols(); ++k) {
    translation.emplace_back(samples.col(k).head<3>());
    rotation.emplace_back(samples.col(k).tail<3>());
  }
  auto lin = std::make_shared<const engine::SampledTrajectory>(0.0, dt_s, std::move(translation));
  auto rot = std::make_shared<const engine::SampledTrajectory>(0.0, dt_s, std::move(rotation));
  return [lin, rot, ramp_s](double t) {
    const engine::RampValue r = engine::smooth_ramp(t, ramp_s);
    engine::PrescribedHullMotion m;
    const engine::TrajectoryPoint a = lin->at(t), b = rot->at(t);
    const engine::Vector6d x = (engine::Vector6d() << a.position_m, b.position_m).finished();
    const engine::Vector6d v = (engine::Vector6d() << a.velocity_m_per_s, b.velocity_m_per_s).finished();
    const engine::Vector6d acc = (engine::Vector6d() << a.acceleration_m_per_s2, b.acceleration_m_per_s2).finished();
    m.position = r.value * x;
    m.velocity = r.rate_per_s * x + r.value * v;
    m.acceleration = r.rate2_per_s2 * x + 2.0 * r.rate_per_s * v + r.value * acc;
    return m;
  };
}

/// The lines' integrator tolerances (relative, shared with the hull, and
/// absolute) × factor.
void scale_line_tolerances(engine::CoupledOptions& options, double factor) {
  options.relative_tolerance *= factor;
  options.position_tolerance_m *= factor;
  options.slope_tolerance *= factor;
  options.velocity_tolerance_m_per_s *= factor;
}

}  // namespace

DynamicAnalysisResult run_coupled_analysis(const ValidatedProject& validated, const DynamicAnalysisRequest& request) {
  const Project& project = validated.project;
  // The S-C model of the case: statics, hull, external force on the same
  // realizations; its linearized lines are replaced by the FE lines below.
  DynamicAnalysisRequest sc = request;
  sc.level = AnalysisLevel::semi_coupled;
  DynamicModel model = build_dynamic_model(validated, sc);
  const LoadCase& load_case = *model.case_model.load_case;
  const Environment& environment = *model.case_model.environment;

  DynamicAnalysisResult result = result_of_model(model, request, load_case.name, environment.name);
  result.timing.reduction_s = 0.0;  // set below: the FE lines' statics

  // The lines at the hull's static equilibrium, with the case's current.
  engine::Stopwatch start;
  const std::string damaged = load_case.damaged_line.value_or("");
  const std::optional<engine::CurrentProfile>& current = model.case_model.current;
  const engine::Vector6d q0 = model.statics.offset;
  const engine::HullPose pose0 = engine::pose_from_offset(project.hull.reference_point_g, q0);
  const std::vector<LineTypeProperties>& types = *model.case_model.line_types;
  std::vector<const MooringLine*> moorings;
  for (const MooringLine& l : project.mooring.lines) {
    if (l.name != damaged) moorings.push_back(&l);
  }
  const int count = static_cast<int>(moorings.size() + project.risers.size());
  const LineMesh mesh = request.detailed_line_mesh ? LineMesh::own : LineMesh::global_analysis;
  result.line_element_length_m = global_element_length_m(project, mesh);
  std::vector<engine::CoupledLine> lines(static_cast<std::size_t>(count));
  engine::parallel_for(count, engine::worker_count(count), [&](int i) {
    engine::CoupledLine& out = lines[static_cast<std::size_t>(i)];
    DynamicLineSetup setup;
    if (i < static_cast<int>(moorings.size())) {
      const MooringLine& line = *moorings[static_cast<std::size_t>(i)];
      out.name = line.name;
      out.attachment_b_m = line.fairlead_b;
      // The case's elastic catenary of this line, a second start for its FE statics.
      setup = dynamic_mooring_line(project, line, types, current,
                                   pose0.reference_point_g + pose0.rotation * line.fairlead_b,
                                   line_profile(model.statics.lines, line.name), mesh);
    } else {
      const Riser& riser = project.risers[static_cast<std::size_t>(i) - moorings.size()];
      const RiserDesign design = riser_design(project, riser);
      out.name = riser.name;
      out.attachment_b_m = design.hang_off_b;
      setup = dynamic_riser(project, design, current, pose0.reference_point_g + pose0.rotation * design.hang_off_b,
                            riser_profile(model.statics.risers, riser.name), mesh);
    }
    out.model = std::move(setup.model);
    out.environment = std::move(setup.environment);
    out.environment.sea = model.sea;
    out.environment.sea_ramp_s = request.line_dynamics_ramp_s;
    out.initial = std::move(setup.statics);
  });
  result.timing.reduction_s = start.seconds();

  // Wave-frequency motion at the fairleads (the S-C RAO motion of this seed).
  start.restart();
  engine::CoupledOptions options;
  const auto n_wave = static_cast<Eigen::Index>(std::ceil(request.duration_s / kWaveMotionSample_s)) + 2;
  const Eigen::VectorXd wave_times =
      Eigen::VectorXd::LinSpaced(n_wave, 0.0, kWaveMotionSample_s * static_cast<double>(n_wave - 1));
  if (auto wf = wave_frequency_motions(validated, model, wave_times)) {
    options.wave_frequency_motion = ramped_wave_motion(*wf, kWaveMotionSample_s, request.line_dynamics_ramp_s);
    result.wave_frequency_computed = true;
  } else if (environment.waves && model.wave_split_frequency_rad_per_s == 0.0) {
    result.notes.push_back(
        "no wave-frequency motions: the project gives no hull.hydrodynamics.excitation_file (.3), "
        "rao_file (.4) or excitation: morison_maccamy_fuchs; the fairleads follow the low-frequency motion only");
  }
  result.timing.wave_frequency_s = start.seconds();

  // Hull + lines together.
  const auto n_out = static_cast<long>(std::floor(request.duration_s / request.output_step_s + 1e-9));
  for (long k = 1; k <= n_out; ++k) options.output_times_s.push_back(static_cast<double>(k) * request.output_step_s);
  options.threads = engine::worker_count(count);
  options.take_freed_cores = true;
  const double scale = request.tolerance_scale;
  scale_line_tolerances(options, scale * kCoupledLineToleranceScale);
  options.hull_position_tolerance_m *= scale;
  options.hull_rotation_tolerance_rad *= scale;
  result.notes.push_back(fmt::format(
      "coupled: the lines' integrator tolerances are {:g} of the single-line defaults (at those the risers' "
      "top-tension std under wave-frequency motion, and a lightly damped heave, are not converged)",
      kCoupledLineToleranceScale));
  if (options.wave_frequency_motion) {
    // Full setups every CoupledOptions::steps_between_full_setups (8)
    // steps, each refreshing only the elements that moved
    // (docs/decisions/coupled-dynamics-performance.md, "The coupled Newton
    // solve and end B").
    options.element_refresh_slope = kWaveFrequencyElementRefreshSlope;
    options.element_refresh_velocity_m_per_s = kWaveFrequencyElementRefreshVelocity_m_per_s;
  }
  options.max_steps_between_outputs = request.coupled_max_steps_between_outputs;
  engine::HullLoads loads;
  loads.lines = engine::LinearizedLines{};
  loads.external = model.loads.external;
  if (request.progress && loads.external) {
    auto next = std::make_shared<double>(0.0);
    const auto progress = request.progress;
    const double duration = request.duration_s;
    loads.external = [inner = loads.external, next, progress, duration](double t, const engine::Vector6d& q,
                                                                        const engine::Vector6d& qd) {
      if (t >= *next) {
        progress(std::min(1.0, t / duration));
        *next = t + 0.01 * duration;
      }
      return inner(t, q, qd);
    };
  }
  engine::CoupledTimeSeries series;
  try {
    series = engine::simulate_coupled(model.hull, loads, project.hull.reference_point_g, q0, lines, options);
  } catch (const engine::IntegrationError& e) {
    throw engine::SolverError(fmt::format("load case {}: coupled analysis failed at t = {:.6g} s: {}", load_case.name,
                                          e.time_reached_s(), e.what()),
                              e.diagnostics());
  } catch (const engine::SolverError& e) {
    throw engine::SolverError(fmt::format("load case {}: coupled analysis: {}", load_case.name, e.what()),
                              e.diagnostics());
  }
  if (request.progress) request.progress(1.0);
  result.times_s = series.times_s;
  result.low_frequency = series.position;
  result.timing.dynamics_s = series.wall_clock_s;
  result.coupled_solver = series.statistics;
  result.coupled_state_size = series.state_size;
  result.coupled_lines = count;
  result.coupled_element_matrix_evaluations = series.element_matrix_evaluations;
  result.coupled_element_matrices_kept = series.element_matrices_kept;
  result.wave_frequency.setZero(6, series.times_s.size());
  if (options.wave_frequency_motion) {
    for (Eigen::Index k = 0; k < series.times_s.size(); ++k)
      result.wave_frequency.col(k) = options.wave_frequency_motion(series.times_s[k]).position;
  }
  result.total = result.low_frequency + result.wave_frequency;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    LineDynamicsSeries t;
    t.line = lines[i].name;
    t.tension_N.resize(static_cast<std::size_t>(series.times_s.size()));
    for (Eigen::Index k = 0; k < series.times_s.size(); ++k)
      t.tension_N[static_cast<std::size_t>(k)] = series.end_B_force_N[i].col(k).norm();
    t.solver = series.statistics;
    result.dynamic_tensions.push_back(std::move(t));
  }
  start.restart();
  if (request.compute_tensions) result.tensions = quasi_static_fairlead_tensions(project, types, damaged, result.total);
  result.timing.tensions_s = start.seconds();
  {
    std::size_t worst = 0;
    for (std::size_t i = 1; i < series.step_limiting_outputs.size(); ++i) {
      if (series.step_limiting_outputs[i] > series.step_limiting_outputs[worst]) worst = i;
    }
    const std::string part = worst < lines.size() ? "line " + lines[worst].name : "the hull";
    result.notes.push_back(fmt::format("coupled: {} had the largest local error at {} of {} outputs (it sets the step)",
                                       part, series.step_limiting_outputs[worst], series.times_s.size() - 1));
  }
  long elements = 0;
  for (const engine::CoupledLine& line : lines) elements += fe_elements(line.model);
  const std::string mesh_note = line_mesh_note(project, mesh, elements);
  result.notes.push_back(
      fmt::format("coupled: hull and {} dynamic FE lines ({} mooring lines, {} risers) in one IDA system of "
                  "{} states; wave-frequency motion built up over the first {:g} s; current on the lines{}{}",
                  count, moorings.size(), project.risers.size(), series.state_size, request.line_dynamics_ramp_s,
                  model.sea ? ", " + line_wave_kinematics_note(*model.sea) : std::string(),
                  mesh_note.empty() ? std::string() : "; " + mesh_note));
  return result;
}

}  // namespace spiral::design
