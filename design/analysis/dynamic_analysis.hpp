#pragma once
// Time-domain hull analyses of one load case at the two cheap levels of
// DESIGN.md §1: uncoupled and semi-coupled (S-C, plain and enhanced).
//
//   uncoupled     the mooring lines as nonlinear quasi-static catenaries
//                 (build_mooring_model: no current on the lines, no line
//                 damping or inertia), solved at the instantaneous fairlead
//                 positions inside the hull equations; risers (if any) as
//                 their linearization at the static equilibrium of the case
//                 (the quick static case: each mooring line in its own
//                 model, so a catenary carries no current).
//   sc            Corrêa & Jacob's semi-coupled scheme: the coupled static
//                 equilibrium of hull and lines with the current profile on
//                 every mooring line and riser (run_static_case with
//                 lines_carry_current: FE statics with current drag, whatever
//                 the line's `model`; the quick statics keep the model), the
//                 line array reduced there to F0 and the 6x6 tangent K, the
//                 hull integrated from that position with
//                 F_lines = F0 − K (q − q0).
//   sc-enhanced   sc plus the lines' damping and added mass at the fairleads
//                 (line_hydrodynamics.hpp; after Cruces Girón, Corrêa, Jacob
//                 et al., Marine Structures 39, 2014, and Webster 1995).
//
// Hull (hull_dynamics.hpp): M + A(w_LF) (hull.hydrodynamics), or with
// `radiation: memory` M + A(inf) and Cummins' memory force with the kernel
// from the .1 data (engine/hull/radiation_memory.hpp), B_lin and
// quadratic damping from the project, C_hydro and F_hs0 from hull_model.
// External low-frequency force, each term only where the project has the data
// (otherwise a note says what is missing):
//   * slow drift by Newman's approximation (slow_drift.hpp) from the mean
//     drift coefficients, on the seeded wave realization of the environment;
//   * current on the hull by the coefficient table with the relative velocity
//     V_rel = V_c(z = 0) − (x', y') (OCIMF form, quadratic in V_rel);
//   * wind: mean speed at the table's reference height + a seeded gust
//     realization of the environment's spectrum (NPD or API; none = steady),
//     with the relative velocity U(t) e_w − (x', y').
// The slow drift and the gust depend on time only: they are tabulated once at
// 0.1 s and read by Catmull-Rom interpolation (engine/analysis/forcing_table.hpp;
// accuracy and cost against the direct sums: docs/decisions/forcing-table.md).
// The integrator runs at rtol 1e-7, atol 1e-6 m / 1e-8 rad (forced runs; free
// decays keep the 1e-10 defaults).
// Wave-frequency motions are superposed on the low-frequency ones (total = LF
// + WF) from the .4 RAOs, or RAOs computed from .1 + .3 as
//   xi(w) = [−w² (M + A(w)) + i w (B(w) + B_lin) + C_hydro + K_lines]^-1 X(w)
// (WAMIT e^{iwt} convention); without .3/.4 there are none (a note says so).
// Morison hull (hull.hydrodynamics.model: morison, engine/hull/morison_hull.hpp):
// M + the members' strip added mass; the member loads (wave inertia and
// pressure, drag on the relative velocity current + waves − hull) join the
// external force, so the one integration carries LF and WF motions together
// (the strips sit at the static equilibrium); the two are split by a
// zero-phase low-pass at half the lowest wave frequency of the realization;
// the members replace hull.current_coefficients in the dynamics.
// Fairlead tensions: quasi-static catenary of every intact mooring line at the
// instantaneous (total) fairlead position, at every output step.
//
// Errors: InputError (unknown case or level, headings outside a database),
// engine::FileFormatError (hydrodynamic files), engine::SolverError
// (equilibrium, line or integrator failure).
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "design/analysis/line_dynamics.hpp"
#include "design/analysis/static_case.hpp"
#include "design/project/validated_project.hpp"
#include "engine/analysis/hull_dynamics.hpp"
#include "engine/analysis/low_frequency_damping.hpp"
#include "engine/hull/radiation_memory.hpp"
#include "engine/hull/wamit_1.hpp"
#include "engine/hull/wamit_3.hpp"
#include "engine/environment/wave_realization.hpp"

