#include "design/analysis/line_dynamics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "design/project/line_properties.hpp"
#include "design/model/mooring_model.hpp"
#include "design/model/riser_model.hpp"
#include "engine/analysis/fe_static_line.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/numerics/sampled_trajectory.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/lines/fe_line_dynamics.hpp"
#include "engine/common/stopwatch.hpp"
#include "engine/environment/fixed_point_wave_kinematics.hpp"

namespace spiral::design {
namespace {

// Seabed damping per unit area (Pa·s/m), times the contact width (diameter). MoorDyn-C 2.7's
// default cBot is 3e5; against MoorDyn on the OC4 chain the difference moved no statistic by
// more than 0.04 kN (tests/data/validation/moordyn-oc4-surge/README.md).
constexpr double kSeabedDamping_Pa_s_per_m = 1.0e5;
constexpr double kFrictionVelocity_m_per_s = 0.01;

engine::FeDynamicEnvironment dynamic_environment(const Project& project,
                                                 const std::optional<engine::CurrentProfile>& current,
                                                 double contact_diameter_m) {
  engine::FeDynamicEnvironment env;
  env.statics = fe_environment(project, current, contact_diameter_m);
  env.seabed_lateral_friction = project.site.seabed.friction_lateral;
  env.seabed_damping_N_s_per_m2 = kSeabedDamping_Pa_s_per_m * contact_diameter_m;
  env.friction_velocity_m_per_s = kFrictionVelocity_m_per_s;
  return env;
}

/// The position at unstretched arc length `s_m` from the anchor along a
/// profile (linear between its points, its ends held beyond them). A
/// riser's profile has a point per FE node (≈ 900) and the FE start asks
/// at every node: the segment by bisection.
template <class Point>
Eigen::Vector3d profile_position(const std::vector<Point>& profile, double s_m) {
  if (s_m <= profile.front().arc_length_m) return profile.front().position_g;
  const auto b = std::partition_point(profile.begin() + 1, profile.end(),
                                      [s_m](const Point& point) { return point.arc_length_m < s_m; });
  if (b == profile.end()) return profile.back().position_g;
  const Point& a = *(b - 1);
  const double span = b->arc_length_m - a.arc_length_m;
  const double t = span > 0.0 ? (s_m - a.arc_length_m) / span : 1.0;
  return a.position_g + t * (b->position_g - a.position_g);
}

}  // namespace

DynamicLineSetup dynamic_mooring_line(const Project& project, const MooringLine& line,
                                      const std::vector<LineTypeProperties>& types,
                                      const std::optional<engine::CurrentProfile>& current,
                                      const Eigen::Vector3d& fairlead_g,
                                      const std::vector<engine::LineProfilePoint>* known_shape, LineMesh mesh) {
  DynamicLineSetup setup;
  setup.model = with_line_mesh(project, mesh, fe_line_model(project, line, types));
  engine::FeLineModel& model = setup.model;
  setup.environment = dynamic_environment(project, current, model.sections.front().hydro_diameter_m);
  try {
    setup.statics = engine::solve_fe_line_statics(model, setup.environment.statics, {line.anchor_g, fairlead_g});
  } catch (const engine::SolverError& e) {
    // The default start is an inextensible catenary; a taut line whose
    // touchdown is at the anchor (the slack side of a damaged case) can
    // defeat Newton from there. The elastic catenary's shape at the same
    // ends is close to the FE answer (without current and bending).
    std::string message = e.what();
    if (known_shape && known_shape->size() >= 2) {
      engine::FeStaticsOptions options;
      options.initial_shape = [known_shape](double s_m) { return profile_position(*known_shape, s_m); };
      try {
        setup.statics =
            engine::solve_fe_line_statics(model, setup.environment.statics, {line.anchor_g, fairlead_g}, options);
        message.clear();
      } catch (const engine::SolverError& again) {
        message += fmt::format("; from the elastic catenary's shape: {}", again.what());
      }
    }
    if (!message.empty())
      throw engine::SolverError(
          fmt::format("line {}: FE statics at the static equilibrium failed: {}", line.name, message));
  }
  // Polyester: the dynamic EA at each section's mean static tension.
  std::vector<LineTypeProperties> segment_types;
  for (const LineSegment& segment : line.segments) segment_types.push_back(find_type(types, segment.type));
  const std::vector<double> incremental_EA = incremental_axial_stiffness_N(
      segment_types, engine::node_sections(model, setup.statics), setup.statics.node_tension_N);
  for (std::size_t s = 0; s < model.sections.size(); ++s) {
    if (segment_types[s].kind == LineKind::polyester) model.sections[s].EA_dynamic_N = incremental_EA[s];
  }
  return setup;
}

DynamicLineSetup dynamic_riser(const Project& project, const RiserDesign& own_mesh_design,
                               const std::optional<engine::CurrentProfile>& current, const Eigen::Vector3d& hang_off_g,
                               const std::vector<RiserProfilePoint>* equilibrium, LineMesh mesh) {
  RiserDesign design = own_mesh_design;
  design.fe_model = with_line_mesh(project, mesh, std::move(design.fe_model));
  DynamicLineSetup setup;
  setup.model = design.fe_model;
  setup.environment = dynamic_environment(project, current, design.sections.front().properties.hydrodynamic_diameter_m);
  engine::FeStaticsOptions options;
  if (equilibrium && equilibrium->size() >= 2) {
    options.initial_shape = [equilibrium](double s_m) { return profile_position(*equilibrium, s_m); };
    options.initial_shape_is_equilibrium = true;
    // Every FE node, the one moved onto the touchdown point included.
    if (equilibrium->size() == engine::fe_line_mesh(design.fe_model).size())
      for (const RiserProfilePoint& point : *equilibrium)
        options.warm_start_node_arc_length_m.push_back(point.arc_length_m);
  }
  const std::unique_ptr<engine::FeStaticLine> line = riser_static_line(project, design, current, options);
  try {
    line->solve(hang_off_g);
  } catch (const engine::SolverError& e) {
    throw engine::SolverError(
        fmt::format("riser {}: FE statics at the static equilibrium failed: {}", design.name, e.what()));
  }
  setup.statics = *line->last_result();
  return setup;
}

std::optional<double> global_element_length_m(const Project& project, LineMesh mesh) {
  return mesh == LineMesh::global_analysis ? project.global_analysis.element_length_m : std::nullopt;
}

engine::FeLineModel with_line_mesh(const Project& project, LineMesh mesh, engine::FeLineModel model) {
  const std::optional<double> length = global_element_length_m(project, mesh);
  if (!length) return model;
  for (engine::FeLineSection& section : model.sections) section.element_length_m = *length;
  model.refinement.reset();
  return model;
}

long fe_elements(const engine::FeLineModel& model) { return static_cast<long>(engine::fe_line_mesh(model).size()) - 1; }

long dynamic_line_elements(const std::vector<LineDynamicsSeries>& series) {
  long elements = 0;
  for (const LineDynamicsSeries& s : series) elements += s.elements;
  return elements;
}

std::string line_mesh_note(const Project& project, LineMesh mesh, long elements) {
  const std::optional<double> length = global_element_length_m(project, mesh);
  if (!length) return {};
  return fmt::format(
      "the lines on the global-analysis mesh (global_analysis.element_length: elements of at most {:g} m, {} in "
      "all); the statics, the stiffness, the SOZ and the riser checks on each line's own fe mesh",
      *length, elements);
}

std::string line_wave_kinematics_note(const engine::WaveRealization& sea) {
  using engine::FixedPointWaveKinematics;
  return fmt::format(
      "linear wave kinematics at each element's midpoint, at its Gauss points in the wave zone (where the midpoint "
      "would err by more than {:g} of the surface velocity), carried to the line's present position by their "
      "gradients and moved at {:g} m, summed every {:.3g} s and interpolated cubically in time (rms error {:g} of "
      "the acceleration)",
      FixedPointWaveKinematics::kWaveZoneMidpointError, FixedPointWaveKinematics::kLinePointDrift_m,
      FixedPointWaveKinematics::default_sample_interval_s(sea), FixedPointWaveKinematics::kSampledAccelerationError);
}

namespace {

/// One line or riser (`kind` names it in errors) whose top end sits at
/// `attachment_b` on the hull; `make_setup` builds it with the top at a
/// global position.
template <class MakeSetup>
LineDynamicsSeries run_one(const Project& project, std::size_t index, const std::string& name, const char* kind,
                           const Eigen::Vector3d& attachment_b, const MakeSetup& make_setup,
                           const LineDynamicsInput& input) {
  engine::Stopwatch start;
  const Eigen::Vector3d& ref = project.hull.reference_point_g;
  auto fairlead_at = [&](const engine::Vector6d& offset) {
    const engine::HullPose pose = engine::pose_from_offset(ref, offset);
    return Eigen::Vector3d(pose.reference_point_g + pose.rotation * attachment_b);
  };
  const Eigen::Vector3d rest = fairlead_at(input.static_offset);
  DynamicLineSetup setup = make_setup(rest);
  setup.environment.sea = input.sea;
  setup.environment.sea_ramp_s = input.ramp_s;
  const engine::FeLineModel& model = setup.model;
  const engine::FeDynamicEnvironment& env = setup.environment;
  const engine::FeStaticsResult& statics = setup.statics;

  std::vector<Eigen::Vector3d> samples;
  samples.reserve(static_cast<std::size_t>(input.motion.cols()));
  for (Eigen::Index k = 0; k < input.motion.cols(); ++k) samples.push_back(fairlead_at(input.motion.col(k)));
  const auto trajectory =
      input.motion_times_s.empty()
          ? std::make_shared<const engine::SampledTrajectory>(input.t0_s, input.dt_s, std::move(samples))
          : std::make_shared<const engine::SampledTrajectory>(input.motion_times_s, std::move(samples));
  engine::FeDynamicsOptions options;
  options.start_time_s = input.t0_s;
  options.max_steps_between_outputs = input.max_steps_between_samples;
  options.relative_tolerance *= input.tolerance_scale;
  options.position_tolerance_m *= input.tolerance_scale;
  options.slope_tolerance *= input.tolerance_scale;
  options.velocity_tolerance_m_per_s *= input.tolerance_scale;
  const double t0 = input.t0_s, ramp = input.ramp_s;
  options.end_B_motion = [trajectory, rest, t0, ramp](double t) {
    const engine::TrajectoryPoint p = trajectory->at(t);
    const engine::RampValue r = engine::smooth_ramp(t - t0, ramp);
    const Eigen::Vector3d d = p.position_m - rest;
    engine::EndKinematics k;
    k.position_m = rest + r.value * d;
    k.velocity_m_per_s = r.rate_per_s * d + r.value * p.velocity_m_per_s;
    k.acceleration_m_per_s2 =
        r.rate2_per_s2 * d + 2.0 * r.rate_per_s * p.velocity_m_per_s + r.value * p.acceleration_m_per_s2;
    return k;
  };

  LineDynamicsSeries series;
  series.line = name;
  series.elements = fe_elements(model);
  const std::vector<double> times = line_dynamics_output_times(input);
  const std::size_t n = times.size();
  series.tension_N.resize(n);
  try {
    engine::FeLineDynamics dynamics(model, env, statics, options);
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0) dynamics.advance_to(times[k]);
      if (input.on_sample) {
        const engine::FeLineDynamicSnapshot state = dynamics.snapshot();
        series.tension_N[k] = state.end_B_force_N.norm();
        input.on_sample(index, k, state);
      } else {
        series.tension_N[k] = k == 0 ? statics.end_B_force_N.norm() : dynamics.end_B_force_N().norm();
      }
    }
    series.solver = dynamics.statistics();
  } catch (const engine::SolverError& e) {
    throw engine::SolverError(fmt::format("{} {}: FE dynamics failed: {}", kind, name, e.what()));
  }
  series.wall_s = start.seconds();
  return series;
}

}  // namespace

