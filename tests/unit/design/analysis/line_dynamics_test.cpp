// Dynamic mooring-line tensions from a prescribed hull motion, assembled from
// the OC4 project: the quasi-static limit of a slow motion, a hull at rest,
// and a failing line named in the error.
#include "design/analysis/line_dynamics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>

#include "design/analysis/static_case.hpp"
#include "design/model/environment_loads.hpp"
#include "engine/common/rigid_body.hpp"
#include "engine/common/solver_error.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/validated_project.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/numerics/statistics.hpp"
#include "engine/environment/wave_realization.hpp"

namespace spiral::design {
namespace {

const std::string kOc4 = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml";

LineDynamicsInput surge_motion(double amplitude_m, double period_s, double duration_s) {
  LineDynamicsInput in;
  in.dt_s = 0.5;
  const auto n = static_cast<Eigen::Index>(duration_s / in.dt_s) + 1;
  in.motion.setZero(6, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    in.motion(0, k) = amplitude_m * std::sin(2.0 * std::numbers::pi * in.dt_s * static_cast<double>(k) / period_s);
  }
  in.ramp_s = 0.0;  // the sine starts at zero offset; its velocity jump is what the ramp test covers
  return in;
}

TEST(LineDynamics, HullAtRestKeepsTheStaticTension) {
  const ValidatedProject p = load_validated_project(kOc4);
  const std::vector<LineDynamicsSeries> lines = run_line_dynamics(p.project, surge_motion(0.0, 100.0, 120.0));
  ASSERT_EQ(lines.size(), 3u);
  for (const LineDynamicsSeries& l : lines) {
    for (double t : l.tension_N) EXPECT_NEAR(t, l.tension_N.front(), 1e-6 * l.tension_N.front()) << l.line;
  }
}

// Waves on the lines: with the hull held still, a regular wave (3 m, 10 s)
// on the OC4 chains makes their fairlead tension oscillate at the wave
// period (the drag and inertia of the upper chain in the orbital flow).
TEST(LineDynamics, ARegularWaveOnTheLinesMakesTheTensionOscillateAtItsPeriod) {
  const ValidatedProject p = load_validated_project(kOc4);
  LineDynamicsInput in = surge_motion(0.0, 100.0, 200.0);
  in.ramp_s = 20.0;
  engine::RegularWaveInput wave;
  wave.amplitude_m = 3.0;
  wave.omega_rad_per_s = 2.0 * std::numbers::pi / 10.0;
  wave.water_depth_m = p.project.site.depth_m;
  in.sea = std::make_shared<const engine::WaveRealization>(engine::make_regular_wave(wave));
  const std::vector<LineDynamicsSeries> lines = run_line_dynamics(p.project, in);
  const LineDynamicsSeries& l1 = lines.front();                              // L1 lies along the wave direction (+x)
  std::vector<double> late(l1.tension_N.begin() + 200, l1.tension_N.end());  // after 100 s
  const double period = engine::zero_upcrossing_period_s(late, in.dt_s);
  EXPECT_NEAR(period, 10.0, 0.2);
  const auto [lo, hi] = std::minmax_element(late.begin(), late.end());
  EXPECT_GT(*hi - *lo,
            3e-4 * *hi);  // measured 1.7 kN of 1.1 MN (1.5e-3; 1.3 kN without Wheeler stretching); still water: < 1e-6
  std::cout << "regular wave on the lines: L1 tension range " << (*hi - *lo) / 1e3 << " kN, period " << period
            << " s\n";
}

// Risers run with the lines: at rest each keeps its static top tension (the
// equilibrium's, from the same FE model) — the deep-water scenario's 12 SCRs.
TEST(LineDynamics, RisersAtRestKeepTheirStaticTopTension) {
  const ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  LineDynamicsInput in = surge_motion(0.0, 100.0, 10.0);
  const std::vector<LineDynamicsSeries> series = run_line_dynamics(p.project, in);
  ASSERT_EQ(series.size(), p.project.mooring.lines.size() + p.project.risers.size());
  for (std::size_t i = p.project.mooring.lines.size(); i < series.size(); ++i) {
    const LineDynamicsSeries& r = series[i];
    EXPECT_EQ(r.line, p.project.risers[i - p.project.mooring.lines.size()].name);
    EXPECT_GT(r.tension_N.front(), 1e6) << r.line;  // an SCR in 1800 m: MN
    for (double t : r.tension_N) EXPECT_NEAR(t, r.tension_N.front(), 1e-6 * t) << r.line;
  }
}

// A surge of 5 m over 200 s moves the fairleads at ≤ 0.16 m/s: drag and
// inertia are < 0.5 % of the tension, so after the build-up the dynamic
// tension follows the quasi-static catenary at the same fairlead position
// (still water: no current on either).
TEST(LineDynamics, SlowSurgeFollowsTheQuasiStaticCatenary) {
  const ValidatedProject p = load_validated_project(kOc4);
  LineDynamicsInput in = surge_motion(5.0, 200.0, 400.0);
  in.ramp_s = 50.0;
  const std::vector<LineDynamicsSeries> lines = run_line_dynamics(p.project, in);
  LineArrayModel catenaries = build_mooring_model(p.project);
  double worst = 0.0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    ASSERT_EQ(lines[l].line, catenaries.lines[l]->name());
    for (Eigen::Index k = 0; k < in.motion.cols(); ++k) {
      const double t = in.dt_s * static_cast<double>(k);
      if (t < 100.0) continue;
      const engine::HullPose pose = engine::pose_from_offset(p.project.hull.reference_point_g, in.motion.col(k));
      const double quasi_static =
          catenaries.lines[l]
              ->solve(pose.reference_point_g + pose.rotation * catenaries.lines[l]->attachment_b())
              .top_tension_N;
      worst = std::max(worst, std::abs(lines[l].tension_N[static_cast<std::size_t>(k)] / quasi_static - 1.0));
    }
    EXPECT_GT(lines[l].solver.steps, 0);
  }
  // Drag/inertia (< 0.5 %), the FE mesh vs the exact catenary (10 m
  // elements: ~1e-5) and the integrator (~0.25 %).
  EXPECT_LT(worst, 0.01);
}

// An integrator that gives up (here: a work limit of 3 steps per sample)
// stops the line with its name, the time reached and the cause.
TEST(LineDynamics, AFailingLineIsNamedWithTheTimeReached) {
  const ValidatedProject p = load_validated_project(kOc4);
  LineDynamicsInput in = surge_motion(1.0, 20.0, 40.0);
  in.max_steps_between_samples = 3;
  try {
    run_line_dynamics(p.project, in);
    FAIL() << "the work limit must stop the integration";
  } catch (const engine::SolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("line L1: FE dynamics failed"), std::string::npos) << what;
    EXPECT_NE(what.find("IDA failed at t = "), std::string::npos) << what;
    EXPECT_NE(what.find("IDA_TOO_MUCH_WORK"), std::string::npos) << what;
  }
}

