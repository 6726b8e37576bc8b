#pragma once
// A minimal valid project (text) shared by the loader and validation tests;
// each test splices one error into it with replace().

#include <gtest/gtest.h>

#include <string>

namespace spiral::design {

/// A minimal valid project; tests splice in errors by text replacement.
inline const std::string kMinimal = R"(version: 1
name: minimal
site:
  depth: 100.0
  water_density: 1025.0
  gravity: 9.81
  seabed: {friction_axial: 1.0, friction_lateral: 1.0, normal_stiffness: 1.0e5}
line_types:
  - {name: c, kind: user, diameter: 0.1, mass_per_length: 100.0, axial_stiffness: 1.0e9, breaking_load: 5.0e6}
mooring:
  lines:
    - name: L1
      anchor: {radius: 500.0, azimuth_deg: 0.0}
      fairlead: [10.0, 0.0, -10.0]
      segments:
        - {type: c, length: 550.0}
hull:
  reference_point: [0.0, 0.0, 0.0]
  mass: 1.0e7
  center_of_gravity: [0.0, 0.0, -5.0]
  radii_of_gyration: [30.0, 30.0, 30.0]
  displaced_volume: 1.0e4
  center_of_buoyancy: [0.0, 0.0, -10.0]
  waterplane_area: 400.0
  waterplane_inertia: [1.0e5, 1.0e5]
environments:
  - name: calm
load_cases:
  - {name: lc1, environment: calm}
criteria:
  mooring: {code: api_rp_2sk}
)";

inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace spiral::design
