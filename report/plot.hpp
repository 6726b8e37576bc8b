#pragma once
// 2D engineering plots drawn with cairo into any surface (PDF page, SVG,
// PNG): x–y line and scatter plots with axis labels and units, legends,
// reference circles (allowable offsets), and bar charts with a limit line.
// Sizes are in the surface's user units (pt for PDF and SVG); fonts scale
// with `PlotStyle::font_size`.

#include <cairo.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/image.hpp"

namespace spiral::report {

enum class Marker { circle, square, triangle, diamond };

struct Series {
  std::string label;  ///< empty: not in the legend
  std::vector<double> x, y;
  Rgb color{0.12, 0.47, 0.71};
  double line_width = 1.3;  ///< 0: markers only
  bool dashed = false;
  bool markers = false;
  bool step = false;  ///< piecewise constant: y[i] holds from x[i] to x[i+1]
  Marker marker = Marker::circle;
};

/// A circle in data units (with equal axes: an allowable-offset circle).
struct PlotCircle {
  double cx = 0.0, cy = 0.0, radius = 0.0;
  std::string label;
  Rgb color{0.84, 0.15, 0.16};
  bool dashed = true;
};

/// Text placed at a data point.
struct PlotLabel {
  double x = 0.0, y = 0.0;
  std::string text;
};

struct Plot {
  std::string title;
  std::string x_label;  ///< with its unit, e.g. "Offset (m)"
  std::string y_label;
  std::vector<Series> series;
  std::vector<PlotCircle> circles;
  std::vector<PlotLabel> labels;
  std::vector<std::pair<double, std::string>> x_lines;        ///< vertical reference lines (dashed)
  std::optional<std::pair<double, double>> x_range, y_range;  ///< default: the data, padded
  bool equal_aspect = false;                                  ///< 1 data unit is as long on both axes
  bool legend = true;
  int legend_columns = 0;    ///< 0: automatic
  bool legend_left = false;  ///< top-left instead of top-right
};

struct Bar {
  std::string label;
  double value = 0.0;
  Rgb color{0.12, 0.47, 0.71};
  std::string note;  ///< drawn above the bar (small)
};

struct BarChart {
  std::string title;
  std::string y_label;
  std::vector<Bar> bars;
  std::optional<double> limit;  ///< horizontal limit line
  std::string limit_label;
  std::optional<double> y_max;
};

struct PlotStyle {
  double font_size = 8.5;
};

/// Draws into the rectangle (0, 0, width, height) of the current user space.
void draw_plot(cairo_t* cr, const Plot& plot, double width, double height, const PlotStyle& style = {});
void draw_bar_chart(cairo_t* cr, const BarChart& chart, double width, double height, const PlotStyle& style = {});

/// "Nice" tick values (1, 2, 2.5, 5 × 10^k steps) covering [lo, hi], about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target);

/// A qualitative palette (Tableau 10) for distinguishing series.
Rgb palette(std::size_t index);

/// A closed polar polygon in plan view: radius_m[i] in direction
/// directions_deg[i] (CCW from +x), back to the first point.
Series polar_polygon(const std::vector<double>& directions_deg, const std::vector<double>& radius_m);

}  // namespace spiral::report