std::vector<double> line_dynamics_output_times(const LineDynamicsInput& input) {
  std::size_t count = static_cast<std::size_t>(input.motion.cols());
  if (!input.motion_times_s.empty())
    count = static_cast<std::size_t>(std::floor((input.motion_times_s.back() - input.t0_s) / input.dt_s + 1e-9)) + 1;
  std::vector<double> times(count);
  for (std::size_t k = 0; k < count; ++k) times[k] = input.t0_s + input.dt_s * static_cast<double>(k);
  return times;
}

std::vector<LineDynamicsSeries> run_line_dynamics(const Project& project, const LineDynamicsInput& input) {
  if (!(input.dt_s > 0.0) || input.motion.cols() < 2 || !(input.ramp_s >= 0.0) || !(input.tolerance_scale > 0.0)) {
    throw std::invalid_argument(
        fmt::format("line dynamics: needs dt > 0 s, >= 2 motion samples, ramp >= 0 s and a tolerance scale > 0, "
                    "got {} s, {}, {} s, {}",
                    input.dt_s, input.motion.cols(), input.ramp_s, input.tolerance_scale));
  }
  if (!input.motion.allFinite()) throw std::invalid_argument("line dynamics: the hull motion has non-finite samples");
  if (!input.motion_times_s.empty() &&
      (input.motion_times_s.size() != static_cast<std::size_t>(input.motion.cols()) ||
       !(input.t0_s >= input.motion_times_s.front()) || !(input.t0_s < input.motion_times_s.back()))) {
    throw std::invalid_argument(
        fmt::format("line dynamics: needs one time per motion sample and t0 inside them, got {} times for {} "
                    "samples, t0 {} s",
                    input.motion_times_s.size(), input.motion.cols(), input.t0_s));
  }
  auto selected = [&](const std::string& name) {
    return input.only.empty() || std::find(input.only.begin(), input.only.end(), name) != input.only.end();
  };
  for (const std::string& name : input.only) {
    const bool line =
        name != input.damaged_line && std::any_of(project.mooring.lines.begin(), project.mooring.lines.end(),
                                                  [&](const MooringLine& l) { return l.name == name; });
    const bool riser = input.include_risers && std::any_of(project.risers.begin(), project.risers.end(),
                                                           [&](const Riser& r) { return r.name == name; });
    if (!line && !riser)
      throw std::invalid_argument(fmt::format("line dynamics: \"{}\" is no intact mooring line or riser", name));
  }
  const std::vector<LineTypeProperties> types = input.line_types ? *input.line_types : resolve_line_types(project);
  std::vector<const MooringLine*> lines;
  for (const MooringLine& l : project.mooring.lines) {
    if (l.name != input.damaged_line && selected(l.name)) lines.push_back(&l);
  }
  std::vector<const Riser*> risers;
  for (const Riser& r : project.risers) {
    if (input.include_risers && selected(r.name)) risers.push_back(&r);
  }
  std::vector<LineDynamicsSeries> out(lines.size() + risers.size());
  const int count = static_cast<int>(out.size());
  engine::parallel_for(count, engine::worker_count(count), [&](int i) {
    const auto k = static_cast<std::size_t>(i);
    if (k < lines.size()) {
      const MooringLine& line = *lines[k];
      out[k] = run_one(
          project, k, line.name, "line", line.fairlead_b,
          [&](const Eigen::Vector3d& top) {
            return dynamic_mooring_line(project, line, types, input.current, top,
                                        input.static_lines ? line_profile(*input.static_lines, line.name) : nullptr,
                                        input.mesh);
          },
          input);
    } else {
      const Riser& riser = *risers[k - lines.size()];
      const RiserDesign design = riser_design(project, riser);
      out[k] = run_one(
          project, k, riser.name, "riser", design.hang_off_b,
          [&](const Eigen::Vector3d& top) {
            return dynamic_riser(project, design, input.current, top, nullptr, input.mesh);
          },
          input);
    }
  });
  return out;
}

}  // namespace spiral::design
