#include "engine/lines/riser_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;

double circle_area(double diameter_m) { return 0.25 * kPi * diameter_m * diameter_m; }

void require(bool condition, const char* field, const std::string& expectation, double value, const char* unit) {
  if (!condition || !std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("{}: must be {}, got {} {}", field, expectation, value, unit));
  }
}

void validate(const PipeSection& s, const Seawater& water) {
  require(s.outer_diameter_m > 0.0, "pipe.outer_diameter_m", "> 0", s.outer_diameter_m, "m");
  if (s.wall_thickness_m.has_value() == s.inner_diameter_m.has_value()) {
    throw std::invalid_argument(
        "pipe: give exactly one of wall_thickness_m (homogeneous steel wall) and inner_diameter_m "
        "(layered flexible wall, its bore)");
  }
  require(s.contents_density_kg_per_m3 >= 0.0, "pipe.contents_density_kg_per_m3", ">= 0", s.contents_density_kg_per_m3,
          "kg/m^3");
  const auto& e = s.explicit_properties;
  if (s.wall_thickness_m) {
    require(*s.wall_thickness_m > 0.0 && *s.wall_thickness_m < 0.5 * s.outer_diameter_m, "pipe.wall_thickness_m",
            fmt::format("in (0, OD/2 = {})", 0.5 * s.outer_diameter_m), *s.wall_thickness_m, "m");
    require(s.yield_stress_Pa > 0.0, "pipe.yield_stress_Pa", "> 0", s.yield_stress_Pa, "Pa");
    if (!e.EA_N || !e.EI_N_m2) {
      require(s.youngs_modulus_Pa > 0.0, "pipe.youngs_modulus_Pa", "> 0", s.youngs_modulus_Pa, "Pa");
    }
    if (!e.mass_per_length_kg_per_m) {
      require(s.steel_density_kg_per_m3 > 0.0, "pipe.steel_density_kg_per_m3", "> 0", s.steel_density_kg_per_m3,
              "kg/m^3");
    }
  } else {
    require(*s.inner_diameter_m > 0.0 && *s.inner_diameter_m < s.outer_diameter_m, "pipe.inner_diameter_m",
            fmt::format("in (0, OD = {})", s.outer_diameter_m), *s.inner_diameter_m, "m");
    if (!e.EA_N || !e.EI_N_m2 || !e.mass_per_length_kg_per_m) {
      throw std::invalid_argument(
          "pipe.explicit_properties: a layered (flexible) wall needs EA_N, EI_N_m2 and "
          "mass_per_length_kg_per_m (there is no steel wall to derive them from)");
    }
  }
  if (e.EA_N) require(*e.EA_N > 0.0, "pipe.explicit_properties.EA_N", "> 0", *e.EA_N, "N");
  if (e.EI_N_m2) {
    require(*e.EI_N_m2 >= 0.0, "pipe.explicit_properties.EI_N_m2", ">= 0", *e.EI_N_m2, "N*m^2");
  }
  if (e.mass_per_length_kg_per_m) {
    require(*e.mass_per_length_kg_per_m > 0.0, "pipe.explicit_properties.mass_per_length_kg_per_m", "> 0",
            *e.mass_per_length_kg_per_m, "kg/m");
  }
  if (s.coating) {
    require(s.coating->thickness_m > 0.0, "pipe.coating.thickness_m", "> 0", s.coating->thickness_m, "m");
    require(s.coating->density_kg_per_m3 >= 0.0, "pipe.coating.density_kg_per_m3", ">= 0", s.coating->density_kg_per_m3,
            "kg/m^3");
  }
  if (s.buoyancy) {
    const double coated = s.outer_diameter_m + (s.coating ? 2.0 * s.coating->thickness_m : 0.0);
    require(s.buoyancy->outer_diameter_m > coated, "pipe.buoyancy.outer_diameter_m",
            fmt::format("> coated OD ({} m)", coated), s.buoyancy->outer_diameter_m, "m");
    require(s.buoyancy->density_kg_per_m3 >= 0.0, "pipe.buoyancy.density_kg_per_m3", ">= 0",
            s.buoyancy->density_kg_per_m3, "kg/m^3");
  }
  require(water.density_kg_per_m3 > 0.0, "water.density_kg_per_m3", "> 0", water.density_kg_per_m3, "kg/m^3");
  require(water.gravity_m_per_s2 > 0.0, "water.gravity_m_per_s2", "> 0", water.gravity_m_per_s2, "m/s^2");
}

