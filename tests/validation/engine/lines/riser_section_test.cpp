// Validation of the riser cross-section kernel (engine/lines/riser_section.hpp)
// against the derived SCR properties of shared/data/reference-platforms.md
// §2.5/§2.8, textbook effective-tension identities (Sparks 1984) and
// hand-computed stress cases whose arithmetic is written out below.

#include "engine/lines/riser_section.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
const Seawater kWater{1025.0, 9.80665};  // reference-platforms "Conventions"

// --- tolerances ------------------------------------------------------------
// The sheet prints its derived numbers rounded; half a unit of the last printed
// digit is the widest error that rounding can explain.
constexpr double kSheetMassTol_kg_per_m = 0.05;  // printed to 0.1 kg/m
constexpr double kSheetWeightTol_N_per_m = 0.5;  // printed to 1 N/m
// Identities that hold algebraically: only floating-point round-off remains
// (a few ulps of the largest term, relative).
constexpr double kIdentityRelTol = 1e-12;
// Hand-computed stresses below are written to 0.001 MPa.
constexpr double kHandStressTol_Pa = 0.001e6;

PipeSection production_scr() {
  // §2.8: 10 x production SCR, OD 273.1 mm, WT 25.4 mm, oil 800 kg/m^3; E 207 GPa,
  // steel 7850 kg/m^3 (§2.5, tag U).
  PipeSection s;
  s.outer_diameter_m = 0.2731;
  s.wall_thickness_m = 0.0254;
  s.contents_density_kg_per_m3 = 800.0;
  return s;
}

PipeSection export_scr() {
  // §2.8: 2 x gas export SCR, OD 508 mm, WT 25.4 mm, gas 200 kg/m^3.
  PipeSection s;
  s.outer_diameter_m = 0.508;
  s.wall_thickness_m = 0.0254;
  s.contents_density_kg_per_m3 = 200.0;
  return s;
}

double relative_error(double value, double reference) { return std::abs(value - reference) / std::abs(reference); }

TEST(RiserSection, ProductionScrMatchesReferenceSheet) {
  const auto p = pipe_section_properties(production_scr(), kWater);
  // Sheet §2.8: 155.2 kg/m steel; w_e 1,237 N/m; EA 4.09e9 N; EI 3.17e7 N m^2.
  EXPECT_NEAR(p.steel_mass_kg_per_m, 155.2, kSheetMassTol_kg_per_m);
  EXPECT_NEAR(p.effective_weight_N_per_m, 1237.0, kSheetWeightTol_N_per_m);
  EXPECT_NEAR(p.EA_N, 4.09e9, 0.005e9);     // printed to 3 significant figures
  EXPECT_NEAR(p.EI_N_m2, 3.17e7, 0.005e7);  // printed to 3 significant figures
  EXPECT_DOUBLE_EQ(p.inner_diameter_m, 0.2223);
  EXPECT_DOUBLE_EQ(p.mass_per_length_kg_per_m, p.steel_mass_kg_per_m);  // bare pipe
  EXPECT_DOUBLE_EQ(p.hydrodynamic_diameter_m, 0.2731);
}

TEST(RiserSection, ExportScrMatchesReferenceSheet) {
  const auto p = pipe_section_properties(export_scr(), kWater);
  // Sheet §2.8: 302.3 kg/m; w_e 1,249 N/m; EA 7.97e9 N; EI 2.33e8 N m^2.
  EXPECT_NEAR(p.steel_mass_kg_per_m, 302.3, kSheetMassTol_kg_per_m);
  EXPECT_NEAR(p.effective_weight_N_per_m, 1249.0, kSheetWeightTol_N_per_m);
  EXPECT_NEAR(p.EA_N, 7.97e9, 0.005e9);
  EXPECT_NEAR(p.EI_N_m2, 2.33e8, 0.005e8);
}