namespace spiral::design {

/// coupled: hull and every dynamic FE line integrated together (coupled_analysis.hpp).
enum class AnalysisLevel { uncoupled, semi_coupled, semi_coupled_enhanced, coupled };

/// "uncoupled", "sc", "sc-enhanced", "coupled" (the CLI names).
const char* to_string(AnalysisLevel level);
/// Parses the CLI name; throws InputError (path `--level`) for anything else.
AnalysisLevel parse_analysis_level(const std::string& name, const Project& project);

/// How the enhanced S-C reduces the lines' damping and inertia to the hull:
/// the quasi-static shape derivative (line_hydrodynamics.hpp), or the lines'
/// dynamic FE models' impedance, fitted with relaxations
/// (line_dynamic_reduction.hpp; mooring lines and risers). The dynamic one
/// is the default: it brings the offset std within 5 % of the coupled level
/// on every case of the default FPS and on OC4, where the quasi-static one
/// is 6–9 % low in four of the six (docs/decisions/enhanced-sc-accuracy.md).
enum class LineReduction { quasi_static, dynamic };

struct DynamicAnalysisRequest {
  std::string load_case;
  AnalysisLevel level = AnalysisLevel::semi_coupled;
  double duration_s = 10800.0;  ///< > 0
  double output_step_s = 0.5;   ///< > 0, <= duration
  std::uint64_t seed = 1;       ///< waves use `seed`, the wind gust `seed` + 1000003
  bool compute_tensions = true;
  /// Also the dynamic tensions: every mooring line as a dynamic FE line with
  /// the hull motion prescribed at its fairlead (design/analysis/line_dynamics.hpp).
  bool line_dynamics = false;
  double line_dynamics_ramp_s = 20.0;  ///< build-up ramp of the prescribed motion, >= 0
  /// Coupled level: the integrator's work limit per output step (IDA
  /// gives up beyond it: a step-size collapse stops the case, not the machine).
  long coupled_max_steps_between_outputs = 500000;
  /// The dynamic FE lines' integrator tolerances (the coupled system's, the
  /// hull's in it included, and `line_dynamics`') × this: < 1 for a
  /// convergence reference (the accuracy–time curve of
  /// docs/decisions/coupled-dynamics-performance.md), > 0.
  double tolerance_scale = 1.0;
  /// The coupled level's and `line_dynamics`' FE lines on each line's own
  /// `fe` mesh instead of the project's global_analysis one (a check of that
  /// mesh; no effect when the project sets none).
  bool detailed_line_mesh = false;
  /// A free decay, as in a model basin: the hull is pulled from the level's
  /// static equilibrium by the constant force (C + K) d — C the
  /// hydrostatic stiffness, K the lines' S-C stiffness there, so d is where
  /// the S-C hull comes to rest — built up by the smooth ramp over the first
  /// half of `release_s`, held, and released at `release_s`. The
  /// environment is the load case's (a decay test runs a case with current
  /// only, or with nothing). Every level starts from its equilibrium with
  /// its lines in their static state, so the pull goes through the same
  /// line models as the decay (the polyester's dynamic EA acts about the
  /// mean strain, seabed friction where the lines have it).
  struct FreeDecay {
    engine::Vector6d displacement = engine::Vector6d::Zero();  ///< m (surge, sway, heave), rad (roll, pitch, yaw)
    double release_s = 300.0;                                  ///< > 0, < duration
  };
  std::optional<FreeDecay> decay;
  LineReduction line_reduction = LineReduction::dynamic;  ///< sc-enhanced only
  /// The static case of this load case when the caller has it already
  /// (a stage runs every case's statics first); null: solved here. It must be
  /// run_static_case of `load_case` with its own damaged line. The S-C levels
  /// solve their own (lines_carry_current) unless this one has the current on
  /// every line; the uncoupled level takes it unless it has lines_carry_current.
  const StaticCaseResult* statics = nullptr;
  /// FE line solutions at the rest position shared with other analyses of the
  /// same model (a stage's storms): the S-C static case solved here takes and
  /// adds to them. May be null.
  RestSolutionCache* rest_solutions = nullptr;
  /// Called with the fraction done (0..1) during the dynamics; may be empty.
  std::function<void(double)> progress;
};

/// Wall-clock seconds of each phase of one analysis (DESIGN.md §1: every
/// level reports its cost beside its results), JSON `timing_s`.
struct AnalysisTimings {
  double equilibrium_s = 0.0;     ///< static case (equilibrium); 0 when a stage's static case is reused
  double reduction_s = 0.0;       ///< K reduction (+ line hydrodynamics for sc-enhanced; the FE statics, coupled)
  double forcing_s = 0.0;         ///< wave/wind realizations and the tabulated forcing
  double dynamics_s = 0.0;        ///< the time integration
  double wave_frequency_s = 0.0;  ///< wave-frequency motions
  double tensions_s = 0.0;        ///< fairlead tensions from the motions
  double line_dynamics_s = 0.0;   ///< prescribed-motion FE lines (--line-dynamics, non-coupled levels)

