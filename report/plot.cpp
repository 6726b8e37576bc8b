#include "report/plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "report/text.hpp"

namespace spiral::report {

namespace {

struct Frame {
  double x0, y0, w, h;            // plot area on the surface
  double xmin, xmax, ymin, ymax;  // data range
  double px(double x) const { return x0 + (x - xmin) / (xmax - xmin) * w; }
  double py(double y) const { return y0 + h - (y - ymin) / (ymax - ymin) * h; }
};

std::string tick_label(double v, double step) {
  if (std::abs(v) < 1e-9 * step) v = 0.0;
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  return fmt::format("{:.{}f}", v, decimals);
}

void set_color(cairo_t* cr, const Rgb& c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

void dash(cairo_t* cr, bool on, double unit) {
  if (on) {
    const double d[] = {4 * unit, 2.5 * unit};
    cairo_set_dash(cr, d, 2, 0);
  } else {
    cairo_set_dash(cr, nullptr, 0, 0);
  }
}

void title_and_frame(cairo_t* cr, const std::string& title, double width, double font, double& top) {
  top = 4;
  if (!title.empty()) {
    set_font(cr, font * 1.15, true);
    set_color(cr, {0.1, 0.1, 0.12});
    draw_text(cr, 0, font * 1.2, title);
    top = font * 1.9;
  }
  (void)width;
}

/// Grid, ticks and labels; returns the frame.
void axes(cairo_t* cr, const Frame& f, const std::vector<double>& xt, const std::vector<double>& yt,
          const std::string& xl, const std::string& yl, double font) {
  cairo_set_line_width(cr, 0.4);
  set_color(cr, {0.86, 0.87, 0.89});
  for (const double x : xt) {
    cairo_move_to(cr, f.px(x), f.y0);
    cairo_line_to(cr, f.px(x), f.y0 + f.h);
  }
  for (const double y : yt) {
    cairo_move_to(cr, f.x0, f.py(y));
    cairo_line_to(cr, f.x0 + f.w, f.py(y));
  }
  cairo_stroke(cr);
  set_color(cr, {0.25, 0.25, 0.28});
  cairo_set_line_width(cr, 0.8);
  cairo_rectangle(cr, f.x0, f.y0, f.w, f.h);
  cairo_stroke(cr);
  set_font(cr, font, false);
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1.0, ystep = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  for (const double x : xt) {
    cairo_move_to(cr, f.px(x), f.y0 + f.h);
    cairo_line_to(cr, f.px(x), f.y0 + f.h + 3);
    cairo_stroke(cr);
    draw_text_centered(cr, f.px(x), f.y0 + f.h + 4 + font, tick_label(x, xstep));
  }
  double widest = 0;
  for (const double y : yt) {
    cairo_move_to(cr, f.x0 - 3, f.py(y));
    cairo_line_to(cr, f.x0, f.py(y));
    cairo_stroke(cr);
    const std::string t = tick_label(y, ystep);
    widest = std::max(widest, text_width(cr, t));
    draw_text_right(cr, f.x0 - 5, f.py(y) + font * 0.35, t);
  }
  set_font(cr, font * 1.05, false);
  draw_text_centered(cr, f.x0 + f.w / 2, f.y0 + f.h + 2.6 * font + 4, xl);
  draw_text_vertical(cr, f.x0 - widest - 8 - font * 0.3, f.y0 + f.h / 2, yl);
}

/// A filled marker of radius r (pt) centred on (x, y).
void draw_marker(cairo_t* cr, Marker m, double x, double y, double r) {
  switch (m) {
    case Marker::circle:
      cairo_arc(cr, x, y, r, 0, 2 * M_PI);
      break;
    case Marker::square:
      cairo_rectangle(cr, x - r * 0.9, y - r * 0.9, 1.8 * r, 1.8 * r);
      break;
    case Marker::triangle:
      cairo_move_to(cr, x, y - 1.25 * r);
      cairo_line_to(cr, x + 1.1 * r, y + 0.8 * r);
      cairo_line_to(cr, x - 1.1 * r, y + 0.8 * r);
      cairo_close_path(cr);
      break;
    case Marker::diamond:
      cairo_move_to(cr, x, y - 1.3 * r);
      cairo_line_to(cr, x + 1.1 * r, y);
      cairo_line_to(cr, x, y + 1.3 * r);
      cairo_line_to(cr, x - 1.1 * r, y);
      cairo_close_path(cr);
      break;
  }
  cairo_fill(cr);
}

void path_series(cairo_t* cr, const Frame& f, const Series& s) {
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const double X = f.px(s.x[i]), Y = f.py(s.y[i]);
    if (i == 0)
      cairo_move_to(cr, X, Y);
    else if (s.step) {
      cairo_line_to(cr, X, f.py(s.y[i - 1]));
      cairo_line_to(cr, X, Y);
    } else
      cairo_line_to(cr, X, Y);
  }
}

void legend(cairo_t* cr, const Frame& f, const std::vector<std::pair<std::string, const Series*>>& entries,
            const std::vector<const PlotCircle*>& circles, double font, int columns, bool left) {
  const std::size_t n = entries.size() + circles.size();
  if (n == 0) return;
  set_font(cr, font * 0.92, false);
  double item_w = 0;
  for (const auto& e : entries) item_w = std::max(item_w, text_width(cr, e.first));
  for (const auto* c : circles) item_w = std::max(item_w, text_width(cr, c->label));
  item_w += 26;
  const int cols = columns > 0 ? columns : static_cast<int>((n + 7) / 8);
  const int rows = static_cast<int>((n + cols - 1) / cols);
  const double row_h = font * 1.3;
  const double W = cols * item_w + 6, H = rows * row_h + 6;
  const double x = left ? f.x0 + 6 : f.x0 + f.w - W - 6, y = f.y0 + 6;
  cairo_rectangle(cr, x, y, W, H);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
  cairo_fill_preserve(cr);
  set_color(cr, {0.7, 0.7, 0.72});
  cairo_set_line_width(cr, 0.5);
  cairo_stroke(cr);
  for (std::size_t i = 0; i < n; ++i) {
    const double ix = x + 4 + static_cast<double>(i / static_cast<std::size_t>(rows)) * item_w;
    const double iy = y + 3 + static_cast<double>(i % static_cast<std::size_t>(rows)) * row_h + row_h / 2;
    if (i < entries.size()) {
      const Series& s = *entries[i].second;
      set_color(cr, s.color);
      if (s.line_width > 0) {
        cairo_set_line_width(cr, std::max(1.0, s.line_width));
        dash(cr, s.dashed, 1.0);
        cairo_move_to(cr, ix, iy);
        cairo_line_to(cr, ix + 18, iy);
        cairo_stroke(cr);
        dash(cr, false, 1.0);
      }
      if (s.markers) draw_marker(cr, s.marker, ix + 9, iy, 2.2);
      set_color(cr, {0.1, 0.1, 0.12});
      draw_text(cr, ix + 22, iy + font * 0.32, entries[i].first);
    } else {
      const PlotCircle& c = *circles[i - entries.size()];
      set_color(cr, c.color);
      cairo_set_line_width(cr, 1.0);
      dash(cr, c.dashed, 1.0);
      cairo_move_to(cr, ix, iy);
      cairo_line_to(cr, ix + 18, iy);
      cairo_stroke(cr);
      dash(cr, false, 1.0);
      set_color(cr, {0.1, 0.1, 0.12});
      draw_text(cr, ix + 22, iy + font * 0.32, c.label);
    }
  }
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo)) hi = lo + 1.0;
  const double raw = (hi - lo) / std::max(1, target);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * p;
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * p >= raw) {
      step = m * p;
      break;
    }
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) ticks.push_back(t);
  return ticks;
}

