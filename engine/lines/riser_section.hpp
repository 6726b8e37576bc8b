#pragma once
// Riser cross-section mechanics: section properties (areas, EA, EI, masses,
// effective weight), pressures, effective <-> wall tension, wall stresses
// (axial, hoop, radial), von Mises equivalent stress, allowable-stress
// utilization and the minimum-bending-radius check for flexibles.
//
// Sources (cited again at each formula in riser_section.cpp):
//  - R. D. Sparks, "The influence of tension, pressure and weight on pipe and
//    riser deformations and stresses", J. Energy Resources Technology 106
//    (1984) 46-54 (volume/pages recalled): effective tension and effective (apparent) weight;
//    also Sparks, "Fundamentals of Marine Riser Mechanics" (2007), ch. 3.
//  - DNV-OS-F201 "Dynamic Risers" (2010), effective-tension definition (Sec. 3/4,
//    section recalled):
//    T_e = T_w - p_i A_i + p_e A_e.
//  - G. Lamé (1852) thick-walled cylinder; S. Timoshenko & J. N. Goodier,
//    "Theory of Elasticity" (3rd ed., 1970), thick-walled cylinder: hoop and radial stresses.
//  - API RP 2RD (1998), §4.2-4.5 (sections and factors recalled, not re-read):
//    von Mises equivalent stress against
//    C_f * sigma_a, sigma_a = 2/3 SMYS (see RiserDesignCondition).
//
// Conventions: SI; pressures are gauge (above atmospheric); tension positive;
// z is the global elevation (z = 0 at mean water level, up positive).
//
// Two kinds of wall (PipeWall):
//  - homogeneous: a metallic (steel) tube of wall thickness WT; every result
//    here applies, including the von Mises check.
//  - layered: an unbonded flexible pipe (API Spec 17J / API RP 17B): carcass,
//    pressure sheath, armour layers and outer sheath. It has no single E or
//    wall to take a von Mises stress; the manufacturer gives EA, EI and the
//    mass, the pipe is identified by its bore (internal diameter), and its
//    capacity is checked by the minimum bending radius (check_bending_radius)
//    and tension limits (API RP 17B: MBR and allowable tension / compression
//    per load condition). Section properties and the effective <-> true-wall
//    tension conversion (Sparks' identity holds for any tube with a bore and
//    an outer diameter) apply; check_pipe_stress throws.
//
// Every function throws std::invalid_argument naming the offending field when
// an input is outside its stated range or not finite; none returns NaN.

#include <optional>

#include "engine/common/seawater.hpp"

