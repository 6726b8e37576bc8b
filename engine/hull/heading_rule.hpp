#pragma once
// The heading rule of the hull's heading tables (mean_environmental_loads.hpp,
// "Relative heading"): angles wrapped into [0, 2π), and a table periodic —
// interpolated across the wrap-around gap from its last heading to its first
// — when that gap is no wider than its widest interior gap. Shared by the
// loads' interpolation and the drift table's symmetry images and fill
// (mean_drift_headings.hpp), which must agree on what gets interpolated.

#include <vector>

namespace spiral::engine {

/// Headings closer than this count as one (degrees written to 5–6 digits).
inline constexpr double kHeadingTolerance_rad = 1e-6;

/// `angle_rad` wrapped into [0, 2π); an angle within `snap_rad` below 2π is 0.
double wrap_0_2pi(double angle_rad, double snap_rad = 0.0);

/// Whether the table with these headings (strictly increasing, last − first
/// < 2π) interpolates across its wrap-around gap: more than one heading, and
/// the gap no wider than the widest interior gap (+ kHeadingTolerance_rad).
bool wraps_around(const std::vector<double>& headings_rad);

/// The widest gap the rule interpolates across: the interior gaps, and the
/// wrap-around one when wraps_around(); 0 for fewer than two headings.
double widest_interpolated_gap(const std::vector<double>& headings_rad);

}  // namespace spiral::engine
