// Project loader, section risers and the riser criteria
// (project_loader_sections.hpp).

#include "design/project/project_loader_sections.hpp"

namespace spiral::design::loader_detail {
namespace {

const EnumTable<RiserKind> kRiserKinds = {
    {"scr", RiserKind::scr}, {"lazy_wave", RiserKind::lazy_wave}, {"flexible", RiserKind::flexible}};

RiserSection read_riser_section(MapReader& r) {
  RiserSection s;
  assign(s.length_m, r.number("length", "m", kRequired));
  assign(s.outer_diameter_m, r.number("outer_diameter", "m", kRequired));
  assign(s.contents_density_kg_per_m3, r.number("contents_density", "kg/m^3", kRequired));
  s.wall_thickness_m = r.number("wall_thickness", "m", kOptional);
  s.inner_diameter_m = r.number("inner_diameter", "m", kOptional);
  s.youngs_modulus_Pa = r.number("youngs_modulus", "Pa", kOptional);
  s.yield_stress_Pa = r.number("yield_stress", "Pa", kOptional);
  s.steel_density_kg_per_m3 = r.number("steel_density", "kg/m^3", kOptional);
  s.coating_thickness_m = r.number("coating_thickness", "m", kOptional);
  s.coating_density_kg_per_m3 = r.number("coating_density", "kg/m^3", kOptional);
  s.buoyancy_outer_diameter_m = r.number("buoyancy_outer_diameter", "m", kOptional);
  s.buoyancy_density_kg_per_m3 = r.number("buoyancy_density", "kg/m^3", kOptional);
  s.axial_stiffness_N = r.number("axial_stiffness", "N", kOptional);
  s.bending_stiffness_N_m2 = r.number("bending_stiffness", "N m^2", kOptional);
  s.mass_per_length_kg_per_m = r.number("mass_per_length", "kg/m", kOptional);
  assign(s.drag_normal, r.number("drag_normal", "", kOptional));
  assign(s.drag_axial, r.number("drag_axial", "", kOptional));
  assign(s.added_mass_normal, r.number("added_mass_normal", "", kOptional));
  assign(s.added_mass_axial, r.number("added_mass_axial", "", kOptional));
  return s;
}

}  // namespace

RiserCriteriaOverrides read_riser_criteria(MapReader& r) {
  RiserCriteriaOverrides c;
  r.map("design_factor", kOptional, [&](MapReader& f) {
    c.design_factor_normal = f.number("normal", "", kOptional);
    c.design_factor_extreme = f.number("extreme", "", kOptional);
    c.design_factor_survival = f.number("survival", "", kOptional);
  });
  c.min_effective_tension_N = r.number("min_effective_tension", "N", kOptional);
  c.max_top_tension_N = r.number("max_top_tension", "N", kOptional);
  c.max_top_angle_rad = r.angle("max_top_angle", kOptional);
  c.max_flex_joint_rotation_rad = r.angle("max_flex_joint_rotation", kOptional);
  c.min_bending_radius_m = r.number("min_bending_radius", "m", kOptional);
  c.max_touchdown_excursion_m = r.number("max_touchdown_excursion", "m", kOptional);
  return c;
}

Riser read_riser(MapReader& r) {
  Riser riser;
  assign(riser.name, r.text("name", kRequired));
  assign(riser.kind, r.enumeration("kind", kRiserKinds, kRequired));
  assign(riser.hang_off_b, r.position("hang_off", kRequired));
  assign(riser.azimuth_rad, r.angle("azimuth", kRequired));
  assign(riser.top_angle_rad, r.angle("top_angle", kRequired));
  r.list_of_maps("sections", kRequired, [&](MapReader& s) { riser.sections.push_back(read_riser_section(s)); });
  assign(riser.internal_pressure_Pa, r.number("internal_pressure", "Pa", kOptional));
  read_fe_mesh(r, riser.fe);
  r.map("criteria", kOptional, [&](MapReader& c) { riser.criteria = read_riser_criteria(c); });
  return riser;
}

}  // namespace spiral::design::loader_detail