TEST(RiserSection, FloodedPipeWeighsItsSteelInWater) {
  // Archimedes: a pipe open to the sea (contents = sea water) has
  // w_e = (rho_s - rho_w) A_s g, the submerged weight of the steel alone.
  auto s = production_scr();
  s.contents_density_kg_per_m3 = kWater.density_kg_per_m3;
  const auto p = pipe_section_properties(s, kWater);
  const double steel_in_water = (7850.0 - 1025.0) * p.steel_area_m2 * kWater.gravity_m_per_s2;
  EXPECT_LE(relative_error(p.effective_weight_N_per_m, steel_in_water), kIdentityRelTol);
}

TEST(RiserSection, OpenEndedHangingPipeEffectiveTensionIsLinearWithZeroAtFreeEnd) {
  // A flooded pipe hangs vertically from z = 0 to an open end at z = -L.
  // Free-body of the part below z (no approximation): its weight in air minus
  // the sea pressure on the steel annulus at the open end (the water inside is
  // carried by the sea, not by the pipe):
  //   T_wall(z) = m_s g (z + L) - p_e(-L) A_s.
  // Sparks: T_eff(z) = T_wall - p_i A_i + p_e A_o with p_i = p_e = rho g (-z)
  // must then equal w_e (z + L), zero at the free end.
  auto s = production_scr();
  s.contents_density_kg_per_m3 = kWater.density_kg_per_m3;
  const auto p = pipe_section_properties(s, kWater);
  const double L = 1800.0;
  const double g = kWater.gravity_m_per_s2;
  for (double z : {-L, -1500.0, -900.0, -1.0, 0.0}) {
    const double pe = external_pressure_Pa(z, kWater);
    const PipePressures pr{pe, pe};  // open to the sea: bore pressure equals the sea's
    const double T_wall = p.steel_mass_kg_per_m * g * (z + L) - external_pressure_Pa(-L, kWater) * p.steel_area_m2;
    const double T_eff = effective_tension_N(T_wall, pr, p);
    const double expected = p.effective_weight_N_per_m * (z + L);
    // Absolute floor: at the free end both sides are zero; compare against the top value.
    EXPECT_NEAR(T_eff, expected, kIdentityRelTol * p.effective_weight_N_per_m * L) << "z = " << z;
    EXPECT_NEAR(wall_tension_N(T_eff, pr, p), T_wall, kIdentityRelTol * p.steel_mass_kg_per_m * g * L) << "z = " << z;
  }
}

TEST(RiserSection, ClosedEmptyHangingPipeEffectiveTensionIsLinearWithZeroAtFreeEnd) {
  // Empty pipe (contents 0, bore at atmospheric pressure) with a massless cap at
  // z = -L: the sea pushes the cap up with p_e(-L) A_o.
  //   T_wall(z) = m_s g (z + L) - p_e(-L) A_o;  T_eff = T_wall + p_e(z) A_o = w_e (z + L),
  // w_e = (m_s - rho_w A_o) g.
  auto s = production_scr();
  s.contents_density_kg_per_m3 = 0.0;
  const auto p = pipe_section_properties(s, kWater);
  const double L = 1000.0;
  for (double z : {-L, -400.0, 0.0}) {
    const double T_wall =
        p.steel_mass_kg_per_m * kWater.gravity_m_per_s2 * (z + L) - external_pressure_Pa(-L, kWater) * p.outer_area_m2;
    const double T_eff = effective_tension_N(T_wall, {0.0, external_pressure_Pa(z, kWater)}, p);
    EXPECT_NEAR(T_eff, p.effective_weight_N_per_m * (z + L), kIdentityRelTol * std::abs(p.effective_weight_N_per_m) * L)
        << "z = " << z;
  }
}

