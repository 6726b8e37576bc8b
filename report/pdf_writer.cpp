// The PDF writer: a two-pass flow layout on A4 (pass 1 measures and
// paginates without drawing, so that the contents list and "page n of N"
// are known; pass 2 draws).
#include <cairo-pdf.h>
#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>

#include "report/cairo_image.hpp"
#include "report/color_map.hpp"
#include "report/document.hpp"
#include "report/text.hpp"

namespace spiral::report {

namespace {

constexpr double kPageW = 595.28, kPageH = 841.89;  // A4, pt
constexpr double kMarginX = 54, kTop = 66, kBottom = 60;
constexpr double kContentW = kPageW - 2 * kMarginX;
constexpr double kBodyFont = 9.5, kLineH = 13.0;
constexpr double kTableFont = 7.8, kRowH = 11.5;
constexpr Rgb kInk{0.10, 0.11, 0.14};
constexpr Rgb kAccent{0.08, 0.25, 0.45};
constexpr double kHeadingLineH = 19.0;  // pt, a section heading's line at 15 pt

void ink(cairo_t* cr, const Rgb& c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

std::vector<std::string> wrap(cairo_t* cr, const std::string& text, double width) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string word, line;
  while (words >> word) {
    const std::string candidate = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_width(cr, candidate) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = candidate;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

class Layout {
 public:
  Layout(cairo_t* cr, bool draw, const ReportDocument& doc, int total_pages, std::map<std::size_t, int> section_pages)
      : cr_(cr), draw_(draw), doc_(doc), total_pages_(total_pages), section_pages_(std::move(section_pages)) {}

  int pages() const { return page_; }
  const std::map<std::size_t, int>& section_pages() const { return found_pages_; }

  void run() {
    title_page();
    for (std::size_t i = 0; i < doc_.sections.size(); ++i) section(i);
    finish_page();
  }

 private:
  void finish_page() {
    if (page_open_ && draw_) cairo_show_page(cr_);
    page_open_ = false;
  }

  void new_page() {
    finish_page();
    ++page_;
    page_open_ = true;
    y_ = kTop;
    if (!draw_ || page_ == 1) return;
    set_font(cr_, 7.5, false);
    ink(cr_, {0.45, 0.47, 0.5});
    draw_text(cr_, kMarginX, 40, doc_.running_header);
    draw_text_right(cr_, kPageW - kMarginX, 40, doc_.title.title);
    cairo_set_line_width(cr_, 0.5);
    cairo_move_to(cr_, kMarginX, 46);
    cairo_line_to(cr_, kPageW - kMarginX, 46);
    cairo_stroke(cr_);
    draw_text(cr_, kMarginX, kPageH - 30, doc_.running_footer);
    draw_text_right(cr_, kPageW - kMarginX, kPageH - 30, fmt::format("Page {} of {}", page_, total_pages_));
  }

  void ensure(double height) {
    if (y_ + height > kPageH - kBottom) new_page();
  }

  void title_page() {
    new_page();
    const TitlePage& t = doc_.title;
    if (draw_) {
      cairo_rectangle(cr_, 0, 0, kPageW, 12);
      ink(cr_, kAccent);
      cairo_fill(cr_);
      set_font(cr_, 11, true);
      ink(cr_, kAccent);
      draw_text(cr_, kMarginX, 120, "spiral · integrated mooring–riser design");
      set_font(cr_, 26, true);
      ink(cr_, kInk);
      draw_text(cr_, kMarginX, 170, t.title);
      set_font(cr_, 15, false);
      draw_text(cr_, kMarginX, 196, t.subtitle);
      set_font(cr_, 13, true);
      draw_text(cr_, kMarginX, 240, t.project);
      set_font(cr_, kBodyFont, false);
      double y = 258;
      for (const auto& line : wrap(cr_, t.description, kContentW)) {
        draw_text(cr_, kMarginX, y, line);
        y += kLineH;
      }
      y += 14;
      for (const auto& [key, value] : t.facts) {
        set_font(cr_, kBodyFont, true);
        draw_text(cr_, kMarginX, y, key);
        set_font(cr_, kBodyFont, false);
        draw_text(cr_, kMarginX + 110, y, value);
        y += kLineH + 1;
      }
      y += 16;
      const Rgb box = t.pass ? kPassColor : kFailColor;
      set_font(cr_, 11, true);
      const auto verdict = wrap(cr_, t.verdict, kContentW - 24);
      const double box_h = 16 + 15.0 * static_cast<double>(verdict.size());
      cairo_rectangle(cr_, kMarginX, y, kContentW, box_h);
      cairo_set_source_rgba(cr_, box.r, box.g, box.b, 0.12);
      cairo_fill_preserve(cr_);
      ink(cr_, box);
      cairo_set_line_width(cr_, 1.2);
      cairo_stroke(cr_);
      for (std::size_t i = 0; i < verdict.size(); ++i) draw_text(cr_, kMarginX + 12, y + 20 + 15.0 * i, verdict[i]);
      y += box_h + 30;
      set_font(cr_, 12, true);
      ink(cr_, kInk);
      draw_text(cr_, kMarginX, y, "Contents");
      y += 18;
      set_font(cr_, kBodyFont, false);
      for (std::size_t i = 0; i < doc_.sections.size(); ++i) {
        const std::string entry = fmt::format("{}  {}", i + 1, doc_.sections[i].title);
        draw_text(cr_, kMarginX + 8, y, entry);
        const auto it = section_pages_.find(i);
        if (it != section_pages_.end()) draw_text_right(cr_, kPageW - kMarginX, y, std::to_string(it->second));
        y += kLineH + 1;
      }
    }
    // The title page is a page of its own.
  }

  void section(std::size_t index) {
    const Section& s = doc_.sections[index];
    if (s.new_page)
      new_page();
    else
      ensure(80);
    found_pages_[index] = page_;
    // A long title (a matrix case's name) wraps instead of running off the page.
    set_font(cr_, 15, true);
    const std::vector<std::string> lines = wrap(cr_, fmt::format("{}  {}", index + 1, s.title), kContentW);
    const double extra = kHeadingLineH * static_cast<double>(std::max<std::size_t>(lines.size(), 1) - 1);
    if (draw_) {
      ink(cr_, kAccent);
      for (std::size_t i = 0; i < lines.size(); ++i)
        draw_text(cr_, kMarginX, y_ + 15 + kHeadingLineH * static_cast<double>(i), lines[i]);
      cairo_set_line_width(cr_, 0.8);
      cairo_move_to(cr_, kMarginX, y_ + 22 + extra);
      cairo_line_to(cr_, kPageW - kMarginX, y_ + 22 + extra);
      cairo_stroke(cr_);
    }
    y_ += 36 + extra;
    for (const Block& block : s.blocks) {
      std::visit([this](const auto& b) { this->block(b); }, block);
    }
  }

  void block(const Paragraph& p) {
    set_font(cr_, kBodyFont, false);
    for (const auto& line : wrap(cr_, p.text, kContentW)) {
      ensure(kLineH);
      if (draw_) {
        ink(cr_, kInk);
        draw_text(cr_, kMarginX, y_ + 10, line);
      }
      y_ += kLineH;
    }
    y_ += 6;
  }

  void block(const KeyValues& kv) {
    set_font(cr_, kBodyFont, true);
    double key_w = 0;
    for (const auto& [k, v] : kv.items) key_w = std::max(key_w, text_width(cr_, k));
    key_w = std::min(key_w + 14, kContentW * 0.42);
    for (const auto& [k, v] : kv.items) {
      set_font(cr_, kBodyFont, false);
      const auto lines = wrap(cr_, v, kContentW - key_w);
      ensure(kLineH * static_cast<double>(std::max<std::size_t>(1, lines.size())));
      if (draw_) {
        ink(cr_, kInk);
        set_font(cr_, kBodyFont, true);
        draw_text(cr_, kMarginX, y_ + 10, k);
        set_font(cr_, kBodyFont, false);
        for (std::size_t i = 0; i < lines.size(); ++i) draw_text(cr_, kMarginX + key_w, y_ + 10 + i * kLineH, lines[i]);
      }
      y_ += kLineH * static_cast<double>(std::max<std::size_t>(1, lines.size()));
    }
    y_ += 8;
  }

  void block(const Table& t) {
    ++table_number_;
    // Column widths: the widest text of each column, scaled to the content width if needed.
    const std::size_t n = t.headers.size();
    std::vector<double> widths(n, 0.0);
    set_font(cr_, kTableFont, true);
    for (std::size_t c = 0; c < n; ++c) widths[c] = text_width(cr_, t.headers[c]) + 10;
    set_font(cr_, kTableFont, false);
    for (const auto& row : t.rows)
      for (std::size_t c = 0; c < n && c < row.size(); ++c)
        widths[c] = std::max(widths[c], text_width(cr_, row[c].text) + 10);
    double total = 0;
    for (const double w : widths) total += w;
    const double scale = total > kContentW ? kContentW / total : 1.0;
    for (double& w : widths) w *= scale;
    total *= scale;
    const double font = kTableFont * scale;  // a wide table shrinks its type to fit the column

    // Caption, header, rows; the header repeats on a new page.
    set_font(cr_, 8.5, true);  // measured in the bold face it is drawn in
    const auto caption = wrap(cr_, fmt::format("Table {}. {}", table_number_, t.caption), kContentW);
    ensure(caption.size() * 11.0 + 2 * kRowH + 8);
    if (draw_) {
      ink(cr_, kInk);
      set_font(cr_, 8.5, true);
      for (std::size_t i = 0; i < caption.size(); ++i) draw_text(cr_, kMarginX, y_ + 9 + i * 11.0, caption[i]);
    }
    y_ += caption.size() * 11.0 + 4;
    auto header = [&] {
      if (draw_) {
        cairo_rectangle(cr_, kMarginX, y_, total, kRowH + 3);
        ink(cr_, {0.86, 0.89, 0.93});
        cairo_fill(cr_);
        ink(cr_, kInk);
        set_font(cr_, font, true);
        double x = kMarginX;
        for (std::size_t c = 0; c < n; ++c) {
          if (c == 0)
            draw_text(cr_, x + 4, y_ + kRowH - 1.5, t.headers[c]);
          else
            draw_text_right(cr_, x + widths[c] - 4, y_ + kRowH - 1.5, t.headers[c]);
          x += widths[c];
        }
      }
      y_ += kRowH + 3;
    };
    header();
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      if (y_ + kRowH > kPageH - kBottom) {
        new_page();
        header();
      }
      if (draw_) {
        if (r % 2 == 1) {
          cairo_rectangle(cr_, kMarginX, y_, total, kRowH);
          ink(cr_, {0.96, 0.97, 0.98});
          cairo_fill(cr_);
        }
        double x = kMarginX;
        for (std::size_t c = 0; c < n && c < t.rows[r].size(); ++c) {
          const TableCell& cell = t.rows[r][c];
          set_font(cr_, font, cell.status != CellStatus::none);
          ink(cr_, cell.status == CellStatus::pass ? kPassColor : cell.status == CellStatus::fail ? kFailColor : kInk);
          if (c == 0)
            draw_text(cr_, x + 4, y_ + kRowH - 2.5, cell.text);
          else
            draw_text_right(cr_, x + widths[c] - 4, y_ + kRowH - 2.5, cell.text);
          x += widths[c];
        }
      }
      y_ += kRowH;
    }
    if (draw_) {
      ink(cr_, {0.6, 0.62, 0.66});
      cairo_set_line_width(cr_, 0.6);
      cairo_move_to(cr_, kMarginX, y_);
      cairo_line_to(cr_, kMarginX + total, y_);
      cairo_stroke(cr_);
    }
    y_ += 14;
  }

  void block(const Figure& f) {
    ++figure_number_;
    double w = kContentW, h = w / f.aspect;
    const double max_h = (kPageH - kTop - kBottom) * 0.62;
    if (h > max_h) h = max_h, w = h * f.aspect;
    set_font(cr_, 8.5, false);
    const auto caption = wrap(cr_, fmt::format("Figure {}. {}", figure_number_, f.caption), kContentW);
    ensure(h + caption.size() * 11.0 + 10);
    const double x = kMarginX + (kContentW - w) / 2;
    if (draw_) {
      cairo_save(cr_);
      cairo_translate(cr_, x, y_);
      if (f.image) {
        const SurfacePtr surface = to_surface(*f.image);
        cairo_scale(cr_, w / f.image->width, h / f.image->height);
        cairo_set_source_surface(cr_, surface.get(), 0, 0);
        cairo_pattern_set_filter(cairo_get_source(cr_), CAIRO_FILTER_GOOD);
        cairo_paint(cr_);
      } else if (f.draw) {
        f.draw(cr_, w, h);
      }
      cairo_restore(cr_);
      if (f.image) {
        ink(cr_, {0.7, 0.72, 0.75});
        cairo_set_line_width(cr_, 0.5);
        cairo_rectangle(cr_, x, y_, w, h);
        cairo_stroke(cr_);
      }
    }
    y_ += h + 4;
    if (draw_) {
      ink(cr_, kInk);
      set_font(cr_, 8.5, false);
      for (std::size_t i = 0; i < caption.size(); ++i) draw_text(cr_, kMarginX, y_ + 9 + i * 11.0, caption[i]);
    }
    y_ += caption.size() * 11.0 + 12;
  }

  cairo_t* cr_;
  bool draw_;
  const ReportDocument& doc_;
  int total_pages_;
  std::map<std::size_t, int> section_pages_;
  std::map<std::size_t, int> found_pages_;
  int page_ = 0;
  bool page_open_ = false;
  double y_ = 0;
  int table_number_ = 0;
  int figure_number_ = 0;
};

}  // namespace

int write_pdf(const ReportDocument& document, const std::string& file) {
  // Pass 1: paginate on a PDF surface that writes nowhere (same font metrics).
  cairo_surface_t* null_surface = cairo_pdf_surface_create_for_stream(
      [](void*, const unsigned char*, unsigned int) { return CAIRO_STATUS_SUCCESS; }, nullptr, kPageW, kPageH);
  const SurfacePtr measure_surface(null_surface);
  const ContextPtr measure(cairo_create(measure_surface.get()));
  Layout pass1(measure.get(), false, document, 0, {});
  pass1.run();

  const SurfacePtr surface(cairo_pdf_surface_create(file.c_str(), kPageW, kPageH));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(fmt::format("{}: cannot create the PDF", file));
  }
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE,
                                 (document.title.title + " — " + document.title.project).c_str());
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "spiral");
  {
    const ContextPtr context(cairo_create(surface.get()));
    Layout pass2(context.get(), true, document, pass1.pages(), pass1.section_pages());
    pass2.run();
  }
  cairo_surface_finish(surface.get());
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(fmt::format("{}: cannot write the PDF ({})", file,
                                         cairo_status_to_string(cairo_surface_status(surface.get()))));
  }
  return pass1.pages();
}

}  // namespace spiral::report
