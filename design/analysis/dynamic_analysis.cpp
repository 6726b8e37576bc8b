// Uncoupled and semi-coupled time-domain hull analyses of one load case
// (dynamic_analysis.hpp has the method and its sources).
#include "design/analysis/dynamic_analysis.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "design/project/request_error.hpp"
#include "design/model/environment_loads.hpp"
#include "design/model/hull_model.hpp"
#include "design/analysis/coupled_analysis.hpp"
#include "design/analysis/line_dynamic_reduction.hpp"
#include "design/analysis/line_hydrodynamics.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/warning_note.hpp"
#include "design/project/project_validation.hpp"
#include "engine/analysis/fairlead_velocity.hpp"
#include "engine/analysis/forcing_table.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/analysis/low_frequency_damping.hpp"
#include "engine/numerics/sampled_trajectory.hpp"
#include "engine/numerics/statistics.hpp"
#include "engine/environment/wave_realization.hpp"
#include "engine/environment/wind.hpp"
#include "engine/environment/wind_realization.hpp"
#include "engine/hull/first_order_wave_response.hpp"
#include "engine/hull/motion_raos.hpp"
#include "engine/hull/mean_environmental_loads.hpp"
#include "engine/hull/morison_hull.hpp"
#include "engine/hull/radiation_memory.hpp"
#include "engine/hull/slow_drift.hpp"
#include "engine/hull/wamit_3.hpp"
#include "engine/common/dof_names.hpp"
#include "engine/common/stopwatch.hpp"
#include "engine/common/table_range_error.hpp"

