#pragma once
// A report as data: a title page and sections of blocks (paragraphs,
// key–value lists, tables, figures). Stage reports build one (e.g.
// report/static_stage_report.hpp); the writers turn it into a PDF, an HTML
// index with the same figures and tables, and CSV files of every table.
// Later stages add their own sections; nothing here knows about analyses.

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "design/project/warning_note.hpp"
#include "report/image.hpp"

// cairo's context type, declared as cairo.h does, so that users of the
// document need not see cairo.
typedef struct _cairo cairo_t;

namespace spiral::report {

enum class CellStatus { none, pass, fail };

struct TableCell {
  std::string text;             ///< as shown (formatted, with the unit in the header)
  std::optional<double> value;  ///< full-precision value for the CSV; absent: `text` is written
  CellStatus status = CellStatus::none;
};

struct Table {
  std::string id;  ///< file stem of the CSV (tables/<id>.csv); [a-z0-9-]
  std::string caption;
  std::vector<std::string> headers;  ///< with units, e.g. "T max (kN)"
  std::vector<std::vector<TableCell>> rows;
};

/// Draws a vector figure into (0, 0, width, height) of the current user space.
using DrawFunction = std::function<void(cairo_t*, double width, double height)>;

struct Figure {
  std::string id;  ///< file stem (figures/<id>.png or .svg); [a-z0-9-]
  std::string caption;
  double aspect = 1.6;         ///< width / height
  std::optional<Image> image;  ///< a raster figure (3D views), or
  DrawFunction draw;           ///< a vector figure (plots)
};

struct Paragraph {
  std::string text;
};

/// A result's note as a paragraph: "Warning: …" for a warning
/// (design/project/warning_note.hpp), "Note: …" for the others.
inline Paragraph note_paragraph(const std::string& note) {
  return {std::string(design::is_warning(note) ? "Warning: " : "Note: ") + std::string(design::note_text(note)) + "."};
}

struct KeyValues {
  std::vector<std::pair<std::string, std::string>> items;
};

using Block = std::variant<Paragraph, KeyValues, Table, Figure>;

struct Section {
  std::string title;
  std::vector<Block> blocks;
  bool new_page = true;
};

struct TitlePage {
  std::string title;     ///< e.g. "Preliminary stage report"
  std::string subtitle;  ///< e.g. "Static analyses"
  std::string project;   ///< project name
  std::string description;
  std::vector<std::pair<std::string, std::string>> facts;  ///< project file, date, version, model hash, ...
  std::string verdict;                                     ///< one line, e.g. "PASS: every case meets API RP 2SK"
  bool pass = true;
};

struct ReportDocument {
  TitlePage title;
  std::string running_header;  ///< top of every page after the title
  std::string running_footer;  ///< bottom left of every page
  std::vector<Section> sections;
};

/// Writes the PDF (A4 portrait). Throws std::runtime_error naming the file.
/// Returns the number of pages.
int write_pdf(const ReportDocument& document, const std::string& file);

/// Writes figures/<id>.png|svg, tables/<id>.csv and index.html into `folder`
/// (which exists). Throws std::runtime_error naming the file.
void write_html(const ReportDocument& document, const std::string& folder);

/// Writes a vector figure as an SVG file of the PDF's text-column width
/// (the HTML index's figures). Throws std::runtime_error naming the file.
void write_svg(const Figure& figure, const std::string& file);

/// A CSV of the table (RFC 4180 quoting).
std::string table_csv(const Table& table);

}  // namespace spiral::report
