#include "engine/hull/wamit_format.hpp"
#include "engine/hull/wamit_12d.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace spiral::engine {
namespace {

constexpr double kPeriodRelTolerance = 1e-6;  // equal periods as printed with 5-6 digits
constexpr double kHeadingTolerance_deg = 1e-6;

struct DiagonalEntry {
  double period_s;
  double heading_deg;
  int dof;  // 1..6
  double re;
  std::size_t line;
};

// Sorted distinct values, merging those within `tol(value)` of the previous one.
template <typename Tol>
std::vector<double> distinct(std::vector<double> values, Tol tol) {
  std::sort(values.begin(), values.end());
  std::vector<double> out;
  for (double v : values) {
    if (out.empty() || v - out.back() > tol(out.back())) out.push_back(v);
  }
  return out;
}

template <typename Tol>
std::size_t index_of(const std::vector<double>& sorted, double v, Tol tol) {
  auto it = std::lower_bound(sorted.begin(), sorted.end(), v - tol(v));
  // The merged representative is the smallest member of its group, within tol.
  return static_cast<std::size_t>(it - sorted.begin());
}

}  // namespace

MeanDriftTable parse_wamit_12d_mean_drift(std::istream& text, const std::string& file_name, double rho, double g,
                                          double ulen, double period_scale) {
  if (!(period_scale > 0.0) || !std::isfinite(period_scale)) {
    throw std::invalid_argument(fmt::format("WAMIT .12d: period_scale must be > 0, got {}", period_scale));
  }
  if (!(rho > 0.0) || !(g > 0.0) || !(ulen > 0.0) || !std::isfinite(rho * g * ulen)) {
    throw std::invalid_argument(
        fmt::format("WAMIT .12d: rho, g and ULEN must be > 0, got {} kg/m^3, {} m/s^2, {} m", rho, g, ulen));
  }
  std::vector<DiagonalEntry> diagonal;
  std::string line;
  std::size_t line_number = 0;
  bool seen_content = false;
  while (std::getline(text, line)) {
    ++line_number;
    const auto tokens = detail::split_whitespace(line, true);
    if (tokens.empty()) continue;
    double first = 0.0;
    if (!seen_content && !detail::parse_real(tokens[0], first)) {
      seen_content = true;  // a title line
      continue;
    }
    seen_content = true;
    if (tokens.size() != 9) {
      throw FileFormatError(
          file_name, line_number,
          fmt::format("expected 9 fields `PER1 PER2 BETA1 BETA2 I MOD PHS RE IM`, got {}", tokens.size()));
    }
    std::array<double, 9> v{};
    int dof = 0;
    for (std::size_t k = 0; k < 9; ++k) {
      if (k == 4) {
        if (!detail::parse_int(tokens[k], dof)) {
          throw FileFormatError(file_name, line_number,
                                fmt::format("field 5 (I, load component) must be an integer "
                                            "1..6, got \"{}\"",
                                            tokens[k]));
        }
        continue;
      }
      if (!detail::parse_real(tokens[k], v[k])) {
        static constexpr std::array<const char*, 9> kNames = {"PER1", "PER2", "BETA1", "BETA2", "I",
                                                              "MOD",  "PHS",  "RE",    "IM"};
        throw FileFormatError(
            file_name, line_number,
            fmt::format("field {} ({}) must be a finite real number, got \"{}\"", k + 1, kNames[k], tokens[k]));
      }
    }
    if (dof < 1 || dof > 6) {
      throw FileFormatError(
          file_name, line_number,
          fmt::format("load component I = {} outside 1..6 (multi-body files are not supported)", dof));
    }
    const double per1 = v[0];
    const double per2 = v[1];
    const bool same_period = std::abs(per1 - per2) <= kPeriodRelTolerance * std::max(std::abs(per1), std::abs(per2));
    const bool same_heading = std::abs(v[2] - v[3]) <= kHeadingTolerance_deg;
    if (!same_period || !same_heading) continue;  // off-diagonal: not a mean drift term
    if (!(per1 > 0.0)) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("period must be > 0 s on the diagonal, got {} s (WAMIT "
                                        "codes for zero/infinite period are not supported)",
                                        per1));
    }
    diagonal.push_back({per1, v[2], dof, v[7], line_number});
  }
  if (text.bad()) throw FileFormatError(file_name, line_number, "read error");
  if (diagonal.empty()) {
    throw FileFormatError(file_name, 0, "no diagonal (PER1 = PER2, BETA1 = BETA2) entries: no mean drift data");
  }

  const auto period_tol = [](double p) { return kPeriodRelTolerance * std::abs(p); };
  const auto heading_tol = [](double) { return kHeadingTolerance_deg; };
  std::vector<double> periods;
  std::vector<double> headings;
  for (const auto& e : diagonal) {
    periods.push_back(e.period_s);
    headings.push_back(e.heading_deg);
  }
  periods = distinct(std::move(periods), period_tol);
  headings = distinct(std::move(headings), heading_tol);
  const std::size_t np = periods.size();
  const std::size_t nb = headings.size();

  MeanDriftTable table;
  // Increasing frequency = decreasing period.
  for (std::size_t k = 0; k < np; ++k) {
    table.omega_rad_per_s.push_back(2.0 * std::numbers::pi / (periods[np - 1 - k] * period_scale));
  }
  for (double h : headings) table.headings_rad.push_back(h * std::numbers::pi / 180.0);

  std::array<std::vector<std::size_t>, 6> source_line;  // 0: not given
  for (const auto& e : diagonal) {
    const std::size_t i = static_cast<std::size_t>(e.dof - 1);
    if (!table.present[i]) {
      table.present[i] = true;
      table.coefficient[i] = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(np), static_cast<Eigen::Index>(nb));
      source_line[i].assign(np * nb, 0);
    }
    const std::size_t kp = index_of(periods, e.period_s, period_tol);
    const std::size_t row = np - 1 - kp;
    const std::size_t col = index_of(headings, e.heading_deg, heading_tol);
    // WAMIT normalisation of second-order loads: rho g ULEN^k, k = 1 forces, 2 moments.
    const double value = rho * g * std::pow(ulen, e.dof <= 3 ? 1 : 2) * e.re;
    std::size_t& seen = source_line[i][row * nb + col];
    auto& slot = table.coefficient[i](static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(col));
    if (seen != 0) {
      if (std::abs(slot - value) > 1e-9 * std::max(std::abs(slot), std::abs(value))) {
        throw FileFormatError(file_name, e.line,
                              fmt::format("diagonal entry I = {}, PER = {} s, BETA = {} deg repeats line {} with a "
                                          "different value",
                                          e.dof, e.period_s, e.heading_deg, seen));
      }
      continue;
    }
    seen = e.line;
    slot = value;
  }
  for (std::size_t i = 0; i < 6; ++i) {
    if (!table.present[i]) continue;
    for (std::size_t row = 0; row < np; ++row) {
      for (std::size_t col = 0; col < nb; ++col) {
        if (source_line[i][row * nb + col] == 0) {
          throw FileFormatError(file_name, 0,
                                fmt::format("incomplete mean drift diagonal: I = {} missing at PER = {} s, BETA = "
                                            "{} deg",
                                            i + 1, periods[np - 1 - row], headings[col]));
        }
      }
    }
  }
  return table;
}

MeanDriftTable read_wamit_12d_mean_drift(const std::filesystem::path& path, double rho, double g, double ulen,
                                         double period_scale) {
  std::ifstream in(path);
  if (!in) throw FileFormatError(path.string(), 0, "cannot open WAMIT .12d file");
  return parse_wamit_12d_mean_drift(in, path.string(), rho, g, ulen, period_scale);
}

}  // namespace spiral::engine
