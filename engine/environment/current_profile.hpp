#pragma once
// Depth profile of a uni-directional current (DESIGN.md §5: "current: depth
// profile (interpolated)").
//
// The profile is a table of (z, speed) with one heading for all depths:
//   - z in the global frame (m, z up, 0 at mean water level, seabed at -depth),
//     strictly increasing;
//   - speed >= 0 m/s; the velocity points along heading_rad (direction of
//     propagation, CCW from global +x, DESIGN.md §4) and is horizontal.
// Between table points the speed is interpolated linearly in z; beyond the
// ends (above the top point, below the bottom point) it is held at the end
// value. A one-point table is a uniform current. Veering (heading varying with
// depth) is not modelled.
//
// power_law_current_profile() builds such a table from OpenFAST's sub-surface
// current (HydroDyn Current.f90, shared/data/reference-platforms.md §2.6):
//   V(z) = V0 ((z + h) / h)^(1/7)   for -h <= z <= 0   (h = water depth)
// i.e. the classical 1/7 power law of DNV-RP-C205 §4.1.4 (tidal current,
// exponent alpha = 1/7 typical) measured from the seabed.
//
// Errors: std::invalid_argument naming the field and its unit.

#include <Eigen/Core>
#include <vector>

namespace spiral::engine {

struct CurrentProfile {
  std::vector<double> z_m;            ///< strictly increasing, finite
  std::vector<double> speed_m_per_s;  ///< same size as z_m, each >= 0
  double heading_rad = 0.0;           ///< direction of propagation, CCW from +x
};

/// Throws std::invalid_argument if the table is empty, sizes differ, z is not
/// strictly increasing or a value is not finite / speed < 0.
void validate_current_profile(const CurrentProfile& profile);

/// Horizontal current velocity (m/s, global frame, z component 0) at height z (m).
Eigen::Vector3d current_velocity_g(const CurrentProfile& profile, double z_m);

struct PowerLawCurrentInput {
  double surface_speed_m_per_s = 0.0;  ///< V0 at z = 0, >= 0
  double water_depth_m = 0.0;          ///< h > 0
  double heading_rad = 0.0;            ///< direction of propagation
  double exponent = 1.0 / 7.0;         ///< > 0 (OpenFAST and DNV-RP-C205: 1/7)
  int points = 21;                     ///< table points from -h to 0, >= 2
};

/// Table of V(z) = V0 ((z + h)/h)^exponent at `points` depths evenly spaced
/// from the seabed (-h, speed 0) to the surface (0, V0). The linear
/// interpolation of the table under-estimates the curve between points (the
/// power law is concave); use more points near the seabed if that matters.
CurrentProfile power_law_current_profile(const PowerLawCurrentInput& input);

}  // namespace spiral::engine