void check_conversion_inputs(double tension_N, const PipePressures& pressures) {
  require(std::isfinite(tension_N), "tension_N", "finite", tension_N, "N");
  require(std::isfinite(pressures.internal_Pa), "pressures.internal_Pa", "finite", pressures.internal_Pa, "Pa");
  require(std::isfinite(pressures.external_Pa), "pressures.external_Pa", "finite", pressures.external_Pa, "Pa");
}

}  // namespace

PipeSectionProperties pipe_section_properties(const PipeSection& section, const Seawater& water) {
  validate(section, water);
  PipeSectionProperties p;
  const double od = section.outer_diameter_m;
  p.outer_diameter_m = od;
  p.outer_area_m2 = circle_area(od);
  if (section.wall_thickness_m) {
    // Areas and second moment of a circular tube (reference-platforms §2.5).
    const double id = od - 2.0 * *section.wall_thickness_m;
    p.wall = PipeWall::homogeneous;
    p.wall_thickness_m = *section.wall_thickness_m;
    p.inner_diameter_m = id;
    p.yield_stress_Pa = section.yield_stress_Pa;
    p.inner_area_m2 = circle_area(id);
    p.steel_area_m2 = p.outer_area_m2 - p.inner_area_m2;  // pi/4 (OD^2 - ID^2)
    p.second_moment_m4 = kPi / 64.0 * (std::pow(od, 4) - std::pow(id, 4));
  } else {
    // Layered flexible wall (API 17J): the bore is the pipe's identity; the
    // layers between bore and outer sheath have no single steel area or I.
    p.wall = PipeWall::layered;
    p.inner_diameter_m = *section.inner_diameter_m;
    p.inner_area_m2 = circle_area(p.inner_diameter_m);
  }

  // Layers outside the wall: coating, then smeared buoyancy (each an annulus).
  p.coated_diameter_m = od + (section.coating ? 2.0 * section.coating->thickness_m : 0.0);
  if (section.coating) {
    p.coating_mass_kg_per_m = section.coating->density_kg_per_m3 * (circle_area(p.coated_diameter_m) - p.outer_area_m2);
  }
  p.hydrodynamic_diameter_m = p.coated_diameter_m;
  if (section.buoyancy) {
    p.hydrodynamic_diameter_m = section.buoyancy->outer_diameter_m;
    p.buoyancy_mass_kg_per_m = section.buoyancy->density_kg_per_m3 *
                               (circle_area(p.hydrodynamic_diameter_m) - circle_area(p.coated_diameter_m));
  }
  p.displaced_area_m2 = circle_area(p.hydrodynamic_diameter_m);

  // EA = E A_s, EI = E pi/64 (OD^4 - ID^4), m = rho_s A_s (reference-platforms §2.5),
  // each replaced by the manufacturer's value where given (a layered wall
  // has no single E, rho: validate() requires all three for it).
  const ExplicitSectionProperties& given = section.explicit_properties;
  p.EA_N = given.EA_N.value_or(section.youngs_modulus_Pa * p.steel_area_m2);
  p.EI_N_m2 = given.EI_N_m2.value_or(section.youngs_modulus_Pa * p.second_moment_m4);
  p.steel_mass_kg_per_m = given.mass_per_length_kg_per_m.value_or(section.steel_density_kg_per_m3 * p.steel_area_m2);
  p.mass_per_length_kg_per_m = p.steel_mass_kg_per_m + p.coating_mass_kg_per_m + p.buoyancy_mass_kg_per_m;
  p.contents_mass_kg_per_m = section.contents_density_kg_per_m3 * p.inner_area_m2;

  // Effective (apparent) weight, Sparks (1984); DNV-OS-F201 (Sec. 4, recalled):
  // w_e = (m + m_c - rho_w A_displaced) g. Summing pressure end-cap forces of the
  // internal and external fluid columns into the tension (T_eff) turns the real
  // pressure field on a curved pipe into this Archimedes buoyancy per length.
  p.effective_weight_N_per_m =
      (p.mass_per_length_kg_per_m + p.contents_mass_kg_per_m - water.density_kg_per_m3 * p.displaced_area_m2) *
      water.gravity_m_per_s2;
  return p;
}

double external_pressure_Pa(double z_m, const Seawater& water) {
  require(std::isfinite(z_m), "z_m", "finite", z_m, "m");
  // Hydrostatic gauge pressure below the mean water level; waves not included.
  return z_m < 0.0 ? water.density_kg_per_m3 * water.gravity_m_per_s2 * (-z_m) : 0.0;
}

