#include "report/text.hpp"

#include <numbers>

namespace spiral::report {

void set_font(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, kFontFamily, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

void draw_text(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
  cairo_new_path(cr);
}

void draw_text_centered(cairo_t* cr, double x, double y, const std::string& text) {
  draw_text(cr, x - text_width(cr, text) / 2, y, text);
}

void draw_text_right(cairo_t* cr, double x, double y, const std::string& text) {
  draw_text(cr, x - text_width(cr, text), y, text);
}

void draw_text_vertical(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_save(cr);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, -std::numbers::pi / 2);
  draw_text_centered(cr, 0, 0, text);
  cairo_restore(cr);
}

}  // namespace spiral::report
