#pragma once
// Dynamic mooring-line tensions from a prescribed hull motion (DESIGN.md §1:
// the second half of the uncoupled analysis, and the dynamic tensions of the
// S-C levels): every intact mooring line and every riser as a dynamic FE
// line (engine/lines/fe_line_dynamics.hpp), started from its FE static
// solution at the hull's static equilibrium with the case's current on it,
// its fairlead or hang-off moved along the hull motion (low + wave
// frequency), anchor or riser foot fixed. Risers are their FE statics model
// (riser_model.hpp: bending, seabed) with the sections' added mass and
// displaced area.
//
// The fairlead trajectory is the natural cubic spline through the fairlead
// positions at the motion's output times (C² for the implicit integrator),
// blended in from the static position by a quintic build-up ramp over
// `ramp_s` (the motion at t = 0 already carries a wave-frequency offset, and
// a line cannot start moving with a jump). Values inside the ramp are a
// build-up transient.
//
// Per line: Morison drag and added mass on the velocity relative to the
// current and the waves (input.sea: linear kinematics at a point per element
// that follows its midpoint to 0.5 m — fixed_point_wave_kinematics.hpp says
// why and what it costs),
// polyester with its dynamic EA at the section's mean static tension
// (design/project/line_properties.hpp), seabed penalty from site.seabed with contact
// damping c = c_bot · d (c_bot = 1e5 Pa·s/m; MoorDyn-C 2.7's default is 3e5,
// immaterial on the OC4 chain: tests/data/validation/moordyn-oc4-surge) and Coulomb
// friction (site.seabed.friction_axial / friction_lateral, regularised below
// 0.01 m/s). Lines run in parallel on all cores.
//
// Errors: a line whose dynamics fail throws engine::SolverError naming the
// line or riser, the time reached and the cause.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "design/project/line_properties.hpp"
#include "design/project/project.hpp"
#include "design/analysis/statics_study.hpp"
#include "design/criteria/riser_checks.hpp"
#include "design/model/riser_model.hpp"
#include "engine/numerics/sundials_ida.hpp"
#include "engine/common/eigen_types.hpp"
#include "engine/environment/current_profile.hpp"
#include "engine/lines/fe_line_dynamics.hpp"

