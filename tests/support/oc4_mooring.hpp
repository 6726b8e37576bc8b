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

#include <memory>
#include <vector>

#include "engine/analysis/static_equilibrium.hpp"
#include "engine/analysis/static_line.hpp"

namespace spiral::test {

/// The OC4 mooring as static lines for the coupled analyses.
inline std::vector<std::unique_ptr<engine::StaticLine>> oc4_static_lines(double seabed_friction = 1.0) {
  std::vector<std::unique_ptr<engine::StaticLine>> lines;
  for (auto& model : oc4_mooring_system().lines) {
    model.line.seabed_friction = seabed_friction;
    lines.push_back(std::make_unique<engine::CatenaryStaticLine>(
        model.name, model.anchor_g, model.fairlead_b, model.anchor_height_above_seabed_m, model.line));
  }
  return lines;
}

/// The OC4 full system (platform + tower + RNA) hydrostatics as quoted in
/// shared/data/reference-platforms.md §1.2: C33 3.836e6 N/m (report),
/// C44 = C55 = 9.892e8 N·m/rad (buoyancy + gravity), rest force
/// ρgV − mg = 1.398911e8 − 1.40751e7·9.80665 N.
inline engine::HullStaticModel oc4_hull_statics() {
  engine::HullStaticModel hull;
  hull.hydrostatic_stiffness(2, 2) = 3.836e6;
  hull.hydrostatic_stiffness(3, 3) = 9.892e8;
  hull.hydrostatic_stiffness(4, 4) = 9.892e8;
  hull.rest_force(2) = 1.398911e8 - 1.40751e7 * 9.80665;
  return hull;
}

}  // namespace spiral::test
