#pragma once
// Riser safe operational zones (SOZ, DESIGN.md §7) and the offset check.
//
// The SOZ of a riser is the set of horizontal offsets d of the hull reference
// point (global frame, from its rest position) for which the riser meets all
// of its criteria (riser_statics_row: von Mises with the design factor of the
// condition, min effective tension, max top tension, top angle, flex-joint
// rotation, min bending radius; plus the TDP excursion here). It is stored as
// a polar polygon: the allowable offset in each direction of a grid (default
// 5°), measured counter-clockwise from +x like every direction of the format.
// A hull offset towards the riser's azimuth is its "near" position (hang-off
// towards the touchdown point), away from it "far", at ±90° "cross".
//
// Per direction the riser's FE statics (riser_static_line's model) is solved
// with the hang-off displaced by the offset (plus the mean heave and
// rotations of a load case when one is given):
//  1. march outwards from d = 0 in steps of `march_step_pct_depth` up to
//     `search_limit_pct_depth` until a point fails (each solve warm-started
//     from the nearest converged offset of that direction or an earlier one
//     of its task, and converged to 1e-5 of the force scale — 1e-10 in the
//     refinement; a march point within 2.5e-3 of utilization 1 is solved
//     again to 1e-10, soz.cpp). The march resolves the zone to one step radially; near
//     the centre the directions are closer than that along the arc, so a
//     march point within one step of arc of a passing point of an earlier
//     direction of the task at the same offset is not solved (blocks of 2, 3
//     or 6 directions, the block's first solved; deterministic: tasks are
//     fixed). The bracket's passing end is always solved: skipped points
//     below a failure are solved downwards until one passes;
//  2. refine the bracket [last pass, first fail] to `tolerance_m` with a
//     safeguarded regula falsi (Illinois) on the governing utilization − 1,
//     kept at least 0.4 tolerance inside the bracket so it closes from both
//     sides (worst case: bisection);
//  3. continue the coarse march past the failure up to the search limit: a
//     point that passes again opens a band that is not connected to the zone
//     (the zone is not star-shaped); its edges are refined the same way and
//     reported, but the allowable offset stays the first boundary — the
//     band cannot be reached without crossing a failing offset.
// A direction that passes up to the search limit reports the limit as its
// allowable offset and `limited_by_search`. A riser that fails at zero offset
// has no zone: every direction reports 0 and the result names the criterion.
//
// The platform SOZ is the intersection: per direction the smallest riser
// allowable offset and the riser that sets it. Between grid directions the
// allowable offset is interpolated linearly in angle (the polygon's edges).
//
// Risers related by a rotation about the vertical or a reflection in a
// vertical plane share a zone (soz_symmetry.hpp): with no current and no
// hull roll/pitch/yaw the problem — FE riser, flat isotropic seabed (axial
// friction only), gravity, criteria incl. the flex-joint axis in the
// azimuth plane — is invariant under both, so a riser of the same design,
// criteria and hang-off depth that such a map carries onto another, with
// the direction grid onto itself, has that riser's zone mapped (exact up to
// the search tolerance). A riser that is its own mirror image is searched
// on one half. The default scenario's 12 SCRs: P6–P8 and E2 are P1–P3 and
// E1 turned by 180°, P4, P9 and P5, P10 are P3 and P2 mirrored, P1 and E1
// are searched on one half each — 3 risers' worth of searches instead of 12.
// Any current or hull rotation breaks the symmetry and every riser is
// solved.
//
// Parallel: risers × direction chunks on all cores (std::thread); each task
// owns its FE state; results go to pre-sized slots, so the output does not
// depend on the number of threads. Solver failures inside the march are not
// hidden: the offset counts as failing with criterion "no_static_solution" and
// the solver's message is kept.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "design/criteria/riser_checks.hpp"
#include "design/model/riser_model.hpp"
#include "design/analysis/static_case.hpp"
#include "design/project/validated_project.hpp"
#include "engine/environment/current_profile.hpp"

