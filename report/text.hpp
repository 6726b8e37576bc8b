#pragma once
// Internal: text with cairo's toy API in one family (DejaVu Sans, installed
// with fonts-dejavu-core), sizes in user units (px for images, pt for PDF).

#include <cairo.h>

#include <string>

namespace spiral::report {

inline constexpr const char* kFontFamily = "DejaVu Sans";

void set_font(cairo_t* cr, double size, bool bold = false);
double text_width(cairo_t* cr, const std::string& text);
/// Baseline at y, starting at x.
void draw_text(cairo_t* cr, double x, double y, const std::string& text);
void draw_text_centered(cairo_t* cr, double x, double y, const std::string& text);
void draw_text_right(cairo_t* cr, double x, double y, const std::string& text);
/// Rotated 90° counter-clockwise, centred on (x, y) along the text.
void draw_text_vertical(cairo_t* cr, double x, double y, const std::string& text);

}  // namespace spiral::report
