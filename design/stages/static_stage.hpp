#pragma once
// The static part of the preliminary stage (DESIGN.md §2): a thin composition
// of the existing design analyses whose results a stage report shows —
//  - pretensions: every line at zero offset (run_statics);
//  - the coupled static case of still water and of every load case (intact,
//    or with its damaged line removed: run_static_case);
//  - restoring-force curves of the line array along 0° and 90°;
//  - the mooring code check per line and case, and the offset limit check.
//
// With risers, the stage also computes the riser safe operational zones
// (soz.hpp) in still water with the stage's model and step (stages[i].soz:
// catenary screening at 15° unless the project asks otherwise) and checks
// every load case's static offset against the platform zone. With hull
// hydrodynamics, it runs the enhanced S-C 3-h storm of the governing load
// case (stage_dynamics.hpp: dynamic tension and extreme offset checks).
//
// Code check: the quasi-static check of mooring_checks.hpp per line and case.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "design/criteria/mooring_checks.hpp"
#include "design/soz/soz.hpp"
#include "design/stages/stage_dynamics.hpp"
#include "design/analysis/static_case.hpp"
#include "design/analysis/statics_study.hpp"
#include "design/project/validated_project.hpp"
#include "engine/hull/wamit_gdf.hpp"

namespace spiral::design {

/// The line array's restoring force against a horizontal offset of the hull
/// along one direction (no rotation, no heave).
struct RestoringCurve {
  double direction_deg = 0.0;          ///< CCW from +x
  std::vector<double> offset_m;        ///< along the direction, >= 0, ascending
  std::vector<double> force_N;         ///< restoring force, −F·d (> 0 pushes the hull back)
  std::optional<std::string> stopped;  ///< why the sweep ended early (a line could not be solved)
};

/// One line's code check in one case.
struct LineCodeCheck {
  std::string line;
  double max_tension_N = 0.0;
  double utilization_mbl = 0.0;  ///< T_max / MBL of the governing segment (no factor)
  double safety_factor = 0.0;    ///< SF applied (see the file comment)
  double utilization = 0.0;      ///< code utilization T_max · SF / MBL; pass when <= 1
  bool pass = true;
};

struct CaseCheck {
  std::string case_name;
  LineIntegrity integrity = LineIntegrity::intact;
  double safety_factor = 0.0;
  std::vector<LineCodeCheck> lines;      ///< same order as StaticCaseResult::lines
  double offset_m = 0.0;                 ///< horizontal offset of the equilibrium
  std::optional<double> offset_limit_m;  ///< criteria.max_offset_pct_depth · depth
  bool offset_pass = true;
  bool lines_pass = true;
  bool risers_pass = true;  ///< every riser meets its criteria (StaticCaseResult::risers)
  /// Static offset against the platform SOZ (load cases, when a zone exists).
  std::optional<OffsetCheck> soz;
  bool soz_pass = true;
  bool pass = true;
  /// Index into `lines` of the most utilized line (-1 when there is none).
  int governing_line = -1;
};

/// Per line: the breaking load of each segment, anchor to fairlead, for
/// utilization along the profile.
struct LineStrength {
  std::string name;
  std::vector<double> segment_mbl_N;
  std::vector<std::string> segment_types;
};

/// The check that decides the verdict: the failing check of largest
/// utilization, or the largest utilization overall when every check passes.
struct GoverningCheck {
  std::string case_name;
  std::string check;      ///< "mooring code", "offset limit", "riser criteria", "riser SOZ",
                          ///< "dynamic tension", "extreme offset (SOZ)"
  std::string item;       ///< line or riser name; empty for the offset limit
  std::string criterion;  ///< riser criterion, or what the utilization measures
  double utilization = 0.0;
  bool pass = true;
};

struct StaticStageOptions {
  bool soz = true;       ///< the SOZ and offset check (projects with risers)
  bool dynamics = true;  ///< the S-C storm (projects with hull hydrodynamics)
};

struct StaticStageResults {
  std::string stage = "preliminary";
  std::string code;                       ///< mooring code name (to_string(MooringCode))
  StaticsResult pretension;               ///< zero offset
  std::vector<StaticCaseResult> cases;    ///< still water first, then the load cases in project order
  std::vector<CaseCheck> checks;          ///< same order as `cases`
  std::vector<RestoringCurve> restoring;  ///< 0° and 90°
  std::vector<LineStrength> strengths;    ///< project line order
  int worst_case = 0;                     ///< index into `cases` of the largest code utilization
  /// Still-water zones and the load cases' static offsets (offset_checks) against them.
  std::optional<SozResult> soz;
  std::optional<StageDynamics> dynamics;  ///< the S-C storm of the governing load case
  std::vector<std::string> notes;         ///< what the stage left out and why
  /// The hull's panel mesh (hull.geometry.panel_mesh), full surface, body frame; empty without one.
  std::vector<engine::Panel> hull_panels_b;
  GoverningCheck governing;
  bool pass = true;  ///< every case passes, and the dynamic checks
  double wall_time_s = 0.0;
};

/// Offsets of a restoring curve: 0 … 10 % of depth in 20 steps.
inline constexpr double kRestoringMaxOffsetFractionOfDepth = 0.10;
inline constexpr int kRestoringSteps = 20;

/// The parts of the stage that do not depend on a load case: the
/// pretensions at zero offset, the segment strengths and the restoring curves.
struct MooringOverview {
  StaticsResult pretension;
  std::vector<LineStrength> strengths;
  std::vector<RestoringCurve> restoring;  ///< 0° and 90°
};

/// Throws engine::SolverError when a line cannot be solved at zero offset.
MooringOverview run_mooring_overview(const ValidatedProject& project);

/// One static case as every stage runs it: `load_case` none is still water,
/// whose analytic stiffness is cross-checked by finite differences (once per
/// stage). Throws as run_static_case.
StaticCaseResult run_stage_static_case(const ValidatedProject& project, const std::optional<std::string>& load_case,
                                       RestSolutionCache* cache = nullptr);

/// The still-water zones with the preliminary stage's settings; none without risers.
std::optional<SozResult> run_stage_soz(const ValidatedProject& project);

/// The hull's panel mesh for the stage's 3-D views (empty without one).
/// Throws engine::FileFormatError for a malformed mesh.
std::vector<engine::Panel> stage_hull_panels(const Project& project);

/// The stage from its parts (`cases`: still water first, then every load
/// case in project order): the code, offset-limit, riser and SOZ checks, the
/// worst case and the governing check. The storm is added by add_stage_storm;
/// with options.dynamics and no hull hydrodynamics a note says why there is none.
StaticStageResults reduce_static_stage(const ValidatedProject& project, MooringOverview overview,
                                       std::vector<StaticCaseResult> cases, std::optional<SozResult> soz,
                                       std::vector<engine::Panel> hull_panels_b,
                                       const StaticStageOptions& options = {});

/// The load case whose S-C storm the stage runs (index into `stage.cases`)
/// and why; none without load cases or hull hydrodynamics.
struct StormChoice {
  std::size_t case_index = 0;
  std::string why;
};
std::optional<StormChoice> stage_storm_choice(const Project& project, const StaticStageResults& stage);

/// Adds the storm of stage_storm_choice: its checks join the verdict and the governing check.
void add_stage_storm(StaticStageResults& stage, StageDynamics storm);

/// Runs the static stage: every part above in turn. Throws InputError /
/// engine::SolverError as run_static_case does (the message names the case
/// and line), and engine::FileFormatError for a malformed panel mesh (before
/// any analysis).
StaticStageResults run_static_stage(const ValidatedProject& project, const StaticStageOptions& options = {});

/// The SOZ settings of the project's preliminary stage (defaults when it lists none).
StageSoz preliminary_soz_settings(const Project& project);

}  // namespace spiral::design