namespace spiral::design {

/// The dynamic analysis behind the extreme offset check (dynamic_analysis.hpp,
/// level sc-enhanced, tensions off).
struct SozExtremeOptions {
  double duration_s = 10800.0;  ///< > 0; the MPM is always scaled to a 3-h sea state
  std::uint64_t seed = 1;       ///< of the wave and wind realizations
};

/// The riser model the zone is computed with.
/// fe: the reference (riser_static_line: FE with bending, current drag, seabed).
/// catenary: a screening model — the multi-segment elastic catenary (no
/// current, no bending) with the boundary-layer TDP curvature κ = w/H and
/// bending moment EI κ (Pesce et al. 1998); fast, approximate.
enum class SozModel { fe, catenary };

const char* to_string(SozModel model);

struct SozOptions {
  double step_deg = 5.0;     ///< direction step, > 0, must divide 360
  double tolerance_m = 0.1;  ///< bracket width of each allowable offset, > 0
  /// Coarse march step, % of depth, > 0. 2.5 % (45 m in 1800 m): the FE
  /// Newton solve warm-started one step away still converges without a
  /// continuation, twice as far it does not (docs/decisions/soz-search-speed.md).
  double march_step_pct_depth = 2.5;
  double search_limit_pct_depth = 20.0;  ///< largest offset searched, % of depth, > march step
  /// Load case: its current on the risers, the mean heave/rotations of its
  /// static equilibrium and its design condition; the offset check covers that
  /// case only. None: no current, no heave/rotations, `condition` below, and
  /// the offset check covers every load case of the project.
  std::optional<std::string> load_case;
  DesignCondition condition = DesignCondition::normal;  ///< without load_case
  /// Without load_case: check each case against the zone of its own current
  /// and design condition (run_soz computes one per distinct pair, besides
  /// the still-water zone). False: every case against the still-water zone.
  bool zone_per_current = true;
  bool offset_check = true;  ///< run the load cases' static equilibria and check them
  /// With offset_check: the zones of the cases' currents and design
  /// conditions only, without the cases' equilibria and checks (the
  /// pretension optimizer solves the cases itself).
  bool zones_only = false;
  /// Also the extreme offsets: the enhanced S-C time-domain analysis of every
  /// checked load case (soz_check.cpp). None: static (mean) offsets only.
  std::optional<SozExtremeOptions> extreme;
  std::vector<std::string> exclude_risers;  ///< left out of the analysis (e.g. sensitivity)
  SozModel model = SozModel::fe;
  /// Solve each distinct zone once: risers that are turned or mirrored
  /// copies of another, and the mirrored half of a riser symmetric about its
  /// own plane, are copied (soz_symmetry.hpp; exact up to the search
  /// tolerance). Off: every riser and direction is searched (tests).
  bool exploit_symmetry = true;
  int threads = 0;  ///< 0: std::thread::hardware_concurrency()
  /// Called before each block of a riser's directions is searched, with the
  /// fraction of the run's blocks started (0..1; the zones per current count
  /// as equal parts). Called from the worker threads, concurrently: it must
  /// be thread-safe. May throw to stop the run (the blocks not yet started
  /// then stop at once): the exception leaves run_soz. May be empty.
  std::function<void(double)> progress;
};

/// Where the risers hang when the hull is at zero horizontal offset, and what acts on them.
struct SozConditions {
  std::string name = "still-water";  ///< load case name, or still-water
  double heave_m = 0.0;
  Eigen::Vector3d rotation_rad = Eigen::Vector3d::Zero();  ///< roll, pitch, yaw
  std::optional<engine::CurrentProfile> current;
  DesignCondition condition = DesignCondition::normal;
};

/// An allowable band beyond the first boundary (zone not star-shaped).
struct SozBand {
  double from_m = 0.0;
  double to_m = 0.0;  ///< the search limit if it stays open
};

struct SozDirection {
  double direction_deg = 0.0;
  double allowable_offset_m = 0.0;
  /// Criterion that fails just beyond the allowable offset (the largest
  /// utilization there), "no_static_solution", or "search_limit".
  std::string governing_criterion;
  double governing_utilization = 0.0;  ///< at the failing end of the final bracket
  bool limited_by_search = false;
  std::vector<SozBand> reopened_bands;  ///< non-empty: the zone is not star-shaped here
  std::string solver_message;           ///< when a solve failed
  int solves = 0;
};

struct RiserSoz {
  std::string name;
  RiserKind kind = RiserKind::scr;
  double azimuth_deg = 0.0;
  /// At zero offset: the governing criterion and its utilization.
  std::string zero_offset_governing_criterion;
  double zero_offset_utilization = 0.0;
  bool fails_at_zero_offset = false;
  std::vector<SozDirection> directions;  ///< one per grid direction
  /// Allowable offset (m) at the riser's near (towards its azimuth), far and
  /// the two cross directions, interpolated on the polygon.
  double near_m = 0.0, far_m = 0.0, cross_left_m = 0.0, cross_right_m = 0.0;
  std::string near_governing, far_governing;
  bool star_shaped = true;
  int solves = 0;
  /// Set when the zone is another riser's zone turned about the vertical
  /// (compute_soz: identical design and criteria, no current, no hull
  /// rotations, azimuths a whole number of grid steps apart); then solves = 0.
  std::string zone_rotated_from;
  /// Set when the zone is another riser's zone mirrored in a vertical plane
  /// (same conditions as above, the placements mirror images on the grid).
  std::string zone_mirrored_from;
  /// The riser is its own mirror image in the plane of its foot and hang-off
  /// (on the grid): one half of its directions is solved, the other mirrored.
  bool zone_mirror_symmetric = false;
};

struct PlatformSoz {
  std::vector<double> allowable_offset_m;        ///< per grid direction: min over risers
  std::vector<std::string> governing_riser;      ///< the riser that sets it
  std::vector<std::string> governing_criterion;  ///< that riser's criterion there
};

/// What an offset check compares with the zone.
enum class OffsetCheckKind {
  static_mean,  ///< the mean offset of the case's static equilibrium
  extreme,      ///< the 3-h extreme offset of its time-domain storm (OffsetExtreme)
};

const char* to_string(OffsetCheckKind kind);  ///< "static" | "extreme"

/// How the extreme offset of a check was found (kind extreme).
struct OffsetExtreme {
  double duration_s = 0.0;  ///< simulated record
  std::uint64_t seed = 1;
  /// 3-h MPM of the utilization channel r(t) = |d(t)| / allowable(θ(t)) by
  /// the three estimators of engine::most_probable_maximum; the check uses
  /// Weibull (soz_check.cpp says why).
  double ratio_mpm_gumbel = 0.0, ratio_mpm_weibull = 0.0, ratio_mpm_rayleigh = 0.0;
  double record_max_ratio = 0.0;  ///< largest r(t) of the record
  double record_max_ratio_time_s = 0.0;
  double mean_offset_m = 0.0;  ///< mean |d(t)| of the record
  double offset_mpm_m = 0.0;   ///< 3-h MPM (Weibull) of |d(t)| itself, for reference
};

/// One load case's offset (static mean, or extreme) against the platform SOZ.
struct OffsetCheck {
  std::string case_name;
  LineIntegrity integrity = LineIntegrity::intact;
  std::optional<std::string> damaged_line;
  /// static: the mean (static equilibrium) offset. extreme: ratio = 3-h MPM
  /// of r(t) (OffsetExtreme), direction the one of the record's largest r(t),
  /// offset_m = ratio × allowable_m there.
  OffsetCheckKind kind = OffsetCheckKind::static_mean;
  double offset_m = 0.0;  ///< horizontal offset of the reference point
  double direction_deg = 0.0;
  double allowable_m = 0.0;  ///< platform SOZ in that direction (interpolated)
  double margin_m = 0.0;     ///< allowable − offset
  double ratio = 0.0;        ///< offset / allowable (≤ 1 passes; infinite if allowable is 0)
  bool passes = true;
  std::string governing_riser;
  /// The zone it was checked against: the case's own (with its current) or still-water.
  std::string zone;
  std::optional<OffsetExtreme> extreme;  ///< kind extreme only
};

/// A zone the offset check used besides the result's own (run_soz without
/// load_case): the risers under one current and design condition of the
/// load cases, at zero mean heave/rotations.
struct SozZone {
  std::string name;  ///< "<environment>/<condition>": the first environment with that current
  SozConditions conditions;
  std::vector<std::string> cases;  ///< the load cases checked against it
  std::vector<RiserSoz> risers;
  PlatformSoz platform;
  int solves = 0;
  double zone_wall_s = 0.0;
};

struct SozResult {
  std::string project;
  double depth_m = 0.0;
  SozOptions options;
  SozConditions conditions;
  std::vector<double> directions_deg;
  std::vector<RiserSoz> risers;
  PlatformSoz platform;
  std::vector<OffsetCheck> offset_checks;
  std::vector<SozZone> zones;  ///< the zones per current (run_soz), besides this one
  std::vector<std::string> notes;
  int solves = 0;            ///< riser static solves of the zone computation (all zones)
  double zone_wall_s = 0.0;  ///< all zones
  double check_wall_s = 0.0;
  int threads = 1;
};

/// Throws InputError for a step that does not divide 360, bad tolerances,
/// an unknown load case or excluded riser; engine::SolverError when a riser
/// cannot be solved at zero offset.
void validate_soz_options(const Project& project, const SozOptions& options);

/// The zones of `risers` under `conditions` (no offset check, no load case
/// lookup): the core computation, usable on designs built in code.
SozResult compute_soz(const Project& project, const std::vector<RiserDesign>& risers, const SozConditions& conditions,
                      const SozOptions& options);

/// Zones of the project's risers, platform intersection and offset check.
/// Without options.load_case (and with zone_per_current) also one zone per
/// distinct current and design condition of the checked cases (zones), each
/// case checked against its own; with options.extreme the extreme offsets too.
SozResult run_soz(const ValidatedProject& project, const SozOptions& options);

/// One static case's horizontal offset against the platform zone of `zone`
/// (`zone_name` says which zone it is: "still-water" or "case"). Used by
/// run_soz and by stages that already hold their static cases.
OffsetCheck check_offset(const SozResult& zone, const StaticCaseResult& static_case, const std::string& zone_name);

/// spiral's one extreme-offset rule (soz_check.cpp says why), used by `spiral
/// soz --extreme` and every stage: on a motion record (global surge and sway
/// in rows 0-1, at `times_s`), the utilization channel r(t) = |d(t)| /
/// A(θ(t)) against the platform zone, its 3-h MPM by the Weibull fit to the
/// record's peaks as the ratio, reported as an offset in the direction of the
/// record's largest r(t). A record too short for the fit keeps its largest
/// sample and says why in `fit_note` (empty when fitted).
OffsetCheck extreme_offset_check(const SozResult& zone, const StaticCaseResult& static_case,
                                 const Eigen::Matrix<double, 6, Eigen::Dynamic>& motion, const Eigen::VectorXd& times_s,
                                 const std::string& zone_name, std::string& fit_note);

/// The 3-h MPM of the horizontal offset |d(t)| by the same rule (Weibull fit
/// to the peaks), for the offset limit, which has no direction.
struct OffsetMpm {
  double offset_m = 0.0;  ///< the MPM, or the record's largest sample when not fitted
  bool fitted = false;    ///< false: constant record, or too short for the fit (`note`)
  std::string note;
};
OffsetMpm horizontal_offset_mpm(const std::vector<double>& offset_m, double dt_s);

/// Allowable offset of a polar polygon (grid `directions_deg`, uniform step)
/// in `direction_deg`, by linear interpolation in angle.
double polygon_allowable(const std::vector<double>& directions_deg, const std::vector<double>& allowable_m,
                         double direction_deg);

/// One riser's criteria as a function of the hull's horizontal offset, for
/// one thread (it holds no mutable state; solutions are passed back in for
/// warm starts). The zone search, the brute-force test sweep and the bench
/// all go through it.
class RiserOffsetEvaluator {
 public:
  struct Evaluation {
    /// Checks, incl. max_touchdown_excursion when the riser has that criterion.
    RiserStaticsRow row;
    /// FE model only; null when the solve failed.
    std::shared_ptr<const engine::FeStaticsResult> solution;
    /// Solver message when the solve failed (the row then fails "no_static_solution").
    std::string error;
    /// Touchdown point (global); none when the riser is fully suspended.
    std::optional<Eigen::Vector3d> touchdown_g;
    bool passes() const { return error.empty() && row.passes; }
  };
  /// Solves the riser at zero offset (the reference of the TDP excursion).
  /// Throws engine::SolverError when it cannot.
  RiserOffsetEvaluator(const Project& project, const RiserDesign& design, const SozConditions& conditions,
                       SozModel model);
  /// Newton tolerance of a solve. final: the engine's default (1e-10 of the
  /// force scale). march: 1e-6 — the criteria move by ~1e-6 of themselves,
  /// far below what the pass/fail of a march sample or a 0.1 m tolerance
  /// can see, and the chord iterations of the warm start stop earlier; no
  /// touchdown node move (the final solves keep it for the TDP curvature).
  enum class Precision { march, final };
  /// The row at hull offset `offset_xy_m` (m, global x, y), warm-started from
  /// `warm` (a solution of this evaluator) or, when null, from the zero-offset one.
  Evaluation evaluate(const Eigen::Vector2d& offset_xy_m, const engine::FeStaticsResult* warm,
                      Precision precision = Precision::final) const;
  const Evaluation& zero_offset() const { return zero_; }
  const RiserDesign& design() const { return design_; }

 private:
  Eigen::Vector3d hang_off_g(const Eigen::Vector2d& offset_xy_m) const;
  /// The evaluation of a solve that failed with `message` (fails "no_static_solution").
  Evaluation failed(std::string message) const;
  Evaluation solve_fe(const Eigen::Vector3d& hang_off_g, const engine::FeStaticsResult* warm,
                      Precision precision) const;
  Evaluation solve_catenary(const Eigen::Vector3d& hang_off_g) const;
  void add_touchdown_check(Evaluation& e, const std::optional<Eigen::Vector3d>& touchdown_g) const;

  const Project& project_;
  const RiserDesign& design_;
  SozConditions conditions_;
  SozModel model_;
  engine::FeEnvironment environment_;
  Eigen::Vector3d reference_touchdown_g_ = Eigen::Vector3d::Zero();
  bool has_reference_touchdown_ = false;
  Evaluation zero_;
};

}  // namespace spiral::design
