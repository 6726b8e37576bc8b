// Validation of the section risers and of the riser criteria
// (project_validation_checks.hpp).

#include <utility>

#include "design/project/project_validation_checks.hpp"

namespace spiral::design::validation_detail {
namespace {

void check_riser_section(const Riser& riser, const RiserSection& s, const std::string& at, Reporter& r) {
  const char* c = "riser_value_positive";
  positive(r, at + ".length", s.length_m, "m", c);
  positive(r, at + ".outer_diameter", s.outer_diameter_m, "m", c);
  at_least(r, at + ".contents_density", s.contents_density_kg_per_m3, 0.0, "kg/m^3", "riser_value_non_negative");
  positive(r, at + ".wall_thickness", s.wall_thickness_m, "m", c);
  positive(r, at + ".inner_diameter", s.inner_diameter_m, "m", c);
  positive(r, at + ".youngs_modulus", s.youngs_modulus_Pa, "Pa", c);
  positive(r, at + ".yield_stress", s.yield_stress_Pa, "Pa", c);
  positive(r, at + ".steel_density", s.steel_density_kg_per_m3, "kg/m^3", c);
  positive(r, at + ".coating_thickness", s.coating_thickness_m, "m", c);
  positive(r, at + ".coating_density", s.coating_density_kg_per_m3, "kg/m^3", c);
  positive(r, at + ".buoyancy_density", s.buoyancy_density_kg_per_m3, "kg/m^3", c);
  positive(r, at + ".axial_stiffness", s.axial_stiffness_N, "N", c);
  positive(r, at + ".bending_stiffness", s.bending_stiffness_N_m2, "N m^2", c);
  positive(r, at + ".mass_per_length", s.mass_per_length_kg_per_m, "kg/m", c);
  for (const auto& [key, value] :
       {std::pair{".drag_normal", s.drag_normal}, std::pair{".drag_axial", s.drag_axial},
        std::pair{".added_mass_normal", s.added_mass_normal}, std::pair{".added_mass_axial", s.added_mass_axial}}) {
    at_least(r, at + key, value, 0.0, "", "coefficient_non_negative");
  }
  if (s.wall_thickness_m && s.outer_diameter_m > 0.0 && !(*s.wall_thickness_m < 0.5 * s.outer_diameter_m)) {
    r.fail(at + ".wall_thickness", "wall_thinner_than_radius",
           fmt::format("must be < outer_diameter / 2 = {} m, got {} m", 0.5 * s.outer_diameter_m, *s.wall_thickness_m));
  }
  if (s.inner_diameter_m && s.wall_thickness_m) {
    r.fail(at + ".inner_diameter", "bore_defined_once",
           "give wall_thickness (steel wall) or inner_diameter (flexible bore), not both");
  } else if (s.inner_diameter_m && s.outer_diameter_m > 0.0 && !(*s.inner_diameter_m < s.outer_diameter_m)) {
    r.fail(at + ".inner_diameter", "bore_inside_pipe",
           fmt::format("must be < outer_diameter {} m, got {} m", s.outer_diameter_m, *s.inner_diameter_m));
  }
  if (s.coating_thickness_m.has_value() != s.coating_density_kg_per_m3.has_value()) {
    r.fail(at, "coating_complete", "give coating_thickness (m) and coating_density (kg/m^3) together");
  }
  if (s.buoyancy_outer_diameter_m.has_value() != s.buoyancy_density_kg_per_m3.has_value()) {
    r.fail(at, "buoyancy_complete", "give buoyancy_outer_diameter (m) and buoyancy_density (kg/m^3) together");
  }
  if (s.buoyancy_outer_diameter_m && !(*s.buoyancy_outer_diameter_m > s.outer_diameter_m)) {
    r.fail(at + ".buoyancy_outer_diameter", "buoyancy_outside_pipe",
           fmt::format("must be > outer_diameter {} m, got {} m", s.outer_diameter_m, *s.buoyancy_outer_diameter_m));
  }
  if (s.buoyancy_outer_diameter_m && riser.kind != RiserKind::lazy_wave) {
    r.fail(at + ".buoyancy_outer_diameter", "key_not_applicable",
           fmt::format("buoyancy sections apply to lazy_wave risers only, got kind {}", to_string(riser.kind)));
  }
  const bool steel = s.wall_thickness_m && s.youngs_modulus_Pa && s.steel_density_kg_per_m3;
  if (riser.kind != RiserKind::flexible) {
    for (const auto& [key, present] : {std::pair{"wall_thickness (m)", s.wall_thickness_m.has_value()},
                                       std::pair{"youngs_modulus (Pa)", s.youngs_modulus_Pa.has_value()},
                                       std::pair{"yield_stress (Pa)", s.yield_stress_Pa.has_value()},
                                       std::pair{"steel_density (kg/m^3)", s.steel_density_kg_per_m3.has_value()}}) {
      if (!present) {
        r.fail(at, "steel_riser_complete", fmt::format("a {} riser section needs {}", to_string(riser.kind), key));
      }
    }
  } else if (!steel &&
             !(s.axial_stiffness_N && s.bending_stiffness_N_m2 && s.mass_per_length_kg_per_m && s.inner_diameter_m)) {
    r.fail(at, "flexible_riser_complete",
           "a flexible riser section needs inner_diameter (m, the bore), axial_stiffness (N), "
           "bending_stiffness (N m^2) and mass_per_length (kg/m), or the steel wall_thickness, "
           "youngs_modulus and steel_density");
  }
}

}  // namespace

void check_riser_criteria(Reporter& r, const std::string& at, const RiserCriteriaOverrides& c) {
  for (const auto& [key, value] : {std::pair{".design_factor.normal", c.design_factor_normal},
                                   std::pair{".design_factor.extreme", c.design_factor_extreme},
                                   std::pair{".design_factor.survival", c.design_factor_survival}}) {
    if (value && !(*value > 0.0 && *value <= 1.0)) {
      r.fail(at + key, "design_factor_range",
             fmt::format("must be in (0, 1] (fraction of the yield stress), got {}", *value));
    }
  }
  at_least(r, at + ".min_effective_tension", c.min_effective_tension_N, 0.0, "N", "riser_criterion_non_negative");
  positive(r, at + ".max_top_tension", c.max_top_tension_N, "N", "riser_criterion_positive");
  positive(r, at + ".min_bending_radius", c.min_bending_radius_m, "m", "riser_criterion_positive");
  positive(r, at + ".max_touchdown_excursion", c.max_touchdown_excursion_m, "m", "riser_criterion_positive");
  for (const auto& [key, value] : {std::pair{".max_top_angle_deg", c.max_top_angle_rad},
                                   std::pair{".max_flex_joint_rotation_deg", c.max_flex_joint_rotation_rad}}) {
    if (value && !(*value > 0.0 && *value < std::numbers::pi / 2)) {
      r.fail(at + key, "riser_angle_limit_range",
             fmt::format("must be in (0, 90) deg, got {:.6g} deg", *value * kRadToDeg));
    }
  }
}

void check_risers(const Project& p, Reporter& r) {
  unique_names(r, p.risers, "risers", "riser", "riser_name_unique");
  for (std::size_t i = 0; i < p.risers.size(); ++i) {
    const Riser& riser = p.risers[i];
    const std::string at = fmt::format("risers[{}]", i);
    if (!(riser.top_angle_rad >= 0.0 && riser.top_angle_rad < std::numbers::pi / 2)) {
      r.fail(at + ".top_angle_deg", "top_angle_range",
             fmt::format("must be in [0, 90) deg from vertical, got {:.6g} deg", riser.top_angle_rad * kRadToDeg));
    }
    if (riser.sections.empty()) {
      r.fail(at + ".sections", "riser_has_sections", "a riser needs at least one section");
    }
    for (std::size_t s = 0; s < riser.sections.size(); ++s) {
      check_riser_section(riser, riser.sections[s], fmt::format("{}.sections[{}]", at, s), r);
    }
    at_least(r, at + ".internal_pressure", riser.internal_pressure_Pa, 0.0, "Pa", "riser_value_non_negative");
    check_fe_mesh(r, at + ".fe", riser.fe);
    check_riser_criteria(r, at + ".criteria", riser.criteria);
    if (riser.kind == RiserKind::flexible && !riser_criteria(p.criteria, riser).min_bending_radius_m) {
      r.fail(at + ".criteria.min_bending_radius", "flexible_min_bending_radius",
             "a flexible riser needs min_bending_radius (m), in criteria.risers or in the riser's "
             "criteria");
    }
    const bool has_buoyancy = std::any_of(riser.sections.begin(), riser.sections.end(), [](const RiserSection& s) {
      return s.buoyancy_outer_diameter_m.has_value();
    });
    if (riser.kind == RiserKind::lazy_wave && !has_buoyancy) {
      r.fail(at + ".sections", "lazy_wave_buoyancy_section",
             "a lazy_wave riser needs a buoyancy section (buoyancy_outer_diameter, "
             "buoyancy_density)");
    }
  }
}

}  // namespace spiral::design::validation_detail
