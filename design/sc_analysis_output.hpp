#pragma once
// Results of a dynamic analysis (sc_analysis.hpp) as files:
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

#include "design/sc_analysis.hpp"
#include "engine/numerics/statistics.hpp"

namespace spiral::design {

/// Welch segment length for a record of `samples` samples: the largest power
/// of two <= samples/8 (>= 8 segments averaged with 50 % overlap, ~15 for a
/// full record), at least 16 samples (and at most `samples`).
std::size_t welch_segment_length(std::size_t samples);

/// Last bin of a Welch spectrum that matters: the bins above it hold at most
/// 1e-6 of the variance (the Nyquist tail of a 0.5 s record is noise).
Eigen::Index spectrum_last_significant_bin(const engine::Spectrum& spectrum);

/// Writes the CSV; throws std::runtime_error naming the file if it cannot.
void write_dynamic_time_series_csv(const DynamicAnalysisResult& result,
                                   const std::filesystem::path& file);

/// Statistics of every channel (total motions, LF motions, tensions) and the
/// run's metadata. Channels too short for an extreme-value fit carry
/// "extremes_unavailable" with the reason instead of the MPMs.
nlohmann::json dynamic_analysis_to_json(const DynamicAnalysisResult& result,
                                        const std::string& project_name);

}  // namespace spiral::design