  /// The level's own cost: every phase but the prescribed-motion FE lines.
  double level_s() const {
    return equilibrium_s + reduction_s + forcing_s + dynamics_s + wave_frequency_s + tensions_s;
  }
  double total_s() const { return level_s() + line_dynamics_s; }
};

/// The low-frequency model of a case as the hull integrator takes it, with
/// what it was built from (for tests: free decay, mean offset).
struct DynamicModel {
  /// The case's hull, line types and environment, built once for the run and
  /// shared by its static case, its dynamics and its dynamic lines.
  CaseModel case_model;
  /// Wave-frequency motion RAOs at the static equilibrium (.4, or .1 + .3
  /// with the case's line stiffness); empty without waves or those files.
  std::shared_ptr<const engine::MotionRaoTable> wave_raos;
  engine::HullDynamicsModel hull;
  engine::HullLoads loads;
  engine::Vector6d initial_offset = engine::Vector6d::Zero();  ///< static equilibrium q0
  StaticCaseResult statics;                                    ///< the S-C static case
  std::optional<engine::Matrix6d> line_added_mass;             ///< sc-enhanced
  std::optional<engine::Matrix6d> line_damping;                ///< sc-enhanced
  std::vector<engine::LineRelaxation> line_relaxations;        ///< sc-enhanced, dynamic reduction
  /// sc-enhanced: the reduction applied (quasi-static where the dynamic
  /// one was asked but its fit could not stand for the lines: notes say why).
  std::optional<LineReduction> line_reduction;
  /// hull.hydrodynamics.radiation: memory — A(inf), the kernel and their diagnostics.
  std::optional<engine::RadiationMemory> radiation_memory;
  /// Morison hull in waves: the LF/WF split frequency of the integrated
  /// motion, rad/s (0: the WF motions come from RAOs, or there are none).
  double wave_split_frequency_rad_per_s = 0.0;
  engine::Vector6d mean_slow_drift_force = engine::Vector6d::Zero();  ///< sum a_k² D_k, global
  /// The slow-drift force alone, F_sd(t) (global), empty without waves or drift data.
  std::function<engine::Vector6d(double)> slow_drift;
  /// The case's seeded wave realization (empty without waves): the slow
  /// drift, the Morison hull and the dynamic lines all see this one sea.
  std::shared_ptr<const engine::WaveRealization> sea;
  /// sc-enhanced: the wave-frequency motions at the output times (a
  /// function of time alone), computed for the lines' drag linearization and
  /// taken again for the result; empty without them.
  std::optional<Eigen::Matrix<double, 6, Eigen::Dynamic>> wave_frequency_at_outputs;
  std::vector<std::string> notes;
  AnalysisTimings timing;  ///< equilibrium, reduction and forcing: what building the model cost
};

/// Builds the model of `request` (no integration). `fairlead_velocity_std`
/// (m/s, per line and global axis), when given, sets the velocity amplitude of
/// the enhanced S-C drag linearization; else a first sc pass supplies it.
DynamicModel build_dynamic_model(const ValidatedProject& project, const DynamicAnalysisRequest& request);

struct TensionSeries {
  std::string line;
  std::vector<double> tension_N;
  std::vector<Eigen::Vector3d> fairlead_g_m;  ///< fairlead position (global) at the total motion
};

struct DynamicAnalysisResult {
  std::string case_name;
  std::string environment;
  AnalysisLevel level = AnalysisLevel::semi_coupled;
  std::uint64_t seed = 1;
  double tolerance_scale = 1.0;  ///< the request's
  /// The global-analysis element length the dynamic FE lines (coupled level,
  /// line_dynamics) ran on, m; absent: each line's own mesh.
  std::optional<double> line_element_length_m;
  std::optional<DynamicAnalysisRequest::FreeDecay> decay;  ///< the request's
  Eigen::VectorXd times_s;
  Eigen::Matrix<double, 6, Eigen::Dynamic> low_frequency;   ///< m, rad
  Eigen::Matrix<double, 6, Eigen::Dynamic> wave_frequency;  ///< m, rad (zero without RAOs)
  Eigen::Matrix<double, 6, Eigen::Dynamic> total;           ///< LF + WF
  bool wave_frequency_computed = false;
  std::vector<TensionSeries> tensions;  ///< quasi-static
  /// With request.line_dynamics (mooring lines), or from the coupled run
  /// (mooring lines, then risers: their top tension).
  std::vector<LineDynamicsSeries> dynamic_tensions;
  engine::Vector6d static_offset = engine::Vector6d::Zero();
  engine::Vector6d mean_slow_drift_force = engine::Vector6d::Zero();
  std::optional<engine::Matrix6d> line_added_mass;
  std::optional<engine::Matrix6d> line_damping;
  std::vector<engine::LineRelaxation> line_relaxations;  ///< sc-enhanced, dynamic reduction
  std::optional<LineReduction> line_reduction;           ///< sc-enhanced: the one applied (DynamicModel's)
  engine::CvodeStatistics solver;                        ///< hull integrator (not the coupled level)
  /// Surge, sway and yaw as equivalent linear oscillators over the run (not
  /// the coupled level; engine/analysis/low_frequency_damping.hpp).
  std::vector<engine::DofDamping> low_frequency_damping;
  /// Coupled level: the one IDA integration of hull + lines, and its size.
  std::optional<engine::IdaStatistics> coupled_solver;
  long coupled_state_size = 0;
  int coupled_lines = 0;
  /// Coupled level: element-matrix evaluations, and those its full setups kept.
  long coupled_element_matrix_evaluations = 0;
  long coupled_element_matrices_kept = 0;
  std::vector<std::string> notes;
  AnalysisTimings timing;
};

/// Wave-frequency hull motions (global, m, rad) of the model's case at
/// `times_s` on its sea, from its RAOs; empty without them or without waves.
std::optional<Eigen::Matrix<double, 6, Eigen::Dynamic>> wave_frequency_motions(const ValidatedProject& project,
                                                                               const DynamicModel& model,
                                                                               const Eigen::VectorXd& times_s);

/// A result that carries the model's case data, notes and set-up timings
/// (no series yet) at `request.level`.
DynamicAnalysisResult result_of_model(const DynamicModel& model, const DynamicAnalysisRequest& request,
                                      const std::string& case_name, const std::string& environment_name);

/// Quasi-static fairlead tension of every intact mooring line (catenary) at
/// each column of `total` (hull offsets, m, rad).
std::vector<TensionSeries> quasi_static_fairlead_tensions(const Project& project,
                                                          const std::vector<LineTypeProperties>& types,
                                                          const std::string& damaged_line,
                                                          const Eigen::Matrix<double, 6, Eigen::Dynamic>& total);

/// The seeded sea of `waves` over `duration_s` from t = 0 (200 components per
/// direction, 11 directions when spread): every level and the dynamic lines
/// of one case, seed and duration see this one sea.
engine::WaveRealization realize_sea(const Project& project, const Waves& waves, double duration_s, std::uint64_t seed);

/// Any level; coupled goes to run_coupled_analysis (coupled_analysis.hpp).
DynamicAnalysisResult run_dynamic_analysis(const ValidatedProject& project, const DynamicAnalysisRequest& request);

}  // namespace spiral::design