namespace spiral::design {

/// The S-C levels' prescribed-motion FE lines' integrator tolerances (the
/// relative one and the lines' absolute ones) when their ends follow
/// wave-frequency hull motion, as a fraction of the single-line defaults
/// (FeDynamicsOptions), which were chosen on a chain under slow and 10-s
/// motion. Measured (the enhanced S-C motion of the operating case lc5,
/// 1800 s, against ×0.1): at the defaults the top-tension std of the 12
/// risers +22 to +33 %, the mooring lines' +13 to +15 %, and in the first
/// seconds a start-up burst of E1's top tension to 3.78 MN (+25 % over the
/// converged maximum) — IDA's steps, long while the build-up ramp barely moves
/// the ends, grow past what the wave-frequency motion then needs and ring
/// the risers' lightly damped axial modes; ×0.1 takes 2.1× the steps (1.9×
/// the time; docs/decisions/enhanced-sc-accuracy.md). Without WF motion the
/// defaults are within 0.5 %. The coupled level uses this scale too: at the
/// single-line tolerances its risers' std is +10 to +12 % on lc5 and +2 to
/// +3 % on lc1 against 0.03 of the tolerances, with it within 1.2 % and
/// 0.6 % (200 s, std after 60 s, a full setup every 8 steps; 2026-12-07,
/// after the coupled Newton solve's end-B fix, 8f7a11a). The prescribed lines'
/// error is not the Newton iteration's: with a setup at every step and the single-line
/// tolerances, lc5's risers (100 s, std after 30 s) are still +47 to +88 %
/// against 0.03 of them (0.1: +0.6 to +1.3 %); each line alone takes its own,
/// longer steps, where in the coupled system the most demanding line sets
/// the step for all.
inline constexpr double kWaveFrequencyLineToleranceScale = 0.1;

/// Which mesh a dynamic FE line gets: its own `fe` mesh (the local
/// analysis: `spiral lines --motion`'s riser criteria along the line), or the
/// project's global-analysis mesh where it sets one (`global_analysis`: the
/// coupled level and `--line-dynamics`, whose outputs are the top tensions).
enum class LineMesh { own, global_analysis };

struct LineDynamicsInput {
  std::string damaged_line;                                   ///< excluded mooring line ("" intact)
  std::optional<engine::CurrentProfile> current;              ///< on the lines
  engine::Vector6d static_offset = engine::Vector6d::Zero();  ///< hull equilibrium the lines start from
  double t0_s = 0.0;
  double dt_s = 0.5;  ///< spacing of the outputs (and of `motion` when evenly sampled), > 0
  Eigen::Matrix<double, 6, Eigen::Dynamic> motion;  ///< hull offset (m, rad) at t0 + k dt, or at motion_times_s
  /// Optional: the times of `motion`'s columns (a history at its own,
  /// possibly uneven, times: strictly increasing, t0_s among or after the
  /// first). The outputs are then at t0 + k dt up to the last time.
  std::vector<double> motion_times_s;
  double ramp_s = 20.0;                     ///< build-up ramp, >= 0
  long max_steps_between_samples = 500000;  ///< integrator work limit per sample
  bool include_risers = true;               ///< risers too (FE with bending, hang-off moving with the hull)
  /// Only these mooring lines and risers, by name (empty: every intact line
  /// and, with include_risers, every riser). A name that is neither, or the
  /// damaged line, is std::invalid_argument (callers check user input first).
  std::vector<std::string> only;
  /// Multiplies every integrator tolerance (FeDynamicsOptions): < 1 for a
  /// reference run, > 0.
  double tolerance_scale = 1.0;
  /// The lines' mesh: their own, or the project's global-analysis one.
  LineMesh mesh = LineMesh::own;
  /// Called at every output sample with the line's index in the result (the
  /// mooring lines, then the risers), the sample's index and the line's state
  /// (one line's calls come from one thread, in order; lines run in parallel).
  std::function<void(std::size_t line, std::size_t sample, const engine::FeLineDynamicSnapshot& state)> on_sample;
  /// Waves on the lines (linear kinematics at each element's static
  /// midpoint, engine/environment/fixed_point_wave_kinematics.hpp); null: none.
  std::shared_ptr<const engine::WaveRealization> sea;
  /// The project's resolved line types (a case model's); null: resolved here.
  std::shared_ptr<const std::vector<LineTypeProperties>> line_types;
  /// The static case's mooring lines at static_offset (null: none): a
  /// line whose FE statics fail from the default initial shape starts again
  /// from its profile there, as the coupled level's lines do.
  const std::vector<LineStaticsRow>* static_lines = nullptr;
};

struct LineDynamicsSeries {
  std::string line;               ///< mooring line or riser name
  std::vector<double> tension_N;  ///< top (fairlead, hang-off) tension at the motion's sample times
  long elements = 0;              ///< the line's FE elements
  engine::IdaStatistics solver;
  double wall_s = 0.0;
};

/// A line ready for the dynamics: its FE model (polyester sections at their
/// dynamic EA), dynamic environment (seabed damping and friction as above)
/// and static solution with its top end at `top_g`.
struct DynamicLineSetup {
  engine::FeLineModel model;
  engine::FeDynamicEnvironment environment;
  engine::FeStaticsResult statics;
};

/// Throws engine::SolverError naming the line when its statics fail.
/// `known_shape` (optional): the line's profile from anchor to fairlead at
/// these ends by another model (the case's elastic catenary): when the FE
/// Newton from its default initial shape fails, it starts again from this one.
DynamicLineSetup dynamic_mooring_line(const Project& project, const MooringLine& line,
                                      const std::vector<LineTypeProperties>& types,
                                      const std::optional<engine::CurrentProfile>& current,
                                      const Eigen::Vector3d& top_g,
                                      const std::vector<engine::LineProfilePoint>* known_shape = nullptr,
                                      LineMesh mesh = LineMesh::own);
/// A riser (FE with bending, from its foot to the hang-off at `top_g`).
/// `equilibrium` (optional): its FE node profile solved at these ends in this
/// current before (a static case's RiserStaticsRow::profile): Newton starts
/// from it (engine::FeStaticsOptions::initial_shape_is_equilibrium) instead
/// of swinging a cold shape into the current.
DynamicLineSetup dynamic_riser(const Project& project, const RiserDesign& design,
                               const std::optional<engine::CurrentProfile>& current, const Eigen::Vector3d& top_g,
                               const std::vector<RiserProfilePoint>* equilibrium = nullptr,
                               LineMesh mesh = LineMesh::own);

/// The element length of the global-analysis mesh where `mesh` asks for it
/// and the project sets one (global_analysis.element_length); otherwise
/// none: each line keeps its own mesh.
std::optional<double> global_element_length_m(const Project& project, LineMesh mesh);

/// The line's FE model on the project's global-analysis mesh where `mesh`
/// asks for it and the project sets one: every section in equal elements of
/// at most global_analysis.element_length, no touchdown refinement.
engine::FeLineModel with_line_mesh(const Project& project, LineMesh mesh, engine::FeLineModel model);

/// The FE elements of a line's model.
long fe_elements(const engine::FeLineModel& model);
/// The elements of every line of `series`.
long dynamic_line_elements(const std::vector<LineDynamicsSeries>& series);

/// How the coupled level's or --line-dynamics' lines are meshed, for the
/// analyses' notes ("" on each line's own mesh).
std::string line_mesh_note(const Project& project, LineMesh mesh, long elements);

/// How the dynamic FE lines carry a sea, for the analyses' notes: linear
/// kinematics at each element's midpoint, summed on a time grid and
/// interpolated (engine/environment/fixed_point_wave_kinematics.hpp).
std::string line_wave_kinematics_note(const engine::WaveRealization& sea);

/// The output times of `input` (t0 + k dt over the motion).
std::vector<double> line_dynamics_output_times(const LineDynamicsInput& input);

/// Every intact mooring line, then (include_risers) every riser; with
/// `input.only`, those of them.
std::vector<LineDynamicsSeries> run_line_dynamics(const Project& project, const LineDynamicsInput& input);

}  // namespace spiral::design
