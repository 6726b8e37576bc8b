#pragma once
// Results of a dynamic analysis (dynamic_analysis.hpp) as files:
//   * time series CSV: one row per output time, columns
//     time_s, {surge_m, sway_m, heave_m, roll_deg, pitch_deg, yaw_deg} for
//     the total motion, the same with _lf and _wf suffixes, then
//     qs_tension_<line>_N (the quasi-static catenary) for every intact mooring
//     line, tension_<name>_N for every dynamic FE line and riser (coupled, or
//     --line-dynamics), and the fairlead positions (docs/output-format.md);
//   * JSON summary: per channel mean/std/min/max, MPM of the 3-h maximum
//     (Gumbel, Weibull, Rayleigh) and minimum, spectral peak period; the
//     wall-clock time of each step and the integrator statistics.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "design/analysis/dynamic_analysis.hpp"
#include "design/results/time_series_output.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {

/// The columns of the time series CSV, in its order, at full precision (the
/// Python API hands them over as arrays).
std::vector<TimeSeriesColumn> dynamic_time_series_columns(const DynamicAnalysisResult& result);

/// The time series CSV (the caller writes it, as every output file of the app).
std::string dynamic_time_series_csv(const DynamicAnalysisResult& result);

/// Statistics of every channel (total motions, LF motions, tensions) and the
/// run's metadata. Channels too short for an extreme-value fit carry
/// "extremes_unavailable" with the reason instead of the MPMs.
nlohmann::json dynamic_analysis_to_json(const DynamicAnalysisResult& result, const std::string& project_name);

/// Equivalent linear oscillators (engine/analysis/low_frequency_damping.hpp)
/// keyed by DOF name: natural period, damping ratio, and the mass,
/// stiffness and damping behind them, SI, rotations per radian — the same
/// object in summary.json and comparison.json.
nlohmann::json low_frequency_damping_to_json(const std::vector<engine::DofDamping>& oscillators);

}  // namespace spiral::design