Rgb palette(std::size_t index) {
  static constexpr std::array<Rgb, 10> kTableau = {{{0.12, 0.47, 0.71},
                                                    {1.00, 0.50, 0.05},
                                                    {0.17, 0.63, 0.17},
                                                    {0.84, 0.15, 0.16},
                                                    {0.58, 0.40, 0.74},
                                                    {0.55, 0.34, 0.29},
                                                    {0.89, 0.47, 0.76},
                                                    {0.50, 0.50, 0.50},
                                                    {0.74, 0.74, 0.13},
                                                    {0.09, 0.75, 0.81}}};
  return kTableau[index % kTableau.size()];
}

void draw_plot(cairo_t* cr, const Plot& plot, double width, double height, const PlotStyle& style) {
  const double font = style.font_size;
  cairo_save(cr);
  double top = 0;
  title_and_frame(cr, plot.title, width, font, top);

  // Data range.
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const Series& s : plot.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      xmin = std::min(xmin, s.x[i]);
      xmax = std::max(xmax, s.x[i]);
      ymin = std::min(ymin, s.y[i]);
      ymax = std::max(ymax, s.y[i]);
    }
  }
  for (const PlotCircle& c : plot.circles) {
    xmin = std::min(xmin, c.cx - c.radius);
    xmax = std::max(xmax, c.cx + c.radius);
    ymin = std::min(ymin, c.cy - c.radius);
    ymax = std::max(ymax, c.cy + c.radius);
  }
  for (const auto& [x, label] : plot.x_lines) {
    xmin = std::min(xmin, x);
    xmax = std::max(xmax, x);
  }
  if (xmin > xmax) xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  if (xmax - xmin < 1e-12) xmin -= 1, xmax += 1;
  if (ymax - ymin < 1e-12) ymin -= 1, ymax += 1;
  const double padx = 0.03 * (xmax - xmin), pady = 0.06 * (ymax - ymin);
  if (plot.x_range)
    std::tie(xmin, xmax) = *plot.x_range;
  else
    xmin -= padx, xmax += padx;
  if (plot.y_range)
    std::tie(ymin, ymax) = *plot.y_range;
  else
    ymin -= pady, ymax += pady;

  const double left = 3.4 * font + 28, bottom = 3.4 * font + 6, right = 8;
  Frame f{left, top + 4, width - left - right, height - top - 4 - bottom, xmin, xmax, ymin, ymax};
  if (plot.equal_aspect) {
    // Grow the range along the axis that has room so that both scales match.
    const double sx = f.w / (xmax - xmin), sy = f.h / (ymax - ymin);
    if (sx > sy) {
      const double c = (xmin + xmax) / 2, half = f.w / sy / 2;
      f.xmin = c - half, f.xmax = c + half;
    } else {
      const double c = (ymin + ymax) / 2, half = f.h / sx / 2;
      f.ymin = c - half, f.ymax = c + half;
    }
  }
  const auto xt = nice_ticks(f.xmin, f.xmax, std::max(3, static_cast<int>(f.w / (font * 7))));
  const auto yt = nice_ticks(f.ymin, f.ymax, std::max(3, static_cast<int>(f.h / (font * 4))));
  axes(cr, f, xt, yt, plot.x_label, plot.y_label, font);

  cairo_rectangle(cr, f.x0, f.y0, f.w, f.h);
  cairo_save(cr);
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const auto& [x, label] : plot.x_lines) {
    set_color(cr, {0.84, 0.15, 0.16});
    cairo_set_line_width(cr, 0.9);
    dash(cr, true, 1.0);
    cairo_move_to(cr, f.px(x), f.y0);
    cairo_line_to(cr, f.px(x), f.y0 + f.h);
    cairo_stroke(cr);
    dash(cr, false, 1.0);
    set_font(cr, font * 0.9, false);
    draw_text_vertical(cr, f.px(x) - 3, f.y0 + f.h * 0.7, label);
  }
  for (const PlotCircle& c : plot.circles) {
    set_color(cr, c.color);
    cairo_set_line_width(cr, 1.0);
    dash(cr, c.dashed, 1.0);
    cairo_save(cr);
    cairo_translate(cr, f.px(c.cx), f.py(c.cy));
    cairo_scale(cr, c.radius / (f.xmax - f.xmin) * f.w, c.radius / (f.ymax - f.ymin) * f.h);
    cairo_arc(cr, 0, 0, 1, 0, 2 * M_PI);
    cairo_restore(cr);
    cairo_stroke(cr);
    dash(cr, false, 1.0);
  }
  for (const Series& s : plot.series) {
    set_color(cr, s.color);
    if (s.line_width > 0 && s.x.size() > 1) {
      cairo_set_line_width(cr, s.line_width);
      dash(cr, s.dashed, 1.0);
      path_series(cr, f, s);
      cairo_stroke(cr);
      dash(cr, false, 1.0);
    }
    if (s.markers) {
      for (std::size_t i = 0; i < s.x.size(); ++i) draw_marker(cr, s.marker, f.px(s.x[i]), f.py(s.y[i]), 2.4);
    }
  }
  set_font(cr, font * 0.85, false);
  set_color(cr, {0.15, 0.15, 0.18});
  for (const PlotLabel& l : plot.labels) draw_text(cr, f.px(l.x) + 4, f.py(l.y) - 3, l.text);
  cairo_restore(cr);

  if (plot.legend) {
    std::vector<std::pair<std::string, const Series*>> entries;
    for (const Series& s : plot.series)
      if (!s.label.empty()) entries.emplace_back(s.label, &s);
    std::vector<const PlotCircle*> circles;
    for (const PlotCircle& c : plot.circles)
      if (!c.label.empty()) circles.push_back(&c);
    legend(cr, f, entries, circles, font, plot.legend_columns, plot.legend_left);
  }
  cairo_restore(cr);
}

