#include "report/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace spiral::report {

namespace {
// matplotlib viridis sampled at 0, 0.1, …, 1 (#440154 … #FDE725).
constexpr std::array<std::array<int, 3>, 11> kViridis = {{{0x44, 0x01, 0x54},
                                                          {0x48, 0x24, 0x75},
                                                          {0x41, 0x44, 0x87},
                                                          {0x35, 0x5F, 0x8D},
                                                          {0x2A, 0x78, 0x8E},
                                                          {0x21, 0x91, 0x8C},
                                                          {0x22, 0xA8, 0x84},
                                                          {0x44, 0xBF, 0x70},
                                                          {0x7A, 0xD1, 0x51},
                                                          {0xBD, 0xDF, 0x26},
                                                          {0xFD, 0xE7, 0x25}}};
}  // namespace

Rgb viridis(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  const double x = t * 10.0;
  const int i = std::min(9, static_cast<int>(std::floor(x)));
  const double f = x - i;
  const auto& a = kViridis[static_cast<std::size_t>(i)];
  const auto& b = kViridis[static_cast<std::size_t>(i + 1)];
  return {((1 - f) * a[0] + f * b[0]) / 255.0, ((1 - f) * a[1] + f * b[1]) / 255.0,
          ((1 - f) * a[2] + f * b[2]) / 255.0};
}

Rgb utilization_color(double utilization) { return utilization > 1.0 ? kFailColor : viridis(utilization); }

}  // namespace spiral::report
