#pragma once
// The time-domain part of a stage (DESIGN.md §2): one load case's S-C
// analysis (dynamic_analysis.hpp) reduced to what a stage checks and reports —
// the motion channels (surge, sway, yaw and the horizontal offset; heave,
// roll, pitch and the vertical motion of the riser hang-off that moves most,
// which the wave-frequency response drives), the fairlead tension of the
// most loaded line, their statistics
// (moments, Welch spectrum, MPM of the 3-h maximum) and the two dynamic
// checks:
//  - tension: the line's MPM fairlead tension against its fairlead segment's
//    MBL with the code's dynamic factor (mooring_checks.hpp).
//  - extreme offset: spiral's one extreme-offset rule against the platform
//    SOZ (extreme_offset_check, soz.hpp: the 3-h MPM of offset/allowable,
//    Weibull), when a zone is given.
// Channel MPMs (and so the tension check): the Gumbel estimate of
// engine/numerics/statistics.hpp (segment maxima, max-stable, so it scales to
// 3 h without assuming a narrow band); the Weibull one beside it.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "design/criteria/mooring_checks.hpp"
#include "design/analysis/dynamic_analysis.hpp"
#include "design/soz/soz.hpp"
#include "design/analysis/static_case.hpp"
#include "design/project/validated_project.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {

/// Where a storm's tension channel comes from.
enum class TensionSource {
  quasi_static,  ///< the catenary at the instantaneous fairlead (the S-C levels)
  coupled,       ///< the dynamic FE line of the coupled run
};

/// Name prefix of the hang-off channel, followed by the riser's name.
inline constexpr std::string_view kHangOffHeavePrefix = "hang-off heave ";

/// One channel of a stage's dynamic analysis and its statistics.
struct StormChannel {
  std::string name;  ///< surge, sway, yaw, offset, "tension <line>", heave, roll, pitch, "hang-off heave <riser>"
  std::string unit;  ///< m, deg or N (the values below are in it)
  std::vector<double> values;  ///< per output time
  /// Its statistics (engine::analyze_channel): the moments always; the
  /// one-sided Welch spectrum (up to its last significant bin), the periods
  /// and the extremes only when `extremes_note` is empty.
  engine::ChannelStatistics statistics;
  std::string extremes_note;  ///< why the extremes are missing (constant or short channel)

  const engine::ChannelMoments& moments() const { return statistics.moments; }
  /// MPM of the 3-h maximum and minimum (Gumbel); absent with `extremes_note`.
  std::optional<double> mpm_max() const { return extreme(statistics.maximum.mpm_gumbel); }
  std::optional<double> mpm_min() const { return extreme(statistics.minimum.mpm_gumbel); }
  /// The Weibull MPM of the maximum, a second estimate for comparison.
  std::optional<double> mpm_max_weibull() const { return extreme(statistics.maximum.mpm_weibull); }

 private:
  std::optional<double> extreme(double value) const {
    return extremes_note.empty() ? std::optional<double>(value) : std::nullopt;
  }
};

struct StageDynamics {
  std::string case_name;
  LineIntegrity integrity = LineIntegrity::intact;
  std::optional<std::string> damaged_line;
  std::string selection;  ///< why this case was analysed
  AnalysisLevel level = AnalysisLevel::semi_coupled_enhanced;
  double duration_s = 0.0;
  double output_step_s = 0.0;
  std::uint64_t seed = 1;
  std::vector<double> times_s;
  /// surge (m), sway (m), yaw (deg), offset (m, horizontal), the tension of
  /// the most loaded line (N, when the project has mooring lines), heave (m),
  /// roll and pitch (deg), and the vertical displacement of the riser hang-off
  /// with the largest one's standard deviation (m, when it has risers). Look
  /// channels up by name: which of them exist depends on the project.
  std::vector<StormChannel> channels;
  std::string most_loaded_line;  ///< by its largest sampled fairlead tension
  TensionSource tension_source = TensionSource::quasi_static;
  double fairlead_mbl_N = 0.0;         ///< MBL of that line's fairlead segment
  double dynamic_safety_factor = 0.0;  ///< API SF_dyn, or γ_dyn for DNV
  double tension_utilization = 0.0;    ///< see the file comment; pass when <= 1
  bool tension_pass = true;
  std::optional<OffsetCheck> extreme_offset;  ///< kind extreme, with a zone
  std::vector<std::string> notes;
  AnalysisTimings timing;  ///< of the analysis (equilibrium 0 when the stage's static case was reused)
  double wall_s = 0.0;     ///< the whole analysis and its statistics
  int solver_steps = 0;

  /// The channel called `name`, or nullptr.
  const StormChannel* channel(std::string_view name) const;
  /// The most loaded line's tension channel, or nullptr (no mooring lines).
  const StormChannel* tension() const;
};

/// Channel statistics of a uniformly sampled record (dt_s > 0).
StormChannel summarize_storm_channel(std::string name, std::string unit, std::vector<double> values, double dt_s);

/// The load case's seed (LoadCase::seed), 1 for still water or an unknown name.
int case_seed(const Project& project, const std::string& case_name);

/// The stage's view of one finished analysis `result` of `request` (whose
/// `statics` is the case's static equilibrium): channels, statistics and the
/// two dynamic checks. The tension channel is the mooring line `tension_line`
/// (empty: the most loaded one); a coupled result's tensions are its dynamic
/// FE tensions (risers left out), the other levels' the quasi-static ones.
/// `wall_s` is left to the caller (it timed the analysis).
StageDynamics summarize_stage_dynamics(const ValidatedProject& project, const StaticCaseResult& statics,
                                       const DynamicAnalysisRequest& request, const DynamicAnalysisResult& result,
                                       const SozResult* zone, std::string selection,
                                       const std::string& tension_line = "");

/// Runs the analysis of `statics.case_name` at `level` (3 h, 0.5 s, seed 1),
/// reusing `statics` as its static equilibrium. `zone`: the platform SOZ for
/// the extreme-offset check (none: no check). `rest_solutions`: shared with
/// the stage's other storms (DynamicAnalysisRequest). Throws as run_dynamic_analysis.
StageDynamics run_stage_dynamics(const ValidatedProject& project, const StaticCaseResult& statics, AnalysisLevel level,
                                 const SozResult* zone, std::string selection,
                                 RestSolutionCache* rest_solutions = nullptr);

}  // namespace spiral::design