void draw_bar_chart(cairo_t* cr, const BarChart& chart, double width, double height, const PlotStyle& style) {
  const double font = style.font_size;
  cairo_save(cr);
  double top = 0;
  title_and_frame(cr, chart.title, width, font, top);
  double ymax = chart.limit.value_or(0.0);
  for (const Bar& b : chart.bars) ymax = std::max(ymax, b.value);
  ymax = chart.y_max.value_or(ymax * 1.12);
  if (!(ymax > 0)) ymax = 1;
  const double left = 3.4 * font + 28, bottom = 3.4 * font + 6, right = 8;
  const Frame f{left, top + 4, width - left - right, height - top - 4 - bottom, 0.0, 1.0, 0.0, ymax};
  const auto yt = nice_ticks(0, ymax, std::max(3, static_cast<int>(f.h / (font * 4))));
  axes(cr, f, {}, yt, "", chart.y_label, font);
  const std::size_t n = chart.bars.size();
  const double slot = f.w / std::max<std::size_t>(1, n);
  set_font(cr, font * (n > 20 ? 0.75 : 0.9), false);
  for (std::size_t i = 0; i < n; ++i) {
    const Bar& b = chart.bars[i];
    const double x = f.x0 + slot * (i + 0.15), w = slot * 0.7;
    set_color(cr, b.color);
    cairo_rectangle(cr, x, f.py(b.value), w, f.py(0) - f.py(b.value));
    cairo_fill(cr);
    set_color(cr, {0.1, 0.1, 0.12});
    draw_text_centered(cr, x + w / 2, f.y0 + f.h + 4 + font, b.label);
    if (!b.note.empty()) {
      cairo_save(cr);
      set_font(cr, font * 0.72, false);
      draw_text_centered(cr, x + w / 2, f.py(b.value) - 2, b.note);
      cairo_restore(cr);
    }
  }
  if (chart.limit) {
    set_color(cr, {0.84, 0.15, 0.16});
    cairo_set_line_width(cr, 1.0);
    dash(cr, true, 1.0);
    cairo_move_to(cr, f.x0, f.py(*chart.limit));
    cairo_line_to(cr, f.x0 + f.w, f.py(*chart.limit));
    cairo_stroke(cr);
    dash(cr, false, 1.0);
    set_font(cr, font * 0.9, false);
    draw_text_right(cr, f.x0 + f.w - 4, f.py(*chart.limit) - 3, chart.limit_label);
  }
  cairo_restore(cr);
}

Series polar_polygon(const std::vector<double>& directions_deg, const std::vector<double>& radius_m) {
  Series s;
  constexpr double kDegToRad = std::numbers::pi / 180.0;
  for (std::size_t k = 0; k <= directions_deg.size() && !directions_deg.empty(); ++k) {
    const std::size_t i = k % directions_deg.size();
    s.x.push_back(radius_m[i] * std::cos(directions_deg[i] * kDegToRad));
    s.y.push_back(radius_m[i] * std::sin(directions_deg[i] * kDegToRad));
  }
  return s;
}

}  // namespace spiral::report