TEST(LineDynamics, NonFiniteMotionIsRejected) {
  const ValidatedProject p = load_validated_project(kOc4);
  LineDynamicsInput in = surge_motion(1.0, 20.0, 40.0);
  in.motion(0, 40) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(run_line_dynamics(p.project, in), std::invalid_argument);
}

// The default scenario's L2 in lc3 (L10 removed, the hull 41 m towards L2's
// side): the taut polyester line's touchdown sits at its anchor and the FE
// Newton from the default inextensible-catenary start fails; from the case's
// elastic catenary it converges. Without current it gives the catenary's
// fairlead tension; the survival current on the slack line lowers it by
// 18 % (printed), the current-on-lines effect the S-C statics lacks (issue 17).
TEST(DynamicMooringLine, StartsAgainFromTheElasticCatenaryWhenTheDefaultStartFails) {
  ValidatedProject vp = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  // Without the scenario's mean wave drift: the pose where the default start
  // fails (with the drift the hull sits 2.5 m further and it converges).
  vp.project.hull.mean_drift.reset();
  const Project& p = vp.project;
  StaticCaseRequest request;
  request.load_case = "lc3-survival-45deg-damaged-L10";
  const StaticCaseResult statics = run_static_case(vp, request);
  const auto line =
      std::find_if(p.mooring.lines.begin(), p.mooring.lines.end(), [](const MooringLine& l) { return l.name == "L2"; });
  const auto row =
      std::find_if(statics.lines.begin(), statics.lines.end(), [](const LineStaticsRow& r) { return r.name == "L2"; });
  ASSERT_NE(row, statics.lines.end());
  const engine::HullPose pose = engine::pose_from_offset(p.hull.reference_point_g, statics.offset);
  const Eigen::Vector3d fairlead_g = pose.reference_point_g + pose.rotation * line->fairlead_b;
  const auto environment = std::find_if(p.environments.begin(), p.environments.end(),
                                        [&](const Environment& e) { return e.name == statics.environment; });
  const auto current = current_profile_of(*environment);
  EXPECT_THROW(dynamic_mooring_line(p, *line, vp.line_types, current, fairlead_g), engine::SolverError);
  const DynamicLineSetup loaded = dynamic_mooring_line(p, *line, vp.line_types, current, fairlead_g, &row->profile);
  std::cout << "L2 fairlead tension: catenary " << row->fairlead_tension_N << " N, FE with current "
            << loaded.statics.node_tension_N.back() << " N\n";
  // Without the current the two models of the same line between the same
  // ends agree (FE: 1e-10 force tolerance; the difference is the mesh).
  const DynamicLineSetup still = dynamic_mooring_line(p, *line, vp.line_types, std::nullopt, fairlead_g, &row->profile);
  EXPECT_NEAR(still.statics.node_tension_N.back(), row->fairlead_tension_N, 0.01 * row->fairlead_tension_N);
}