TEST(RiserSection, PressureProfiles) {
  // p_e = rho g (-z) below water, 0 above; p_i = p_top + rho_c g (z_top - z).
  EXPECT_DOUBLE_EQ(external_pressure_Pa(-100.0, kWater), 1025.0 * 9.80665 * 100.0);
  EXPECT_DOUBLE_EQ(external_pressure_Pa(5.0, kWater), 0.0);
  const InternalPressureProfile prof{10.0e6, -28.0, 800.0};
  EXPECT_DOUBLE_EQ(internal_pressure_Pa(prof, -28.0), 10.0e6);
  EXPECT_DOUBLE_EQ(internal_pressure_Pa(prof, -1828.0), 10.0e6 + 800.0 * 9.80665 * 1800.0);
}

TEST(RiserSection, CoatingAndSmearedBuoyancyAddMassAndDisplacement) {
  // Lazy-wave buoyancy section: production SCR + 50 mm coating of 900 kg/m^3 +
  // smeared buoyancy to D_b = 1.0 m at 450 kg/m^3.
  auto s = production_scr();
  s.coating = PipeCoating{0.05, 900.0};
  s.buoyancy = SmearedBuoyancy{1.0, 450.0};
  const auto p = pipe_section_properties(s, kWater);
  const double Dc = 0.2731 + 0.1;
  const double m_coat = 900.0 * kPi / 4.0 * (Dc * Dc - 0.2731 * 0.2731);
  const double m_buoy = 450.0 * kPi / 4.0 * (1.0 - Dc * Dc);
  EXPECT_LE(relative_error(p.coating_mass_kg_per_m, m_coat), kIdentityRelTol);
  EXPECT_LE(relative_error(p.buoyancy_mass_kg_per_m, m_buoy), kIdentityRelTol);
  EXPECT_DOUBLE_EQ(p.hydrodynamic_diameter_m, 1.0);
  const double we = (p.steel_mass_kg_per_m + m_coat + m_buoy + p.contents_mass_kg_per_m - 1025.0 * kPi / 4.0) * 9.80665;
  EXPECT_LE(relative_error(p.effective_weight_N_per_m, we), kIdentityRelTol);
  EXPECT_LT(p.effective_weight_N_per_m, 0.0);  // the buoyancy section floats: the "wave" rises
  // EA, EI stay those of the steel pipe.
  EXPECT_DOUBLE_EQ(p.EA_N, pipe_section_properties(production_scr(), kWater).EA_N);
}

TEST(RiserSection, FlexibleUsesExplicitProperties) {
  // Low & Langley (OMAE 2006) flexible, reference-platforms §2.5: OD 0.396 m,
  // 165 kg/m, EA 5.0e8 N, EI 120.8 kN m^2 (bore assumed 0.25 m for the areas).
  PipeSection s;
  s.outer_diameter_m = 0.396;
  s.inner_diameter_m = 0.25;
  s.explicit_properties = ExplicitSectionProperties{5.0e8, 120.8e3, 165.0};
  const auto p = pipe_section_properties(s, kWater);
  EXPECT_DOUBLE_EQ(p.EA_N, 5.0e8);
  EXPECT_DOUBLE_EQ(p.EI_N_m2, 120.8e3);
  EXPECT_DOUBLE_EQ(p.mass_per_length_kg_per_m, 165.0);
  const double we = (165.0 - 1025.0 * kPi / 4.0 * 0.396 * 0.396) * 9.80665;
  EXPECT_LE(relative_error(p.effective_weight_N_per_m, we), kIdentityRelTol);
}

