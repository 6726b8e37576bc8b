#pragma once
// Reader of WAMIT low-order geometry files (.gdf): a hull's wetted surface as
// flat quadrilateral panels, the mesh format most BEM codes read and write
// (WAMIT, NEMOH, Capytaine, HAMS, BEMRosetta).
//
// Format (WAMIT User Manual v7 ch. 6, "low-order geometry"; recalled, not
// re-read): free-format text
//   line 1  title (any text)
//   line 2  ULEN GRAV   (length scale of the data, m; gravity, m/s²)
//   line 3  ISX ISY     (1: the plane x = 0, resp. y = 0, is a plane of
//                        symmetry and only one side is given; 0: none)
//   line 4  NPAN        (number of panels)
//   then NPAN × 4 vertices x y z in body coordinates (units of ULEN), 12
//   numbers per panel in any line layout (3 or 12 a line are both common;
//   a triangle repeats a vertex). Text after the numbers of lines 2–4 is a
//   comment ("ULEN GRAV").
// Coordinates are scaled by ULEN to metres here.
//
// Errors: FileFormatError with the file and the 1-based line of the problem
// (missing file, non-numeric token, symmetry flag not 0/1, NPAN < 1, fewer
// vertices than NPAN × 4 announce, numbers after the last panel).

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace spiral::engine {

using Panel = std::array<Eigen::Vector3d, 4>;

struct PanelMesh {
  std::string title;
  double ulen_m = 1.0;
  double gravity_m_per_s2 = 9.80665;
  bool symmetric_x = false;   ///< ISX = 1: mirrored about x = 0
  bool symmetric_y = false;   ///< ISY = 1: mirrored about y = 0
  std::vector<Panel> panels;  ///< as written, scaled to m (body frame)
};

/// Parses .gdf text; `file_name` appears in error messages only (the other
/// WAMIT readers have the same pair, so a fuzzer or a test feeds text).
PanelMesh parse_gdf(std::istream& text, const std::string& file_name);
/// Reads a .gdf file.
PanelMesh read_gdf(const std::filesystem::path& file);

/// The whole surface: the panels and their mirror images per ISX / ISY, each
/// mirrored panel with its vertex order reversed so that it keeps its
/// outward normal.
std::vector<Panel> full_surface(const PanelMesh& mesh);

}  // namespace spiral::engine
