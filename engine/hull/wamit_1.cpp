#include "engine/hull/wamit_1.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <stdexcept>

namespace spiral::engine {
namespace {

// Periods/frequencies are printed with ~6 significant digits; rows of the same
// frequency repeat the same digits, so a relative match of 1e-9 separates
// neighbouring frequencies (relative spacing >= 1e-4 in practice) and merges
// only true repeats.
constexpr double kSameFrequencyRelTol = 1e-9;

enum class RowKind { regular, infinite_frequency, zero_frequency };

struct Block {
  Matrix6d added_mass = Matrix6d::Zero();
  Matrix6d damping = Matrix6d::Zero();
  std::array<std::array<std::size_t, 6>, 6> seen_on_line{};
};

Matrix6d interpolate(const std::vector<double>& omega, const std::vector<Matrix6d>& values, double w,
                     const char* what) {
  if (!std::isfinite(w)) {
    throw std::invalid_argument(fmt::format("{}: frequency must be finite, got {} rad/s", what, w));
  }
  if (omega.empty()) {
    throw std::invalid_argument(fmt::format("{}: the coefficient table is empty", what));
  }
  if (w <= omega.front()) return values.front();
  if (w >= omega.back()) return values.back();
  const auto upper = std::upper_bound(omega.begin(), omega.end(), w);
  const std::size_t j = static_cast<std::size_t>(upper - omega.begin());
  const double s = (w - omega[j - 1]) / (omega[j] - omega[j - 1]);
  return (1.0 - s) * values[j - 1] + s * values[j];
}

}  // namespace

int wamit_radiation_length_exponent(int i, int j) {
  if (i < 1 || i > 6 || j < 1 || j > 6) {
    throw std::invalid_argument(
        fmt::format("wamit_radiation_length_exponent: indices must be in 1..6, got ({}, {})", i, j));
  }
  // WAMIT User Manual v7 §4.1: k = 3 + one per rotational index.
  return 3 + (i >= 4 ? 1 : 0) + (j >= 4 ? 1 : 0);
}

HydroCoefficients parse_wamit_1(std::istream& text, const std::string& file_name, const WamitReadOptions& options) {
  detail::validate_wamit_options(options, "wamit .1 reader");
  const double rho = options.water.density_kg_per_m3;
  const bool period_column = options.frequency_column == FrequencyColumn::period_s;
  const char* column_name = period_column ? "PER" : "OMEGA";

  // Regular rows keyed by the column-1 value as read; limits separately.
  std::vector<std::pair<double, Block>> regular;  // (omega, block), in file order
  std::optional<Block> infinite;
  std::optional<Block> zero;
  std::size_t rows = 0;

  std::string line;
  std::size_t line_number = 0;
  bool first_content_line = true;
  while (std::getline(text, line)) {
    ++line_number;
    const auto tokens = detail::split_whitespace(line);
    if (tokens.empty()) continue;
    double column1 = 0.0;
    const bool numeric_first = detail::parse_real(tokens[0], column1);
    if (first_content_line && !numeric_first) {  // title line (NEMOH/Capytaine exporters)
      first_content_line = false;
      continue;
    }
    first_content_line = false;
    if (tokens.size() != 4 && tokens.size() != 5) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("expected 5 fields `{} I J Abar Bbar` (Bbar may be absent "
                                        "on limit rows), got {}: \"{}\"",
                                        column_name, tokens.size(), line));
    }
    if (!numeric_first) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("{} must be a finite real number, got \"{}\"", column_name, tokens[0]));
    }
    int i = 0;
    int j = 0;
    if (!detail::parse_int(tokens[1], i) || !detail::parse_int(tokens[2], j)) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("DOF indices I J must be integers, got \"{}\" \"{}\"", tokens[1], tokens[2]));
    }
    if (i < 1 || j < 1 || i > 6 || j > 6) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("DOF indices must be in 1..6 (single body), got ({}, {})", i, j));
    }
    double a_bar = 0.0;
    if (!detail::parse_real(tokens[3], a_bar)) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("Abar({},{}) must be a finite real number, got \"{}\"", i, j, tokens[3]));
    }
    double b_bar = 0.0;
    if (tokens.size() == 5 && !detail::parse_real(tokens[4], b_bar)) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("Bbar({},{}) must be a finite real number, got \"{}\"", i, j, tokens[4]));
    }

    RowKind kind = RowKind::regular;
    double omega = 0.0;
    if (period_column) {
      if (column1 == 0.0) {
        kind = RowKind::infinite_frequency;
      } else if (column1 < 0.0) {
        kind = RowKind::zero_frequency;
      } else {
        omega = 2.0 * std::numbers::pi / (column1 * options.period_scale);
        if (!std::isfinite(omega)) {
          // A period of 1e-310 s parses as a finite number; 2π over it does not.
          throw FileFormatError(file_name, line_number,
                                fmt::format("{} {} gives no finite frequency", column_name, column1));
        }
      }
    } else {
      if (column1 == 0.0) {
        kind = RowKind::zero_frequency;
      } else if (column1 < 0.0) {
        throw FileFormatError(file_name, line_number,
                              fmt::format("OMEGA must be >= 0 rad/s in a frequency-column file, "
                                          "got {} (no infinite-frequency code is defined for "
                                          "this layout)",
                                          column1));
      } else {
        omega = column1 / options.period_scale;
      }
    }
    if (kind == RowKind::regular && tokens.size() != 5) {
      throw FileFormatError(
          file_name, line_number,
          fmt::format("expected 5 fields `{} I J Abar Bbar` on a finite-frequency row, got 4", column_name));
    }

    Block* block = nullptr;
    if (kind == RowKind::infinite_frequency) {
      if (!infinite) infinite.emplace();
      block = &*infinite;
    } else if (kind == RowKind::zero_frequency) {
      if (!zero) zero.emplace();
      block = &*zero;
    } else {
      auto it = std::find_if(regular.rbegin(), regular.rend(), [&](const auto& entry) {
        return std::abs(entry.first - omega) <= kSameFrequencyRelTol * omega;
      });
      if (it == regular.rend()) {
        regular.emplace_back(omega, Block{});
        block = &regular.back().second;
      } else {
        block = &it->second;
      }
    }
    auto& seen = block->seen_on_line[i - 1][j - 1];
    if (seen != 0) {
      throw FileFormatError(
          file_name, line_number,
          fmt::format("({},{}) at {} = {} given twice (first on line {})", i, j, column_name, column1, seen));
    }
    seen = line_number;
    // WAMIT User Manual v7 §4.1: A = rho L^k Abar, B = rho L^k w Bbar.
    const double scale = rho * std::pow(options.ulen_m, wamit_radiation_length_exponent(i, j));
    block->added_mass(i - 1, j - 1) = scale * a_bar;
    if (kind == RowKind::regular) block->damping(i - 1, j - 1) = scale * omega * b_bar;
    ++rows;
  }
  if (text.bad()) throw FileFormatError(file_name, line_number, "read error");
  if (rows == 0) throw FileFormatError(file_name, 0, "no coefficients found (empty .1 file)");

  std::sort(regular.begin(), regular.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  HydroCoefficients out;
  out.file = file_name;
  out.omega_rad_per_s.reserve(regular.size());
  for (const auto& [omega, block] : regular) {
    out.omega_rad_per_s.push_back(omega);
    out.added_mass.push_back(block.added_mass);
    out.damping.push_back(block.damping);
  }
  if (infinite) out.added_mass_infinite = infinite->added_mass;
  if (zero) out.added_mass_zero = zero->added_mass;
  return out;
}

HydroCoefficients read_wamit_1(const std::filesystem::path& file, const WamitReadOptions& options) {
  std::ifstream in(file);
  if (!in) throw FileFormatError(file.string(), 0, "cannot open WAMIT .1 file");
  return parse_wamit_1(in, file.string(), options);
}

Matrix6d added_mass_at(const HydroCoefficients& c, double omega_rad_per_s) {
  return interpolate(c.omega_rad_per_s, c.added_mass, omega_rad_per_s, "added_mass_at");
}

Matrix6d damping_at(const HydroCoefficients& c, double omega_rad_per_s) {
  return interpolate(c.omega_rad_per_s, c.damping, omega_rad_per_s, "damping_at");
}

}  // namespace spiral::engine
