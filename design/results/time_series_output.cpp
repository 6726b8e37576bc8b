#include "design/results/time_series_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/numerics/statistics.hpp"

namespace spiral::design {

std::string time_series_csv(const std::vector<TimeSeriesColumn>& columns) {
  std::ostringstream out;
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c > 0 ? "," : "") << columns[c].name;
  out << '\n';
  const std::size_t rows = columns.empty() ? 0 : columns.front().values.size();
  for (std::size_t k = 0; k < rows; ++k) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) out << ',';
      out << fmt::format(fmt::runtime(columns[c].csv_format), columns[c].values[k]);
    }
    out << '\n';
  }
  return out.str();
}

nlohmann::json channel_json(const std::string& name, const std::string& unit, const std::vector<double>& x,
                            double dt_s) {
  nlohmann::json j;
  j["name"] = name;
  j["unit"] = unit;
  const engine::ChannelMoments m = engine::channel_moments(x);
  j["mean"] = m.mean;
  j["std"] = m.std_dev;
  j["min"] = m.minimum;
  j["max"] = m.maximum;
  if (m.std_dev <= 1e-12 * std::max(1.0, std::abs(m.mean))) {
    j["extremes_unavailable"] = "constant channel";
    return j;
  }
  try {
    const engine::ChannelStatistics s = engine::analyze_channel(x, dt_s, engine::welch_segment_length(x.size()));
    j["spectral_peak_period_s"] = s.spectral_peak_period_s;
    // The Welch spectrum (one-sided S(w), unit²·s/rad) up to where it holds
    // all but 1e-6 of the variance: the Nyquist tail of a 0.5 s record is noise.
    const engine::Spectrum& sp = s.spectrum;
    const Eigen::Index last = engine::spectrum_last_significant_bin(sp);
    std::vector<double> w(static_cast<std::size_t>(last + 1)), d(static_cast<std::size_t>(last + 1));
    for (Eigen::Index k = 0; k <= last; ++k) {
      w[static_cast<std::size_t>(k)] = sp.frequency_rad_s(k);
      d[static_cast<std::size_t>(k)] = sp.density(k);
    }
    j["spectrum"] = {{"frequency_rad_per_s", w}, {"density_per_rad_per_s", d}, {"welch_segments", sp.segments}};
    j["zero_upcrossing_period_s"] = s.zero_upcrossing_period_s;
    j["mpm_max_3h"] = {
        {"gumbel", s.maximum.mpm_gumbel}, {"weibull", s.maximum.mpm_weibull}, {"rayleigh", s.maximum.mpm_rayleigh}};
    j["mpm_min_3h"] = {
        {"gumbel", s.minimum.mpm_gumbel}, {"weibull", s.minimum.mpm_weibull}, {"rayleigh", s.minimum.mpm_rayleigh}};
  } catch (const std::exception& e) {
    j["extremes_unavailable"] = e.what();
  }
  return j;
}

}  // namespace spiral::design