TEST(RiserSection, FlexibleLayeredWallHasABoreButNoSteelWall) {
  // An 8-inch flexible (bore 0.2032 m) with the Low & Langley outer sheath and
  // data-sheet properties, oil-filled: the contents fill the bore, the wall
  // carries no von Mises check (API 17J / RP 17B: MBR and tension limits).
  PipeSection s;
  s.outer_diameter_m = 0.396;
  s.inner_diameter_m = 0.2032;
  s.contents_density_kg_per_m3 = 800.0;
  s.explicit_properties = ExplicitSectionProperties{5.0e8, 120.8e3, 165.0};
  const auto p = pipe_section_properties(s, kWater);
  EXPECT_EQ(p.wall, PipeWall::layered);
  EXPECT_DOUBLE_EQ(p.inner_diameter_m, 0.2032);
  EXPECT_DOUBLE_EQ(p.steel_area_m2, 0.0);
  const double bore_m2 = kPi / 4.0 * 0.2032 * 0.2032;
  EXPECT_LE(relative_error(p.contents_mass_kg_per_m, 800.0 * bore_m2), kIdentityRelTol);
  const double we = (165.0 + 800.0 * bore_m2 - 1025.0 * kPi / 4.0 * 0.396 * 0.396) * 9.80665;
  EXPECT_LE(relative_error(p.effective_weight_N_per_m, we), kIdentityRelTol);
  // Sparks' identity needs only the bore and the outer area: T_w = T_e + p_i A_i - p_e A_o.
  const PipePressures pressures{12.0e6, 1.0e6};
  const double outer_m2 = kPi / 4.0 * 0.396 * 0.396;
  EXPECT_LE(relative_error(wall_tension_N(5.0e5, pressures, p), 5.0e5 + 12.0e6 * bore_m2 - 1.0e6 * outer_m2),
            kIdentityRelTol);
  try {
    check_pipe_stress(p, StressCheckInput{});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("check_bending_radius"), std::string::npos) << e.what();
  }
}

TEST(RiserSection, LayeredWallNeedsEveryExplicitPropertyAndOneBore) {
  PipeSection s;
  s.outer_diameter_m = 0.396;
  s.inner_diameter_m = 0.2032;
  s.explicit_properties = ExplicitSectionProperties{5.0e8, 120.8e3, std::nullopt};
  EXPECT_THROW(pipe_section_properties(s, kWater), std::invalid_argument);
  s.explicit_properties.mass_per_length_kg_per_m = 165.0;
  s.wall_thickness_m = 0.05;  // and a steel wall: two bores
  EXPECT_THROW(pipe_section_properties(s, kWater), std::invalid_argument);
  s.wall_thickness_m.reset();
  s.inner_diameter_m.reset();  // no bore at all
  EXPECT_THROW(pipe_section_properties(s, kWater), std::invalid_argument);
}

TEST(RiserSection, SingleOverrideReplacesOnlyItsSteelFormula) {
  // An SCR with only EA given (e.g. a measured value): EI and mass stay steel.
  PipeSection s = production_scr();
  s.explicit_properties.EA_N = 3.5e9;
  const auto p = pipe_section_properties(s, kWater);
  const auto steel = pipe_section_properties(production_scr(), kWater);
  EXPECT_DOUBLE_EQ(p.EA_N, 3.5e9);
  EXPECT_DOUBLE_EQ(p.EI_N_m2, steel.EI_N_m2);
  EXPECT_DOUBLE_EQ(p.steel_mass_kg_per_m, steel.steel_mass_kg_per_m);
  EXPECT_EQ(p.wall, PipeWall::homogeneous);
}

TEST(RiserSection, BarlowHoopUnderPureInternalPressureIsPDOver2t) {
  // Thin-wall textbook: sigma_h = p D / (2 t). OD 0.3 m, WT 0.02 m, p = 10 MPa:
  // 10e6 * 0.3 / 0.04 = 75 MPa.
  PipeSection s;
  s.outer_diameter_m = 0.3;
  s.wall_thickness_m = 0.02;
  const auto p = pipe_section_properties(s, kWater);
  StressCheckInput in;
  in.hoop_model = HoopStressModel::barlow_outer;
  in.loads.pressures = {10.0e6, 0.0};
  const auto r = check_pipe_stress(p, in);
  EXPECT_NEAR(r.outer_tension_fibre.hoop_Pa, 75.0e6, kHandStressTol_Pa);
  EXPECT_NEAR(r.inner_tension_fibre.hoop_Pa, 75.0e6, kHandStressTol_Pa);
  EXPECT_DOUBLE_EQ(r.inner_tension_fibre.radial_Pa, -10.0e6);
  EXPECT_DOUBLE_EQ(r.outer_tension_fibre.radial_Pa, 0.0);
}

