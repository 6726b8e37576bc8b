#include "report/render3d.hpp"

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "report/color_map.hpp"
#include "report/view_overlay.hpp"

namespace spiral::report {

namespace {

using Eigen::Vector3d;

constexpr double kDegToRad = std::numbers::pi / 180.0;
/// Eye distance from the target along the view axis, m: beyond any scene
/// (the default scenario spans ~5 km); with a 24-bit depth buffer over twice
/// this, depth resolves 2.4 mm.
constexpr double kEyeDistance_m = 20000.0;
constexpr Rgb kHullColor{0.93, 0.66, 0.18};
constexpr Rgb kSeabedColor{0.80, 0.74, 0.62};
constexpr Rgb kGridColor{0.62, 0.56, 0.46};
constexpr Rgb kWaterColumnColor{0.84, 0.90, 0.96};
constexpr Rgb kAnchorColor{0.35, 0.12, 0.10};
constexpr Rgb kFairleadColor{0.05, 0.05, 0.05};
/// Sea surface opacity in the iso views: enough to read as water, little
/// enough that the line colours below still match the colour bar closely.
constexpr double kSeaAlpha = 0.14;

struct ContextDeleter {
  void operator()(osmesa_context* c) const { OSMesaDestroyContext(c); }
};

void color(const Rgb& c, double alpha = 1.0) { glColor4d(c.r, c.g, c.b, alpha); }
void vertex(const Vector3d& p) { glVertex3d(p.x(), p.y(), p.z()); }
void normal(const Vector3d& n) { glNormal3d(n.x(), n.y(), n.z()); }

Vector3d any_perpendicular(const Vector3d& axis) {
  const Vector3d a = std::abs(axis.z()) < 0.9 ? Vector3d::UnitZ() : Vector3d::UnitX();
  return axis.cross(a).normalized();
}

/// A lit cylinder from p0 to p1 with flat end caps.
void draw_cylinder(const Vector3d& p0, const Vector3d& p1, double radius, int sides) {
  const Vector3d axis = (p1 - p0).normalized();
  const Vector3d u = any_perpendicular(axis);
  const Vector3d v = axis.cross(u);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= sides; ++i) {
    const double a = 2.0 * std::numbers::pi * i / sides;
    const Vector3d n = std::cos(a) * u + std::sin(a) * v;
    normal(n);
    vertex(p0 + radius * n);
    vertex(p1 + radius * n);
  }
  glEnd();
  for (const auto& [center, dir] : {std::pair{p0, Vector3d(-axis)}, std::pair{p1, axis}}) {
    glBegin(GL_TRIANGLE_FAN);
    normal(dir);
    vertex(center);
    for (int i = 0; i <= sides; ++i) {
      const double a = 2.0 * std::numbers::pi * i / sides;
      vertex(center + radius * (std::cos(a) * u + std::sin(a) * v));
    }
    glEnd();
  }
}

/// Camera frame: right, up, forward (unit, right-handed: right = forward × up).
struct Basis {
  Vector3d right, up, forward;
};

Basis basis_of(const Camera& camera) {
  switch (camera.kind) {
    case ViewKind::plan:
      return {Vector3d::UnitX(), Vector3d::UnitY(), -Vector3d::UnitZ()};
    case ViewKind::elevation:
      return {Vector3d::UnitX(), Vector3d::UnitZ(), Vector3d::UnitY()};
    case ViewKind::iso:
    case ViewKind::hull_closeup:
      break;
  }
  const double az = camera.azimuth_deg * kDegToRad, el = camera.elevation_deg * kDegToRad;
  const Vector3d eye_dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  const Vector3d forward = -eye_dir;
  const Vector3d right = forward.cross(Vector3d::UnitZ()).normalized();
  return {right, right.cross(forward), forward};
}

struct Bounds {
  Vector3d lo = Vector3d::Constant(1e300), hi = Vector3d::Constant(-1e300);
  void add(const Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool empty() const { return lo.x() > hi.x(); }
};

std::vector<Vector3d> hull_points_g(const SceneHull& hull) {
  std::vector<Vector3d> body;
  for (const engine::Panel& panel : hull.panels_b)
    for (const Vector3d& v : panel) body.push_back(v);
  if (body.empty() && hull.geometry) {
    for (const auto& c : hull.geometry->columns) {
      const double r = c.diameter_m / 2;
      for (const double z : {c.z_bottom_m, c.z_top_m}) {
        for (const auto& [dx, dy] : {std::pair{r, 0.0}, {-r, 0.0}, {0.0, r}, {0.0, -r}}) {
          body.emplace_back(c.center_b.x() + dx, c.center_b.y() + dy, z);
        }
      }
    }
    for (const auto& p : hull.geometry->pontoons) {
      body.push_back(p.from_b);
      body.push_back(p.to_b);
    }
  }
  if (body.empty()) {
    const Vector3d h = hull.box_size_m / 2;
    for (const double sx : {-1.0, 1.0})
      for (const double sy : {-1.0, 1.0})
        for (const double z : {hull.box_bottom_b_m, hull.box_bottom_b_m + hull.box_size_m.z()})
          body.emplace_back(sx * h.x(), sy * h.y(), z);
  }
  std::vector<Vector3d> out;
  for (const Vector3d& p : body) out.push_back(hull.reference_point_g + hull.rotation * p);
  return out;
}

/// The seabed rectangle: the horizontal extent of the scene with a margin.
void seabed_rectangle(const Scene& scene, double& x0, double& x1, double& y0, double& y1) {
  Bounds b;
  for (const SceneLine& line : scene.lines)
    for (const Vector3d& p : line.points_g) b.add(p);
  for (const Vector3d& p : hull_points_g(scene.hull)) b.add(p);
  const double margin = 0.08 * std::max(b.hi.x() - b.lo.x(), b.hi.y() - b.lo.y()) + 50.0;
  x0 = b.lo.x() - margin;
  x1 = b.hi.x() + margin;
  y0 = b.lo.y() - margin;
  y1 = b.hi.y() + margin;
}

double nice_step(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

void draw_background(const Camera& camera) {
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  const bool plan = camera.kind == ViewKind::plan;
  glBegin(GL_QUADS);
  glColor3d(0.80, 0.84, 0.89);
  glVertex2d(-1, -1);
  glVertex2d(1, -1);
  glColor3d(plan ? 0.80 : 0.96, plan ? 0.84 : 0.97, plan ? 0.89 : 0.99);
  glVertex2d(1, 1);
  glVertex2d(-1, 1);
  glEnd();
  glEnable(GL_DEPTH_TEST);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
}

void draw_hull(const SceneHull& hull) {
  color(kHullColor);
  auto g = [&](const Vector3d& b) -> Vector3d { return hull.reference_point_g + hull.rotation * b; };
  if (!hull.panels_b.empty()) {
    // Flat shading per panel; the normal from the diagonals also holds for a
    // triangle written with a repeated vertex (two-sided lighting is on, so
    // the mesh's normal convention does not matter).
    glBegin(GL_QUADS);
    for (const engine::Panel& p : hull.panels_b) {
      const Vector3d n = (p[2] - p[0]).cross(p[3] - p[1]);
      if (n.norm() < 1e-12) continue;  // a degenerate panel has no face to draw
      normal(hull.rotation * n.normalized());
      for (const Vector3d& v : p) vertex(g(v));
    }
    glEnd();
    return;
  }
  if (hull.geometry && (!hull.geometry->columns.empty() || !hull.geometry->pontoons.empty())) {
    for (const auto& c : hull.geometry->columns) {
      draw_cylinder(g({c.center_b.x(), c.center_b.y(), c.z_bottom_m}), g({c.center_b.x(), c.center_b.y(), c.z_top_m}),
                    c.diameter_m / 2, 40);
    }
    color({0.80, 0.56, 0.16});
    for (const auto& p : hull.geometry->pontoons) draw_cylinder(g(p.from_b), g(p.to_b), p.diameter_m / 2, 20);
    return;
  }
  // A box: six lit faces.
  const Vector3d h = hull.box_size_m / 2;
  const double z0 = hull.box_bottom_b_m, z1 = z0 + hull.box_size_m.z();
  const Vector3d c[8] = {g({-h.x(), -h.y(), z0}), g({h.x(), -h.y(), z0}),  g({h.x(), h.y(), z0}),
                         g({-h.x(), h.y(), z0}),  g({-h.x(), -h.y(), z1}), g({h.x(), -h.y(), z1}),
                         g({h.x(), h.y(), z1}),   g({-h.x(), h.y(), z1})};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  glBegin(GL_QUADS);
  for (const auto& f : faces) {
    normal((c[f[1]] - c[f[0]]).cross(c[f[2]] - c[f[1]]).normalized());
    for (const int i : f) vertex(c[i]);
  }
  glEnd();
}

/// A line as a camera-facing ribbon of `width` (m) with round joints, unlit.
void draw_ribbon(const SceneLine& line, const Basis& basis, double width) {
  const auto& pts = line.points_g;
  if (pts.size() < 2) return;
  auto col = [&](std::size_t i) {
    return line.values.empty() ? line.color : utilization_color(line.values[std::min(i, line.values.size() - 1)]);
  };
  const double r = width / 2;
  glBegin(GL_QUADS);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vector3d axis = pts[i + 1] - pts[i];
    Vector3d side = axis.cross(basis.forward);
    if (side.norm() < 1e-12) continue;  // along the view axis: the joint discs cover it
    side = side.normalized() * r;
    color(col(i));
    vertex(pts[i] - side);
    vertex(pts[i] + side);
    color(col(i + 1));
    vertex(pts[i + 1] + side);
    vertex(pts[i + 1] - side);
  }
  glEnd();
  constexpr int kJointSides = 12;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    glBegin(GL_TRIANGLE_FAN);
    color(col(i));
    vertex(pts[i]);
    for (int k = 0; k <= kJointSides; ++k) {
      const double a = 2.0 * std::numbers::pi * k / kJointSides;
      vertex(pts[i] + r * (std::cos(a) * basis.right + std::sin(a) * basis.up));
    }
    glEnd();
  }
}

void draw_square_marker(const Vector3d& p, const Basis& basis, double half, const Rgb& c) {
  color(c);
  glBegin(GL_QUADS);
  vertex(p - half * basis.right - half * basis.up);
  vertex(p + half * basis.right - half * basis.up);
  vertex(p + half * basis.right + half * basis.up);
  vertex(p - half * basis.right + half * basis.up);
  glEnd();
}

void draw_horizontal_rect(double x0, double x1, double y0, double y1, double z) {
  glBegin(GL_QUADS);
  glNormal3d(0, 0, 1);
  glVertex3d(x0, y0, z);
  glVertex3d(x1, y0, z);
  glVertex3d(x1, y1, z);
  glVertex3d(x0, y1, z);
  glEnd();
}

void setup_lights() {
  const GLfloat ambient[] = {0.40f, 0.40f, 0.42f, 1.0f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const GLfloat key_dir[] = {0.15f, -0.75f, 0.65f, 0.0f};  // towards the light, world frame
  const GLfloat key[] = {0.70f, 0.70f, 0.68f, 1.0f};
  const GLfloat fill_dir[] = {0.6f, 0.4f, 0.3f, 0.0f};
  const GLfloat fill[] = {0.22f, 0.23f, 0.26f, 1.0f};
  const GLfloat black[] = {0, 0, 0, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, key_dir);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, key);
  glLightfv(GL_LIGHT0, GL_SPECULAR, black);
  glLightfv(GL_LIGHT1, GL_POSITION, fill_dir);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fill);
  glLightfv(GL_LIGHT1, GL_SPECULAR, black);
  glLightfv(GL_LIGHT0, GL_AMBIENT, black);
  glLightfv(GL_LIGHT1, GL_AMBIENT, black);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_NORMALIZE);
}

