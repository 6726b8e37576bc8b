#pragma once
// The OC4-DeepCwind mooring (three catenary chain lines in 200 m) and hull
// statics as engine models, built from the MAP++ deck in
// shared/data/validation/oc4/ and reference-platforms.md so that the engine
// tests do not depend on the project loader.

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "engine/analysis/static_equilibrium.hpp"
#include "engine/analysis/static_line.hpp"
#include "engine/lines/fe_line_statics.hpp"

namespace spiral::test {

struct Oc4Line {
  std::string name;
  Eigen::Vector3d anchor_g;
  Eigen::Vector3d fairlead_b;
  engine::CatenaryLine line;
};

inline std::vector<Oc4Line> oc4_lines(double seabed_friction = 1.0) {
  constexpr double kDepth_m = 200.0;
  constexpr double kAnchorRadius_m = 837.6;
  constexpr double kFairleadRadius_m = 40.868;
  constexpr double kFairleadZ_m = -14.0;
  // Wet weight as in shared/data/validation/README.md: (113.35 - 1025 pi/4 0.0766^2) g, g = 9.80665.
  const double weight_N_per_m = (113.35 - 1025.0 * std::numbers::pi / 4.0 * 0.0766 * 0.0766) * 9.80665;
  std::vector<Oc4Line> lines;
  const char* names[] = {"L1", "L2", "L3"};
  const double azimuths_deg[] = {60.0, 180.0, 300.0};
  for (int i = 0; i < 3; ++i) {
    const double a = azimuths_deg[i] * std::numbers::pi / 180.0;
    Oc4Line line;
    line.name = names[i];
    line.anchor_g = {kAnchorRadius_m * std::cos(a), kAnchorRadius_m * std::sin(a), -kDepth_m};
    line.fairlead_b = {kFairleadRadius_m * std::cos(a), kFairleadRadius_m * std::sin(a), kFairleadZ_m};
    line.line.segments = {{835.35, weight_N_per_m, 7.536e8}};
    line.line.seabed_friction = seabed_friction;  // MAP++ CB = 1.0
    lines.push_back(line);
  }
  return lines;
}

/// The OC4 mooring as static lines for the coupled analyses.
inline std::vector<std::unique_ptr<engine::StaticLine>> oc4_static_lines(double seabed_friction = 1.0) {
  std::vector<std::unique_ptr<engine::StaticLine>> lines;
  for (const Oc4Line& l : oc4_lines(seabed_friction)) {
    lines.push_back(std::make_unique<engine::CatenaryStaticLine>(l.name, l.anchor_g, l.fairlead_b, 0.0, l.line));
  }
  return lines;
}

/// The first OC4 chain as an FE line: 835.35 m in 40 elements, EA and mass
/// of the MAP deck's chain, normal drag 2 and added mass 1 on 0.0766 m.
/// (Added mass acts in the dynamics only.)
inline engine::FeLineModel oc4_fe_chain_model() {
  engine::FeLineSection section;
  section.length_m = 835.35;
  section.EA_N = 7.536e8;
  section.weight_N_per_m = oc4_lines(0.0).front().line.segments[0].weight_N_per_m;
  section.mass_kg_per_m = 113.35;
  section.hydro_diameter_m = 0.0766;
  section.drag_normal = 2.0;
  section.added_mass_normal = 1.0;
  section.element_length_m = 835.35 / 40.0;
  engine::FeLineModel model;
  model.sections = {section};
  return model;
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
