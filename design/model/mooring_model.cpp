#include "design/model/mooring_model.hpp"

#include "engine/lines/catenary_payout.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "design/project/project_validation.hpp"

namespace spiral::design {

const LineTypeProperties& find_type(const std::vector<LineTypeProperties>& types, const std::string& name) {
  const auto it = std::find_if(types.begin(), types.end(), [&](const LineTypeProperties& t) { return t.name == name; });
  if (it == types.end()) throw std::invalid_argument(fmt::format("unknown line type '{}'", name));
  return *it;
}

std::vector<LineTypeProperties> resolve_line_types(const Project& project) {
  std::vector<LineTypeProperties> resolved;
  resolved.reserve(project.line_types.size());
  for (const LineTypeInput& input : project.line_types) {
    resolved.push_back(resolve_line_type(input, project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2));
  }
  return resolved;
}

engine::CatenaryLine catenary_of(const Project& project, const MooringLine& line,
                                 const std::vector<LineTypeProperties>& types) {
  engine::CatenaryLine catenary;
  catenary.seabed_friction = project.site.seabed.friction_axial;
  for (const LineSegment& segment : line.segments) {
    const LineTypeProperties& type = find_type(types, segment.type);
    catenary.segments.push_back({segment.length_m, type.submerged_weight_N_per_m, type.axial_stiffness_N});
  }
  if (line.segments.size() > 1) catenary.joint_load_N.assign(line.segments.size() - 1, 0.0);
  const double rho = project.site.water_density_kg_per_m3;
  const double g = project.site.gravity_m_per_s2;
  for (const Attachment& attachment : line.attachments) {
    // Net downward load of a point body in water: weight minus buoyancy. A
    // clump is heavier than the water it displaces, a buoy lighter.
    catenary.joint_load_N.at(static_cast<std::size_t>(attachment.after_segment)) +=
        (attachment.mass_kg - rho * attachment.volume_m3) * g;
  }
  return catenary;
}

namespace {

engine::FeLineModel fe_model_of(const Project& project, const MooringLine& line,
                                const std::vector<LineTypeProperties>& types) {
  engine::FeLineModel model;
  for (const LineSegment& segment : line.segments) {
    const LineTypeProperties& type = find_type(types, segment.type);
    engine::FeLineSection section;
    section.length_m = segment.length_m;
    section.EA_N = type.axial_stiffness_N;
    section.mass_kg_per_m = type.mass_per_length_kg_per_m;
    section.weight_N_per_m = type.submerged_weight_N_per_m;
    section.hydro_diameter_m = type.hydrodynamic_diameter_m;
    section.drag_normal = type.drag_normal;
    section.drag_tangential = type.drag_axial;
    section.displaced_area_m2 = std::numbers::pi / 4.0 * type.hydrodynamic_diameter_m * type.hydrodynamic_diameter_m;
    section.added_mass_normal = type.added_mass_normal;
    section.added_mass_tangential = type.added_mass_axial;
    section.element_length_m = std::min(line.fe.element_length_m, segment.length_m);
    model.sections.push_back(section);
  }
  const engine::CatenaryLine catenary = catenary_of(project, line, types);
  model.joint_load_N = catenary.joint_load_N;
  if (line.fe.touchdown_refinement) {
    // The zone is centred on the touchdown point of the at-rest line (hull at
    // its reference point), from the multi-segment catenary: its laid length
    // is the arc from the anchor to the TDP.
    const engine::CatenaryGeometry at_rest = catenary_geometry_at_rest(project, line);
    try {
      model.refinement = touchdown_refinement_zone(line.fe, engine::solve_catenary(catenary, at_rest).laid_length_m);
    } catch (const engine::SolverError& error) {
      throw engine::SolverError(
          fmt::format("line '{}': fe.touchdown_refinement needs the touchdown point of the line at rest: {}", line.name,
                      error.what()));
    }
  }
  return model;
}

void check_excluded_line(const Project& project, const std::string& excluded_line) {
  if (!excluded_line.empty() && std::none_of(project.mooring.lines.begin(), project.mooring.lines.end(),
                                             [&](const MooringLine& l) { return l.name == excluded_line; })) {
    throw std::invalid_argument(fmt::format("no mooring line named '{}'", excluded_line));
  }
}

}  // namespace

engine::CatenaryGeometry catenary_geometry_at_rest(const Project& project, const MooringLine& line) {
  const Eigen::Vector3d fairlead_g = project.hull.reference_point_g + line.fairlead_b;
  return {(fairlead_g - line.anchor_g).head<2>().norm(), fairlead_g.z() - line.anchor_g.z(),
          std::max(0.0, line.anchor_g.z() + project.site.depth_m)};
}

double pretension_at_rest_N(const Project& project, const MooringLine& line,
                            const std::vector<LineTypeProperties>& types, double payout_m) {
  return engine::solve_catenary(engine::with_payout(catenary_of(project, line, types), payout_m),
                                catenary_geometry_at_rest(project, line))
      .fairlead_tension_N;
}

LineArrayModel build_mooring_model(const Project& project, const std::string& excluded_line) {
  return build_mooring_model(project, resolve_line_types(project), excluded_line);
}

LineArrayModel build_mooring_model(const Project& project, const std::vector<LineTypeProperties>& types,
                                   const std::string& excluded_line) {
  check_excluded_line(project, excluded_line);
  LineArrayModel model;
  model.reference_point_g = project.hull.reference_point_g;
  for (const MooringLine& line : project.mooring.lines) {
    if (line.name == excluded_line) continue;
    // The anchor sits on the seabed unless the project places it above (z > -depth).
    const double anchor_height_m = std::max(0.0, line.anchor_g.z() + project.site.depth_m);
    model.lines.push_back(std::make_unique<engine::CatenaryStaticLine>(
        line.name, line.anchor_g, line.fairlead_b, anchor_height_m, catenary_of(project, line, types)));
    MooringLineDesign design{line.name, {}};
    for (const LineSegment& segment : line.segments) design.segment_types.push_back(find_type(types, segment.type));
    model.designs.push_back(std::move(design));
  }
  return model;
}

LineArrayModel build_line_array(const Project& project, const LineArrayOptions& options) {
  return build_line_array(project, resolve_line_types(project), options);
}

LineArrayModel build_line_array(const Project& project, const std::vector<LineTypeProperties>& types,
                                const LineArrayOptions& options) {
  check_excluded_line(project, options.excluded_line);
  LineArrayModel model;
  model.reference_point_g = project.hull.reference_point_g;
  for (const MooringLine& line : project.mooring.lines) {
    if (line.name == options.excluded_line) continue;
    const double anchor_height_m = std::max(0.0, line.anchor_g.z() + project.site.depth_m);
    if (line.model == LineModel::fe || (options.lines_carry_current && options.current)) {
      const engine::FeLineModel fe = fe_model_of(project, line, types);
      model.lines.push_back(std::make_unique<engine::FeStaticLine>(
          line.name, line.anchor_g, line.fairlead_b, fe,
          fe_environment(project, options.current, fe.sections.front().hydro_diameter_m), options.fe_statics));
    } else {
      model.lines.push_back(std::make_unique<engine::CatenaryStaticLine>(
          line.name, line.anchor_g, line.fairlead_b, anchor_height_m, catenary_of(project, line, types)));
    }
    MooringLineDesign design{line.name, {}};
    for (const LineSegment& segment : line.segments) design.segment_types.push_back(find_type(types, segment.type));
    model.designs.push_back(std::move(design));
  }
  if (options.include_risers) {
    for (std::size_t i = 0; i < project.risers.size(); ++i) {
      const Riser& riser = project.risers[i];
      try {
        model.risers.push_back(riser_design(project, riser));
      } catch (const engine::SolverError& error) {
        // A riser that cannot take its design top angle is an input problem.
        throw InputError(
            {make_issue(project, fmt::format("risers[{}].sections", i), "riser_geometry_feasible", error.what())});
      }
      model.lines.push_back(riser_static_line(project, model.risers.back(), options.current, options.fe_statics));
    }
  }
  return model;
}

engine::FeLineModel fe_line_model(const Project& project, const MooringLine& line,
                                  const std::vector<LineTypeProperties>& types) {
  return fe_model_of(project, line, types);
}

}  // namespace spiral::design
