#pragma once
// What a 3D view shows, in the global frame (DESIGN.md §4: origin at mean
// water level, z up, seabed at z = −depth), and how it is looked at. Built
// from results by the stage reports (report/stage_scene.hpp); the renderer
// (report/render3d.hpp) only draws it.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "design/project/project.hpp"
#include "engine/hull/wamit_gdf.hpp"
#include "report/image.hpp"

namespace spiral::report {

/// A line or riser as a polyline with a colour-mapped value per point.
struct SceneLine {
  std::string name;
  std::vector<Eigen::Vector3d> points_g;  ///< m, anchor (or riser end) to the hull
  std::vector<double> values;             ///< per point, mapped by utilization_color(); empty: `color`
  Rgb color{0.55, 0.55, 0.58};            ///< used when `values` is empty
  bool riser = false;                     ///< drawn thinner (and with its own key in the legend)
};

/// The hull: member geometry in the body frame and the body pose.
struct SceneHull {
  std::optional<design::HullGeometry> geometry;  ///< absent: a box (below)
  /// Panels of the project's panel mesh (body frame, full surface): drawn as
  /// the hull instead of the members or the box when not empty.
  std::vector<engine::Panel> panels_b;
  Eigen::Vector3d box_size_m{60.0, 60.0, 40.0};  ///< box when no geometry: x, y, z extent
  double box_bottom_b_m = -25.0;                 ///< body z of the box bottom
  Eigen::Vector3d reference_point_g = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< body -> global
};

struct Scene {
  double depth_m = 1000.0;  ///< > 0
  SceneHull hull;
  std::vector<SceneLine> lines;
  std::vector<Eigen::Vector3d> anchors_g;
  std::vector<Eigen::Vector3d> fairleads_g;
  std::string value_label = "Utilization";  ///< colour bar title
};

enum class ViewKind { iso, plan, elevation, hull_closeup };

/// An orthographic camera. Image axes: `plan` looks down −z with +x to the
/// right and +y up; `elevation` looks along +y (from the south) with +x to
/// the right and +z up; `iso` and `hull_closeup` look from `azimuth_deg`
/// (direction from the target to the eye, CCW from +x) at `elevation_deg`
/// above the horizon with +z up. The image spans 2·half_width_m across its
/// width, centred on `target_g`; metres per pixel = 2·half_width_m / width.
struct Camera {
  ViewKind kind = ViewKind::iso;
  Eigen::Vector3d target_g = Eigen::Vector3d::Zero();
  double half_width_m = 1000.0;
  double azimuth_deg = -60.0;
  double elevation_deg = 30.0;
};

/// A camera that frames the whole scene (or the hull and its fairleads, for
/// `hull_closeup`) in an image of the given aspect ratio (width / height).
Camera frame_view(const Scene& scene, ViewKind kind, double aspect);

struct ViewOptions {
  int width = 1600;  ///< final image size, px
  int height = 1200;
  int supersample = 2;         ///< rendered at this factor, then box-filtered down (anti-aliasing)
  std::string title;           ///< drawn top-left; empty: none
  bool overlay = true;         ///< title, colour bar, scale bar / axes
  double line_width_px = 3.5;  ///< mooring line thickness in the final image
  double riser_width_px = 2.0;
};

}  // namespace spiral::report
