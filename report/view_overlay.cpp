#include "report/view_overlay.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "report/cairo_image.hpp"
#include "report/color_map.hpp"
#include "report/text.hpp"

namespace spiral::report {

namespace {

double nice_length(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

void panel(cairo_t* cr, double x, double y, double w, double h) {
  cairo_rectangle(cr, x, y, w, h);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.82);
  cairo_fill_preserve(cr);
  cairo_set_source_rgba(cr, 0.55, 0.58, 0.62, 1);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
}

void color_bar(cairo_t* cr, const Scene& scene, double W, double H, double f, bool has_risers) {
  const double bar_w = 22 * f, bar_h = 0.42 * H;
  const double x = W - 120 * f, y = 0.20 * H;
  panel(cr, x - 14 * f, y - 58 * f, 128 * f, bar_h + (has_risers ? 150 : 110) * f);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  set_font(cr, 15 * f, true);
  draw_text(cr, x - 4 * f, y - 36 * f, scene.value_label);
  set_font(cr, 13 * f, false);
  draw_text(cr, x - 4 * f, y - 16 * f, "T·SF / MBL");
  constexpr int kSteps = 200;
  for (int i = 0; i < kSteps; ++i) {
    const Rgb c = viridis(1.0 - (i + 0.5) / kSteps);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_rectangle(cr, x, y + bar_h * i / kSteps, bar_w, bar_h / kSteps + 0.5);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_line_width(cr, 1.0 * f);
  cairo_rectangle(cr, x, y, bar_w, bar_h);
  cairo_stroke(cr);
  set_font(cr, 14 * f, false);
  for (int k = 0; k <= 5; ++k) {
    const double ty = y + bar_h * (1.0 - k / 5.0);
    cairo_move_to(cr, x + bar_w, ty);
    cairo_line_to(cr, x + bar_w + 6 * f, ty);
    cairo_stroke(cr);
    draw_text(cr, x + bar_w + 10 * f, ty + 5 * f, fmt::format("{:.1f}", k / 5.0));
  }
  // Fail swatch and riser key (risers are drawn thin, on the same scale:
  // von Mises, or curvature × MBR for flexibles).
  double ky = y + bar_h + 18 * f;
  cairo_set_source_rgb(cr, kFailColor.r, kFailColor.g, kFailColor.b);
  cairo_rectangle(cr, x, ky, bar_w, 14 * f);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  draw_text(cr, x + bar_w + 10 * f, ky + 12 * f, "> 1 fail");
  if (has_risers) {
    ky += 26 * f;
    cairo_set_source_rgb(cr, 0.38, 0.38, 0.42);
    cairo_rectangle(cr, x, ky + 5 * f, bar_w, 4 * f);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    draw_text(cr, x + bar_w + 10 * f, ky + 12 * f, "riser (thin)");
  }
  ky += 26 * f;
  cairo_set_source_rgb(cr, 0.35, 0.12, 0.10);
  cairo_rectangle(cr, x + 6 * f, ky + 2 * f, 10 * f, 10 * f);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  draw_text(cr, x + bar_w + 10 * f, ky + 12 * f, "anchor");
}

void scale_bar(cairo_t* cr, double m_per_px, double H, double f) {
  const double length_m = nice_length(260 * f * m_per_px);
  const double px = length_m / m_per_px;
  const double x = 30 * f, y = H - 42 * f, h = 8 * f;
  panel(cr, x - 12 * f, y - 30 * f, px + 80 * f, 62 * f);
  for (int i = 0; i < 4; ++i) {
    if (i % 2 == 0)
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    else
      cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_rectangle(cr, x + px * i / 4, y, px / 4, h);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.0 * f);
  cairo_rectangle(cr, x, y, px, h);
  cairo_stroke(cr);
  set_font(cr, 14 * f, false);
  draw_text(cr, x - 3 * f, y - 8 * f, "0");
  draw_text_centered(cr, x + px / 2, y - 8 * f, fmt::format("{:g}", length_m / 2));
  draw_text(cr, x + px - 8 * f, y - 8 * f, fmt::format("{:g} m", length_m));
}

void axes_triad(cairo_t* cr, const OverlayGeometry& g, double W, double H, double f) {
  const double cx = W - 180 * f, cy = H - 70 * f, len = 44 * f;
  const char* names[3] = {"x", "y", "z"};
  const Eigen::Vector3d axes[3] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
  cairo_set_line_width(cr, 2.0 * f);
  set_font(cr, 15 * f, true);
  const Rgb colors[3] = {{0.75, 0.1, 0.1}, {0.1, 0.55, 0.1}, {0.1, 0.2, 0.75}};
  for (int i = 0; i < 3; ++i) {
    const double dx = axes[i].dot(g.right), dy = -axes[i].dot(g.up);
    if (std::hypot(dx, dy) < 0.05) continue;  // along the view axis
    cairo_set_source_rgb(cr, colors[i].r, colors[i].g, colors[i].b);
    cairo_move_to(cr, cx, cy);
    cairo_line_to(cr, cx + len * dx, cy + len * dy);
    cairo_stroke(cr);
    draw_text_centered(cr, cx + (len + 12 * f) * dx, cy + (len + 12 * f) * dy + 5 * f, names[i]);
  }
}

void depth_scale(cairo_t* cr, const Scene& scene, const OverlayGeometry& g, double W, double H, double f) {
  // z axis on the left edge: the world z of a pixel row is up·target − (row − H/2)·m_per_px.
  auto row_of = [&](double z) { return H / 2 - (z - g.target_g.z()) / g.m_per_px; };
  const double step = nice_length(scene.depth_m / 6.0);
  const double x = 18 * f;
  set_font(cr, 13 * f, false);
  cairo_set_source_rgb(cr, 0.15, 0.2, 0.3);
  cairo_set_line_width(cr, 1.0 * f);
  cairo_move_to(cr, x + 52 * f, row_of(0));
  cairo_line_to(cr, x + 52 * f, row_of(-scene.depth_m));
  cairo_stroke(cr);
  for (double z = 0; z >= -scene.depth_m + 0.4 * step; z -= step) {
    cairo_move_to(cr, x + 46 * f, row_of(z));
    cairo_line_to(cr, x + 52 * f, row_of(z));
    cairo_stroke(cr);
    draw_text(cr, x, row_of(z) + 4 * f, fmt::format("{:g}", z));
  }
  set_font(cr, 13 * f, true);
  draw_text(cr, x, row_of(-scene.depth_m) + 4 * f, fmt::format("{:g}", -scene.depth_m));
  draw_text(cr, x, row_of(-scene.depth_m) + 24 * f, fmt::format("seabed, depth {:g} m", scene.depth_m));
  draw_text(cr, x + 60 * f, row_of(0) - 8 * f, "mean water level, z = 0");
  (void)W;
}

}  // namespace

void draw_view_overlay(Image& image, const Scene& scene, const Camera& camera, const OverlayGeometry& geometry,
                       const ViewOptions& options) {
  const SurfacePtr surface = to_surface(image);
  const ContextPtr context(cairo_create(surface.get()));
  cairo_t* cr = context.get();
  // Type sized for the figure printed at text width (~17 cm): 14 f px is ~6 pt there.
  const double W = image.width, H = image.height, f = W / 1100.0;
  const bool has_risers =
      std::any_of(scene.lines.begin(), scene.lines.end(), [](const SceneLine& l) { return l.riser; });
  if (!options.title.empty()) {
    set_font(cr, 24 * f, true);
    const double tw = text_width(cr, options.title);
    panel(cr, 14 * f, 14 * f, tw + 28 * f, 44 * f);
    cairo_set_source_rgb(cr, 0.08, 0.12, 0.2);
    draw_text(cr, 28 * f, 44 * f, options.title);
  }
  color_bar(cr, scene, W, H, f, has_risers);
  switch (camera.kind) {
    case ViewKind::plan:
      scale_bar(cr, geometry.m_per_px, H, f);
      axes_triad(cr, geometry, W, H, f);
      break;
    case ViewKind::elevation:
      scale_bar(cr, geometry.m_per_px, H, f);
      depth_scale(cr, scene, geometry, W, H, f);
      axes_triad(cr, geometry, W, H, f);
      break;
    case ViewKind::iso:
    case ViewKind::hull_closeup: {
      axes_triad(cr, geometry, W, H, f);
      set_font(cr, 14 * f, false);
      const std::string note = camera.kind == ViewKind::iso
                                   ? fmt::format("Orthographic view; water depth {:g} m; seabed grid {:g} m",
                                                 scene.depth_m, geometry.grid_step_m)
                                   : "Hull close-up: fairleads marked; lines continue to their anchors";
      panel(cr, 18 * f, H - 44 * f, text_width(cr, note) + 24 * f, 30 * f);
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      draw_text(cr, 30 * f, H - 23 * f, note);
      break;
    }
  }
  cairo_surface_flush(surface.get());
  image = from_surface(surface.get());
}

}  // namespace spiral::report