double internal_pressure_Pa(const InternalPressureProfile& profile, double z_m, double gravity_m_per_s2) {
  require(profile.contents_density_kg_per_m3 >= 0.0, "internal_pressure.contents_density_kg_per_m3", ">= 0",
          profile.contents_density_kg_per_m3, "kg/m^3");
  require(std::isfinite(z_m), "z_m", "finite", z_m, "m");
  require(std::isfinite(profile.reference_pressure_Pa), "internal_pressure.reference_pressure_Pa", "finite",
          profile.reference_pressure_Pa, "Pa");
  require(std::isfinite(profile.reference_elevation_m), "internal_pressure.reference_elevation_m", "finite",
          profile.reference_elevation_m, "m");
  // Static column of contents below the reference point (no friction losses):
  // p_i(z) = p_ref + rho_c g (z_ref - z).
  return profile.reference_pressure_Pa +
         profile.contents_density_kg_per_m3 * gravity_m_per_s2 * (profile.reference_elevation_m - z_m);
}

double effective_tension_N(double wall_tension_N, const PipePressures& pressures,
                           const PipeSectionProperties& properties) {
  // Sparks (1984); DNV-OS-F201 (Sec. 3, recalled): T_e = T_w - p_i A_i + p_e A_e.
  // A_e is the steel OD area although w_e uses the full displaced area: a coating
  // or smeared-buoyancy layer (low axial stiffness) sits in the ambient hydrostatic
  // stress state, its wall force is -p_e A_layer, and adding it to the steel's
  // T_w turns p_e A_e(steel) into p_e A_displaced -- the Archimedes-consistent
  // form. So T_w here is the wall tension of the steel alone.
  check_conversion_inputs(wall_tension_N, pressures);
  return wall_tension_N - pressures.internal_Pa * properties.inner_area_m2 +
         pressures.external_Pa * properties.outer_area_m2;
}

double wall_tension_N(double effective_tension_N, const PipePressures& pressures,
                      const PipeSectionProperties& properties) {
  check_conversion_inputs(effective_tension_N, pressures);
  return effective_tension_N + pressures.internal_Pa * properties.inner_area_m2 -
         pressures.external_Pa * properties.outer_area_m2;
}

double von_mises_Pa(double axial_Pa, double hoop_Pa, double radial_Pa) {
  // von Mises (distortion-energy) equivalent of principal stresses
  // (API RP 2RD §4.2; DNV-OS-F201 Sec. 5; sections recalled).
  const double a = axial_Pa - hoop_Pa;
  const double b = hoop_Pa - radial_Pa;
  const double c = radial_Pa - axial_Pa;
  return std::sqrt(0.5 * (a * a + b * b + c * c));
}

double api_rp_2rd_design_factor(RiserDesignCondition condition) {
  // API RP 2RD (1998) §4.5 (recalled): sigma_allow = C_f * (2/3) SMYS with
  // C_f = 1.0 (normal operating), 1.2 (extreme), 1.5 (survival / temporary).
  constexpr double basic = 2.0 / 3.0;
  switch (condition) {
    case RiserDesignCondition::normal_operating:
      return basic * 1.0;
    case RiserDesignCondition::extreme:
      return basic * 1.2;
    case RiserDesignCondition::survival_temporary:
      return basic * 1.5;
  }
  throw std::invalid_argument("api_rp_2rd_design_factor: unknown RiserDesignCondition");
}

