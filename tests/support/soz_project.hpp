#pragma once
// A small riser project for the SOZ tests: 400 m of water, steel catenary
// risers of the default scenario's production section (273.1 × 25.4 mm, oil),
// 12° top angle, 5 m elements refined to 1 m over 120 m around the TDP.
// At rest: top tension ≈ 0.63 MN, touchdown ≈ 230 m from the hang-off
// (inextensible catenary a = Z / (1/cos 78° − 1) ≈ 99 m).

#include <string>

namespace spiral::test {

inline std::string soz_riser_yaml(const std::string& name, double azimuth_deg, double hang_off_radius_m = 0.0,
                                  const std::string& extra = "") {
  return "  - name: " + name + "\n    kind: scr\n    hang_off: {radius: " + std::to_string(hang_off_radius_m) +
         ", azimuth_deg: " + std::to_string(azimuth_deg) +
         ", z: -20.0}\n    azimuth_deg: " + std::to_string(azimuth_deg) +
         "\n    top_angle_deg: 12.0\n    sections:\n"
         "      - {length: 700.0, outer_diameter: 0.2731, wall_thickness: 0.0254, youngs_modulus: "
         "2.07e11,\n"
         "         yield_stress: 4.48e8, steel_density: 7850.0, contents_density: 800.0}\n"
         "    fe: {element_length: 5.0, touchdown_refinement: {length: 120.0, element_length: "
         "1.0}}\n" +
         extra;
}

/// The project text with the given `risers:` entries and riser criteria.
inline std::string soz_project_yaml(const std::string& risers, const std::string& criteria =
                                                                   "    min_effective_tension: 0.0\n"
                                                                   "    max_top_tension: 0.9e6\n"
                                                                   "    max_top_angle_deg: 16.0\n") {
  return R"(version: 1
name: soz-test
site:
  depth: 400.0
  water_density: 1025.0
  gravity: 9.80665
  seabed: {friction_axial: 0.5, friction_lateral: 0.5, normal_stiffness: 1.0e5}
line_types:
  - {name: c, kind: user, diameter: 0.1, mass_per_length: 100.0, axial_stiffness: 1.0e9, breaking_load: 5.0e6}
mooring:
  lines:
    - name: L1
      anchor: {radius: 1200.0, azimuth_deg: 180.0}
      fairlead: {radius: 10.0, azimuth_deg: 180.0, z: -10.0}
      segments:
        - {type: c, length: 1250.0}
hull:
  reference_point: [0.0, 0.0, 0.0]
  mass: 1.0e7
  center_of_gravity: [0.0, 0.0, -5.0]
  radii_of_gyration: [30.0, 30.0, 30.0]
  displaced_volume: 1.0e4
  center_of_buoyancy: [0.0, 0.0, -10.0]
  waterplane_area: 400.0
  waterplane_inertia: [1.0e5, 1.0e5]
risers:
)" + risers +
         R"(environments:
  - name: calm
  - name: current-east
    current:
      heading_deg: 0.0
      profile: [[0.0, 1.0], [-400.0, 0.5]]
load_cases:
  - {name: lc1, environment: calm, condition: normal}
  - {name: lc2, environment: current-east, condition: extreme}
criteria:
  mooring: {code: api_rp_2sk}
  risers:
)" + criteria;
}

}  // namespace spiral::test
