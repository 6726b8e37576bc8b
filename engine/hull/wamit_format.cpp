#include "engine/hull/wamit_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace spiral::engine::detail {

void validate_wamit_options(const WamitReadOptions& options, const char* reader) {
  const auto bad = [](double v) { return !(v > 0.0) || !std::isfinite(v); };
  if (bad(options.ulen_m)) {
    throw std::invalid_argument(fmt::format("{}: ulen_m must be > 0 m, got {} m", reader, options.ulen_m));
  }
  if (bad(options.period_scale)) {
    throw std::invalid_argument(fmt::format("{}: period_scale must be > 0, got {}", reader, options.period_scale));
  }
  if (bad(options.water.density_kg_per_m3) || bad(options.water.gravity_m_per_s2)) {
    throw std::invalid_argument(fmt::format("{}: water density and gravity must be > 0, got {} kg/m^3 and {} m/s^2",
                                            reader, options.water.density_kg_per_m3, options.water.gravity_m_per_s2));
  }
}

std::vector<std::string_view> split_whitespace(std::string_view line, bool comma_separates) {
  const char* separators = comma_separates ? " \t\r\f\v," : " \t\r\f\v";
  std::vector<std::string_view> tokens;
  std::size_t pos = 0;
  while (pos < line.size()) {
    const std::size_t start = line.find_first_not_of(separators, pos);
    if (start == std::string_view::npos) break;
    const std::size_t end = line.find_first_of(separators, start);
    tokens.push_back(line.substr(start, end == std::string_view::npos ? line.size() - start : end - start));
    pos = end == std::string_view::npos ? line.size() : end;
  }
  return tokens;
}

bool parse_int(std::string_view token, int& value) {
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && ptr == last;
}

bool parse_real(std::string_view token, double& value) {
  // Fortran writers may use a D exponent (1.0D+03); read it as E.
  char buffer[64];
  if (token.empty() || token.size() >= sizeof(buffer)) return false;
  std::size_t n = 0;
  for (char c : token) buffer[n++] = (c == 'D' || c == 'd') ? 'E' : c;
  const char* first = buffer;
  const char* last = buffer + n;
  if (*first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && ptr == last && std::isfinite(value);
}

std::vector<double> distinct_sorted(std::vector<double> values, double rel_tol, double abs_tol) {
  std::sort(values.begin(), values.end());
  std::vector<double> out;
  for (double v : values) {
    if (out.empty() || std::abs(v - out.back()) > rel_tol * std::abs(v) + abs_tol) {
      out.push_back(v);
    }
  }
  return out;
}

int index_in(const std::vector<double>& grid, double value, double rel_tol, double abs_tol) {
  // The nearest of the grid points either side of `value`, by the acceptance
  // test of distinct_sorted. (The first point >= value − tol is not enough: a
  // fuzzed .4 file had headings 9e-6 and 1e-5 deg, 1e-6 deg + 1 ulp apart; for
  // 1e-5 that search stopped at 9e-6, outside the tolerance, never looked at
  // 1e-5 itself, and the index −1 wrote outside the table.)
  const double tol = rel_tol * std::abs(value) + abs_tol;
  const auto upper = std::upper_bound(grid.begin(), grid.end(), value);
  int best = -1;
  double best_distance = 0.0;
  const auto consider = [&](std::vector<double>::const_iterator it) {
    const double distance = std::abs(value - *it);
    if (distance <= tol && (best < 0 || distance < best_distance)) {
      best = static_cast<int>(it - grid.begin());
      best_distance = distance;
    }
  };
  if (upper != grid.begin()) consider(upper - 1);
  if (upper != grid.end()) consider(upper);
  return best;
}

}  // namespace spiral::engine::detail