StressCheckResult check_pipe_stress(const PipeSectionProperties& p, const StressCheckInput& in) {
  require(in.design_factor > 0.0 && in.design_factor <= 1.0, "stress_check.design_factor", "in (0, 1]",
          in.design_factor, "");
  require(std::isfinite(in.loads.wall_tension_N), "stress_check.loads.wall_tension_N", "finite",
          in.loads.wall_tension_N, "N");
  require(std::isfinite(in.loads.bending_moment_N_m), "stress_check.loads.bending_moment_N_m", "finite",
          in.loads.bending_moment_N_m, "N*m");
  require(std::isfinite(in.loads.pressures.internal_Pa), "stress_check.loads.pressures.internal_Pa", "finite",
          in.loads.pressures.internal_Pa, "Pa");
  require(std::isfinite(in.loads.pressures.external_Pa), "stress_check.loads.pressures.external_Pa", "finite",
          in.loads.pressures.external_Pa, "Pa");
  if (p.wall == PipeWall::layered) {
    throw std::invalid_argument(
        "check_pipe_stress: a layered (flexible) pipe wall has no homogeneous wall stress; check "
        "its minimum bending radius (check_bending_radius) and tension limits instead");
  }
  require(p.steel_area_m2 > 0.0 && p.second_moment_m4 > 0.0, "section.steel_area_m2", "> 0", p.steel_area_m2, "m^2");

  const double pi = in.loads.pressures.internal_Pa;
  const double pe = in.loads.pressures.external_Pa;
  const double ro = 0.5 * p.outer_diameter_m;
  const double ri = 0.5 * p.inner_diameter_m;
  const double t = p.wall_thickness_m;

  // Axial: wall tension over the steel area +/- bending M r / I (engineering beam
  // theory), evaluated at the inner and outer wall on both fibres.
  const double axial_mean = in.loads.wall_tension_N / p.steel_area_m2;
  const double m = std::abs(in.loads.bending_moment_N_m);
  const double bend_outer = m * ro / p.second_moment_m4;
  const double bend_inner = m * ri / p.second_moment_m4;

  // Hoop and radial stress at r = r_i and r = r_o.
  double hoop_inner = 0.0;
  double hoop_outer = 0.0;
  switch (in.hoop_model) {
    case HoopStressModel::lame_thick_wall: {
      // Lamé thick cylinder (Timoshenko & Goodier): sigma_h(r) = A + B / r^2,
      // A = (p_i r_i^2 - p_e r_o^2)/(r_o^2 - r_i^2), B = (p_i - p_e) r_i^2 r_o^2/(r_o^2 - r_i^2).
      const double d = ro * ro - ri * ri;
      const double a = (pi * ri * ri - pe * ro * ro) / d;
      const double b = (pi - pe) * ri * ri * ro * ro / d;
      hoop_inner = a + b / (ri * ri);
      hoop_outer = a + b / (ro * ro);
      break;
    }
    case HoopStressModel::thin_wall_mid:
      // Mid-wall thin-wall form (DNV-OS-F201/F101 style, recalled): (p_i - p_e)(D - t)/(2t).
      hoop_inner = hoop_outer = (pi - pe) * (p.outer_diameter_m - t) / (2.0 * t);
      break;
    case HoopStressModel::barlow_outer:
      // Barlow: (p_i - p_e) D / (2t) on the outer diameter (conservative).
      hoop_inner = hoop_outer = (pi - pe) * p.outer_diameter_m / (2.0 * t);
      break;
  }
  // Radial stress equals minus the pressure on each face (boundary condition of
  // any model; the Lamé solution satisfies it exactly).
  const double radial_inner = -pi;
  const double radial_outer = -pe;

  auto point = [](double axial, double hoop, double radial) {
    return PointStresses{axial, hoop, radial, von_mises_Pa(axial, hoop, radial)};
  };
  StressCheckResult r;
  r.outer_tension_fibre = point(axial_mean + bend_outer, hoop_outer, radial_outer);
  r.outer_compression_fibre = point(axial_mean - bend_outer, hoop_outer, radial_outer);
  r.inner_tension_fibre = point(axial_mean + bend_inner, hoop_inner, radial_inner);
  r.inner_compression_fibre = point(axial_mean - bend_inner, hoop_inner, radial_inner);

  const std::array<std::pair<SectionPoint, double>, 4> candidates = {{
      {SectionPoint::outer_tension_fibre, r.outer_tension_fibre.von_mises_Pa},
      {SectionPoint::outer_compression_fibre, r.outer_compression_fibre.von_mises_Pa},
      {SectionPoint::inner_tension_fibre, r.inner_tension_fibre.von_mises_Pa},
      {SectionPoint::inner_compression_fibre, r.inner_compression_fibre.von_mises_Pa},
  }};
  const auto governing = std::max_element(candidates.begin(), candidates.end(),
                                          [](const auto& lhs, const auto& rhs) { return lhs.second < rhs.second; });
  r.governing_point = governing->first;
  r.max_von_mises_Pa = governing->second;

  // API RP 2RD §4.5: sigma_vm <= C_f sigma_a, written as a design factor on SMYS.
  r.allowable_stress_Pa = in.design_factor * p.yield_stress_Pa;
  r.utilization = r.max_von_mises_Pa / r.allowable_stress_Pa;
  return r;
}

BendingRadiusCheck check_bending_radius(double curvature_1_per_m, double minimum_bending_radius_m) {
  require(std::isfinite(curvature_1_per_m), "curvature_1_per_m", "finite", curvature_1_per_m, "1/m");
  require(minimum_bending_radius_m > 0.0, "minimum_bending_radius_m", "> 0", minimum_bending_radius_m, "m");
  BendingRadiusCheck c;
  const double kappa = std::abs(curvature_1_per_m);
  // R = 1/kappa (plane-curve radius of curvature); a straight pipe has R = infinity.
  c.bending_radius_m = kappa > 0.0 ? 1.0 / kappa : std::numeric_limits<double>::infinity();
  // MBR / R written as kappa * MBR so that it stays finite for a straight pipe.
  c.utilization = kappa * minimum_bending_radius_m;
  c.passes = c.utilization <= 1.0;
  return c;
}

}  // namespace spiral::engine
