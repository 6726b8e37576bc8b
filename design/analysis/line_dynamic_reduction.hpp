#pragma once
// The enhanced S-C's lines from their dynamic FE models, in place of the
// quasi-static reduction of line_hydrodynamics.hpp: each line's end
// dynamic stiffness K_dyn(ω) about its current-loaded static state
// (engine/lines/fe_line_impedance.hpp) over the low-frequency band, mapped
// to the hull (T = [I, −[a×]], a the fairlead arm), summed, and fitted
// with a dashpot, an added mass and two relaxations per group (mooring
// lines, risers; engine/analysis/line_relaxation_fit):
// the lines' damping and their stiffening at low frequency, which a line
// restrained by a strong current has (its shape relaxes through the water
// over tens to hundreds of seconds) and the quasi-static reduction cannot
// carry (docs/decisions/enhanced-sc-accuracy.md). The S-C's K stays the
// static one (K_dyn(0)); the relaxations add to it as frequency rises.
//
// The drag is linearized stochastically on each line's own motion: the
// hull's motion record (its low- and wave-frequency motion) gives each
// fairlead's velocity covariance, and the line follows its fairlead
// quasi-statically in the expected drag slope (as the quasi-static
// reduction does); the waves' own velocities on the line are not in it.
// Seabed friction is left out (it
// has no linear form at rest; with it the default FPS's offset std moved
// by 0.03 %).
//
// Measured against the coupled level (default FPS 1800 s, OC4 1200 s, seed
// 1), horizontal-offset std: lc1 −4.6 %, lc2 −3.5 %, lc3 −3.3 %, lc4
// −4.5 %, lc5 −1.1 %, OC4 +1.5 % (the quasi-static reduction: +0.1 %,
// −6.3 %, −8.3 %, −6.2 %, −8.8 %, +2.9 %) (docs/decisions/enhanced-sc-accuracy.md).
// A 3-h storm's reduction of 16 mooring lines and 12 risers, with its first
// S-C run, takes 0.80 s on one core (2026-12-07; 1.22 s before the risers'
// statics started from the static case's solution, the condensation used
// the factors' tails and the first run's CVODE solve was compiled here).
//
// Errors: engine::SolverError naming the line when its FE statics fail.

#include <optional>
#include <string>
#include <vector>

#include "design/analysis/static_case.hpp"
#include "design/project/line_properties.hpp"
#include "design/project/project.hpp"
#include "engine/analysis/hull_dynamics.hpp"
#include "engine/environment/current_profile.hpp"

namespace spiral::design {

struct DynamicLineReduction {
  engine::Matrix6d damping = engine::Matrix6d::Zero();
  engine::Matrix6d added_mass = engine::Matrix6d::Zero();
  std::vector<engine::LineRelaxation> relaxations;
  double relative_residual = 0.0;  ///< of the fit over the band (the worse of the two groups)
  int lines = 0;                   ///< the lines reduced
  int frequencies = 0;             ///< of the band fitted (the shorter of the two groups')
  double lowest_frequency_rad_per_s = 0.0, highest_frequency_rad_per_s = 0.0;  ///< of the band fitted
  std::string relaxation_summary;  ///< "14.4 s, 112 s (mooring lines); … (risers)"
  /// Why the fit cannot stand for the lines (a residual above 15 % even
  /// over a shortened band, or a band that no longer covers the hull's
  /// surge, sway and yaw modes); empty: usable.
  std::string unusable_reason;
};

/// Every intact mooring line (not `damaged_line`) and every riser, at the
/// hull's equilibrium of `statics` in `current`; the mooring lines and the
/// risers fitted apart, each group over the band or, when a resonance of
/// the lines in it leaves more than 15 % of the fit, over the band
/// shortened from the top (unusable_reason says when that is not enough).
/// A mooring line's FE statics start again from its
/// catenary profile in `statics` when the default initial shape fails (as
/// the coupled level's do). `hull_motion` (offsets from the origin, m and
/// rad, one column per `motion_step_s`) linearizes the lines' drag; with
/// fewer than three columns the drag is linearized about the current.
DynamicLineReduction dynamic_line_reduction(const Project& project, const std::vector<LineTypeProperties>& types,
                                            const std::optional<engine::CurrentProfile>& current,
                                            const StaticCaseResult& statics, const std::string& damaged_line,
                                            const Eigen::Matrix<double, 6, Eigen::Dynamic>& hull_motion,
                                            double motion_step_s);

}  // namespace spiral::design
