#include "design/project/project_summary.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace spiral::design {

namespace {
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

/// Plan azimuth in [0, 360) degrees, counter-clockwise from global +x.
double azimuth_deg(const Eigen::Vector3d& point) {
  const double a = std::atan2(point.y(), point.x()) * kRadToDeg;
  return a < 0.0 ? a + 360.0 : a;
}
}  // namespace

std::string project_summary(const Project& project, const std::vector<LineTypeProperties>& line_types) {
  std::string out;
  out += fmt::format("Project '{}' ({}), format v{}\n", project.name, project.source_file, project.version);
  const Site& site = project.site;
  out += fmt::format(
      "Site: depth {:.1f} m, water density {:.1f} kg/m³, g {:.5f} m/s², seabed friction {:.2f} (axial) / {:.2f} "
      "(lateral)\n",
      site.depth_m, site.water_density_kg_per_m3, site.gravity_m_per_s2, site.seabed.friction_axial,
      site.seabed.friction_lateral);

  out += fmt::format("\nLine types ({}):\n", line_types.size());
  out += fmt::format("  {:<14} {:<10} {:>8} {:>10} {:>10} {:>12} {:>11}\n", "name", "kind", "d mm", "m kg/m", "w N/m",
                     "EA MN", "MBL kN");
  for (const LineTypeProperties& t : line_types) {
    out += fmt::format("  {:<14} {:<10} {:>8.1f} {:>10.2f} {:>10.2f} {:>12.1f} {:>11.0f}\n", t.name, to_string(t.kind),
                       t.nominal_diameter_m * 1e3, t.mass_per_length_kg_per_m, t.submerged_weight_N_per_m,
                       t.axial_stiffness_N / 1e6, t.breaking_load_N / 1e3);
  }

  out += fmt::format("\nMooring lines ({}):\n", project.mooring.lines.size());
  out += fmt::format("  {:<10} {:>9} {:>10} {:>11} {:>10}  {}\n", "name", "az °", "anchor r m", "anchor z m",
                     "length m", "segments (anchor -> fairlead)");
  for (const MooringLine& line : project.mooring.lines) {
    double length = 0.0;
    std::string segments;
    for (const LineSegment& s : line.segments) {
      length += s.length_m;
      segments += fmt::format("{}{} {:.1f} m", segments.empty() ? "" : " + ", s.type, s.length_m);
    }
    const Eigen::Vector3d& a = line.anchor_g;
    out += fmt::format("  {:<10} {:>9.2f} {:>10.1f} {:>11.1f} {:>10.1f}  {}\n", line.name, azimuth_deg(a),
                       std::hypot(a.x(), a.y()), a.z(), length, segments);
  }
  out += fmt::format("\nHull: mass {:.4g} kg, CoG ({:.2f}, {:.2f}, {:.2f}) m\n", project.hull.mass_kg,
                     project.hull.center_of_gravity_b.x(), project.hull.center_of_gravity_b.y(),
                     project.hull.center_of_gravity_b.z());
  out += fmt::format("Risers: {}\n", project.risers.size());
  out += fmt::format("Environments: {}\n", project.environments.size());
  out += fmt::format("Load cases: {}\n", project.load_cases.size());
  out += fmt::format("Stages: {}\n", project.stages.size());
  if (const auto& length = project.global_analysis.element_length_m)
    out += fmt::format(
        "Global analysis: the coupled level's and --line-dynamics' lines in elements of at most {:g} m\n", *length);
  return out;
}

}  // namespace spiral::design