void draw_scene(const Scene& scene, const Camera& camera, const Basis& basis, double m_per_px,
                const ViewOptions& options) {
  double x0, x1, y0, y1;
  seabed_rectangle(scene, x0, x1, y0, y1);
  const double depth = scene.depth_m;
  const bool closeup = camera.kind == ViewKind::hull_closeup;

  glEnable(GL_LIGHTING);
  // Seabed and its grid (plan, iso), or the water column (elevation).
  if (camera.kind == ViewKind::elevation) {
    glDisable(GL_LIGHTING);
    const double y_back = y1 + 10.0;
    const double below = 0.5 * depth + 1000.0;
    glBegin(GL_QUADS);
    color(kWaterColumnColor);
    glVertex3d(x0 - 1e4, y_back, -depth);
    glVertex3d(x1 + 1e4, y_back, -depth);
    glVertex3d(x1 + 1e4, y_back, 0.0);
    glVertex3d(x0 - 1e4, y_back, 0.0);
    color(kSeabedColor);
    glVertex3d(x0 - 1e4, y_back, -depth - below);
    glVertex3d(x1 + 1e4, y_back, -depth - below);
    glVertex3d(x1 + 1e4, y_back, -depth);
    glVertex3d(x0 - 1e4, y_back, -depth);
    glEnd();
    glEnable(GL_LIGHTING);
  } else if (!closeup) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    color(kSeabedColor);
    draw_horizontal_rect(x0, x1, y0, y1, -depth);
    glDisable(GL_POLYGON_OFFSET_FILL);
    // Grid lines: a "nice" spacing of about an eighth of the extent, 1.2 px wide.
    const double step = nice_step(std::max(x1 - x0, y1 - y0) / 8.0);
    const double half = 0.6 * m_per_px;
    color(kGridColor);
    for (double x = std::ceil(x0 / step) * step; x <= x1; x += step)
      draw_horizontal_rect(x - half, x + half, y0, y1, -depth);
    for (double y = std::ceil(y0 / step) * step; y <= y1; y += step)
      draw_horizontal_rect(x0, x1, y - half, y + half, -depth);
  }

  draw_hull(scene.hull);

  glDisable(GL_LIGHTING);
  for (const SceneLine& line : scene.lines) {
    draw_ribbon(line, basis, (line.riser ? options.riser_width_px : options.line_width_px) * m_per_px);
  }

  // Sea surface, translucent, after every opaque object (iso views only:
  // the plan view would tint every colour, the elevation sees it edge-on).
  if (camera.kind == ViewKind::iso || closeup) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    color({0.25, 0.50, 0.78}, kSeaAlpha);
    if (closeup) {
      const double r = camera.half_width_m * 1.5;
      draw_horizontal_rect(camera.target_g.x() - r, camera.target_g.x() + r, camera.target_g.y() - r,
                           camera.target_g.y() + r, 0.0);
    } else {
      draw_horizontal_rect(x0, x1, y0, y1, 0.0);
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }

  // Anchors and fairleads on top of everything: markers, not geometry.
  glDisable(GL_DEPTH_TEST);
  if (!closeup) {
    for (const Vector3d& a : scene.anchors_g) draw_square_marker(a, basis, 4.0 * m_per_px, kAnchorColor);
  }
  if (closeup) {
    for (const Vector3d& f : scene.fairleads_g) draw_square_marker(f, basis, 3.5 * m_per_px, kFairleadColor);
  }
  glEnable(GL_DEPTH_TEST);
}

}  // namespace

