#pragma once
// The OC4-DeepCwind chain line (NREL OC4 definition; MAP++ deck in
// shared/data/validation/oc4; hydrodynamic coefficients of the OpenFAST
// MoorDyn OC4 input: Cdn 2.0, Can 0.8, Cdt 0.4, Cat 0.25 on the volume-
// equivalent diameter 0.0766 m) as an FE line model with its static solution,
// for the FE dynamics tests and benchmarks.

#include <cmath>
#include <numbers>

#include "engine/lines/fe_line_dynamics.hpp"
#include "engine/lines/fe_line_statics.hpp"

namespace spiral::test {

inline constexpr double kOc4LineLength_m = 835.35;
inline constexpr double kOc4LineEA_N = 7.536e8;
inline constexpr double kOc4LineMass_kg_per_m = 113.35;
inline constexpr double kOc4LineDiameter_m = 0.0766;
inline constexpr double kOc4Depth_m = 200.0;

inline engine::FeLineModel oc4_fe_line(int elements) {
  const double area = std::numbers::pi / 4.0 * kOc4LineDiameter_m * kOc4LineDiameter_m;
  engine::FeLineSection s;
  s.length_m = kOc4LineLength_m;
  s.EA_N = kOc4LineEA_N;
  s.mass_kg_per_m = kOc4LineMass_kg_per_m;
  s.weight_N_per_m = (kOc4LineMass_kg_per_m - 1025.0 * area) * 9.80665;
  s.hydro_diameter_m = kOc4LineDiameter_m;
  s.drag_normal = 2.0;
  s.drag_tangential = 0.4;
  s.displaced_area_m2 = area;
  s.added_mass_normal = 0.8;
  s.added_mass_tangential = 0.25;
  s.element_length_m = kOc4LineLength_m / elements;
  engine::FeLineModel m;
  m.sections = {s};
  return m;
}

/// Seabed of the dynamics: penalty 1e6 N/m² per m of line (penetration
/// w/k ≈ 1 mm), contact damping 7.7e3 N·s/m² (MoorDyn's cBot 1e5 Pa·s/m times
/// the diameter: ≈ 0.36 of critical for the chain's mass).
inline engine::FeDynamicEnvironment oc4_dynamic_environment() {
  engine::FeDynamicEnvironment env;
  env.statics.water_density_kg_per_m3 = 1025.0;
  env.statics.seabed_z_m = -kOc4Depth_m;
  env.statics.seabed_stiffness_N_per_m2 = 1.0e6;
  env.seabed_damping_N_s_per_m2 = 7.7e3;
  return env;
}

/// Line L2 of OC4 in its own vertical plane: anchor at x = −837.6 m on the
/// seabed, fairlead at (−40.868, 0, −14) m.
inline engine::FeLineEnds oc4_line_ends() { return {{-837.6, 0.0, -200.0}, {-40.868, 0.0, -14.0}}; }

}  // namespace spiral::test