// The same line under the S-C levels' prescribed motion (`analyze --level
// sc-enhanced --line-dynamics` of lc3 failed on it): at the S-C static case's
// equilibrium (current on the lines) its FE statics fail from the default
// start, and the line starts again from the static case's profile as the
// coupled level's lines do. The hull held there keeps the static case's
// tension (the same FE line and current: measured 1e-6; tolerance 1e-3).
TEST(LineDynamics, ALineThatFailsFromTheDefaultStartStartsFromTheStaticCase) {
  ValidatedProject vp = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  StaticCaseRequest request;
  request.load_case = "lc3-survival-45deg-damaged-L10";
  request.lines_carry_current = true;
  const StaticCaseResult statics = run_static_case(vp, request);
  const auto environment = std::find_if(vp.project.environments.begin(), vp.project.environments.end(),
                                        [&](const Environment& e) { return e.name == statics.environment; });
  LineDynamicsInput in = surge_motion(0.0, 100.0, 2.0);
  for (Eigen::Index k = 0; k < in.motion.cols(); ++k) in.motion.col(k) = statics.offset;
  in.static_offset = statics.offset;
  in.damaged_line = "L10";
  in.current = current_profile_of(*environment);
  in.include_risers = false;
  in.only = {"L2"};
  EXPECT_THROW(run_line_dynamics(vp.project, in), engine::SolverError);

  in.static_lines = &statics.lines;
  const std::vector<LineDynamicsSeries> out = run_line_dynamics(vp.project, in);
  ASSERT_EQ(out.size(), 1u);
  const auto row =
      std::find_if(statics.lines.begin(), statics.lines.end(), [](const LineStaticsRow& r) { return r.name == "L2"; });
  EXPECT_NEAR(out[0].tension_N.back(), row->fairlead_tension_N, 1e-3 * row->fairlead_tension_N);
}

}  // namespace
}  // namespace spiral::design

namespace spiral::design {
namespace {

// The global-analysis mesh (Project::global_analysis): every section of a
// riser in equal elements of at most the given length, its touchdown
// refinement dropped; its own mesh where asked for or where the project
// sets none.
TEST(LineMesh, TheGlobalAnalysisMeshRemeshesEverySectionWithoutRefinement) {
  ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml");
  p.project.global_analysis.element_length_m.reset();
  const RiserDesign design = riser_design(p.project, p.project.risers.front());
  ASSERT_TRUE(design.fe_model.refinement.has_value());  // the 1 m touchdown zone
  const std::size_t own_nodes = engine::fe_line_mesh(design.fe_model).size();
  EXPECT_EQ(with_line_mesh(p.project, LineMesh::global_analysis, design.fe_model), design.fe_model);

  p.project.global_analysis.element_length_m = 40.0;
  EXPECT_EQ(with_line_mesh(p.project, LineMesh::own, design.fe_model), design.fe_model);
  const engine::FeLineModel global = with_line_mesh(p.project, LineMesh::global_analysis, design.fe_model);
  EXPECT_FALSE(global.refinement.has_value());
  const std::vector<double> nodes = engine::fe_line_mesh(global);
  double length_m = 0.0;
  for (const engine::FeLineSection& section : global.sections) length_m += section.length_m;
  EXPECT_EQ(nodes.size(), static_cast<std::size_t>(std::ceil(length_m / 40.0)) + 1);  // one section: 2,490 m
  for (std::size_t i = 1; i < nodes.size(); ++i) EXPECT_LE(nodes[i] - nodes[i - 1], 40.0 + 1e-9);
  EXPECT_GT(own_nodes, 10 * nodes.size());
}

}  // namespace
}  // namespace spiral::design
