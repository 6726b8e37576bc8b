#include "design/mooring_model.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace spiral::design {

std::vector<LineTypeProperties> resolve_line_types(const Project& project) {
  std::vector<LineTypeProperties> resolved;
  resolved.reserve(project.line_types.size());
  for (const LineTypeInput& input : project.line_types) {
    resolved.push_back(resolve_line_type(input, project.site.water_density_kg_per_m3,
                                         project.site.gravity_m_per_s2));
  }
  return resolved;
}

MooringDesignModel build_mooring_model(const Project& project, const std::string& excluded_line) {
  const std::vector<LineTypeProperties> types = resolve_line_types(project);
  const auto find_type = [&](const std::string& name) -> const LineTypeProperties& {
    const auto it = std::find_if(types.begin(), types.end(),
                                 [&](const LineTypeProperties& t) { return t.name == name; });
    if (it == types.end()) throw std::invalid_argument(fmt::format("unknown line type '{}'", name));
    return *it;
  };
  if (!excluded_line.empty() &&
      std::none_of(project.mooring.lines.begin(), project.mooring.lines.end(),
                   [&](const MooringLine& l) { return l.name == excluded_line; })) {
    throw std::invalid_argument(fmt::format("no mooring line named '{}'", excluded_line));
  }

  const double rho = project.site.water_density_kg_per_m3;
  const double g = project.site.gravity_m_per_s2;
  MooringDesignModel model;
  model.system.reference_point_g = project.hull.reference_point_g;
  for (const MooringLine& line : project.mooring.lines) {
    if (line.name == excluded_line) continue;
    engine::MooringLineModel engine_line;
    MooringLineDesign design_line;
    engine_line.name = design_line.name = line.name;
    engine_line.anchor_g = line.anchor_g;
    engine_line.fairlead_b = line.fairlead_b;
    // The anchor sits on the seabed unless the project places it above (z > -depth).
    engine_line.anchor_height_above_seabed_m = std::max(0.0, line.anchor_g.z() + project.site.depth_m);
    engine_line.line.seabed_friction = project.site.seabed.friction_axial;
    for (const LineSegment& segment : line.segments) {
      const LineTypeProperties& type = find_type(segment.type);
      engine_line.line.segments.push_back(
          {segment.length_m, type.submerged_weight_N_per_m, type.axial_stiffness_N});
      design_line.segment_types.push_back(type);
    }
    if (line.segments.size() > 1) engine_line.line.joint_load_N.assign(line.segments.size() - 1, 0.0);
    for (const Attachment& attachment : line.attachments) {
      // Net downward load of a point body in water: weight minus buoyancy. A
      // clump is heavier than the water it displaces, a buoy lighter.
      engine_line.line.joint_load_N.at(static_cast<std::size_t>(attachment.after_segment)) +=
          (attachment.mass_kg - rho * attachment.volume_m3) * g;
    }
    model.system.lines.push_back(std::move(engine_line));
    model.lines.push_back(std::move(design_line));
  }
  return model;
}

}  // namespace spiral::design
