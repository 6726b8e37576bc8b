// The fully coupled level (engine/analysis/coupled_dynamics.hpp,
// design/analysis/coupled_analysis.hpp) against the levels it must reduce to:
//  * still water: hull and lines stay at the static equilibrium;
//  * lines with negligible mass, drag and seabed friction are quasi-static:
//    the coupled free decay then has the S-C free-decay period (the hull
//    with the 6×6 K of the line array), in surge, heave and yaw;
//  * with their real mass and drag the lines lengthen the surge period
//    (added mass) and damp it — the effects the enhanced S-C estimates;
//  * in a steady current on FE lines, the coupled hull comes to rest at the
//    coupled static equilibrium of hull + FE lines in that current.
// Built from the OC4 project (3 catenary chains, 200 m).
#include "engine/analysis/coupled_dynamics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>

#include "design/analysis/coupled_analysis.hpp"
#include "design/analysis/level_comparison.hpp"
#include "design/results/level_comparison_output.hpp"
#include "design/model/environment_loads.hpp"
#include "design/model/hull_model.hpp"
#include "design/analysis/line_dynamics.hpp"
#include "design/model/mooring_model.hpp"
#include "design/analysis/dynamic_analysis.hpp"
#include "design/analysis/static_case.hpp"
#include "design/project/validated_project.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {
namespace {

const std::string kOc4 = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml";

/// The OC4 lines as coupled FE lines at hull offset q (their statics there).
/// `quasi_static`: mass ×0.01, no added mass, drag, Froude–Krylov, seabed
/// damping or friction — lines whose dynamics the hull cannot feel.
std::vector<engine::CoupledLine> oc4_lines(const Project& project, const engine::Vector6d& q,
                                           const std::optional<engine::CurrentProfile>& current, bool quasi_static) {
  const engine::HullPose pose = engine::pose_from_offset(project.hull.reference_point_g, q);
  const std::vector<LineTypeProperties> types = resolve_line_types(project);
  std::vector<engine::CoupledLine> lines;
  for (const MooringLine& line : project.mooring.lines) {
    DynamicLineSetup s =
        dynamic_mooring_line(project, line, types, current, pose.reference_point_g + pose.rotation * line.fairlead_b);
    if (quasi_static) {
      for (engine::FeLineSection& sec : s.model.sections) {
        sec.mass_kg_per_m *= 0.01;
        sec.displaced_area_m2 = 0.0;
        sec.drag_normal = sec.drag_tangential = 0.0;
      }
      s.environment.seabed_damping_N_s_per_m2 = 0.0;
      s.environment.seabed_lateral_friction = 0.0;
      s.environment.statics.seabed_axial_friction = 0.0;
    }
    engine::CoupledLine c;
    c.name = line.name;
    c.model = s.model;
    c.environment = s.environment;
    c.initial = s.statics;
    c.attachment_b_m = line.fairlead_b;
    lines.push_back(std::move(c));
  }
  return lines;
}

/// OC4 at its still-water equilibrium, the S-C model (hull, linearized lines).
DynamicModel still_water_model(const ValidatedProject& p) {
  DynamicAnalysisRequest request;
  request.load_case = "intact-still-water";
  request.level = AnalysisLevel::semi_coupled;
  return build_dynamic_model(p, request);
}

/// Hull loads for the coupled system: its FE lines replace the linearized line array.
engine::HullLoads loads_without_linearized_lines() {
  engine::HullLoads loads;
  loads.lines = engine::LinearizedLines{};
  return loads;
}

std::vector<double> outputs(double duration_s, double dt_s) {
  std::vector<double> t;
  for (int k = 1; k * dt_s <= duration_s + 1e-9; ++k) t.push_back(k * dt_s);
  return t;
}

double mean_period_s(const Eigen::Matrix<double, 6, Eigen::Dynamic>& x, int dof, double level, double dt_s) {
  std::vector<double> v(static_cast<std::size_t>(x.cols()));
  for (Eigen::Index k = 0; k < x.cols(); ++k) v[static_cast<std::size_t>(k)] = x(dof, k) - level;
  const auto up = engine::upcrossing_times_s(v, dt_s, 0.0);
  EXPECT_GE(up.size(), 3u);
  return (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

/// Ratio of successive positive peaks about `level` (≈ exp(−δ)).
double peak_ratio(const Eigen::Matrix<double, 6, Eigen::Dynamic>& x, int dof, double level) {
  std::vector<double> peaks;
  for (Eigen::Index k = 1; k + 1 < x.cols(); ++k) {
    const double a = x(dof, k) - level;
    if (a > 0.0 && a >= x(dof, k - 1) - level && a > x(dof, k + 1) - level) peaks.push_back(a);
  }
  EXPECT_GE(peaks.size(), 2u);
  return peaks.size() >= 2 ? peaks[1] / peaks[0] : 1.0;
}

TEST(CoupledDynamics, StillWaterStaysAtTheStaticEquilibrium) {
  const ValidatedProject p = load_validated_project(kOc4);
  DynamicAnalysisRequest request;
  request.load_case = "intact-still-water";
  request.level = AnalysisLevel::coupled;
  request.duration_s = 300.0;
  const DynamicAnalysisResult r = run_dynamic_analysis(p, request);
  ASSERT_TRUE(r.coupled_solver.has_value());
  ASSERT_EQ(r.dynamic_tensions.size(), 3u);
  // The static case solves the lines as exact catenaries, the coupled run as
  // FE lines (10 m elements): their equilibria differ by the mesh error,
  // ~1e-5 of the tension, which moves the hull by millimetres at most.
  double drift = 0.0;
  for (Eigen::Index k = 0; k < r.low_frequency.cols(); ++k)
    drift = std::max(drift, (r.low_frequency.col(k) - r.static_offset).head<3>().norm());
  EXPECT_LT(drift, 5e-3);
  // Each FE line keeps its own static tension (1e-5), which is the exact
  // catenary's to the FE mesh error (measured 7e-4 with 10 m elements).
  for (std::size_t l = 0; l < r.dynamic_tensions.size(); ++l) {
    const auto& t = r.dynamic_tensions[l].tension_N;
    for (double v : t) EXPECT_NEAR(v, t.front(), 1e-5 * v);
    EXPECT_NEAR(t.front(), r.tensions[l].tension_N.front(), 1e-3 * t.front());
  }
  std::cout << "still water: largest hull drift " << drift << " m over 300 s, " << r.coupled_solver->steps
            << " steps\n";
}

// Lines whose inertia and damping the hull cannot feel: the coupled free
// decay must have the S-C (linear K) period. Tolerance 0.5 %: the decay is
// from 1 m / 0.5 m / 1° where the catenary stiffness changes by < 0.3 %
// across the swing, the line mass left (1 % of the chain's) adds ~2e-4 to the
// surge mass, and the integrators' period errors are < 1e-4.
TEST(CoupledDynamics, QuasiStaticLinesReproduceTheScFreeDecayPeriods) {
  const ValidatedProject p = load_validated_project(kOc4);
  const DynamicModel model = still_water_model(p);
  const engine::Vector6d q0 = model.initial_offset;
  const struct {
    int dof;
    double displacement, duration_s;
  } cases[] = {{0, 1.0, 400.0}, {2, 0.5, 100.0}, {5, std::numbers::pi / 180.0, 300.0}};
  for (const auto& c : cases) {
    const double dt = 0.1;
    const auto sc = engine::free_decay(model.hull, model.loads.lines, c.dof, c.displacement, c.duration_s, dt);
    const double sc_period = mean_period_s(sc.position, c.dof, q0(c.dof), dt);

    engine::Vector6d start = q0;
    start(c.dof) += c.displacement;
    engine::CoupledOptions options;
    options.output_times_s = outputs(c.duration_s, dt);
    // Free decay: nothing but the hull limits the step, so the hull's
    // tolerance sets BDF2's period error; at 1e-5 m it is < 1e-3 (measured
    // 0.14 / 0.07 / 0.10 %), at the default 1e-4 m heave errs by 0.39 %.
    options.hull_position_tolerance_m = 1e-5;
    options.hull_rotation_tolerance_rad = 1e-7;
    const engine::HullLoads loads = loads_without_linearized_lines();
    const engine::CoupledTimeSeries coupled =
        engine::simulate_coupled(model.hull, loads, p.project.hull.reference_point_g, start,
                                 oc4_lines(p.project, start, std::nullopt, true), options);
    const double coupled_period = mean_period_s(coupled.position, c.dof, q0(c.dof), dt);
    EXPECT_NEAR(coupled_period, sc_period, 5e-3 * sc_period) << "dof " << c.dof;
    std::cout << "dof " << c.dof << ": S-C period " << sc_period << " s, coupled " << coupled_period << " s ("
              << coupled.statistics.steps << " steps)\n";
  }
}

// With the hull's radiation memory (Cummins: A(inf) and the retardation
// kernel from OC4's .1) the coupled hull on quasi-static lines decays as the
// S-C hull with the same memory: same period and same decay of the peaks.
// The coupled run samples the velocity history at its 0.5 s outputs
// (Hermite-interpolated onto the kernel's 0.1 s grid) where the S-C driver
// stops at every 0.1 s (outputs at 0.1 s give the same numbers to 3 digits).
// Measured: periods within 0.07 % (heave) and 0.03 % (pitch), the same
// small difference as without memory (above: the lines' 1 % mass, BDF2),
// whose phase drift over the record leaves the records 2.9 % / 1.3 % of the
// release apart. Tolerances: 0.2 % on the period, 4 % on the records. In
// heave the memory matters: without it (A(w_LF)) the period is 0.77 % off.
TEST(CoupledDynamics, QuasiStaticLinesWithRadiationMemoryDecayAsTheScHullWithIt) {
  ValidatedProject p = load_validated_project(kOc4);
  p.project.hull.hydrodynamics->radiation = RadiationModel::memory;
  const DynamicModel model = still_water_model(p);
  ASSERT_TRUE(model.hull.radiation_memory.has_value());
  const engine::Vector6d q0 = model.initial_offset;
  engine::CvodeOptions cvode = engine::default_hull_integrator_options();
  cvode.relative_tolerance = 1e-8;  // the memory force is piecewise smooth in t
  const struct {
    int dof;
    double displacement, duration_s;
  } cases[] = {{2, 0.5, 100.0}, {4, 2.0 * std::numbers::pi / 180.0, 150.0}};
  for (const auto& c : cases) {
    const auto sc = engine::free_decay(model.hull, model.loads.lines, c.dof, c.displacement, c.duration_s, 0.1, cvode);
    engine::Vector6d start = q0;
    start(c.dof) += c.displacement;
    engine::CoupledOptions options;
    options.output_times_s = outputs(c.duration_s, 0.5);
    options.hull_position_tolerance_m = 1e-5;
    options.hull_rotation_tolerance_rad = 1e-7;
    const engine::CoupledTimeSeries coupled =
        engine::simulate_coupled(model.hull, loads_without_linearized_lines(), p.project.hull.reference_point_g, start,
                                 oc4_lines(p.project, start, std::nullopt, true), options);
    const double sc_period = mean_period_s(sc.position, c.dof, q0(c.dof), 0.1);
    const double coupled_period = mean_period_s(coupled.position, c.dof, q0(c.dof), 0.5);
    // The records at the coupled outputs (every fifth S-C sample).
    double deviation = 0.0, no_memory_deviation = 0.0;
    engine::HullDynamicsModel without = model.hull;
    without.radiation_memory.reset();
    without.added_mass = build_hull_model(p.project).low_frequency_added_mass;
    const engine::CoupledTimeSeries plain =
        engine::simulate_coupled(without, loads_without_linearized_lines(), p.project.hull.reference_point_g, start,
                                 oc4_lines(p.project, start, std::nullopt, true), options);
    for (Eigen::Index k = 0; k < coupled.position.cols(); ++k) {
      const double reference = sc.position(c.dof, 5 * k);
      deviation = std::max(deviation, std::abs(coupled.position(c.dof, k) - reference));
      no_memory_deviation = std::max(no_memory_deviation, std::abs(plain.position(c.dof, k) - reference));
    }
    const double plain_period = mean_period_s(plain.position, c.dof, q0(c.dof), 0.5);
    std::cout << "memory, dof " << c.dof << ": S-C period " << sc_period << " s, coupled " << coupled_period << " s ("
              << plain_period << " s without the memory); largest difference " << deviation / c.displacement
              << " of the release (" << no_memory_deviation / c.displacement << " without the memory)\n";
    EXPECT_NEAR(coupled_period, sc_period, 2e-3 * sc_period) << "dof " << c.dof;
    EXPECT_LT(deviation, 0.04 * c.displacement) << "dof " << c.dof;
    if (c.dof == 2) {
      EXPECT_GT(std::abs(plain_period - sc_period), 5e-3 * sc_period) << "the memory must matter";
    }
  }
}

// The real chains (113 kg/m, Cd 1.1 normal, Ca 1, on the seabed with
// friction) add mass and damping in surge: the coupled period is longer
// and successive peaks decay faster than with quasi-static lines.
TEST(CoupledDynamics, RealLinesAddMassAndDampingInSurge) {
  const ValidatedProject p = load_validated_project(kOc4);
  const DynamicModel model = still_water_model(p);
  engine::Vector6d start = model.initial_offset;
  start(0) += 5.0;
  engine::CoupledOptions options;
  options.output_times_s = outputs(400.0, 0.1);
  const engine::HullLoads loads = loads_without_linearized_lines();
  const auto run = [&](bool quasi_static) {
    return engine::simulate_coupled(model.hull, loads, p.project.hull.reference_point_g, start,
                                    oc4_lines(p.project, start, std::nullopt, quasi_static), options);
  };
  const engine::CoupledTimeSeries light = run(true), real = run(false);
  const double q0 = model.initial_offset(0);
  const double t_light = mean_period_s(light.position, 0, q0, 0.1);
  const double t_real = mean_period_s(real.position, 0, q0, 0.1);
  const double r_light = peak_ratio(light.position, 0, q0);
  const double r_real = peak_ratio(real.position, 0, q0);
  // The quasi-static lines decay as the S-C hull does (the surge peaks there
  // also beat with pitch through the coupling of the two modes).
  const auto sc = engine::free_decay(model.hull, model.loads.lines, 0, 5.0, 400.0, 0.1);
  const double r_sc = peak_ratio(sc.position, 0, q0);
  EXPECT_NEAR(r_light, r_sc, 0.01);
  // Line added mass: the enhanced S-C estimate, A_lines,11 = 8.4 t against
  // M + A = 2.2e7 kg, lengthens the period by ≈ 2e-4.
  EXPECT_GT(t_real, t_light);
  EXPECT_LT(t_real, 1.001 * t_light);
  EXPECT_LT(r_real, r_light - 0.05);
  std::cout << "surge from 5 m: S-C peak ratio " << r_sc << "; quasi-static lines " << t_light << " s, peak ratio "
            << r_light << "; real lines " << t_real << " s, peak ratio " << r_real << "\n";
}

// OC4 with its chains as FE lines (current drag on them) in a steady
// current: the static case is the coupled static equilibrium of hull + FE
// lines. Released from the still-water position, the coupled hull swings
// into the current and comes to rest there: the mean of the last 2 surge
// periods lies within 1 cm of it (1 % of the current's offset; the swing
// left after 1200 s is centimetres, its mean over whole periods much less;
// statics and dynamics share the FE mesh, so no mesh error separates them).
TEST(CoupledDynamics, MeanOffsetInSteadyCurrentIsTheCoupledStaticEquilibrium) {
  ValidatedProject p = load_validated_project(kOc4);
  for (MooringLine& l : p.project.mooring.lines) l.model = LineModel::fe;
  Environment* env = nullptr;
  for (Environment& e : p.project.environments)
    if (e.name == "raft-jonswap") env = &e;
  ASSERT_NE(env, nullptr);
  env->waves.reset();
  ASSERT_TRUE(env->current.has_value());
  for (CurrentPoint& c : env->current->profile) c.speed_m_per_s *= 3.0;  // a ~1 m offset
  const std::optional<engine::CurrentProfile> current = current_profile_of(*env);
  ASSERT_TRUE(current.has_value());

  DynamicAnalysisRequest request;
  request.load_case = "intact-raft-jonswap";
  request.level = AnalysisLevel::semi_coupled;
  const DynamicModel model = build_dynamic_model(p, request);
  const DynamicModel still = [&] {
    DynamicAnalysisRequest r = request;
    r.load_case = "intact-still-water";
    return build_dynamic_model(p, r);
  }();
  const engine::Vector6d q_current = model.initial_offset, q_still = still.initial_offset;
  ASSERT_GT((q_current - q_still).head<2>().norm(), 0.5) << "the current must move the hull";

  engine::CoupledOptions options;
  const double period = 110.0, duration = 1200.0, dt = 0.5;
  options.output_times_s = outputs(duration, dt);
  engine::HullLoads loads = loads_without_linearized_lines();
  loads.external = model.loads.external;  // empty: OC4 has no hull current coefficients
  const engine::CoupledTimeSeries run =
      engine::simulate_coupled(model.hull, loads, p.project.hull.reference_point_g, q_still,
                               oc4_lines(p.project, q_still, current, false), options);
  const auto last = static_cast<Eigen::Index>(2.0 * period / dt);
  const engine::Vector6d mean = run.position.rightCols(last).rowwise().mean();
  EXPECT_NEAR(mean(0), q_current(0), 0.01);
  EXPECT_NEAR(mean(1), q_current(1), 0.01);
  std::cout << "current: static equilibrium surge " << q_current(0) << " m (still water " << q_still(0)
            << " m); coupled mean of the last 220 s " << mean(0) << " m\n";
}

// A step-size collapse (here: a work limit of 2 steps per output) stops the
// run with the time reached, the cause and the part of the system with the
// largest local error.
TEST(CoupledDynamics, AnIntegratorFailureNamesTimeCauseAndPart) {
  const ValidatedProject p = load_validated_project(kOc4);
  const DynamicModel model = still_water_model(p);
  engine::Vector6d start = model.initial_offset;
  start(0) += 5.0;
  engine::CoupledOptions options;
  options.output_times_s = outputs(20.0, 1.0);
  options.max_steps_between_outputs = 2;
  const engine::HullLoads loads = loads_without_linearized_lines();
  try {
    engine::simulate_coupled(model.hull, loads, p.project.hull.reference_point_g, start,
                             oc4_lines(p.project, start, std::nullopt, false), options);
    FAIL() << "the work limit must stop the integration";
  } catch (const engine::IntegrationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("IDA failed at t = "), std::string::npos) << what;
    EXPECT_NE(what.find("IDA_TOO_MUCH_WORK"), std::string::npos) << what;
    EXPECT_NE(what.find("largest local error in "), std::string::npos) << what;
  }
}

// OC4 in still water with one option set wrong: simulate_coupled refuses it
// before integrating, naming the option and the value.
void expect_option_refused(const std::function<void(engine::CoupledOptions&)>& set_wrong, const std::string& message) {
  const ValidatedProject p = load_validated_project(kOc4);
  const DynamicModel model = still_water_model(p);
  engine::CoupledOptions options;
  options.output_times_s = outputs(1.0, 1.0);
  set_wrong(options);
  try {
    engine::simulate_coupled(model.hull, loads_without_linearized_lines(), p.project.hull.reference_point_g,
                             model.initial_offset, oc4_lines(p.project, model.initial_offset, std::nullopt, false),
                             options);
    FAIL() << "must be refused: " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

// The setup interval is an option (the coupled analysis sets 1 under
// wave-frequency motion); fewer than one step between setups is refused.
TEST(CoupledDynamics, ASetupIntervalBelowOneStepIsRefused) {
  expect_option_refused([](engine::CoupledOptions& o) { o.steps_between_full_setups = 0; },
                        "steps_between_full_setups: must be >= 1, got 0");
}

// Selective refresh: with a full setup at every step (as under WF motion)
// an element that has not moved keeps its matrices
// (CoupledOptions::element_refresh_slope). The Newton matrix only sets how
// the iteration converges, so the run must be as accurate as with every
// element refreshed: OC4 released 5 m off in surge with real lines, 150 s,
// both against a run at 0.03 of the tolerances. Measured: the surge error
// 7.4 mm with every element refreshed and with 53 % of the matrices kept,
// the fairlead forces' 917 N both (the two runs differ by 1–2 mm, inside
// that error: their Newton iterates differ); the limit is 1.25× the
// every-element error.
TEST(CoupledDynamics, KeepingTheMatricesOfElementsThatDidNotMoveKeepsTheAccuracy) {
  const ValidatedProject p = load_validated_project(kOc4);
  const DynamicModel model = still_water_model(p);
  engine::Vector6d start = model.initial_offset;
  start(0) += 5.0;
  const engine::HullLoads loads = loads_without_linearized_lines();
  const auto run = [&](bool selective, double tolerance_scale) {
    engine::CoupledOptions options;
    options.output_times_s = outputs(150.0, 0.5);
    options.steps_between_full_setups = 1;
    options.relative_tolerance *= tolerance_scale;
    options.position_tolerance_m *= tolerance_scale;
    options.slope_tolerance *= tolerance_scale;
    options.hull_position_tolerance_m *= tolerance_scale;
    options.hull_rotation_tolerance_rad *= tolerance_scale;
    if (selective) {
      options.element_refresh_slope = 1e-4;
      options.element_refresh_velocity_m_per_s = 0.05;
    }
    return engine::simulate_coupled(model.hull, loads, p.project.hull.reference_point_g, start,
                                    oc4_lines(p.project, start, std::nullopt, false), options);
  };
  const engine::CoupledTimeSeries every = run(false, 1.0), selective = run(true, 1.0), reference = run(false, 0.03);
  EXPECT_EQ(every.element_matrices_kept, 0);
  ASSERT_GT(selective.element_matrices_kept, selective.element_matrix_evaluations / 4)
      << "too few elements kept their matrices: the test would not test the refresh";
  const auto surge_error_m = [&](const engine::CoupledTimeSeries& r) {
    return (r.position.row(0) - reference.position.row(0)).cwiseAbs().maxCoeff();
  };
  const auto force_error_N = [&](const engine::CoupledTimeSeries& r) {
    double e = 0.0;
    for (std::size_t l = 0; l < r.end_B_force_N.size(); ++l)
      e = std::max(e, (r.end_B_force_N[l] - reference.end_B_force_N[l]).cwiseAbs().maxCoeff());
    return e;
  };
  EXPECT_LE(surge_error_m(selective), 1.25 * surge_error_m(every));
  EXPECT_LE(force_error_N(selective), 1.25 * force_error_N(every));
  std::cout << "selective refresh: " << selective.element_matrices_kept << " element matrices kept, "
            << selective.element_matrix_evaluations << " evaluated (every element: " << every.element_matrix_evaluations
            << "); " << selective.statistics.steps << " steps against " << every.statistics.steps << "; surge error "
            << surge_error_m(selective) << " m against " << surge_error_m(every) << " m, fairlead force error "
            << force_error_N(selective) << " N against " << force_error_N(every) << " N\n";
}

TEST(CoupledDynamics, ANegativeRefreshToleranceIsRefused) {
  expect_option_refused([](engine::CoupledOptions& o) { o.element_refresh_velocity_m_per_s = -0.1; },
                        "element_refresh_velocity_m_per_s: must be >= 0 m/s, got -0.1 m/s");
}

// A line whose forces turn non-finite (here: its wave kinematics return NaN
// after 5 s) is named with the time in the failure.
TEST(CoupledDynamics, ANonFiniteLineIsNamed) {
  const ValidatedProject p = load_validated_project(kOc4);
  const DynamicModel model = still_water_model(p);
  const engine::Vector6d start = model.initial_offset;
  std::vector<engine::CoupledLine> lines = oc4_lines(p.project, start, std::nullopt, false);
  lines[1].environment.waves = [](const Eigen::Vector3d&, double t, Eigen::Vector3d& u, Eigen::Vector3d& a) {
    u = a = Eigen::Vector3d::Zero();
    if (t > 5.0) u.x() = std::numeric_limits<double>::quiet_NaN();
  };
  engine::CoupledOptions options;
  options.output_times_s = outputs(20.0, 1.0);
  const engine::HullLoads loads = loads_without_linearized_lines();
  try {
    engine::simulate_coupled(model.hull, loads, p.project.hull.reference_point_g, start, lines, options);
    FAIL() << "a NaN in a line must stop the integration";
  } catch (const engine::SolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("line L2: non-finite forces at t = 5"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace spiral::design

namespace spiral::design {
namespace {

// A level whose solver fails does not take the others with it: the coupled
// run stopped by a work limit is reported with its message, the three
// other levels finish and carry their statistics.
TEST(LevelComparison, AFailingLevelLeavesTheOthersFinished) {
  const ValidatedProject p = load_validated_project(kOc4);
  ComparisonRequest request;
  request.load_case = "intact-raft-jonswap";
  request.duration_s = 100.0;
  request.coupled_max_steps_between_outputs = 2;
  const LevelComparison c = compare_levels(p, request);
  ASSERT_EQ(c.levels.size(), 4u);
  for (const LevelSummary& l : c.levels) {
    if (l.level == AnalysisLevel::coupled) {
      ASSERT_TRUE(l.error.has_value());
      EXPECT_NE(l.error->find("coupled analysis failed at t = "), std::string::npos) << *l.error;
    } else {
      EXPECT_FALSE(l.error.has_value()) << to_string(l.level);
      EXPECT_FALSE(l.channels.empty()) << to_string(l.level);
    }
  }
  const nlohmann::json j = comparison_to_json(c);
  EXPECT_TRUE(j["levels"]["coupled"].contains("error"));
  EXPECT_TRUE(j["levels"]["sc"].contains("max_offset_m"));
}

}  // namespace
}  // namespace spiral::design
