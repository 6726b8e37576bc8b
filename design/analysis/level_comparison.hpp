#pragma once
// The three analysis levels side by side (DESIGN.md §1: "the product must
// show that trade-off"): one load case, one seed, one duration, run at
// uncoupled, sc, sc-enhanced and coupled; per level the statistics of the
// hull offsets and of every mooring line's fairlead tension, their %
// difference against the coupled run, the wall-clock cost and the speed-up
// against coupled.
//
// Tensions per level: the non-coupled levels' dynamic tensions come from
// their hull motion prescribed to the same dynamic FE lines the coupled run
// integrates (request.line_dynamics, design/analysis/line_dynamics.hpp), so the
// tension differences are those of the motions and of the coupling alone;
// their quasi-static catenary tensions are compared as well. A level's
// cost (`wall_s`) is its own analysis — equilibrium, reduction, forcing,
// hull dynamics, WF motions and quasi-static tensions; the prescribed-motion
// FE lines are reported apart (`line_dynamics_wall_s`), being the same FE
// lines the coupled run carries.
//
// Statistics per channel: mean, standard deviation, maximum and the
// most-probable 3-h maximum (Gumbel fit of the cycle maxima,
// engine/numerics/statistics.hpp; the sample maximum when the record is too
// short for the fit). Differences: 100 (level − coupled) / |coupled|.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "design/analysis/dynamic_analysis.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {

struct ChannelSummary {
  std::string name;  ///< offset_m, surge_m, …, tension_<line>_N, qs_tension_<line>_N
  std::string unit;
  engine::ChannelMoments moments;
  double mpm = 0.0;         ///< most-probable 3-h maximum (Gumbel), or the sample maximum
  bool mpm_fitted = false;  ///< false: mpm is the sample maximum
};

struct LevelSummary {
  AnalysisLevel level = AnalysisLevel::semi_coupled;
  double wall_s = 0.0;                ///< the level's own analysis
  double line_dynamics_wall_s = 0.0;  ///< prescribed-motion FE lines (non-coupled levels)
  std::vector<ChannelSummary> channels;
  std::vector<std::string> notes;
  /// Surge, sway and yaw as equivalent linear oscillators over the level's
  /// run (not the coupled level: DynamicAnalysisResult).
  std::vector<engine::DofDamping> low_frequency_damping;
  std::optional<engine::IdaStatistics> coupled_solver;
  /// The solver failure that stopped this level (its channels are then
  /// empty); the other levels still run.
  std::optional<std::string> error;
};

struct LevelComparison {
  std::string case_name;
  std::uint64_t seed = 1;
  double duration_s = 0.0;
  std::vector<LevelSummary> levels;                       ///< uncoupled, sc, sc-enhanced, coupled
  LineReduction line_reduction = LineReduction::dynamic;  ///< sc-enhanced's
};

struct ComparisonRequest {
  std::string load_case;
  double duration_s = 10800.0;
  double output_step_s = 0.5;
  std::uint64_t seed = 1;
  long coupled_max_steps_between_outputs = 500000;        ///< DynamicAnalysisRequest's
  LineReduction line_reduction = LineReduction::dynamic;  ///< sc-enhanced's (DynamicAnalysisRequest's)
  bool detailed_line_mesh = false;                        ///< DynamicAnalysisRequest's
  /// Called with (level name, fraction done of that level); may be empty.
  std::function<void(const std::string&, double)> progress;
};

/// Runs the four levels. A level whose solver fails (engine::SolverError)
/// keeps its message in LevelSummary::error and the others still run; input
/// and file errors throw as run_dynamic_analysis.
LevelComparison compare_levels(const ValidatedProject& project, const ComparisonRequest& request);

/// The summary channels of one analysis result (offsets, dynamic and
/// quasi-static tensions).
std::vector<ChannelSummary> summarize_channels(const DynamicAnalysisResult& result);

/// One level's summary of a finished analysis: its own cost (see the file
/// comment), channels, notes and coupled solver statistics.
LevelSummary summarize_level(const DynamicAnalysisResult& result);

/// 100 (level − coupled) / |coupled|; 0 when the coupled value is 0.
double percent_difference(double level, double coupled);

/// The level's summary, null when the level is missing or failed.
const LevelSummary* find_level(const LevelComparison& comparison, AnalysisLevel level);
/// The channel named `name` of a level, null when it has none.
const ChannelSummary* find_channel(const LevelSummary& level, const std::string& name);

}  // namespace spiral::design
