// The HTML index: the same sections, tables (each with its CSV) and figures
// (PNG for 3D views, SVG for plots) as the PDF, in one self-contained page
// of relative links.
#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "report/cairo_image.hpp"
#include "report/document.hpp"

namespace spiral::report {

namespace {

/// Size of SVG figures, pt: the width of the PDF's text column.
constexpr double kSvgWidth = 487.0;

std::string escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write", file.string()));
}

std::string figure_file(const Figure& f) { return "figures/" + f.id + (f.image ? ".png" : ".svg"); }

void write_figure(const Figure& f, const std::filesystem::path& folder) {
  const auto path = folder / figure_file(f);
  if (f.image) {
    write_png(*f.image, path);
    return;
  }
  write_svg(f, path.string());
}

constexpr const char* kStyle = R"(
body{font-family:"DejaVu Sans",Helvetica,Arial,sans-serif;color:#1a1c24;max-width:1100px;margin:0 auto;padding:0 24px 60px;line-height:1.45}
header{border-top:8px solid #14406f;padding-top:18px}
h1{margin:.2em 0 0;font-size:1.9em} h2{color:#14406f;border-bottom:1px solid #14406f;padding-bottom:4px;margin-top:2em}
.sub{font-size:1.2em;color:#444} .facts td{padding:1px 14px 1px 0} .facts td:first-child{font-weight:bold}
.verdict{padding:10px 14px;font-weight:bold;border:1.5px solid;margin:16px 0}
.pass{color:#2b8c40} .fail{color:#d62728} .verdict.pass{background:#eef7f0} .verdict.fail{background:#fcecec}
table.data{border-collapse:collapse;font-size:.85em;margin:.4em 0 1.4em}
table.data th{background:#dce3ed;padding:3px 8px;text-align:right} table.data td{padding:2px 8px;text-align:right}
table.data th:first-child,table.data td:first-child{text-align:left}
table.data tr:nth-child(even) td{background:#f4f6f9} td.pass,td.fail{font-weight:bold}
.caption{font-weight:bold;font-size:.9em} figure{margin:1em 0 2em} figure img{max-width:100%;border:1px solid #ccd}
figcaption{font-size:.9em} nav li{margin:2px 0} dl.kv{display:grid;grid-template-columns:max-content auto;gap:2px 16px} dl.kv dt{font-weight:bold}
)";

}  // namespace

void write_svg(const Figure& f, const std::string& file) {
  const double h = kSvgWidth / f.aspect;
  const SurfacePtr surface(cairo_svg_surface_create(file.c_str(), kSvgWidth, h));
  {
    const ContextPtr cr(cairo_create(surface.get()));
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    if (f.draw) f.draw(cr.get(), kSvgWidth, h);
  }
  cairo_surface_finish(surface.get());
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(fmt::format("{}: cannot write the figure", file));
  }
}

std::string table_csv(const Table& table) {
  auto quote = [](const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  std::string out;
  for (std::size_t c = 0; c < table.headers.size(); ++c) {
    if (c) out += ',';
    out += quote(table.headers[c]);
  }
  out += "\n";
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) out += ',';
      out += row[c].value ? fmt::format("{:.10g}", *row[c].value) : quote(row[c].text);
    }
    out += "\n";
  }
  return out;
}

void write_html(const ReportDocument& doc, const std::string& folder_name) {
  const std::filesystem::path folder(folder_name);
  std::filesystem::create_directories(folder / "figures");
  std::filesystem::create_directories(folder / "tables");
  const TitlePage& t = doc.title;
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" +
                     escape(t.title + " — " + t.project) + "</title>\n<style>" + kStyle + "</style></head><body>\n";
  html += "<header><div class=\"sub\">spiral · integrated mooring–riser design</div><h1>" + escape(t.title) +
          "</h1><div class=\"sub\">" + escape(t.subtitle) + "</div><h2 style=\"border:0;color:#1a1c24\">" +
          escape(t.project) + "</h2><p>" + escape(t.description) + "</p><table class=\"facts\">";
  for (const auto& [k, v] : t.facts) html += "<tr><td>" + escape(k) + "</td><td>" + escape(v) + "</td></tr>";
  html += "</table><div class=\"verdict " + std::string(t.pass ? "pass" : "fail") + "\">" + escape(t.verdict) +
          "</div><p><a href=\"report.pdf\">PDF report</a></p></header>\n<nav><h2>Contents</h2><ol>";
  for (std::size_t i = 0; i < doc.sections.size(); ++i) {
    html += fmt::format("<li><a href=\"#s{}\">{}</a></li>", i + 1, escape(doc.sections[i].title));
  }
  html += "</ol></nav>\n";
  int tables = 0, figures = 0;
  for (std::size_t i = 0; i < doc.sections.size(); ++i) {
    const Section& s = doc.sections[i];
    html += fmt::format("<section id=\"s{}\"><h2>{} {}</h2>\n", i + 1, i + 1, escape(s.title));
    for (const Block& block : s.blocks) {
      if (const auto* p = std::get_if<Paragraph>(&block)) {
        html += "<p>" + escape(p->text) + "</p>\n";
      } else if (const auto* kv = std::get_if<KeyValues>(&block)) {
        html += "<dl class=\"kv\">";
        for (const auto& [k, v] : kv->items) html += "<dt>" + escape(k) + "</dt><dd>" + escape(v) + "</dd>";
        html += "</dl>\n";
      } else if (const auto* table = std::get_if<Table>(&block)) {
        write_text(folder / "tables" / (table->id + ".csv"), table_csv(*table));
        html += fmt::format("<p class=\"caption\">Table {}. {} <a href=\"tables/{}.csv\">(CSV)</a></p>", ++tables,
                            escape(table->caption), table->id);
        html += "<table class=\"data\"><tr>";
        for (const auto& h : table->headers) html += "<th>" + escape(h) + "</th>";
        html += "</tr>\n";
        for (const auto& row : table->rows) {
          html += "<tr>";
          for (const auto& cell : row) {
            const char* cls = cell.status == CellStatus::pass   ? " class=\"pass\""
                              : cell.status == CellStatus::fail ? " class=\"fail\""
                                                                : "";
            html += std::string("<td") + cls + ">" + escape(cell.text) + "</td>";
          }
          html += "</tr>\n";
        }
        html += "</table>\n";
      } else if (const auto* figure = std::get_if<Figure>(&block)) {
        write_figure(*figure, folder);
        html += fmt::format("<figure><img src=\"{}\" alt=\"{}\"><figcaption>Figure {}. {}</figcaption></figure>\n",
                            figure_file(*figure), escape(figure->caption), ++figures, escape(figure->caption));
      }
    }
    html += "</section>\n";
  }
  html += "<footer><p>" + escape(doc.running_footer) + "</p></footer></body></html>\n";
  write_text(folder / "index.html", html);
}

}  // namespace spiral::report
