#include "engine/hull/wamit_3.hpp"
#include "engine/common/table_range_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
// Column-1 values of one frequency repeat the same printed digits (see wamit_1.cpp).
constexpr double kSameFrequencyRelTol = 1e-9;
// Headings are printed in degrees with >= 4 decimals; 1e-6 deg merges repeats only.
constexpr double kSameHeadingAbsTol_deg = 1e-6;
// A query heading counts as "on" a single-heading table within this angle.
/// A heading this far beyond the ends of the table takes the end value (the
/// hull's own equilibrium yaw; header comment).
constexpr double kHeadingEndHold_rad = 0.5 * kPi / 180.0;

struct Row {
  double omega = 0.0;
  double heading_deg = 0.0;
  int dof = 0;
  std::complex<double> value;
  std::size_t line = 0;
};

WaveTransferTable parse_transfer(std::istream& text, const std::string& file_name, const WamitReadOptions& options,
                                 TransferQuantity quantity) {
  const char* reader = quantity == TransferQuantity::excitation ? "wamit .3 reader" : "wamit .4 reader";
  detail::validate_wamit_options(options, reader);
  const bool period_column = options.frequency_column == FrequencyColumn::period_s;
  const char* column_name = period_column ? "PER" : "OMEGA";

  std::vector<Row> rows;
  std::string line;
  std::size_t line_number = 0;
  bool first_content_line = true;
  while (std::getline(text, line)) {
    ++line_number;
    const auto tokens = detail::split_whitespace(line);
    if (tokens.empty()) continue;
    double column1 = 0.0;
    const bool numeric_first = detail::parse_real(tokens[0], column1);
    if (first_content_line && !numeric_first) {
      first_content_line = false;
      continue;
    }
    first_content_line = false;
    if (tokens.size() != 7) {
      throw FileFormatError(
          file_name, line_number,
          fmt::format("expected 7 fields `{} BETA I MOD PHA RE IM`, got {}: \"{}\"", column_name, tokens.size(), line));
    }
    static constexpr std::array<const char*, 7> kNames = {"", "BETA", "I", "MOD", "PHA", "RE", "IM"};
    if (!numeric_first) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("{} must be a finite real number, got \"{}\"", column_name, tokens[0]));
    }
    std::array<double, 7> v{};
    v[0] = column1;
    int dof = 0;
    for (std::size_t f = 1; f < 7; ++f) {
      const bool ok = f == 2 ? detail::parse_int(tokens[f], dof) : detail::parse_real(tokens[f], v[f]);
      if (!ok) {
        throw FileFormatError(file_name, line_number,
                              fmt::format("{} must be {}, got \"{}\"", kNames[f],
                                          f == 2 ? "an integer" : "a finite real number", tokens[f]));
      }
    }
    if (dof < 1 || dof > 6) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("DOF index I must be in 1..6 (single body), got {}", dof));
    }
    if (!(column1 > 0.0)) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("{} must be > 0 {}, got {} (zero/infinite-frequency codes carry no "
                                        "first-order wave load)",
                                        column_name, period_column ? "s" : "rad/s", column1));
    }
    const double omega = (period_column ? 2.0 * kPi / column1 : column1) / options.period_scale;
    if (!std::isfinite(omega)) {
      // A period of 1e-310 s parses as a finite number; 2π over it does not.
      throw FileFormatError(file_name, line_number,
                            fmt::format("{} {} gives no finite frequency", column_name, column1));
    }
    rows.push_back({omega, v[1], dof, {v[5], v[6]}, line_number});
  }
  if (text.bad()) throw FileFormatError(file_name, line_number, "read error");
  if (rows.empty()) throw FileFormatError(file_name, 0, "no transfer-function rows found (empty file)");

  std::vector<double> omegas;
  std::vector<double> headings;
  omegas.reserve(rows.size());
  headings.reserve(rows.size());
  for (const auto& r : rows) {
    omegas.push_back(r.omega);
    headings.push_back(r.heading_deg);
  }
  omegas = detail::distinct_sorted(std::move(omegas), kSameFrequencyRelTol, 0.0);
  headings = detail::distinct_sorted(std::move(headings), 0.0, kSameHeadingAbsTol_deg);

  WaveTransferTable table;
  table.quantity = quantity;
  table.file = file_name;
  table.omega_rad_per_s = omegas;
  table.headings_rad.reserve(headings.size());
  for (double h : headings) table.headings_rad.push_back(h * kDeg);
  const auto nh = static_cast<Eigen::Index>(headings.size());
  const auto nw = static_cast<Eigen::Index>(omegas.size());
  std::array<Eigen::Matrix<std::size_t, Eigen::Dynamic, Eigen::Dynamic>, 6> seen;
  for (int d = 0; d < 6; ++d) {
    table.values[d] = Eigen::MatrixXcd::Zero(nh, nw);
    seen[d] = Eigen::Matrix<std::size_t, Eigen::Dynamic, Eigen::Dynamic>::Zero(nh, nw);
  }
  const double rho_g = options.water.density_kg_per_m3 * options.water.gravity_m_per_s2;
  for (const auto& r : rows) {
    const int iw = detail::index_in(omegas, r.omega, kSameFrequencyRelTol, 0.0);
    const int ih = detail::index_in(headings, r.heading_deg, 0.0, kSameHeadingAbsTol_deg);
    if (iw < 0 || ih < 0) {
      // Cannot happen: every row's value is on the grid made from the rows. Checked
      // all the same, because an index of -1 would write outside the table.
      throw FileFormatError(file_name, r.line, "frequency or heading not found on the table's grid");
    }
    const int d = r.dof - 1;
    auto& first = seen[d](ih, iw);
    if (first != 0) {
      throw FileFormatError(file_name, r.line,
                            fmt::format("I = {} at {} rad/s, BETA = {} deg given twice (first on "
                                        "line {})",
                                        r.dof, r.omega, r.heading_deg, first));
    }
    first = r.line;
    double scale = 1.0;
    if (quantity == TransferQuantity::excitation) {
      // WAMIT User Manual v7 §4.1: X = rho g L^m Xbar, m = 2 (forces), 3 (moments).
      scale = rho_g * std::pow(options.ulen_m, r.dof <= 3 ? 2 : 3);
    } else {
      // WAMIT User Manual v7 §4.1: xibar = xi / (A / L^n), n = 0 / 1 -> rotations xi/A = xibar / L.
      scale = r.dof <= 3 ? 1.0 : 1.0 / options.ulen_m;
    }
    table.values[d](ih, iw) = scale * r.value;
    table.dof_present[d] = true;
  }
  for (int d = 0; d < 6; ++d) {
    if (!table.dof_present[d]) continue;
    for (Eigen::Index ih = 0; ih < nh; ++ih) {
      for (Eigen::Index iw = 0; iw < nw; ++iw) {
        if (seen[d](ih, iw) == 0) {
          throw FileFormatError(file_name, 0,
                                fmt::format("incomplete table: I = {} missing at {} = {:.6g} {}, BETA = {} deg "
                                            "(every DOF present must be given at every frequency and heading)",
                                            d + 1, column_name,
                                            period_column ? 2.0 * kPi / (omegas[iw] * options.period_scale)
                                                          : omegas[iw] * options.period_scale,
                                            period_column ? "s" : "rad/s", headings[ih]));
        }
      }
    }
  }
  return table;
}

