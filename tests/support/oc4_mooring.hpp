#pragma once
// The OC4-DeepCwind mooring (three catenary chain lines in 200 m) as an engine
// model, built from the MAP++ deck in shared/data/validation/oc4/ so that the
// engine tests do not depend on the project loader.

#include <cmath>
#include <numbers>

#include "engine/analysis/mooring_statics.hpp"

namespace spiral::test {

inline engine::MooringSystemModel oc4_mooring_system() {
  constexpr double kDepth_m = 200.0;
  constexpr double kAnchorRadius_m = 837.6;
  constexpr double kFairleadRadius_m = 40.868;
  constexpr double kFairleadZ_m = -14.0;
  // Wet weight as in shared/data/validation/README.md: (113.35 - 1025 pi/4 0.0766^2) g, g = 9.80665.
  const double weight_N_per_m =
      (113.35 - 1025.0 * std::numbers::pi / 4.0 * 0.0766 * 0.0766) * 9.80665;
  engine::MooringSystemModel system;
  const char* names[] = {"L1", "L2", "L3"};
  const double azimuths_deg[] = {60.0, 180.0, 300.0};
  for (int i = 0; i < 3; ++i) {
    const double a = azimuths_deg[i] * std::numbers::pi / 180.0;
    engine::MooringLineModel line;
    line.name = names[i];
    line.anchor_g = {kAnchorRadius_m * std::cos(a), kAnchorRadius_m * std::sin(a), -kDepth_m};
    line.fairlead_b = {kFairleadRadius_m * std::cos(a), kFairleadRadius_m * std::sin(a), kFairleadZ_m};
    line.line.segments = {{835.35, weight_N_per_m, 7.536e8}};
    line.line.seabed_friction = 1.0;  // MAP++ CB
    system.lines.push_back(line);
  }
  return system;
}

}  // namespace spiral::test
