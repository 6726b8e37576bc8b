#pragma once
// The fully coupled analysis of one load case (DESIGN.md §1, the highest
// level): the hull's low-frequency equations and every intact mooring line
// and every riser as a dynamic FE line, integrated together
// (engine/analysis/coupled_dynamics.hpp).
//
// Built from the same pieces as the S-C levels, so that the levels differ
// only in how the lines enter:
//   * start: the S-C static case (run_static_case, current on every line) —
//     hull at its equilibrium, each line's FE statics there with the case's
//     current (design/analysis/line_dynamics.hpp: polyester at its dynamic EA,
//     seabed damping and friction), risers from their foot to the hang-off;
//   * hull: M + A(w_LF), B_lin, quadratic damping, C_hydro, F_hs0 and the
//     same external low-frequency force (slow drift, wind with gusts,
//     current on the hull, or the Morison members) on the same seeded
//     realizations as the S-C run of that seed; with `radiation: memory`,
//     A(inf) and the retardation kernel as the S-C hull;
//   * wave-frequency motion: the S-C level's RAO motion (same seed),
//     superposed on the hull state at the fairleads (built up over the
//     request's line_dynamics_ramp_s), so that the lines move with LF + WF
//     and their forces act on the LF equations — including the WF line
//     tension and drag, which is what the S-C levels do not see;
//   * the lines' forces replace F0 − K (q − q0) altogether.
// Outputs as the other levels (DynamicAnalysisResult): motions, quasi-static
// tensions at the total motion (for comparison) and the coupled tensions in
// `dynamic_tensions` (mooring lines, then risers), with the IDA statistics.
//
// Errors: as run_dynamic_analysis; a failing integration throws
// engine::SolverError naming the case, the time reached, the part of the
// system with the largest local error (a line, or the hull) and the cause.

#include "design/analysis/dynamic_analysis.hpp"

namespace spiral::design {

/// The coupled level's lines run at this fraction of the single-line
/// tolerances (FeDynamicsOptions), with or without wave-frequency motion:
/// the coupled level is the reference the others are measured against.
/// Under WF motion the risers' top-tension std needs it (+10 to +12 % on
/// the default FPS's operating case at the single-line tolerances, within
/// 1.2 % with it); without, OC4's lightly damped heave does (its std +4.4 %
/// and pitch +1.4 % against 0.03 of the tolerances, 300 s, within 0.6 % and
/// 0.2 % with it, at 2.1× the steps; docs/decisions/coupled-dynamics-performance.md,
/// "The coupled Newton solve and end B").
inline constexpr double kCoupledLineToleranceScale = 0.1;

DynamicAnalysisResult run_coupled_analysis(const ValidatedProject& project, const DynamicAnalysisRequest& request);

}  // namespace spiral::design
