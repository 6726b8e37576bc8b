#pragma once
// What every time-domain result writes the same way: its columns as a CSV
// (one row per output time) and a channel's statistics as JSON
// (docs/output-format.md): mean/std/min/max, and where the record allows an
// extreme-value fit, the Welch spectrum, the spectral peak and mean zero
// up-crossing periods and the MPM of the 3-h maximum and minimum (Gumbel,
// Weibull, Rayleigh).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace spiral::design {

/// One column of a time series: its CSV header, its value at every output
/// time in the column's unit (s, m, deg, N) and how the CSV prints a value.
struct TimeSeriesColumn {
  std::string name;
  std::vector<double> values;
  const char* csv_format = "{}";  ///< fmt format of one value, e.g. "{:.6g}"
};

/// The CSV of `columns` (all of one length): a header row, then one row per time.
std::string time_series_csv(const std::vector<TimeSeriesColumn>& columns);

/// Statistics of a uniformly sampled channel (dt_s > 0). A constant channel,
/// or one too short for an extreme-value fit, carries "extremes_unavailable"
/// with the reason instead of the MPMs.
nlohmann::json channel_json(const std::string& name, const std::string& unit, const std::vector<double>& values,
                            double dt_s);

}  // namespace spiral::design