WaveTransferTable read_transfer(const std::filesystem::path& file, const WamitReadOptions& options,
                                TransferQuantity quantity) {
  std::ifstream in(file);
  if (!in) {
    throw FileFormatError(file.string(), 0,
                          quantity == TransferQuantity::excitation ? "cannot open WAMIT excitation (.3) file"
                                                                   : "cannot open WAMIT RAO (.4) file");
  }
  return parse_transfer(in, file.string(), options, quantity);
}

// Bracketing index j (values[j-1] <= x <= values[j]) and weight of values[j];
// held at the ends.
void bracket(const std::vector<double>& grid, double x, Eigen::Index& lo, Eigen::Index& hi, double& s) {
  if (grid.size() == 1 || x <= grid.front()) {
    lo = hi = 0;
    s = 0.0;
    return;
  }
  if (x >= grid.back()) {
    lo = hi = static_cast<Eigen::Index>(grid.size() - 1);
    s = 0.0;
    return;
  }
  const auto j = static_cast<Eigen::Index>(std::upper_bound(grid.begin(), grid.end(), x) - grid.begin());
  lo = j - 1;
  hi = j;
  s = (x - grid[lo]) / (grid[hi] - grid[lo]);
}

}  // namespace

ExcitationTable parse_wamit_3(std::istream& text, const std::string& file_name, const WamitReadOptions& options) {
  return parse_transfer(text, file_name, options, TransferQuantity::excitation);
}

