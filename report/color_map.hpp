#pragma once
// The colour map of utilization in 3D views, colour bars and bar charts:
// viridis (van der Walt & Smith, matplotlib 2.0; perceptually uniform and
// readable by colour-blind readers and in greyscale) over [0, 1], and one
// distinct red for values above 1 (a failed check must not look like a
// slightly brighter pass).

#include "report/image.hpp"

namespace spiral::report {

/// Colour of a utilization: viridis on [0, 1] (values below 0 clamp to 0),
/// kFailColor above 1.
Rgb utilization_color(double utilization);

inline constexpr Rgb kFailColor{0.84, 0.15, 0.16};
inline constexpr Rgb kPassColor{0.17, 0.55, 0.25};

/// Viridis on [0, 1], clamped.
Rgb viridis(double t);

}  // namespace spiral::report