namespace spiral::design {
namespace {

/// Seed offset of the wind gust stream, so that waves and wind are
/// independent for one user seed (a large prime: no overlap for nearby seeds).
constexpr std::uint64_t kWindSeedOffset = 1000003;
/// Wave components per direction of the realization (wave_realization.hpp:
/// autocorrelation leakage ~ 1/sqrt(2N) = 0.05 for N = 200).
constexpr int kWaveComponents = 200;
/// Directions of a short-crested sea.
constexpr int kSpreadingDirections = 11;
/// Integrator tolerance of the forced runs. The default 1e-10 of
/// hull_dynamics.hpp is for free decays; with random forcing a relative error
/// of 1e-7 is far below the seed-to-seed scatter of any statistic (a few %),
/// and it lies above the catenary closure noise (~1e-9 relative) of the
/// uncoupled line force (hull_dynamics.hpp).
constexpr double kForcedRunRelTol = 1e-7;
/// Absolute tolerances of the forced runs: 1e-6 m (m/s) and 1e-8 rad (rad/s),
/// a thousandth of a millimetre against offsets of metres; the free-decay
/// defaults (1e-10 m) make CVODE resolve the hull's micrometre response to the
/// 1 Hz end of the wind gust and the wave-frequency end of the drift force.
constexpr double kForcedRunAbsTolTranslation = 1e-6;
constexpr double kForcedRunAbsTolRotation = 1e-8;

/// Morison hull in waves: LF and WF motions come out of one integration and
/// are split by a zero-phase low-pass at this fraction of the realization's
/// lowest wave frequency (0.5 w_p by default, so the cut is at 0.25 w_p):
/// the wave band is then wholly WF, the moored surge/sway/yaw modes (periods
/// of minutes) wholly LF.
constexpr double kMorisonSplitFraction = 0.5;

// Below this fraction of critical damping in surge, sway or yaw the run's
// notes warn that its slow-drift response is resonance-dominated on damping
// the model barely has (engine/analysis/low_frequency_damping.hpp: the
// response grows as 1/sqrt(ζ)). A moored floater's slow modes are damped by
// the hull's viscous drag, the wind, wave-drift damping and the lines' drag
// (Faltinsen, Sea Loads, 1990, ch. 5), together several % of critical (the
// default FPS: 24–28 % in surge from its current drag alone; OC4's enhanced
// S-C 4.1 % from its three chains): 1 % is below any such sum and above a
// model that has left them all out (OC4's plain S-C: 0.00 %).
constexpr double kLightLowFrequencyDampingRatio = 0.01;
constexpr std::array<int, 3> kSlowDriftDofs = {0, 1, 5};
// ... of a degree of freedom that moves: below these low-frequency standard
// deviations its slow motion is too small to matter to offsets and tensions
// (0.1 deg of yaw moves a fairlead 70 m off the centre by 0.12 m), whatever
// its damping — as the unexcited sway and yaw of a collinear sea.
constexpr double kSmallestSlowMotion_m = 0.1;
constexpr double kSmallestSlowMotion_rad = 0.1 * std::numbers::pi / 180.0;

/// A free decay's rotations are kept within this (30 deg): the hull models
/// (hydrostatics at the mean waterline, small-angle radiation) are not meant
/// for more.
constexpr double kLargestDecayRotation_rad = std::numbers::pi / 6.0;

/// The Morison load of the members with what it points to (the flow holds
/// raw pointers into this struct; it lives behind a shared_ptr, never moved).
struct MorisonForcing {
  engine::MorisonHull hull;
  std::shared_ptr<const engine::WaveRealization> sea;
  std::optional<engine::CurrentProfile> current;
  engine::MorisonFlow flow;
  engine::HullPose pose;
};

engine::CoefficientTable table_of(const HullLoadCoefficients& c) {
  return {c.headings_rad, c.surge_m2, c.sway_m2, c.yaw_m3};
}

std::vector<double> output_times(double duration_s, double step_s) {
  std::vector<double> t;
  const auto n = static_cast<long>(std::floor(duration_s / step_s + 1e-9));
  for (long k = 0; k <= n; ++k) t.push_back(static_cast<double>(k) * step_s);
  return t;
}

engine::HullSimulationOptions forced_run_options(const DynamicAnalysisRequest& request) {
  engine::HullSimulationOptions options;
  options.output_times_s = output_times(request.duration_s, request.output_step_s);
  options.integrator.relative_tolerance = kForcedRunRelTol;
  Eigen::VectorXd atol(12);
  for (int i = 0; i < 12; ++i) atol(i) = (i % 6) < 3 ? kForcedRunAbsTolTranslation : kForcedRunAbsTolRotation;
  options.integrator.absolute_tolerances = atol;
  return options;
}

/// The motion RAOs of the hull at the case's static equilibrium: the .4
/// file, or the excitation (.3, or the Morison members') through the hull's
/// equation of motion with the static case's line stiffness; empty without
/// waves or without an excitation.
std::shared_ptr<const engine::MotionRaoTable> motion_raos_of(const Project& project, const DynamicModel& model) {
  const auto& hydro = project.hull.hydrodynamics;
  const Environment* environment = model.case_model.environment;
  if (!environment || !environment->waves || !has_wave_excitation(project)) return nullptr;
  const HullModel& hull = *model.case_model.hull;
  const engine::WamitReadOptions read = wamit_options_of(project, *hydro);
  if (hydro->rao_file)
    return std::make_shared<const engine::MotionRaoTable>(engine::read_wamit_4(*hydro->rao_file, read));
  const engine::ExcitationTable excitation = hydro->excitation_file
                                                 ? engine::read_wamit_3(*hydro->excitation_file, read)
                                                 : morison_excitation_of(project, *hull.radiation);
  return std::make_shared<const engine::MotionRaoTable>(
      engine::motion_raos_from_excitation(excitation, *hull.radiation, hull.mass_matrix, model.hull.linear_damping,
                                          hull.statics.hydrostatic_stiffness + model.statics.stiffness));
}

}  // namespace

engine::WaveRealization realize_sea(const Project& project, const Waves& waves, double duration_s, std::uint64_t seed) {
  engine::WaveRealizationInput input;
  input.spectrum = wave_spectrum_of(waves);
  input.mean_heading_rad = waves.heading_rad;
  if (waves.spreading_s) {
    input.spreading = engine::DirectionalSpreading{engine::SpreadingForm::cos_2s, *waves.spreading_s};
    input.direction_count = kSpreadingDirections;
  }
  input.components_per_direction = kWaveComponents;
  input.duration_s = duration_s;
  input.seed = seed;
  input.water_depth_m = project.site.depth_m;
  input.water = {project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2};
  return engine::make_wave_realization(input);
}

std::optional<Eigen::Matrix<double, 6, Eigen::Dynamic>> wave_frequency_motions(const ValidatedProject& validated,
                                                                               const DynamicModel& model,
                                                                               const Eigen::VectorXd& times_s) {
  const Project& project = validated.project;
  if (!model.wave_raos || !model.sea) return std::nullopt;
  const Eigen::Vector3d& ref = project.hull.reference_point_g;
  try {
    const engine::FirstOrderWaveSeries series = engine::prepare_first_order_series(
        *model.sea, *model.wave_raos,
        {ref.x() + model.statics.offset(0), ref.y() + model.statics.offset(1), model.statics.offset(5)});
    return engine::evaluate_first_order_many(series, times_s);
  } catch (const engine::TableRangeError& e) {
    heading_error(project, model.case_model.environment->name, "wave-frequency RAOs (hull.hydrodynamics)", e);
  }
}

const char* to_string(AnalysisLevel level) {
  switch (level) {
    case AnalysisLevel::uncoupled:
      return "uncoupled";
    case AnalysisLevel::semi_coupled:
      return "sc";
    case AnalysisLevel::semi_coupled_enhanced:
      return "sc-enhanced";
    case AnalysisLevel::coupled:
      return "coupled";
  }
  return "?";
}

AnalysisLevel parse_analysis_level(const std::string& name, const Project& project) {
  for (AnalysisLevel level : {AnalysisLevel::uncoupled, AnalysisLevel::semi_coupled,
                              AnalysisLevel::semi_coupled_enhanced, AnalysisLevel::coupled}) {
    if (name == to_string(level)) return level;
  }
  throw request_error(
      project, "level",
      fmt::format("unknown analysis level \"{}\"; allowed: uncoupled | sc | sc-enhanced | coupled", name));
}

DynamicModel build_dynamic_model(const ValidatedProject& validated, const DynamicAnalysisRequest& request) {
  const Project& project = validated.project;
  if (!(request.duration_s > 0.0) || !(request.output_step_s > 0.0) || request.output_step_s > request.duration_s) {
    throw request_error(project, "duration_s",
                        fmt::format("need duration > 0 s and 0 < output step <= duration, got {} s and {} s",
                                    request.duration_s, request.output_step_s));
  }
  if (!(request.tolerance_scale > 0.0) || !std::isfinite(request.tolerance_scale)) {
    throw request_error(project, "tolerance_scale",
                        fmt::format("must be a finite number > 0, got {}", request.tolerance_scale));
  }
  if (request.decay) {
    const engine::Vector6d& d = request.decay->displacement;
    if (!d.allFinite() || d.tail<3>().cwiseAbs().maxCoeff() > kLargestDecayRotation_rad) {
      throw request_error(project, "decay.displacement",
                          fmt::format("need finite displacements and rotations within {:g} deg, got [{}] (m, rad)",
                                      kLargestDecayRotation_rad * 180.0 / std::numbers::pi, fmt::join(d, ", ")));
    }
    if (!(request.decay->release_s > 0.0) || !(request.decay->release_s < request.duration_s)) {
      throw request_error(project, "decay.release_s",
                          fmt::format("the release must come after 0 s and before the end of the run ({} s), got {} s",
                                      request.duration_s, request.decay->release_s));
    }
  }
  DynamicModel model;
  model.case_model = build_case_model(project, request.load_case);
  const LoadCase& load_case = *model.case_model.load_case;
  const Environment& environment = *model.case_model.environment;
  // The S-C levels start from the static case with the current on every line
  // (a stage's quick case is taken when it is that already: no current, or
  // FE lines only); the uncoupled level from the quick one, its catenaries
  // without current.
  StaticCaseRequest statics_request{request.load_case, std::nullopt, false};
  statics_request.lines_carry_current = request.level != AnalysisLevel::uncoupled;
  const bool reuse = request.statics && (statics_request.lines_carry_current ? request.statics->current_on_every_line
                                                                             : !request.statics->lines_carry_current);
  model.statics =
      reuse ? *request.statics : run_static_case(validated, model.case_model, statics_request, request.rest_solutions);
  model.timing.equilibrium_s = model.statics.equilibrium_wall_s;
  model.timing.reduction_s = model.statics.stiffness_wall_s;
  model.notes = model.statics.notes;
  model.initial_offset = model.statics.offset;

  // Hull.
  const HullModel& hull = *model.case_model.hull;
  model.hull.mass = hull.mass_matrix;
  model.hull.added_mass = hull.low_frequency_added_mass;
  model.hull.hydrostatic_stiffness = hull.statics.hydrostatic_stiffness;
  model.hull.hydrostatic_force_at_rest = hull.statics.rest_force;
  if (project.hull.hydrodynamics) {
    const HullHydrodynamics& hydro = *project.hull.hydrodynamics;
    model.hull.linear_damping.diagonal() = hydro.linear_damping;
    model.hull.quadratic_damping = hydro.quadratic_damping;
    if (hydro.radiation == RadiationModel::memory) {
      // Cummins' equation: A(inf) and the retardation kernel from the .1 data
      // (engine/hull/radiation_memory.hpp); the data must reach the
      // frequencies where B(w) has decayed, else an input error.
      try {
        model.radiation_memory =
            engine::make_radiation_memory(*hull.radiation, {hydro.memory_duration_s, hydro.memory_time_step_s});
      } catch (const engine::RadiationDataError& e) {
        throw InputError({make_issue(project, "hull.hydrodynamics.radiation", "radiation_memory_data", e.what())});
      }
      model.hull.added_mass = model.radiation_memory->added_mass_infinite;
      model.hull.radiation_memory = model.radiation_memory->kernel;
      model.notes.push_back(
          fmt::format("radiation memory: A(inf) {} and a {:g} s retardation kernel at {:g} s (Cummins 1962) "
                      "instead of A(w_LF)",
                      model.radiation_memory->added_mass_infinite_from_file
                          ? "from the file's zero-period row"
                          : fmt::format("from Ogilvie's relation over {} frequencies >= {:.3g} rad/s",
                                        model.radiation_memory->ogilvie_frequencies,
                                        model.radiation_memory->ogilvie_omega_min_rad_per_s),
                      hydro.memory_duration_s, hydro.memory_time_step_s));
    }
  } else {
    model.notes.push_back("no hull.hydrodynamics: the hull has no added mass and no wave-frequency motions");
  }

  // Wave-frequency RAOs at this equilibrium: the data files read once for
  // every use below (the enhanced S-C's first pass, the WF motion, the
  // coupled level's fairlead motion).
  model.wave_raos = motion_raos_of(project, model);

  // Lines.
  const Eigen::Vector3d reference_point = project.hull.reference_point_g;
  const std::string damaged = load_case.damaged_line.value_or("");
  engine::LinearizedLines linearized{
      model.statics.line_force, model.statics.dynamic_stiffness, model.statics.offset, std::nullopt, std::nullopt, {}};
  if (request.level == AnalysisLevel::uncoupled) {
    auto mooring =
        std::make_shared<LineArrayModel>(build_mooring_model(project, *model.case_model.line_types, damaged));
    const engine::HullPose pose_eq = engine::pose_from_offset(reference_point, model.statics.offset);
    // The rest of the array (risers; current drag on model: fe lines) held at
    // its linearization about the S-C equilibrium: F_rest0 − K_rest (q − q0).
    const engine::Vector6d rest_force =
        model.statics.line_force - engine::evaluate_line_array(mooring->lines, pose_eq).force;
    engine::Matrix6d rest_stiffness = engine::Matrix6d::Zero();
    for (std::size_t i = model.statics.lines.size(); i < model.statics.line_stiffness.size(); ++i) {
      rest_stiffness += model.statics.line_stiffness[i];
    }
    if (!model.statics.risers.empty()) {
      model.notes.push_back("uncoupled: risers enter linearized about the static equilibrium (F0 − K (q − q0))");
    }
    const engine::Vector6d q0 = model.statics.offset;
    model.loads.lines = engine::NonlinearLineForce(
        [mooring, reference_point, rest_force, rest_stiffness, q0](const engine::Vector6d& q) {
          const engine::HullPose pose = engine::pose_from_offset(reference_point, q);
          engine::Vector6d f = engine::Vector6d::Zero();
          for (const auto& line : mooring->lines) {
            const Eigen::Vector3d arm = pose.rotation * line->attachment_b();
            const Eigen::Vector3d force = line->solve(pose.reference_point_g + arm).force_g;
            f.head<3>() += force;
            f.tail<3>() += arm.cross(force);
          }
          return engine::Vector6d(f + rest_force - rest_stiffness * (q - q0));
        });
  } else {
    model.loads.lines = linearized;
    if (model.statics.dynamic_stiffness_lines > 0) {
      model.notes.push_back(
          fmt::format("polyester: the mean position is the equilibrium on the static EA; the motions about it see "
                      "the dynamic EA at each segment's mean tension ({} lines; DNV-OS-E301 ch. 2 sec. 2 [2.4]), as "
                      "the coupled level's FE lines",
                      model.statics.dynamic_stiffness_lines));
    }
  }

  // External force.
  engine::Stopwatch forcing_start;
  std::shared_ptr<const engine::WaveRealization> sea;
  if (environment.waves) {
    sea = std::make_shared<const engine::WaveRealization>(
        realize_sea(project, *environment.waves, request.duration_s, request.seed));
  }
  model.sea = sea;
  std::shared_ptr<const engine::SlowDriftSeries> drift;
  if (environment.waves && project.hull.mean_drift) {
    const engine::MeanDriftTable& table = *model.case_model.drift;
    try {
      drift = std::make_shared<const engine::SlowDriftSeries>(
          engine::prepare_slow_drift(*sea, table,
                                     {reference_point.x() + model.statics.offset(0),
                                      reference_point.y() + model.statics.offset(1), model.statics.offset(5)}));
    } catch (const engine::TableRangeError& e) {
      heading_error(project, environment.name, "slow drift (hull.mean_drift)", e);
    }
    const double c = std::cos(drift->yaw_rad);
    const double s = std::sin(drift->yaw_rad);
    const engine::Vector6d& b = drift->mean_force_b;
    model.mean_slow_drift_force << c * b(0) - s * b(1), s * b(0) + c * b(1), b(2), c * b(3) - s * b(4),
        s * b(3) + c * b(4), b(5);
    model.slow_drift = [drift](double t) { return engine::slow_drift_force(*drift, t); };
  }
  std::optional<engine::CoefficientTable> current_table;
  Eigen::Vector3d current_velocity = Eigen::Vector3d::Zero();
  // Morison members: inertia, pressure and drag on the relative velocity
  // (current + waves with Wheeler stretching − hull), the strips at the static
  // equilibrium (engine/hull/morison_hull.hpp); they carry the current load on
  // the hull, so the current coefficients are not added again.
  std::shared_ptr<const MorisonForcing> members;
  if (hull.morison) {
    auto m = std::make_shared<MorisonForcing>();
    m->hull = *hull.morison;
    m->sea = sea;
    m->current = current_profile_of(environment);
    m->flow.sea = m->sea.get();
    m->flow.current = m->current ? &*m->current : nullptr;
    m->flow.water_density_kg_per_m3 = project.site.water_density_kg_per_m3;
    if (sea) {
      for (const auto& c : sea->components) m->flow.highest_crest_m += c.amplitude_m;
      model.wave_split_frequency_rad_per_s = kMorisonSplitFraction * sea->omega_min_rad_per_s;
    }
    m->pose = engine::pose_from_offset(reference_point, model.statics.offset);
    members = m;
    if (project.hull.current_coefficients && m->current) {
      model.notes.push_back(
          "Morison hull: the members carry the current load in the dynamics; "
          "hull.current_coefficients act in the static equilibrium only");
    }
  }
  if (const auto profile = current_profile_of(environment);
      profile && project.hull.current_coefficients && !hull.morison) {
    current_table = table_of(*project.hull.current_coefficients);
    current_velocity = engine::current_velocity_g(*profile, 0.0);
  }
  std::optional<engine::CoefficientTable> wind_table;
  double wind_speed = 0.0;
  Eigen::Vector3d wind_direction = Eigen::Vector3d::Zero();
  std::shared_ptr<const engine::WindRealization> gust;
  if (environment.wind && environment.wind->speed_m_per_s > 0.0 && project.hull.wind_coefficients) {
    const Wind& wind = *environment.wind;
    const double height = project.hull.wind_coefficients->reference_height_m;
    wind_table = table_of(*project.hull.wind_coefficients);
    wind_speed = engine::mean_wind_speed_m_per_s({wind.speed_m_per_s, height});
    wind_direction << std::cos(wind.heading_rad), std::sin(wind.heading_rad), 0.0;
    if (wind.spectrum != WindSpectrum::none) {
      engine::WindRealizationInput input;
      input.seed = request.seed + kWindSeedOffset;
      if (wind.spectrum == WindSpectrum::npd) {
        const engine::NpdSpectrumInput npd{wind.speed_m_per_s, height};
        input.spectrum = [npd](double f) { return engine::npd_wind_spectrum(npd, f); };
      } else {
        const engine::ApiSpectrumInput api{wind_speed, height, engine::api_turbulence_intensity(height) * wind_speed,
                                           0.025};
        input.spectrum = [api](double f) { return engine::api_wind_spectrum(api, f); };
      }
      gust = std::make_shared<const engine::WindRealization>(engine::make_wind_realization(input));
    }
  }
  const double rho_w = project.site.water_density_kg_per_m3;
  const double rho_a = project.site.air_density_kg_per_m3;
  if (drift || current_table || wind_table || members) {
    std::shared_ptr<const engine::ForcingTable> forcing;
    if (drift || gust)
      forcing = std::make_shared<const engine::ForcingTable>(drift.get(), gust.get(), request.duration_s);
    model.loads.external = [=](double t, const engine::Vector6d& q, const engine::Vector6d& qd) {
      engine::Vector6d f = engine::Vector6d::Zero();
      Eigen::Matrix<double, 7, 1> tabulated = Eigen::Matrix<double, 7, 1>::Zero();
      if (forcing) tabulated = forcing->at(t);
      if (drift) f += tabulated.head<6>();
      const Eigen::Vector3d hull_velocity(qd(0), qd(1), 0.0);
      if (current_table) {
        f += engine::coefficient_load(*current_table, {rho_w, current_velocity - hull_velocity, q(5)}).load_g;
      }
      if (wind_table) {
        const double u = wind_speed + tabulated(6);
        f += engine::coefficient_load(*wind_table, {rho_a, u * wind_direction - hull_velocity, q(5)}).load_g;
      }
      if (members) {
        f += engine::morison_load(members->hull, members->flow, members->pose.reference_point_g, members->pose.rotation,
                                  t, qd)
                 .force;
      }
      return f;
    };
  }

  model.timing.forcing_s = forcing_start.seconds();

  // A free decay: the pull that holds the hull displaced until its release.
  if (request.decay) {
    const engine::Vector6d pull =
        (model.hull.hydrostatic_stiffness + model.statics.dynamic_stiffness) * request.decay->displacement;
    const double release_s = request.decay->release_s;
    model.loads.external = [inner = model.loads.external, pull, release_s](double t, const engine::Vector6d& q,
                                                                           const engine::Vector6d& qd) {
      engine::Vector6d f = inner ? inner(t, q, qd) : engine::Vector6d::Zero();
      if (t < release_s) f += engine::smooth_ramp(t, 0.5 * release_s).value * pull;
      return f;
    };
    model.notes.push_back(fmt::format(
        "free decay: the hull pulled by (C + K) d, d = [{:.4g}] (m, rad) from the equilibrium, built up over "
        "{:g} s and released at {:g} s",
        fmt::join(request.decay->displacement, ", "), 0.5 * release_s, release_s));
  }

  // Enhanced S-C: the lines' damping and added mass (and, reduced
  // dynamically, their low-frequency stiffening) at the hull.
  if (request.level == AnalysisLevel::semi_coupled_enhanced) {
    engine::Stopwatch start;
    // The lines' drag is linearized on the hull motion of a first plain S-C
    // run (same forcing, same seed), its wave-frequency motion included.
    const engine::HullTimeSeries plain = engine::simulate_hull(model.hull, model.loads, model.initial_offset,
                                                               engine::Vector6d::Zero(), forced_run_options(request));
    Eigen::Matrix<double, 6, Eigen::Dynamic> motion = plain.position;
    model.wave_frequency_at_outputs = wave_frequency_motions(validated, model, plain.times_s);
    if (model.wave_frequency_at_outputs) motion += *model.wave_frequency_at_outputs;
    model.line_reduction = LineReduction::quasi_static;
    if (request.line_reduction == LineReduction::dynamic) {
      // Every line's FE impedance about its current-loaded static state,
      // fitted for the hull's equations.
      const DynamicLineReduction reduced =
          dynamic_line_reduction(project, *model.case_model.line_types, model.case_model.current, model.statics,
                                 damaged, motion, request.output_step_s);
      if (reduced.unusable_reason.empty()) {
        model.line_reduction = LineReduction::dynamic;
        linearized.added_mass = reduced.added_mass;
        linearized.damping = reduced.damping;
        linearized.relaxations = reduced.relaxations;
        model.notes.push_back(fmt::format(
            "sc-enhanced: the damping, added mass and low-frequency stiffening of {} mooring lines and risers from "
            "their dynamic FE models' impedance about the current-loaded equilibrium ({} frequencies, {:.3g}-{:.3g} "
            "rad/s), fitted with a dashpot, an added mass and relaxations of {} (fit residual {:.1f} %; "
            "design/analysis/line_dynamic_reduction.hpp); the normal drag linearized stochastically on the lines' "
            "quasi-static motion for the velocities of a first sc run (Atalik & Utku 1976); the waves' velocities "
            "on the lines are not in the drag's linearization",
            reduced.lines, reduced.frequencies, reduced.lowest_frequency_rad_per_s, reduced.highest_frequency_rad_per_s,
            reduced.relaxation_summary, 100.0 * reduced.relative_residual));
      } else {
        model.notes.push_back(fmt::format(
            "sc-enhanced: the lines' dynamic reduction is not used, {}; their quasi-static reduction instead "
            "(design/analysis/line_dynamic_reduction.hpp)",
            reduced.unusable_reason));
      }
    }
    if (model.line_reduction == LineReduction::quasi_static) {
      // The quasi-static shape derivative.
      LineArrayModel mooring = build_mooring_model(project, *model.case_model.line_types, damaged);
      std::vector<Eigen::Vector3d> fairleads_b;
      for (const auto& line : mooring.lines) fairleads_b.push_back(line->attachment_b());
      const auto covariance =
          engine::fairlead_velocity_covariance(fairleads_b, reference_point, motion, request.output_step_s);
      const LineHydrodynamicsResult lines =
          line_hydrodynamics(mooring, engine::pose_from_offset(reference_point, model.statics.offset), covariance,
                             rho_w, model.case_model.current ? &*model.case_model.current : nullptr);
      linearized.added_mass = lines.added_mass;
      linearized.damping = lines.damping;
      model.notes.push_back(
          "sc-enhanced: mooring-line damping and added mass from the quasi-static line shape derivative "
          "(normal Morison drag linearized stochastically about the current at each node for the velocities "
          "of a first sc run, Atalik & Utku 1976); the current's effect on the line shape, the risers' "
          "damping and line dynamics neglected in these matrices");
    }
    model.line_added_mass = linearized.added_mass;
    model.line_damping = linearized.damping;
    model.line_relaxations = linearized.relaxations;
    model.loads.lines = linearized;
    model.timing.reduction_s += start.seconds();
  }
  return model;
}

DynamicAnalysisResult result_of_model(const DynamicModel& model, const DynamicAnalysisRequest& request,
                                      const std::string& case_name, const std::string& environment_name) {
  DynamicAnalysisResult result;
  result.case_name = case_name;
  result.environment = environment_name;
  result.level = request.level;
  result.seed = request.seed;
  result.tolerance_scale = request.tolerance_scale;
  result.decay = request.decay;
  result.static_offset = model.statics.offset;
  result.mean_slow_drift_force = model.mean_slow_drift_force;
  result.line_added_mass = model.line_added_mass;
  result.line_damping = model.line_damping;
  result.line_relaxations = model.line_relaxations;
  result.line_reduction = model.line_reduction;
  result.notes = model.notes;
  result.timing = model.timing;
  return result;
}

std::vector<TensionSeries> quasi_static_fairlead_tensions(const Project& project,
                                                          const std::vector<LineTypeProperties>& types,
                                                          const std::string& damaged_line,
                                                          const Eigen::Matrix<double, 6, Eigen::Dynamic>& total) {
  std::vector<TensionSeries> tensions;
  LineArrayModel mooring = build_mooring_model(project, types, damaged_line);
  const Eigen::Index n = total.cols();
  for (const auto& line : mooring.lines)
    tensions.push_back({line->name(), std::vector<double>(n), std::vector<Eigen::Vector3d>(n)});
  for (Eigen::Index k = 0; k < n; ++k) {
    const engine::HullPose pose = engine::pose_from_offset(project.hull.reference_point_g, total.col(k));
    for (std::size_t l = 0; l < mooring.lines.size(); ++l) {
      const auto& line = mooring.lines[l];
      const Eigen::Vector3d fairlead = pose.point_g(line->attachment_b());
      tensions[l].fairlead_g_m[static_cast<std::size_t>(k)] = fairlead;
      tensions[l].tension_N[static_cast<std::size_t>(k)] = line->solve(fairlead).top_tension_N;
    }
  }
  return tensions;
}

DynamicAnalysisResult run_dynamic_analysis(const ValidatedProject& validated, const DynamicAnalysisRequest& request) {
  if (request.level == AnalysisLevel::coupled) return run_coupled_analysis(validated, request);
  const Project& project = validated.project;
  DynamicModel model = build_dynamic_model(validated, request);
  const LoadCase& load_case = find_load_case(project, request.load_case);
  const Environment& environment = environment_of(project, load_case);

  DynamicAnalysisResult result = result_of_model(model, request, load_case.name, environment.name);

  // Low-frequency dynamics from the static equilibrium, at rest.
  const engine::HullSimulationOptions options = forced_run_options(request);
  const engine::HullEquations equations = engine::make_hull_equations(model.hull, model.loads);
  if (request.progress && model.loads.external) {
    // Progress from the integrator's time (the force is evaluated at
    // increasing t, up to retried steps); reports at 1 % steps only.
    auto next = std::make_shared<double>(0.0);
    const auto progress = request.progress;
    const double duration = request.duration_s;
    model.loads.external = [inner = model.loads.external, next, progress, duration](double t, const engine::Vector6d& q,
                                                                                    const engine::Vector6d& qd) {
      if (t >= *next) {
        progress(std::min(1.0, t / duration));
        *next = t + 0.01 * duration;
      }
      return inner(t, q, qd);
    };
  }
  const engine::HullTimeSeries lf =
      engine::simulate_hull(model.hull, model.loads, model.initial_offset, engine::Vector6d::Zero(), options);
  if (request.progress) request.progress(1.0);
  result.times_s = lf.times_s;
  result.low_frequency = lf.position;
  result.solver = lf.statistics;
  result.timing.dynamics_s = lf.wall_clock_s;
  result.low_frequency_damping = engine::low_frequency_damping(equations, lf, kSlowDriftDofs);

  // Wave-frequency motions.
  engine::Stopwatch start;
  result.wave_frequency.setZero(6, lf.times_s.size());
  if (model.wave_split_frequency_rad_per_s > 0.0 && lf.times_s.size() >= 2) {
    // Morison hull: the integration carried LF and WF together.
    for (int d = 0; d < 6; ++d) {
      const Eigen::VectorXd total = lf.position.row(d).transpose();
      const std::vector<double> low =
          engine::low_pass_dft(std::span<const double>(total.data(), static_cast<std::size_t>(total.size())),
                               request.output_step_s, model.wave_split_frequency_rad_per_s);
      for (Eigen::Index k = 0; k < total.size(); ++k) {
        result.low_frequency(d, k) = low[static_cast<std::size_t>(k)];
        result.wave_frequency(d, k) = total(k) - low[static_cast<std::size_t>(k)];
      }
    }
    result.wave_frequency_computed = true;
    result.notes.push_back(
        fmt::format("Morison hull: low- and wave-frequency motions integrated together with the member "
                    "loads; split by a zero-phase low-pass at {:.3g} rad/s ({:g} x the lowest wave frequency)",
                    model.wave_split_frequency_rad_per_s, kMorisonSplitFraction));
  } else if (auto wf = model.wave_frequency_at_outputs && model.wave_frequency_at_outputs->cols() == lf.times_s.size()
                           ? std::move(model.wave_frequency_at_outputs)
                           : wave_frequency_motions(validated, model, lf.times_s)) {
    result.wave_frequency = std::move(*wf);
    result.wave_frequency_computed = true;
  } else if (environment.waves) {
    result.notes.push_back(
        "no wave-frequency motions: the project gives no hull.hydrodynamics.excitation_file (.3), "
        "rao_file (.4) or excitation: morison_maccamy_fuchs; "
        "motions are low-frequency only");
  }
  result.total = result.low_frequency + result.wave_frequency;
  result.timing.wave_frequency_s = start.seconds();

  // A slow mode that moves, on next to no damping.
  std::vector<std::string> light;
  for (const engine::DofDamping& d : result.low_frequency_damping) {
    const Eigen::VectorXd slow = result.low_frequency.row(d.dof).transpose();
    if (slow.size() < 2) break;
    const double std_dev =
        engine::channel_moments(std::span<const double>(slow.data(), static_cast<std::size_t>(slow.size()))).std_dev;
    const double floor = d.dof < 3 ? kSmallestSlowMotion_m : kSmallestSlowMotion_rad;
    if (d.natural_period_s > 0.0 && d.damping_ratio < kLightLowFrequencyDampingRatio && std_dev >= floor) {
      light.push_back(fmt::format("{} ({:.0f} s, {:.2f} %)", engine::kDofNames[static_cast<std::size_t>(d.dof)],
                                  d.natural_period_s, 100.0 * d.damping_ratio));
    }
  }
  if (!light.empty()) {
    const bool enhanced = request.level == AnalysisLevel::semi_coupled_enhanced;
    result.notes.push_back(warning_note(fmt::format(
        "all but undamped at the natural period: {} of critical damping (the hull's damping, current, "
        "wind and member drag{}, linearized over this run), below {:g} %: the slow-drift response is resonant on "
        "damping the model barely has. Give the hull its low-frequency damping (hull.hydrodynamics "
        "linear_damping / quadratic_damping, e.g. from a decay test){}",
        fmt::join(light, ", "), enhanced ? " and the lines' damping" : "", 100.0 * kLightLowFrequencyDampingRatio,
        enhanced ? "" : ", or run the enhanced S-C, which adds the lines' damping (--level sc-enhanced)")));
  }

  // Quasi-static fairlead tensions at the total motion.
  start.restart();
  if (request.compute_tensions) {
    result.tensions = quasi_static_fairlead_tensions(project, *model.case_model.line_types,
                                                     load_case.damaged_line.value_or(""), result.total);
  }
  result.timing.tensions_s = start.seconds();

  if (request.line_dynamics && result.times_s.size() >= 2) {
    start.restart();
    LineDynamicsInput lines;
    lines.damaged_line = load_case.damaged_line.value_or("");
    lines.current = model.case_model.current;
    lines.line_types = model.case_model.line_types;
    lines.static_offset = model.initial_offset;
    lines.static_lines = &model.statics.lines;
    lines.t0_s = result.times_s(0);
    lines.dt_s = result.times_s(1) - result.times_s(0);
    lines.motion = result.total;
    lines.ramp_s = request.line_dynamics_ramp_s;
    lines.tolerance_scale = request.tolerance_scale;
    if (result.wave_frequency_computed) lines.tolerance_scale *= kWaveFrequencyLineToleranceScale;
    lines.sea = model.sea;
    lines.mesh = request.detailed_line_mesh ? LineMesh::own : LineMesh::global_analysis;
    result.line_element_length_m = global_element_length_m(project, lines.mesh);
    result.dynamic_tensions = run_line_dynamics(project, lines);
    result.timing.line_dynamics_s = start.seconds();
    const std::string mesh_note = line_mesh_note(project, lines.mesh, dynamic_line_elements(result.dynamic_tensions));
    result.notes.push_back(fmt::format(
        "dynamic tensions: FE mooring lines and risers with the total hull motion "
        "prescribed at the fairleads and hang-offs, built up over the "
        "first {:g} s; current on the lines{}{}{}",
        request.line_dynamics_ramp_s, model.sea ? " and " + line_wave_kinematics_note(*model.sea) : std::string(),
        result.wave_frequency_computed
            ? fmt::format("; under the wave-frequency motion their tolerances are {:g} of the "
                          "single-line defaults",
                          kWaveFrequencyLineToleranceScale)
            : std::string(),
        mesh_note.empty() ? std::string() : "; " + mesh_note));
  }
  return result;
}

}  // namespace spiral::design