Camera frame_view(const Scene& scene, ViewKind kind, double aspect) {
  Camera camera;
  camera.kind = kind;
  if (kind == ViewKind::hull_closeup) {
    camera.azimuth_deg = -55.0;
    camera.elevation_deg = 25.0;
  }
  const Basis basis = basis_of(camera);
  std::vector<Vector3d> points = hull_points_g(scene.hull);
  if (kind == ViewKind::hull_closeup) {
    points.insert(points.end(), scene.fairleads_g.begin(), scene.fairleads_g.end());
  } else {
    double x0, x1, y0, y1;
    seabed_rectangle(scene, x0, x1, y0, y1);
    for (const double x : {x0, x1})
      for (const double y : {y0, y1})
        for (const double z : {-scene.depth_m, 0.0}) points.emplace_back(x, y, z);
  }
  double r0 = 1e300, r1 = -1e300, u0 = 1e300, u1 = -1e300;
  for (const Vector3d& p : points) {
    r0 = std::min(r0, p.dot(basis.right));
    r1 = std::max(r1, p.dot(basis.right));
    u0 = std::min(u0, p.dot(basis.up));
    u1 = std::max(u1, p.dot(basis.up));
  }
  // Margins: room for the title above and the colour bar on the right.
  const double margin = kind == ViewKind::hull_closeup ? 1.25 : 1.06;
  const double half_w = std::max((r1 - r0) / 2, (u1 - u0) / 2 * aspect) * margin;
  camera.half_width_m = half_w / 0.86;
  const double shift_right = 0.09 * camera.half_width_m;        // colour bar strip
  const double shift_up = 0.05 * camera.half_width_m / aspect;  // title strip
  camera.target_g = ((r0 + r1) / 2 + shift_right) * basis.right + ((u0 + u1) / 2 + shift_up) * basis.up;
  return camera;
}

