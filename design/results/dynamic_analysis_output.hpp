#pragma once
// Results of a dynamic analysis (dynamic_analysis.hpp) as files:
//   * time series CSV: one row per output time, columns
//     time_s, {surge_m, sway_m, heave_m, roll_deg, pitch_deg, yaw_deg} for
//     the total motion, the same with _lf and _wf suffixes, then
//     tension_<line>_N for every intact mooring line (docs/output-format.md);
//   * JSON summary: per channel mean/std/min/max, MPM of the 3-h maximum
//     (Gumbel, Weibull, Rayleigh) and minimum, spectral peak period; the
//     wall-clock time of each step and the integrator statistics.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "design/analysis/dynamic_analysis.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {

/// Writes the CSV; throws std::runtime_error naming the file if it cannot.
void write_dynamic_time_series_csv(const DynamicAnalysisResult& result,
                                   const std::filesystem::path& file);

/// Statistics of every channel (total motions, LF motions, tensions) and the
/// run's metadata. Channels too short for an extreme-value fit carry
/// "extremes_unavailable" with the reason instead of the MPMs.
nlohmann::json dynamic_analysis_to_json(const DynamicAnalysisResult& result,
                                        const std::string& project_name);

}  // namespace spiral::design
