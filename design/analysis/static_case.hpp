#pragma once
// One coupled static case of the project (step 1–2 of the semi-coupled
// method, DESIGN.md §1): the equilibrium of hull + every line under a load
// case (intact or with a line removed), then the line array's 6×6 stiffness
// and force vector at that position, cross-checked by finite differences,
// with the natural periods of the moored hull. The S-C levels take it with
// `lines_carry_current` (the current on every mooring line, FE statics); the
// quick statics of the preliminary stage keep each line's own model.

#include <array>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "design/criteria/riser_checks.hpp"
#include "design/model/case_model.hpp"
#include "design/model/riser_model.hpp"
#include "design/analysis/statics_study.hpp"
#include "design/project/validated_project.hpp"
#include "engine/common/rigid_body.hpp"
#include "engine/lines/fe_line_statics.hpp"

namespace spiral::design {

struct StaticCaseRequest {
  std::optional<std::string> load_case;     ///< none: still water, intact
  std::optional<std::string> damaged_line;  ///< overrides the load case's damaged line
  bool finite_difference_check = false;     ///< also compute K by central differences (12 array solves)
  /// The S-C levels' static case: when the load case has current, every
  /// mooring line is an FE line carrying it (LineArrayOptions), whatever its
  /// `model`. Off: the quick statics of the preliminary stage, each line in
  /// its own model (a catenary carries no current).
  bool lines_carry_current = false;
};

/// Horizontal and rotational offset of the hull reference point.
struct OffsetSummary {
  double horizontal_m = 0.0;
  double horizontal_pct_depth = 0.0;
  double direction_deg = 0.0;  ///< of the horizontal offset, CCW from +x, [0, 360)
  double heave_m = 0.0;
  double roll_deg = 0.0;
  double pitch_deg = 0.0;
  double yaw_deg = 0.0;
};

/// A natural mode of the moored hull (undamped, about the equilibrium).
struct NaturalMode {
  double period_s = 0.0;
  std::string dominant_dof;  ///< surge, sway, heave, roll, pitch or yaw
};

struct StaticCaseResult {
  std::string case_name;    ///< load case, or "still-water"
  std::string environment;  ///< environment name, or "none"
  LineIntegrity integrity = LineIntegrity::intact;
  std::optional<std::string> damaged_line;

  engine::Vector6d offset = engine::Vector6d::Zero();  ///< m, rad
  OffsetSummary offset_summary;
  std::vector<LineStaticsRow> lines;  ///< mooring lines
  std::vector<RiserStaticsRow> risers;
  DesignCondition design_condition = DesignCondition::normal;  ///< selects the riser design factor
  bool lines_carry_current = false;                            ///< the request's flag
  /// Every line of the array carried the case's current: no current, or every
  /// mooring line an FE line (`model: fe`, or lines_carry_current). The S-C
  /// levels take only such a case (build_dynamic_model).
  bool current_on_every_line = true;

  engine::Vector6d line_force = engine::Vector6d::Zero();       ///< F of the line array, N, N·m
  engine::Matrix6d stiffness = engine::Matrix6d::Zero();        ///< analytic K of the line array
  std::optional<engine::Matrix6d> stiffness_finite_difference;  ///< central differences
  std::optional<double> stiffness_check_relative_difference;    ///< ‖K − K_fd‖ / ‖K_fd‖
  std::vector<engine::Matrix6d> line_stiffness;                 ///< per line: mooring lines, then risers
  /// The line array's K for the motions about this mean position: every
  /// polyester segment at its dynamic EA at its mean tension, the mean state
  /// itself on the static EA (the static–dynamic convention of DNV-OS-E301
  /// ch. 2 sec. 2 [2.4]; engine::StaticLine::incremental_stiffness_g). Equal
  /// to `stiffness` without polyester. The S-C levels' hull dynamics take it,
  /// as the coupled level's FE lines carry their motions on the dynamic EA.
  engine::Matrix6d dynamic_stiffness = engine::Matrix6d::Zero();
  int dynamic_stiffness_lines = 0;  ///< mooring lines whose EA differs in dynamic_stiffness
  /// Per line, same order: its 6-DOF force on the hull (about the displaced
  /// reference point, global axes); they sum to line_force, as the
  /// line_stiffness sum to stiffness.
  std::vector<engine::Vector6d> line_force_6dof;
  engine::Vector6d hydrostatic_force = engine::Vector6d::Zero();
  engine::Vector6d environment_force = engine::Vector6d::Zero();
  engine::Vector6d residual = engine::Vector6d::Zero();
  engine::Matrix6d hydrostatic_stiffness = engine::Matrix6d::Zero();

  /// What the case does not model although the input asks for it (e.g. wind
  /// without wind coefficients), so that no load is silently dropped.
  std::vector<std::string> notes;

  std::vector<NaturalMode> natural_modes;  ///< ascending period
  /// The same with dynamic_stiffness: the periods the S-C and coupled
  /// dynamics oscillate at (equal to natural_modes without polyester).
  std::vector<NaturalMode> dynamic_natural_modes;
  bool added_mass_included = false;

  int equilibrium_iterations = 0;
  double equilibrium_wall_s = 0.0;
  double stiffness_wall_s = 0.0;
};

/// The FE line solutions (risers, `model: fe` mooring lines) at the hull's
/// rest position, by environment and line name, for the static cases of one
/// project: a case whose environment was solved before (e.g. the damaged case
/// of an intact one) starts from them instead of solving every line cold
/// again, with identical results (the adopted solution is the one a cold
/// solve at the rest position returns). Shared by the tasks of one stage of
/// one model (a spiral run's static cases, its storms): the lines' models
/// must be the same for every case that uses it. Thread-safe.
struct RestSolutionCache {
  std::mutex mutex;
  std::map<std::pair<std::string, std::string>, engine::FeStaticsResult> solutions;
};

/// Throws InputError for an unknown load case or line, engine::SolverError when
/// the equilibrium or a line cannot be solved (the message names it).
/// `cache` (optional): rest-position solutions to take and to add to.
StaticCaseResult run_static_case(const ValidatedProject& project, const StaticCaseRequest& request,
                                 RestSolutionCache* cache = nullptr);
/// The same on a case model already built for `request.load_case`.
StaticCaseResult run_static_case(const ValidatedProject& project, const CaseModel& case_model,
                                 const StaticCaseRequest& request, RestSolutionCache* cache = nullptr);

}  // namespace spiral::design