ExcitationTable read_wamit_3(const std::filesystem::path& file, const WamitReadOptions& options) {
  return read_transfer(file, options, TransferQuantity::excitation);
}

MotionRaoTable parse_wamit_4(std::istream& text, const std::string& file_name, const WamitReadOptions& options) {
  return parse_transfer(text, file_name, options, TransferQuantity::motion_rao);
}

MotionRaoTable read_wamit_4(const std::filesystem::path& file, const WamitReadOptions& options) {
  return read_transfer(file, options, TransferQuantity::motion_rao);
}

Vector6cd transfer_at(const WaveTransferTable& table, double omega_rad_per_s, double heading_rad) {
  if (!std::isfinite(omega_rad_per_s) || !std::isfinite(heading_rad)) {
    throw std::invalid_argument(fmt::format(
        "transfer_at: frequency and heading must be finite, got {} rad/s and {} rad", omega_rad_per_s, heading_rad));
  }
  if (table.omega_rad_per_s.empty() || table.headings_rad.empty()) {
    throw std::invalid_argument("transfer_at: the transfer table is empty");
  }
  const auto& h = table.headings_rad;
  const double h_min = h.front();
  const double h_max = h.back();
  // Wrap into [h_min, h_min + 2 pi).
  double b = h_min + std::fmod(heading_rad - h_min, 2.0 * kPi);
  if (b < h_min) b += 2.0 * kPi;
  if (h.size() == 1) {
    const double gap = std::min(std::abs(b - h_min), std::abs(b - h_min - 2.0 * kPi));
    if (gap > kHeadingEndHold_rad) {
      throw TableRangeError(fmt::format("heading {:.6g} deg outside the database range [{:.6g}, {:.6g}] deg (table {})",
                                        heading_rad / kDeg, h_min / kDeg, h_max / kDeg, table.file));
    }
    b = h_min;
  } else if (b > h_max + kHeadingEndHold_rad && b < h_min + 2.0 * kPi - kHeadingEndHold_rad) {
    throw TableRangeError(fmt::format("heading {:.6g} deg outside the database range [{:.6g}, {:.6g}] deg (table {})",
                                      heading_rad / kDeg, h_min / kDeg, h_max / kDeg, table.file));
  }
  if (b > h_max) b = (b - h_max <= kHeadingEndHold_rad) ? h_max : h_min;
  Eigen::Index w0, w1, b0, b1;
  double sw, sb;
  bracket(table.omega_rad_per_s, omega_rad_per_s, w0, w1, sw);
  bracket(h, b, b0, b1, sb);
  Vector6cd out;
  for (int d = 0; d < 6; ++d) {
    const auto& m = table.values[d];
    const std::complex<double> lo = (1.0 - sw) * m(b0, w0) + sw * m(b0, w1);
    const std::complex<double> hi = (1.0 - sw) * m(b1, w0) + sw * m(b1, w1);
    out(d) = (1.0 - sb) * lo + sb * hi;
  }
  return out;
}

}  // namespace spiral::engine
