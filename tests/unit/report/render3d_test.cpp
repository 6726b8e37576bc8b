// Off-screen 3D views: size, content, the line where the camera says it
// projects, and determinism.
#include "report/render3d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "report/color_map.hpp"

namespace spiral::report {
namespace {

// Lines are drawn unlit in their colour-map colour; a pixel at the centre of
// a 3.5 px line is fully covered at 2x supersampling, so only the 8-bit
// rounding of the colour map separates it from the exact colour.
constexpr int kColorTolerance = 2;
constexpr int kWidth = 800, kHeight = 600;
constexpr double kHalfWidth_m = 1000.0;
constexpr double kUtilization = 0.5;

Scene known_scene() {
  Scene scene;
  scene.depth_m = 1000.0;
  SceneLine line;
  line.name = "L1";
  // A straight line from an anchor on the seabed to a fairlead near the surface.
  const Eigen::Vector3d anchor(-800.0, -400.0, -1000.0), fairlead(-100.0, -50.0, -20.0);
  for (int i = 0; i <= 20; ++i) {
    line.points_g.push_back(anchor + (fairlead - anchor) * (i / 20.0));
    line.values.push_back(kUtilization);
  }
  scene.lines.push_back(line);
  scene.anchors_g.push_back(anchor);
  scene.fairleads_g.push_back(fairlead);
  return scene;
}

Camera plan_camera() {
  Camera camera;
  camera.kind = ViewKind::plan;
  camera.target_g = Eigen::Vector3d::Zero();
  camera.half_width_m = kHalfWidth_m;
  return camera;
}

ViewOptions options() {
  ViewOptions o;
  o.width = kWidth;
  o.height = kHeight;
  return o;
}

TEST(Render3d, KnownSceneHasSizeContentAndTheLineWhereItProjects) {
  const Image image = render_view(known_scene(), plan_camera(), options());
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  ASSERT_EQ(image.rgb.size(), static_cast<std::size_t>(kWidth * kHeight * 3));

  std::set<int> colours;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    colours.insert(image.rgb[i] << 16 | image.rgb[i + 1] << 8 | image.rgb[i + 2]);
  }
  EXPECT_GT(colours.size(), 20u) << "a blank or flat image";

  // Plan view (report/scene.hpp): +x right, +y up, image centred on the
  // target, 2 half_width across the width.
  const double m_per_px = 2.0 * kHalfWidth_m / kWidth;
  const Rgb expected = utilization_color(kUtilization);
  const Scene scene = known_scene();
  for (const double t : {0.3, 0.4, 0.5, 0.6, 0.7}) {
    const Eigen::Vector3d p =
        scene.lines[0].points_g.front() + t * (scene.lines[0].points_g.back() - scene.lines[0].points_g.front());
    const int px = static_cast<int>(std::floor(kWidth / 2.0 + p.x() / m_per_px));
    const int py = static_cast<int>(std::floor(kHeight / 2.0 - p.y() / m_per_px));
    const std::uint8_t* pixel = image.at(px, py);
    EXPECT_NEAR(pixel[0], expected.r * 255, kColorTolerance) << "t " << t << " at " << px << "," << py;
    EXPECT_NEAR(pixel[1], expected.g * 255, kColorTolerance) << "t " << t;
    EXPECT_NEAR(pixel[2], expected.b * 255, kColorTolerance) << "t " << t;
  }
  // Away from the line (mirror point across the image centre): not the line colour.
  const std::uint8_t* away = image.at(kWidth - 200, kHeight / 2 - 80);
  EXPECT_GT(std::abs(away[0] - expected.r * 255) + std::abs(away[1] - expected.g * 255) +
                std::abs(away[2] - expected.b * 255),
            30.0);
}

TEST(Render3d, SameInputRendersByteIdenticalImages) {
  const Scene scene = known_scene();
  for (const ViewKind kind : {ViewKind::iso, ViewKind::plan, ViewKind::elevation, ViewKind::hull_closeup}) {
    const Camera camera = frame_view(scene, kind, static_cast<double>(kWidth) / kHeight);
    ViewOptions o = options();
    o.title = "determinism";
    const Image a = render_view(scene, camera, o);
    const Image b = render_view(scene, camera, o);
    EXPECT_EQ(a.rgb, b.rgb) << static_cast<int>(kind);
    EXPECT_EQ(encode_png(a), encode_png(b)) << static_cast<int>(kind);
  }
}

// A panel-mesh hull (SceneHull::panels_b) is drawn where its panels project,
// in the hull's warm colour, and nothing is there without it.
TEST(Render3d, PanelMeshHullIsDrawnWhereItProjects) {
  const Eigen::Vector3d c(500.0, 250.0, -50.0);  // a 100 m cube, far from the default box at the origin
  const double h = 50.0;
  const auto v = [&](double sx, double sy, double sz) { return Eigen::Vector3d(c + h * Eigen::Vector3d(sx, sy, sz)); };
  Scene with = known_scene();
  with.hull.panels_b = {{v(-1, -1, 1), v(1, -1, 1), v(1, 1, 1), v(-1, 1, 1)},      // top
                        {v(-1, -1, -1), v(-1, 1, -1), v(1, 1, -1), v(1, -1, -1)},  // bottom
                        {v(-1, -1, -1), v(1, -1, -1), v(1, -1, 1), v(-1, -1, 1)},
                        {v(1, -1, -1), v(1, 1, -1), v(1, 1, 1), v(1, -1, 1)},
                        {v(1, 1, -1), v(-1, 1, -1), v(-1, 1, 1), v(1, 1, 1)},
                        {v(-1, 1, -1), v(-1, -1, -1), v(-1, -1, 1), v(-1, 1, 1)}};
  const double m_per_px = 2.0 * kHalfWidth_m / kWidth;
  const int px = static_cast<int>(std::floor(kWidth / 2.0 + c.x() / m_per_px));
  const int py = static_cast<int>(std::floor(kHeight / 2.0 - c.y() / m_per_px));
  const Image drawn = render_view(with, plan_camera(), options());
  const Image bare = render_view(known_scene(), plan_camera(), options());
  const std::uint8_t* hull = drawn.at(px, py);
  const std::uint8_t* background = bare.at(px, py);
  // Warm (red > green > blue, by a margin lighting cannot close) where the
  // cube is; the sea/seabed background there is cool (blue >= red).
  EXPECT_GT(hull[0], hull[1] + 20) << int(hull[0]) << "," << int(hull[1]) << "," << int(hull[2]);
  EXPECT_GT(hull[1], hull[2] + 40) << int(hull[1]) << "," << int(hull[2]);
  EXPECT_GE(background[2], background[0]) << int(background[0]) << "," << int(background[2]);
}

TEST(Render3d, RejectsImpossibleSizes) {
  ViewOptions o = options();
  o.width = 5;
  EXPECT_THROW(render_view(known_scene(), plan_camera(), o), std::runtime_error);
}

TEST(ColorMap, ViridisEndsAndFailColour) {
  EXPECT_NEAR(viridis(0.0).r, 0x44 / 255.0, 1e-12);
  EXPECT_NEAR(viridis(1.0).g, 0xE7 / 255.0, 1e-12);
  EXPECT_EQ(utilization_color(1.2).r, kFailColor.r);
}

}  // namespace
}  // namespace spiral::report
