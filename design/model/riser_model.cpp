#include "design/model/riser_model.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/lines/catenary.hpp"
#include "engine/lines/catenary_top_angle.hpp"

namespace spiral::design {

namespace {

engine::PipeSection pipe_section_of(const RiserSection& s) {
  engine::PipeSection p;
  p.outer_diameter_m = s.outer_diameter_m;
  p.contents_density_kg_per_m3 = s.contents_density_kg_per_m3;
  // A steel wall, or a flexible's layered wall known by its bore (validation
  // allows exactly one of the two).
  p.wall_thickness_m = s.wall_thickness_m;
  p.inner_diameter_m = s.inner_diameter_m;
  if (s.youngs_modulus_Pa) p.youngs_modulus_Pa = *s.youngs_modulus_Pa;
  if (s.steel_density_kg_per_m3) p.steel_density_kg_per_m3 = *s.steel_density_kg_per_m3;
  if (s.yield_stress_Pa) p.yield_stress_Pa = *s.yield_stress_Pa;
  if (s.coating_thickness_m && s.coating_density_kg_per_m3) {
    p.coating = engine::PipeCoating{*s.coating_thickness_m, *s.coating_density_kg_per_m3};
  }
  if (s.buoyancy_outer_diameter_m && s.buoyancy_density_kg_per_m3) {
    p.buoyancy = engine::SmearedBuoyancy{*s.buoyancy_outer_diameter_m, *s.buoyancy_density_kg_per_m3};
  }
  p.explicit_properties = {s.axial_stiffness_N, s.bending_stiffness_N_m2, s.mass_per_length_kg_per_m};
  return p;
}

// Profile points per section for the seabed check below: the sag bend of a
// lazy wave spans hundreds of metres, so 100 points resolve its lowest point
// to well under a metre.
constexpr int kSeabedCheckPointsPerSection = 100;
// The sag may come this close to the seabed (m) before it counts as touching:
// the catenary's round-off on kilometre spans, not a physical clearance.
constexpr double kSeabedClearanceTolerance_m = 1e-6;

/// The catenary of the placement knows the seabed only from the foot to the
/// touchdown point; a lazy wave's sag bend between the hull and the buoyant
/// section must not dip below it either (it would lie there instead).
void check_suspended_above_seabed(const std::string& name, const engine::CatenaryLine& catenary,
                                  const engine::TopAngleCatenary& placement, double z_span_m) {
  engine::CatenaryOptions options;
  options.profile_points_per_segment = kSeabedCheckPointsPerSection;
  const auto solution =
      engine::solve_catenary(catenary, {placement.horizontal_span_m, z_span_m, 0.0}, options,
                             engine::CatenaryGuess{placement.fairlead_horizontal_N, placement.fairlead_vertical_N});
  double lowest_m = std::numeric_limits<double>::infinity();
  double lowest_arc_m = 0.0;
  for (const engine::CatenaryProfilePoint& p : solution.profile) {
    if (!p.on_seabed && p.arc_length_m > solution.laid_length_m && p.z_m < lowest_m) {
      lowest_m = p.z_m;
      lowest_arc_m = p.arc_length_m;
    }
  }
  if (lowest_m < -kSeabedClearanceTolerance_m) {
    throw engine::SolverError(
        fmt::format("riser '{}': at its design top angle the suspended riser would dip {:.1f} m "
                    "below the seabed "
                    "{:.1f} m from the foot (a sag bend on the seabed); shorten the sections above "
                    "the buoyancy or "
                    "add buoyancy",
                    name, -lowest_m, lowest_arc_m));
  }
}

}  // namespace

engine::FeEnvironment fe_environment(const Project& project, const std::optional<engine::CurrentProfile>& current,
                                     double contact_diameter_m) {
  engine::FeEnvironment environment;
  environment.water_density_kg_per_m3 = project.site.water_density_kg_per_m3;
  environment.seabed_z_m = -project.site.depth_m;
  // The project gives the seabed's contact pressure per metre of penetration;
  // a line presses on a strip as wide as its diameter.
  environment.seabed_stiffness_N_per_m2 = project.site.seabed.normal_stiffness_Pa_per_m * contact_diameter_m;
  environment.seabed_axial_friction = project.site.seabed.friction_axial;
  if (current) {
    for (std::size_t i = 0; i < current->z_m.size(); ++i) {
      environment.current.push_back({current->z_m[i], engine::current_velocity_g(*current, current->z_m[i])});
    }
  }
  return environment;
}

std::optional<engine::FeRefinementZone> touchdown_refinement_zone(const FeMesh& mesh, double laid_length_m) {
  if (!mesh.touchdown_refinement || !(laid_length_m > 0.0)) return std::nullopt;
  const TouchdownRefinement& zone = *mesh.touchdown_refinement;
  return engine::FeRefinementZone{std::max(0.0, laid_length_m - 0.5 * zone.length_m), zone.length_m,
                                  zone.element_length_m};
}

RiserDesign riser_design(const Project& project, const Riser& riser) {
  const engine::Seawater water{project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2};
  RiserDesign design;
  design.name = riser.name;
  design.kind = riser.kind;
  design.hang_off_b = riser.hang_off_b;
  design.azimuth_rad = riser.azimuth_rad;
  design.design_top_angle_rad = riser.top_angle_rad;
  design.criteria = riser_criteria(project.criteria, riser);
  design.internal_pressure_top_Pa = riser.internal_pressure_Pa;
  design.contents_density_top_kg_per_m3 = riser.sections.front().contents_density_kg_per_m3;
  for (auto it = riser.sections.rbegin(); it != riser.sections.rend(); ++it) {
    RiserSectionDesign section;
    section.length_m = it->length_m;
    section.properties = engine::pipe_section_properties(pipe_section_of(*it), water);
    // Von Mises applies to a steel wall; a flexible pipe (even one given by
    // steel-like properties) is checked by its bending radius and tensions.
    section.steel = riser.kind != RiserKind::flexible && section.properties.wall == engine::PipeWall::homogeneous;
    design.sections.push_back(section);
  }

  // Foot position: the distance along the azimuth at which the riser, as a
  // catenary of its effective weight, leaves the hang-off at the design angle.
  engine::CatenaryLine catenary;
  double length_m = 0.0;
  for (const RiserSectionDesign& s : design.sections) {
    catenary.segments.push_back({s.length_m, s.properties.effective_weight_N_per_m, s.properties.EA_N});
    length_m += s.length_m;
  }
  const Eigen::Vector3d hang_off_g = project.hull.reference_point_g + riser.hang_off_b;
  const double z_span_m = hang_off_g.z() + project.site.depth_m;
  if (length_m <= z_span_m) {
    throw engine::SolverError(
        fmt::format("riser '{}': length {:.1f} m does not reach the seabed {:.1f} m below "
                    "the hang-off",
                    riser.name, length_m, z_span_m));
  }
  // With the top angle given, the catenary's unknown is the top vertical force
  // (engine/lines/catenary_top_angle.hpp); a lazy wave's buoyant section then
  // stays suspended by construction.
  engine::TopAngleCatenary placement;
  try {
    placement = engine::solve_catenary_for_top_angle(catenary, z_span_m, riser.top_angle_rad);
  } catch (const engine::SolverError& error) {
    throw engine::SolverError(fmt::format("riser '{}' ({:.1f} m): {}; change top_angle_deg or the section lengths",
                                          riser.name, length_m, error.what()));
  }
  const double foot_distance_m = placement.horizontal_span_m;
  check_suspended_above_seabed(riser.name, catenary, placement, z_span_m);
  const Eigen::Vector3d direction(std::cos(riser.azimuth_rad), std::sin(riser.azimuth_rad), 0.0);
  design.foot_g = hang_off_g + foot_distance_m * direction;
  design.foot_g.z() = -project.site.depth_m;
  const double laid_m = placement.laid_length_m;

  for (const RiserSectionDesign& s : design.sections) {
    engine::FeLineSection fe;
    fe.length_m = s.length_m;
    fe.EA_N = s.properties.EA_N;
    fe.EI_Nm2 = s.properties.EI_N_m2;
    fe.mass_kg_per_m = s.properties.mass_per_length_kg_per_m + s.properties.contents_mass_kg_per_m;
    fe.weight_N_per_m = s.properties.effective_weight_N_per_m;
    fe.hydro_diameter_m = s.properties.hydrodynamic_diameter_m;
    fe.element_length_m = riser.fe.element_length_m;
    design.fe_model.sections.push_back(fe);
  }
  // Morison coefficients per section, in FE order.
  for (std::size_t i = 0; i < riser.sections.size(); ++i) {
    const RiserSection& s = riser.sections[riser.sections.size() - 1 - i];
    design.fe_model.sections[i].drag_normal = s.drag_normal;
    design.fe_model.sections[i].drag_tangential = s.drag_axial;
    // Dynamics only: displaced volume and added mass on the hydrodynamic diameter.
    const double d = design.fe_model.sections[i].hydro_diameter_m;
    design.fe_model.sections[i].displaced_area_m2 = 0.25 * std::numbers::pi * d * d;
    design.fe_model.sections[i].added_mass_normal = s.added_mass_normal;
    design.fe_model.sections[i].added_mass_tangential = s.added_mass_axial;
  }
  design.fe_model.refinement = touchdown_refinement_zone(riser.fe, laid_m);
  return design;
}

std::unique_ptr<engine::FeStaticLine> riser_static_line(const Project& project, const RiserDesign& design,
                                                        const std::optional<engine::CurrentProfile>& current,
                                                        const engine::FeStaticsOptions& options) {
  const double contact_diameter_m = design.sections.front().properties.hydrodynamic_diameter_m;
  return std::make_unique<engine::FeStaticLine>(design.name, design.foot_g, design.hang_off_b, design.fe_model,
                                                fe_environment(project, current, contact_diameter_m), options);
}

}  // namespace spiral::design