Image render_view(const Scene& scene, const Camera& camera, const ViewOptions& options) {
  const int s = std::max(1, options.supersample);
  const int W = options.width * s, H = options.height * s;
  if (options.width < 16 || options.height < 16 || W > 8192 || H > 8192) {
    throw std::runtime_error(fmt::format("render_view: image size {}x{} (x{} supersampling) out of range",
                                         options.width, options.height, s));
  }
  std::unique_ptr<osmesa_context, ContextDeleter> context(OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr));
  if (!context) throw std::runtime_error("render_view: cannot create an OSMesa context");
  std::vector<GLubyte> buffer(static_cast<std::size_t>(W) * H * 4);
  if (!OSMesaMakeCurrent(context.get(), buffer.data(), GL_UNSIGNED_BYTE, W, H)) {
    throw std::runtime_error("render_view: cannot bind the OSMesa buffer");
  }

  const Basis basis = basis_of(camera);
  const double m_per_px = 2.0 * camera.half_width_m / options.width;  // final image pixels
  const double half_h = camera.half_width_m * options.height / options.width;

  glViewport(0, 0, W, H);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-camera.half_width_m, camera.half_width_m, -half_h, half_h, 1.0, 2.0 * kEyeDistance_m);
  glMatrixMode(GL_MODELVIEW);
  // View matrix: rows right, up, −forward; eye behind the target.
  const Vector3d eye = camera.target_g - kEyeDistance_m * basis.forward;
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = basis.right.transpose();
  view.block<1, 3>(1, 0) = basis.up.transpose();
  view.block<1, 3>(2, 0) = -basis.forward.transpose();
  view.block<3, 1>(0, 3) = -view.block<3, 3>(0, 0) * eye;
  glLoadMatrixd(view.data());  // Eigen is column-major, as OpenGL expects
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glShadeModel(GL_SMOOTH);
  draw_background(camera);
  setup_lights();
  draw_scene(scene, camera, basis, m_per_px, options);
  glFinish();

  // Box filter s×s → 1; OSMesa rows are bottom-up.
  Image image(options.width, options.height);
  const double inv = 1.0 / (s * s);
  for (int y = 0; y < options.height; ++y) {
    for (int x = 0; x < options.width; ++x) {
      double acc[3] = {0, 0, 0};
      for (int j = 0; j < s; ++j) {
        const GLubyte* row = &buffer[(static_cast<std::size_t>(H - 1 - (y * s + j)) * W + x * s) * 4];
        for (int i = 0; i < s; ++i)
          for (int c = 0; c < 3; ++c) acc[c] += row[i * 4 + c];
      }
      std::uint8_t* p = image.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(std::lround(acc[c] * inv));
    }
  }
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);

  if (options.overlay) {
    OverlayGeometry geometry;
    geometry.right = basis.right;
    geometry.up = basis.up;
    geometry.target_g = camera.target_g;
    geometry.m_per_px = m_per_px;
    double x0, x1, y0, y1;
    seabed_rectangle(scene, x0, x1, y0, y1);
    geometry.grid_step_m = nice_step(std::max(x1 - x0, y1 - y0) / 8.0);
    draw_view_overlay(image, scene, camera, geometry, options);
  }
  return image;
}

}  // namespace spiral::report
