#pragma once
// Cell and naming helpers shared by the stage report sections.

#include <fmt/format.h>

#include <cctype>
#include <string>

#include "report/document.hpp"

namespace spiral::report {

/// A number shown with `decimals` decimals (times `scale`); the CSV keeps full precision.
inline TableCell num(double value, int decimals, double scale = 1.0) {
  return {fmt::format("{:.{}f}", value * scale, decimals), value * scale, CellStatus::none};
}
inline TableCell text(std::string s) { return {std::move(s), std::nullopt, CellStatus::none}; }
inline TableCell verdict(bool pass) {
  return {pass ? "PASS" : "FAIL", std::nullopt, pass ? CellStatus::pass : CellStatus::fail};
}
/// A file-stem-safe id: [a-z0-9-].
inline std::string slug(std::string s) {
  for (char& c : s) c = std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '-';
  return s;
}

}  // namespace spiral::report
