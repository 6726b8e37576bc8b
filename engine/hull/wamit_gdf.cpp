#include "engine/hull/wamit_gdf.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "engine/common/file_format_error.hpp"
#include "engine/hull/wamit_format.hpp"

namespace spiral::engine {

namespace {

/// Reads the leading numbers of a header line; the rest is a comment.
std::vector<double> header_numbers(const std::string& file, std::size_t line_no, const std::string& line,
                                   std::size_t count, const char* what) {
  std::vector<double> out;
  for (const std::string_view token : detail::split_whitespace(line)) {
    if (out.size() == count) break;
    double v = 0.0;
    if (!detail::parse_real(token, v)) {
      throw FileFormatError(file, line_no, std::string("expected ") + what + ", got '" + std::string(token) + "'");
    }
    out.push_back(v);
  }
  if (out.size() < count) throw FileFormatError(file, line_no, std::string("expected ") + what);
  return out;
}

}  // namespace

PanelMesh read_gdf(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw FileFormatError(file, 0, "cannot open the panel mesh (WAMIT .gdf)");
  return parse_gdf(in, file);
}

PanelMesh parse_gdf(std::istream& in, const std::string& file) {
  PanelMesh mesh;
  std::string line;
  std::size_t line_no = 0;
  auto next_line = [&](const char* what) {
    if (!std::getline(in, line)) {
      throw FileFormatError(file, line_no + 1, std::string("file ends before ") + what);
    }
    ++line_no;
  };
  next_line("the title line");
  mesh.title = line;
  next_line("ULEN GRAV");
  const auto ug = header_numbers(file, line_no, line, 2, "ULEN GRAV (two numbers)");
  if (!(ug[0] > 0.0)) throw FileFormatError(file, line_no, "ULEN must be > 0, got " + std::to_string(ug[0]));
  mesh.ulen_m = ug[0];
  mesh.gravity_m_per_s2 = ug[1];
  next_line("ISX ISY");
  const auto sym = header_numbers(file, line_no, line, 2, "ISX ISY (two integers 0 or 1)");
  for (const double s : sym) {
    if (s != 0.0 && s != 1.0) {
      throw FileFormatError(file, line_no, "symmetry flags ISX ISY must be 0 or 1, got " + std::to_string(s));
    }
  }
  mesh.symmetric_x = sym[0] == 1.0;
  mesh.symmetric_y = sym[1] == 1.0;
  next_line("NPAN");
  const double npan = header_numbers(file, line_no, line, 1, "NPAN (number of panels)")[0];
  // The bound keeps the integer cast defined (a fuzzed NPAN of 6.7e62 was
  // undefined behaviour); no BEM mesh comes near 2^31 panels.
  constexpr double kMaxPanels = 2147483647.0;
  if (!(npan >= 1.0) || npan > kMaxPanels || npan != std::floor(npan)) {
    throw FileFormatError(file, line_no,
                          "NPAN must be a positive integer up to 2147483647, got " + std::to_string(npan));
  }
  const auto panels = static_cast<std::size_t>(npan);
  // NPAN is what the file claims, not what it holds: reserve at most a large
  // mesh's worth, so a wrong NPAN costs a "file ends" error, not gigabytes.
  mesh.panels.reserve(std::min<std::size_t>(panels, 100000));

  // Vertex coordinates, 12 numbers a panel in any line layout.
  std::vector<double> numbers;
  numbers.reserve(12);
  while (std::getline(in, line)) {
    ++line_no;
    for (const std::string_view token : detail::split_whitespace(line)) {
      double v = 0.0;
      if (!detail::parse_real(token, v)) {
        throw FileFormatError(file, line_no, "expected a vertex coordinate, got '" + std::string(token) + "'");
      }
      if (mesh.panels.size() == panels) {
        throw FileFormatError(file, line_no,
                              "numbers after the last of the " + std::to_string(panels) + " panels NPAN announces");
      }
      numbers.push_back(v * mesh.ulen_m);
      if (numbers.size() == 12) {
        Panel p;
        for (int k = 0; k < 4; ++k)
          p[static_cast<std::size_t>(k)] = {numbers[3 * k], numbers[3 * k + 1], numbers[3 * k + 2]};
        mesh.panels.push_back(p);
        numbers.clear();
      }
    }
  }
  if (mesh.panels.size() < panels) {
    throw FileFormatError(file, line_no,
                          "file ends after " + std::to_string(mesh.panels.size()) + " complete panels of the " +
                              std::to_string(panels) + " NPAN announces");
  }
  return mesh;
}

std::vector<Panel> full_surface(const PanelMesh& mesh) {
  std::vector<Panel> out = mesh.panels;
  const auto mirror = [&](int axis) {
    const std::size_t n = out.size();
    for (std::size_t i = 0; i < n; ++i) {
      Panel p = out[i];
      for (Eigen::Vector3d& v : p) v(axis) = -v(axis);
      std::swap(p[1], p[3]);  // a reflection flips the orientation: restore it
      out.push_back(p);
    }
  };
  if (mesh.symmetric_x) mirror(0);
  if (mesh.symmetric_y) mirror(1);
  return out;
}

}  // namespace spiral::engine