namespace spiral::engine {

/// A smeared coating layer (insulation, anti-corrosion) bonded outside the pipe wall.
struct PipeCoating {
  double thickness_m = 0.0;        ///< radial thickness, > 0
  double density_kg_per_m3 = 0.0;  ///< material density, >= 0
};

/// Buoyancy modules of a lazy-wave section smeared over the section length
/// (the usual "equivalent line" of OrcaFlex/Flexcom practice): an annulus from
/// the outside of the coated pipe out to `outer_diameter_m`, of `density_kg_per_m3`.
/// The caller smears discrete modules first: for modules of volume V_mod and
/// mass m_mod at pitch s, choose D_b with pi/4 (D_b^2 - D_c^2) = V_mod / s and
/// density m_mod / V_mod.
struct SmearedBuoyancy {
  double outer_diameter_m = 0.0;   ///< equivalent OD, > coated OD
  double density_kg_per_m3 = 0.0;  ///< smeared density, >= 0 (syntactic foam ~ 400-600)
};

/// Explicit properties (flexible pipes, umbilicals; or overrides on a steel
/// pipe): each one given replaces its steel formula. A layered wall needs all three.
struct ExplicitSectionProperties {
  std::optional<double> EA_N;                      ///< axial stiffness, > 0
  std::optional<double> EI_N_m2;                   ///< bending stiffness, >= 0
  std::optional<double> mass_per_length_kg_per_m;  ///< structural mass in air, contents excluded, > 0
};

/// What carries the loads in the pipe wall (see the top of this file).
enum class PipeWall {
  homogeneous,  ///< metallic tube of thickness wall_thickness_m
  layered,      ///< unbonded flexible pipe: bore inner_diameter_m, explicit EA/EI/mass
};

/// Input of `pipe_section_properties`. Exactly one of `wall_thickness_m`
/// (homogeneous wall) and `inner_diameter_m` (layered wall) is given.
struct PipeSection {
  double outer_diameter_m = 0.0;           ///< steel OD, or the flexible's outer-sheath OD, > 0
  std::optional<double> wall_thickness_m;  ///< homogeneous wall: 0 < WT < OD/2
  /// Layered (flexible) wall: the bore, 0 < ID < OD; needs all three explicit_properties.
  std::optional<double> inner_diameter_m;
  double youngs_modulus_Pa = 207.0e9;  ///< steel E (conventional value, reference-platforms §2.5, U)
  double steel_density_kg_per_m3 = 7850.0;
  double yield_stress_Pa = 448.0e6;         ///< SMYS (default: API 5L X65, 448 MPa); homogeneous wall
  double contents_density_kg_per_m3 = 0.0;  ///< bore fluid, >= 0 (0: empty/air-filled)
  std::optional<PipeCoating> coating;
  std::optional<SmearedBuoyancy> buoyancy;
  /// EA, EI and structural mass given by the manufacturer (flexibles) or as
  /// overrides of the steel formulas; OD and the bore define the areas.
  ExplicitSectionProperties explicit_properties;
};

/// Derived properties, per unit length of line where a rate.
struct PipeSectionProperties {
  PipeWall wall = PipeWall::homogeneous;
  double outer_diameter_m = 0.0;         ///< steel OD (copied from the input)
  double wall_thickness_m = 0.0;         ///< steel WT (copied from the input); 0 for a layered wall
  double inner_diameter_m = 0.0;         ///< ID = OD - 2 WT (homogeneous), the bore (layered)
  double coated_diameter_m = 0.0;        ///< OD + 2 t_coat (= OD without coating)
  double hydrodynamic_diameter_m = 0.0;  ///< outermost diameter: buoyancy OD, else coated OD
  double steel_area_m2 = 0.0;            ///< A_s = pi/4 (OD^2 - ID^2); 0 for a layered wall
  double inner_area_m2 = 0.0;            ///< A_i = pi/4 ID^2 (bore)
  double outer_area_m2 = 0.0;            ///< A_o = pi/4 OD^2 (steel OD: used in T_eff)
  double displaced_area_m2 = 0.0;        ///< pi/4 D_hyd^2 (buoyancy per length / (rho g))
  double second_moment_m4 = 0.0;         ///< I = pi/64 (OD^4 - ID^4); 0 for a layered wall
  double EA_N = 0.0;
  double EI_N_m2 = 0.0;
  double steel_mass_kg_per_m = 0.0;  ///< rho_s A_s, or the explicit structural mass
  double coating_mass_kg_per_m = 0.0;
  double buoyancy_mass_kg_per_m = 0.0;
  double mass_per_length_kg_per_m = 0.0;  ///< structural: steel + coating + buoyancy (no contents)
  double contents_mass_kg_per_m = 0.0;    ///< rho_c A_i
  /// w_e = (m + m_c - rho_w A_displaced) g, N/m; > 0 sinks, < 0 buoyant.
  double effective_weight_N_per_m = 0.0;
  double yield_stress_Pa = 0.0;  ///< copied from the input (stress checks)
};

/// Section properties. Formulas: reference-platforms §2.5 (A_s, m, EA, EI, w_e);
/// Sparks (1984) / DNV-OS-F201 Sec. 4 for the effective weight.
PipeSectionProperties pipe_section_properties(const PipeSection& section, const Seawater& water = {});

/// Hydrostatic (gauge) pressure of the sea at elevation z: rho_w g (-z) below the
/// mean water level, 0 above it (no wave pressure).
double external_pressure_Pa(double z_m, const Seawater& water = {});

/// Bore pressure given at a reference elevation (normally the hang-off / top).
struct InternalPressureProfile {
  double reference_pressure_Pa = 0.0;       ///< gauge pressure at the reference elevation
  double reference_elevation_m = 0.0;       ///< z_ref (global z, up positive)
  double contents_density_kg_per_m3 = 0.0;  ///< >= 0
};

/// p_i(z) = p_ref + rho_c g (z_ref - z): static contents column, no flow losses.
double internal_pressure_Pa(const InternalPressureProfile& profile, double z_m, double gravity_m_per_s2 = 9.80665);

/// Pressures acting on the pipe wall at one station (gauge).
struct PipePressures {
  double internal_Pa = 0.0;
  double external_Pa = 0.0;
};

/// Sparks (1984); DNV-OS-F201: T_eff = T_wall - p_i A_i + p_e A_o (A_o, A_i of the
/// steel pipe; a coating or buoyancy layer is taken to be in the ambient
/// hydrostatic stress state, so its buoyancy appears in w_e, not here).
double effective_tension_N(double wall_tension_N, const PipePressures& pressures,
                           const PipeSectionProperties& properties);
/// The inverse: T_wall = T_eff + p_i A_i - p_e A_o.
double wall_tension_N(double effective_tension_N, const PipePressures& pressures,
                      const PipeSectionProperties& properties);

/// Hoop-stress formula.
enum class HoopStressModel {
  /// Lamé thick-wall elastic solution, evaluated at the inner and outer wall
  /// (exact for an elastic cylinder; Timoshenko & Goodier). Default.
  lame_thick_wall,
  /// Mid-wall thin-wall form (p_i - p_e)(OD - WT)/(2 WT), uniform through the wall:
  /// the form of the DNV-OS-F201 / DNV-OS-F101 working-stress checks (recalled).
  thin_wall_mid,
  /// Barlow on the outer diameter (p_i - p_e) OD/(2 WT): the conservative
  /// textbook thin-wall form, sigma = p D / 2t.
  barlow_outer,
};

/// Load state of one cross-section.
struct SectionLoads {
  double wall_tension_N = 0.0;      ///< true wall tension (use wall_tension_N() to convert T_eff)
  double bending_moment_N_m = 0.0;  ///< resultant bending moment magnitude (sign ignored)
  PipePressures pressures;
};

/// Which point of the section governs the equivalent stress.
enum class SectionPoint { outer_tension_fibre, outer_compression_fibre, inner_tension_fibre, inner_compression_fibre };

/// Principal stresses (no torsion/shear) at one point of the wall, Pa, tension positive.
struct PointStresses {
  double axial_Pa = 0.0;
  double hoop_Pa = 0.0;
  double radial_Pa = 0.0;
  double von_mises_Pa = 0.0;
};

/// The allowable-stress condition of API RP 2RD (1998) §4.5 ("recalled": the
/// table was not re-read for this code). The allowable is C_f sigma_a with
/// the basic allowable sigma_a = 2/3 SMYS and C_f = 1.0 / 1.2 / 1.5, i.e. a
/// design factor on SMYS of 0.67 / 0.80 / 1.00.
enum class RiserDesignCondition {
  normal_operating,    ///< 2/3 * 1.0 = 0.67
  extreme,             ///< 2/3 * 1.2 = 0.80
  survival_temporary,  ///< 2/3 * 1.5 = 1.00
};

/// Design factor on SMYS (the product C_f * 2/3 above) for a condition. Recalled values.
double api_rp_2rd_design_factor(RiserDesignCondition condition);

struct StressCheckInput {
  SectionLoads loads;
  HoopStressModel hoop_model = HoopStressModel::lame_thick_wall;
  /// Allowable von Mises stress = design_factor * SMYS; in (0, 1]. Default: normal operating.
  double design_factor = 2.0 / 3.0;
};

struct StressCheckResult {
  PointStresses outer_tension_fibre;
  PointStresses outer_compression_fibre;
  PointStresses inner_tension_fibre;
  PointStresses inner_compression_fibre;
  double max_von_mises_Pa = 0.0;
  SectionPoint governing_point = SectionPoint::outer_tension_fibre;
  double allowable_stress_Pa = 0.0;  ///< design_factor * SMYS
  double utilization = 0.0;          ///< max_von_mises / allowable; <= 1 passes
};

/// Wall stresses at the four extreme points of the section (tension and
/// compression fibres of bending, inner and outer wall) and the utilization
/// sigma_vm / (design_factor * SMYS) (API RP 2RD §4.2, §4.5).
/// Throws std::invalid_argument for design_factor outside (0, 1], non-finite
/// loads, or a layered (flexible) wall, which has no homogeneous wall stress.
StressCheckResult check_pipe_stress(const PipeSectionProperties& properties, const StressCheckInput& input);

/// von Mises equivalent of three principal stresses:
/// sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2) / 2).
double von_mises_Pa(double axial_Pa, double hoop_Pa, double radial_Pa);

/// Minimum-bending-radius check (flexibles; API RP 17B / 17J practice: the
/// bending radius must stay above the manufacturer's MBR for the condition).
struct BendingRadiusCheck {
  /// R = 1 / |kappa|; +infinity for zero curvature (a straight pipe).
  double bending_radius_m = 0.0;
  double utilization = 0.0;  ///< MBR / R = |kappa| MBR; <= 1 passes (finite even when straight)
  bool passes = true;
};

BendingRadiusCheck check_bending_radius(double curvature_1_per_m, double minimum_bending_radius_m);

}  // namespace spiral::engine