TEST(RiserSection, LameHoopTendsToThinWallWithSecondOrderError) {
  // Lamé at the bore, pure internal pressure: p (r_o^2 + r_i^2)/(r_o^2 - r_i^2).
  // Mid-wall thin form: p (D - t)/(2t). Their ratio is exactly 1 + (t/(D - t))^2,
  // so the thin form is second-order accurate in t/D.
  for (double wt : {0.0254, 0.01, 0.002}) {
    PipeSection s;
    s.outer_diameter_m = 0.2731;
    s.wall_thickness_m = wt;
    const auto p = pipe_section_properties(s, kWater);
    StressCheckInput lame;
    lame.loads.pressures = {20.0e6, 0.0};
    StressCheckInput thin = lame;
    thin.hoop_model = HoopStressModel::thin_wall_mid;
    const double h_lame = check_pipe_stress(p, lame).inner_tension_fibre.hoop_Pa;
    const double h_thin = check_pipe_stress(p, thin).inner_tension_fibre.hoop_Pa;
    const double t_over_dm = wt / (0.2731 - wt);
    EXPECT_LE(relative_error(h_lame / h_thin, 1.0 + t_over_dm * t_over_dm), kIdentityRelTol) << "WT = " << wt;
    // Lamé boundary conditions: sigma_r(r_i) = -p_i, sigma_r(r_o) = -p_e.
    EXPECT_DOUBLE_EQ(check_pipe_stress(p, lame).inner_tension_fibre.radial_Pa, -20.0e6);
  }
}

TEST(RiserSection, VonMisesHandComputedCase) {
  // OD 0.3 m, WT 0.02 m (r_o = 0.15, r_i = 0.13), Barlow hoop, p_i = 10 MPa, p_e = 0.
  // Loads chosen by stress: T_wall = 100 MPa * A_s, M = 50 MPa * I / r_o.
  //   hoop = 10 * 0.3 / 0.04 = 75 MPa everywhere; radial = -10 (bore), 0 (outside).
  //   bending at r_i = 50 * 0.13/0.15 = 43.333 MPa.
  // outer tension fibre  (150, 75, 0):        sqrt(0.5(75^2 + 75^2 + 150^2))       = 129.904 MPa
  // outer compr. fibre   (50, 75, 0):         sqrt(0.5(25^2 + 75^2 + 50^2))        =  66.144 MPa
  // inner tension fibre  (143.333, 75, -10):  sqrt(0.5(68.333^2 + 85^2 + 153.333^2)) = 133.052 MPa
  // inner compr. fibre   (56.667, 75, -10):   sqrt(0.5(18.333^2 + 85^2 + 66.667^2))  =  77.478 MPa
  // Governing: inner tension fibre, 133.052 MPa. SMYS 448 MPa, design factor 2/3:
  // allowable 298.667 MPa, utilization 0.44549.
  PipeSection s;
  s.outer_diameter_m = 0.3;
  s.wall_thickness_m = 0.02;
  s.yield_stress_Pa = 448.0e6;
  const auto p = pipe_section_properties(s, kWater);
  StressCheckInput in;
  in.hoop_model = HoopStressModel::barlow_outer;
  in.loads.wall_tension_N = 100.0e6 * p.steel_area_m2;
  in.loads.bending_moment_N_m = 50.0e6 * p.second_moment_m4 / 0.15;
  in.loads.pressures = {10.0e6, 0.0};
  in.design_factor = api_rp_2rd_design_factor(RiserDesignCondition::normal_operating);
  const auto r = check_pipe_stress(p, in);
  EXPECT_NEAR(r.outer_tension_fibre.von_mises_Pa, 129.904e6, kHandStressTol_Pa);
  EXPECT_NEAR(r.outer_compression_fibre.von_mises_Pa, 66.144e6, kHandStressTol_Pa);
  EXPECT_NEAR(r.inner_tension_fibre.von_mises_Pa, 133.052e6, kHandStressTol_Pa);
  EXPECT_NEAR(r.inner_compression_fibre.von_mises_Pa, 77.478e6, kHandStressTol_Pa);
  EXPECT_EQ(r.governing_point, SectionPoint::inner_tension_fibre);
  EXPECT_NEAR(r.max_von_mises_Pa, 133.052e6, kHandStressTol_Pa);
  EXPECT_NEAR(r.allowable_stress_Pa, 298.667e6, kHandStressTol_Pa);
  constexpr double kUtilizationTol = 1e-5;  // hand value printed to 5 decimals
  EXPECT_NEAR(r.utilization, 0.44549, kUtilizationTol);
}

