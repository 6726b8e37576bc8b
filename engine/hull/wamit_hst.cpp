#include "engine/hull/wamit_format.hpp"
#include "engine/hull/wamit_hst.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace spiral::engine {
namespace {}  // namespace

int wamit_hst_length_exponent(int i, int j) {
  if (i < 1 || i > 6 || j < 1 || j > 6) {
    throw std::invalid_argument(fmt::format("wamit_hst_length_exponent: indices must be in 1..6, got ({}, {})", i, j));
  }
  // WAMIT User Manual v7 §4.1/§4.3: k = 2 for (3,3), 3 for heave-rotation pairs,
  // 4 for rotation-rotation pairs: two plus one per rotational index.
  return 2 + (i >= 4 ? 1 : 0) + (j >= 4 ? 1 : 0);
}

WamitHstData parse_wamit_hst(std::istream& text, const std::string& file_name, const WamitHstScaling& scaling) {
  if (!(scaling.ulen_m > 0.0) || !std::isfinite(scaling.ulen_m)) {
    throw std::invalid_argument(fmt::format("wamit_hst.ulen_m: must be > 0, got {} m", scaling.ulen_m));
  }
  if (!(scaling.water.density_kg_per_m3 > 0.0) || !(scaling.water.gravity_m_per_s2 > 0.0)) {
    throw std::invalid_argument(
        fmt::format("wamit_hst.water: density and gravity must be > 0, got {} kg/m^3 and {} m/s^2",
                    scaling.water.density_kg_per_m3, scaling.water.gravity_m_per_s2));
  }
  WamitHstData data;
  data.file = file_name;
  std::array<std::array<std::size_t, 6>, 6> seen_on_line{};  // 0: not seen yet
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(text, line)) {
    ++line_number;
    const auto tokens = detail::split_whitespace(line);
    if (tokens.empty()) continue;
    if (tokens.size() != 3) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("expected 3 fields `I J C(I,J)`, got {}: \"{}\"", tokens.size(), line));
    }
    int i = 0;
    int j = 0;
    double value = 0.0;
    if (!detail::parse_int(tokens[0], i) || !detail::parse_int(tokens[1], j)) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("DOF indices must be integers, got \"{}\" \"{}\"", tokens[0], tokens[1]));
    }
    if (i < 1 || j < 1) {
      throw FileFormatError(file_name, line_number, fmt::format("DOF indices must be in 1..6, got ({}, {})", i, j));
    }
    if (i > 6 || j > 6) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("DOF index ({}, {}) above 6: multi-body or generalised-mode .hst files "
                                        "are not supported",
                                        i, j));
    }
    if (!detail::parse_real(tokens[2], value)) {
      throw FileFormatError(file_name, line_number,
                            fmt::format("C({},{}) must be a finite real number, got \"{}\"", i, j, tokens[2]));
    }
    auto& seen = seen_on_line[i - 1][j - 1];
    if (seen != 0) {
      throw FileFormatError(file_name, line_number, fmt::format("C({},{}) given twice (first on line {})", i, j, seen));
    }
    seen = line_number;
    data.nondimensional(i - 1, j - 1) = value;
    data.restoring_6x6(i - 1, j - 1) = scaling.water.density_kg_per_m3 * scaling.water.gravity_m_per_s2 *
                                       std::pow(scaling.ulen_m, wamit_hst_length_exponent(i, j)) * value;
    ++data.entries_read;
  }
  if (text.bad()) {
    throw FileFormatError(file_name, line_number, "read error");
  }
  if (data.entries_read == 0) {
    throw FileFormatError(file_name, 0, "no coefficients found (empty .hst file)");
  }
  return data;
}

WamitHstData read_wamit_hst(const std::filesystem::path& file, const WamitHstScaling& scaling) {
  std::ifstream in(file);
  if (!in) {
    throw FileFormatError(file.string(), 0, "cannot open WAMIT .hst file");
  }
  return parse_wamit_hst(in, file.string(), scaling);
}

}  // namespace spiral::engine
