#pragma once
// Internal to render3d: the 2D annotations drawn with cairo over a rendered
// view (title, utilization colour bar, scale bar, axes triad, depth scale).

#include <Eigen/Core>

#include "report/image.hpp"
#include "report/scene.hpp"

namespace spiral::report {

/// Where the world lands in the image: pixel = centre + ((p − target)·right,
/// −(p − target)·up) / m_per_px.
struct OverlayGeometry {
  Eigen::Vector3d right, up, target_g;
  double m_per_px = 1.0;
  double grid_step_m = 0.0;  ///< seabed grid spacing
};

void draw_view_overlay(Image& image, const Scene& scene, const Camera& camera, const OverlayGeometry& geometry,
                       const ViewOptions& options);

}  // namespace spiral::report