TEST(RiserSection, UtilizationScalesInverselyWithDesignFactor) {
  // API RP 2RD (recalled): 0.67 / 0.80 / 1.00 of SMYS.
  EXPECT_DOUBLE_EQ(api_rp_2rd_design_factor(RiserDesignCondition::normal_operating), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(api_rp_2rd_design_factor(RiserDesignCondition::extreme), 0.8);
  EXPECT_DOUBLE_EQ(api_rp_2rd_design_factor(RiserDesignCondition::survival_temporary), 1.0);
  const auto p = pipe_section_properties(production_scr(), kWater);
  StressCheckInput in;
  in.loads.wall_tension_N = 2.77e6;
  in.loads.bending_moment_N_m = 2.0e5;
  in.loads.pressures = {25.0e6, 0.3e6};
  double u_times_factor = 0.0;
  for (auto c : {RiserDesignCondition::normal_operating, RiserDesignCondition::extreme,
                 RiserDesignCondition::survival_temporary}) {
    in.design_factor = api_rp_2rd_design_factor(c);
    const auto r = check_pipe_stress(p, in);
    if (u_times_factor == 0.0) u_times_factor = r.utilization * in.design_factor;
    EXPECT_LE(relative_error(r.utilization * in.design_factor, u_times_factor), kIdentityRelTol);
    EXPECT_LE(relative_error(r.utilization, r.max_von_mises_Pa / (in.design_factor * 448.0e6)), kIdentityRelTol);
  }
}

TEST(RiserSection, BendingRadiusCheck) {
  const auto straight = check_bending_radius(0.0, 3.0);
  EXPECT_TRUE(std::isinf(straight.bending_radius_m));
  EXPECT_DOUBLE_EQ(straight.utilization, 0.0);
  EXPECT_TRUE(straight.passes);
  const auto bent = check_bending_radius(-0.25, 3.0);  // R = 4 m, MBR 3 m
  EXPECT_DOUBLE_EQ(bent.bending_radius_m, 4.0);
  EXPECT_DOUBLE_EQ(bent.utilization, 0.75);
  EXPECT_TRUE(bent.passes);
  const auto tight = check_bending_radius(0.5, 3.0);  // R = 2 m < MBR
  EXPECT_DOUBLE_EQ(tight.utilization, 1.5);
  EXPECT_FALSE(tight.passes);
}

TEST(RiserSection, InvalidInputNamesTheField) {
  auto s = production_scr();
  s.wall_thickness_m = 0.2;  // > OD/2
  try {
    pipe_section_properties(s, kWater);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pipe.wall_thickness_m"), std::string::npos) << e.what();
  }
  StressCheckInput in;
  in.design_factor = 1.5;
  EXPECT_THROW(check_pipe_stress(pipe_section_properties(production_scr(), kWater), in), std::invalid_argument);
  EXPECT_THROW(check_bending_radius(0.1, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
