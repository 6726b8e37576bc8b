#include "engine/hull/heading_rule.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace spiral::engine {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double widest_interior_gap(const std::vector<double>& h) {
  double widest = 0.0;
  for (std::size_t j = 1; j < h.size(); ++j) widest = std::max(widest, h[j] - h[j - 1]);
  return widest;
}

}  // namespace

double wrap_0_2pi(double angle_rad, double snap_rad) {
  double a = std::fmod(angle_rad, kTwoPi);
  if (a < 0.0) a += kTwoPi;
  return a >= kTwoPi - snap_rad ? 0.0 : a;
}

bool wraps_around(const std::vector<double>& headings_rad) {
  if (headings_rad.size() < 2) return false;
  const double wrap_gap = headings_rad.front() + kTwoPi - headings_rad.back();
  return wrap_gap <= widest_interior_gap(headings_rad) + kHeadingTolerance_rad;
}

double widest_interpolated_gap(const std::vector<double>& headings_rad) {
  const double widest = widest_interior_gap(headings_rad);
  if (!wraps_around(headings_rad)) return widest;
  return std::max(widest, headings_rad.front() + kTwoPi - headings_rad.back());
}

}  // namespace spiral::engine
