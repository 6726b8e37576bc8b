// Validation of hull hydrostatics (engine/hull/hydrostatics.hpp) and the WAMIT
// .hst reader (engine/hull/wamit_hst.hpp):
//  - box barge: closed-form waterplane and metacentric-height formulas;
//  - OC4-DeepCwind semi: shared/data/reference-platforms.md §1.2 (report values,
//    tag Q, and the sheet's derived checks, tag D) and the λ = 2 proxy of §2.4;
//  - .hst dimensionalisation exponents, malformed and missing files, and the
//    all-zero HAMS file shared/data/hydro/cylinder-buoy/Buoy.hst.
// Test files in tests/data/hydrostatics/ are described in README.md there.

#include "engine/hull/hydrostatics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "engine/hull/wamit_hst.hpp"

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
const Seawater kWater{1025.0, 9.80665};  // reference-platforms "Conventions"
const std::string kDataDir = std::string(SPIRAL_SOURCE_DIR) + "/tests/data/hydrostatics/";

// --- tolerances ------------------------------------------------------------
// Closed-form cases evaluated along two algebraic paths: round-off only.
constexpr double kExactRelTol = 1e-12;
// The sheet prints C33 (columns only) as 3.744e6: 4 significant figures, and
// the brief asks for 0.1 %.
constexpr double kSheetC33RelTol = 1e-3;
// C44 checks: the sheet's inputs are themselves rounded (z_G printed as −9.90
// and −9.902; report C44 to 4 figures); 0.5 % is the sheet's stated agreement.
constexpr double kSheetC44RelTol = 5e-3;
// Columns + braces against the report's C33: the sheet's estimate is 0.4 %
// short of the report (the remaining gap is the report's own geometry model,
// not consulted); 0.5 % bounds it.
constexpr double kBracedC33RelTol = 5e-3;
// Non-dimensional values written with 7 significant figures in the test .hst.
constexpr double kHstDigitsRelTol = 1e-6;

double rel(double value, double reference) { return std::abs(value - reference) / std::abs(reference); }

// ---------------------------------------------------------------------------
// Box barge L x B x T, reference point at the waterplane centre on the SWL.
struct Barge {
  double L = 100.0, B = 20.0, T = 8.0;
  double zg = -2.0;  // KG = T + z_g = 6 m
  HydrostaticBody body() const {
    HydrostaticBody b;
    b.waterplane.area_m2 = L * B;
    b.waterplane.second_moment_xx_m4 = L * B * B * B / 12.0;  // ∫ y^2 dA (roll)
    b.waterplane.second_moment_yy_m4 = B * L * L * L / 12.0;  // ∫ x^2 dA (pitch)
    b.displaced_volume_m3 = L * B * T;
    b.centre_of_buoyancy_m = {0.0, 0.0, -T / 2.0};
    return b;
  }
  BodyMass mass() const { return {kWater.density_kg_per_m3 * L * B * T, {0.0, 0.0, zg}}; }
};

TEST(Hydrostatics, BoxBargeMatchesMetacentricHeightFormulas) {
  const Barge barge;
  const auto r = hydrostatic_restoring(barge.body(), barge.mass(), kWater);
  const double rg = kWater.density_kg_per_m3 * kWater.gravity_m_per_s2;
  const double V = barge.L * barge.B * barge.T;
  // Textbook GM = KB + BM - KG with KB = T/2, BM_T = B^2/(12 T), BM_L = L^2/(12 T).
  const double KB = barge.T / 2.0;
  const double KG = barge.T + barge.zg;
  const double GMt = KB + barge.B * barge.B / (12.0 * barge.T) - KG;
  const double GMl = KB + barge.L * barge.L / (12.0 * barge.T) - KG;
  EXPECT_LE(rel(r.total_6x6(2, 2), rg * barge.L * barge.B), kExactRelTol);
  EXPECT_LE(rel(r.total_6x6(3, 3), rg * V * GMt), kExactRelTol);
  EXPECT_LE(rel(r.total_6x6(4, 4), rg * V * GMl), kExactRelTol);
  EXPECT_LE(rel(r.metacentric_height_transverse_m, GMt), kExactRelTol);
  EXPECT_LE(rel(r.metacentric_height_longitudinal_m, GMl), kExactRelTol);
  // Buoyancy part = rho g (I + V z_b); gravity part = -m g z_g.
  EXPECT_LE(rel(r.buoyancy_6x6(3, 3), rg * (barge.L * std::pow(barge.B, 3) / 12.0 - V * barge.T / 2.0)), kExactRelTol);
  EXPECT_LE(rel(r.gravity_6x6(3, 3), -barge.mass().mass_kg * kWater.gravity_m_per_s2 * barge.zg), kExactRelTol);
  // Symmetric hull, reference point on the centroid: no couplings, no yaw/surge/sway.
  Matrix6d diag_only = r.total_6x6;
  for (int k = 2; k < 5; ++k) diag_only(k, k) = 0.0;
  EXPECT_EQ(diag_only.norm(), 0.0);
  // Free floating: buoyancy balances weight exactly.
  EXPECT_LE(std::abs(r.rest_force(2)), kExactRelTol * rg * V);
}

TEST(Hydrostatics, OffCentreReferencePointCouplesHeaveAndPitchWithWamitSigns) {
  // Reference point a metres aft of the waterplane centroid: x_f = +a. A pitch
  // rotation theta (right-handed about +y) moves a point at x down by x theta,
  // so the centroid sinks a theta and the heave force is +rho g A a theta:
  // F3 = -C35 theta  =>  C35 = -rho g A x_f = -x_f C33 (WAMIT §3.1 sign).
  // Likewise roll phi lifts a point at y by y phi: C34 = +y_f C33.
  Barge barge;
  auto body = barge.body();
  body.waterplane.centroid_m = {7.0, -3.0};
  const auto C = buoyancy_restoring(body, kWater);
  EXPECT_LE(rel(C(2, 4), -7.0 * C(2, 2)), kExactRelTol);
  EXPECT_LE(rel(C(2, 3), -3.0 * C(2, 2)), kExactRelTol);
  EXPECT_EQ(C(2, 4), C(4, 2));
  EXPECT_EQ(C(2, 3), C(3, 2));
}

TEST(Hydrostatics, OffCentreCgAddsYawCouplingAndRestMoment) {
  // WAMIT §3.1: C46 = -rho g V x_b + m g x_g; C56 = -rho g V y_b + m g y_g.
  Barge barge;
  auto body = barge.body();
  body.centre_of_buoyancy_m = {1.0, 0.5, -4.0};
  BodyMass mass = barge.mass();
  mass.mass_kg *= 0.9;  // 10 % buoyancy excess taken by moorings
  mass.centre_of_gravity_m = {2.0, -1.0, -2.0};
  const auto r = hydrostatic_restoring(body, mass, kWater);
  const double rgV = kWater.density_kg_per_m3 * kWater.gravity_m_per_s2 * body.displaced_volume_m3;
  const double mg = mass.mass_kg * kWater.gravity_m_per_s2;
  EXPECT_LE(rel(r.total_6x6(3, 5), -rgV * 1.0 + mg * 2.0), kExactRelTol);
  EXPECT_LE(rel(r.total_6x6(4, 5), -rgV * 0.5 + mg * -1.0), kExactRelTol);
  EXPECT_EQ(r.total_6x6(5, 3), 0.0);  // WAMIT leaves C64, C65 zero
  EXPECT_LE(rel(r.rest_force(2), rgV - mg), kExactRelTol);
  EXPECT_LE(rel(r.rest_force(3), rgV * 0.5 - mg * -1.0), kExactRelTol);
  EXPECT_LE(rel(r.rest_force(4), -(rgV * 1.0 - mg * 2.0)), kExactRelTol);
}

TEST(Hydrostatics, LinearLoadIsRestForceMinusStiffnessTimesDisplacement) {
  const Barge barge;
  const auto r = hydrostatic_restoring(barge.body(), barge.mass(), kWater);
  Vector6d xi = Vector6d::Zero();
  xi(2) = 0.5;   // heave up 0.5 m
  xi(3) = 0.02;  // roll 0.02 rad
  const Vector6d F = linear_hydrostatic_load(r, xi);
  const double rg = kWater.density_kg_per_m3 * kWater.gravity_m_per_s2;
  EXPECT_LE(rel(F(2), -rg * barge.L * barge.B * 0.5), kExactRelTol);
  EXPECT_LE(rel(F(3), -r.total_6x6(3, 3) * 0.02), kExactRelTol);
  EXPECT_EQ(F(0), 0.0);
  EXPECT_EQ(F(5), 0.0);
}

// ---------------------------------------------------------------------------
// OC4-DeepCwind semi (reference-platforms §1.2, §1.3).

double oc4_column_waterplane_area_m2() {
  // §1.3: main column D 6.5 m, three upper offset columns D 12 m pierce the SWL.
  return kPi / 4.0 * 6.5 * 6.5 + 3.0 * kPi / 4.0 * 12.0 * 12.0;
}

double oc4_brace_waterplane_area_m2() {
  // §1.3 cross brace 1, joints (1.625, 2.815, -16.2) -> (11.434, 19.804, 9.13), D 1.6 m:
  // an inclined cylinder cuts the SWL in an ellipse of area pi/4 D^2 / cos(theta),
  // theta from vertical. Braces 2 and 3 are the same brace rotated by ±120°.
  const double dx = 11.434 - 1.625, dy = 19.804 - 2.815, dz = 9.13 - (-16.2);
  const double cos_theta = dz / std::sqrt(dx * dx + dy * dy + dz * dz);
  return 3.0 * kPi / 4.0 * 1.6 * 1.6 / cos_theta;
}

TEST(Hydrostatics, Oc4HeaveStiffnessColumnsOnlyAndWithBraces) {
  HydrostaticBody body;
  body.waterplane.area_m2 = oc4_column_waterplane_area_m2();
  EXPECT_NEAR(body.waterplane.area_m2, 372.48, 0.005);  // sheet §1.2, printed to 0.01 m^2
  const double C33_columns = buoyancy_restoring(body, kWater)(2, 2);
  EXPECT_LE(rel(C33_columns, 3.744e6), kSheetC33RelTol);  // sheet: columns only

  // The report's 3.836e6 (Q) is 2.4 % above: the three cross braces that pierce
  // the SWL (sheet: 2.543 m^2 each, C33 -> 3.821e6) explain all but 0.4 %.
  constexpr double kReportC33 = 3.836e6;
  const double gap = (kReportC33 - C33_columns) / kReportC33;
  EXPECT_GT(gap, 0.02);
  EXPECT_LT(gap, 0.03);
  body.waterplane.area_m2 += oc4_brace_waterplane_area_m2();
  const double C33_braced = buoyancy_restoring(body, kWater)(2, 2);
  EXPECT_LE(rel(C33_braced, 3.821e6), kSheetC33RelTol);  // sheet's braced estimate
  EXPECT_LE(rel(C33_braced, kReportC33), kBracedC33RelTol);
}

TEST(Hydrostatics, Oc4RollStiffnessWithGravityFromReportBuoyancyMatrix) {
  // tests/data/hydrostatics/oc4_report_buoyancy.hst: the report's buoyancy-only
  // C33 = 3.836e6 N/m and C44 = C55 = -3.776e8 N m/rad (Q), non-dimensional with ULEN = 1 m.
  const auto hst = read_wamit_hst(kDataDir + "oc4_report_buoyancy.hst", {1.0, kWater});
  EXPECT_EQ(hst.entries_read, 36);
  EXPECT_LE(rel(hst.restoring_6x6(2, 2), 3.836e6), kHstDigitsRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(3, 3), -3.776e8), kHstDigitsRelTol);

  // Full system (platform with ballast + tower + RNA), sheet §1.1: 1.40751e7 kg,
  // z_G = -9.902 m; displaced volume 13,917 m^3 (S), centre of buoyancy on the axis.
  const BodyMass full{1.40751e7, {-0.0065, 0.0, -9.902}};
  const auto r = hydrostatic_restoring(hst.restoring_6x6, 13917.0, {0.0, 0.0, 0.0}, full, kWater);
  EXPECT_LE(rel(r.total_6x6(3, 3), 9.892e8), kSheetC44RelTol);  // sheet §1.2 (D)
  EXPECT_LE(rel(r.total_6x6(4, 4), 9.892e8), kSheetC44RelTol);

  // Platform only (report mass 1.3473e7 kg, CM 13.46 m below SWL): sheet 1.4008e9.
  const BodyMass platform{1.3473e7, {0.0, 0.0, -13.46}};
  const auto rp = hydrostatic_restoring(hst.restoring_6x6, 13917.0, {0.0, 0.0, 0.0}, platform, kWater);
  EXPECT_LE(rel(rp.total_6x6(3, 3), 1.4008e9), kSheetC44RelTol);

  // Buoyancy rho g V = 1.398911e8 N (HD-sum, S) and the excess left for the mooring:
  // (1.42649e7 - 1.40751e7) g = 1.861e6 N (sheet §2.4, D).
  constexpr double kHdSumBuoyancyRelTol = 1e-6;  // HD-sum prints 7 significant figures
  EXPECT_LE(rel(r.rest_force(2) + full.mass_kg * kWater.gravity_m_per_s2, 1.398911e8), kHdSumBuoyancyRelTol);
  // Printed as 1.861e6 and computed from masses rounded to 6 figures
  // (1.42649e7 - 1.40751e7 kg): a difference of two rounded numbers, good to ~1 kN.
  constexpr double kSheetExcessTol_N = 0.001e6;
  EXPECT_NEAR(r.rest_force(2), 1.861e6, kSheetExcessTol_N);
}

TEST(Hydrostatics, FroudeScaledProxyFromUlen) {
  // Reading the same non-dimensional file with ULEN = 2 applies the Froude
  // scaling of reference-platforms §2.4: C33 x 4, C44 x 16.
  const auto hst = read_wamit_hst(kDataDir + "oc4_report_buoyancy.hst", {2.0, kWater});
  constexpr double kProxySheetRelTol = 5e-4;  // proxy values printed to 4 figures
  EXPECT_LE(rel(hst.restoring_6x6(2, 2), 1.534e7), kProxySheetRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(3, 3), -6.042e9), kProxySheetRelTol);
  // After deballast (§2.4): 1.07427e8 kg, z_G = -19.30 m -> C55 incl. gravity 1.429e10.
  const BodyMass proxy{1.07427e8, {0.0, 0.0, -19.30}};
  const auto r = hydrostatic_restoring(hst.restoring_6x6, 111336.0, {0.0, 0.0, 0.0}, proxy, kWater);
  EXPECT_LE(rel(r.total_6x6(4, 4), 1.429e10), kSheetC44RelTol);
}

// ---------------------------------------------------------------------------
// WAMIT .hst reader.

TEST(WamitHst, LengthExponentRule) {
  EXPECT_EQ(wamit_hst_length_exponent(3, 3), 2);
  EXPECT_EQ(wamit_hst_length_exponent(3, 4), 3);
  EXPECT_EQ(wamit_hst_length_exponent(5, 3), 3);
  EXPECT_EQ(wamit_hst_length_exponent(4, 4), 4);
  EXPECT_EQ(wamit_hst_length_exponent(4, 6), 4);
  EXPECT_EQ(wamit_hst_length_exponent(5, 6), 4);
  EXPECT_THROW(wamit_hst_length_exponent(7, 1), std::invalid_argument);
}

TEST(WamitHst, DimensionalisesEachEntryWithItsExponent) {
  // exponents.hst (ULEN = 2): Cbar33 = 2, Cbar34 = Cbar43 = 3, Cbar35 = Cbar53 = -0.5
  // (one written with a Fortran D exponent), Cbar44 = 7, Cbar46 = 1.1, Cbar55 = 13,
  // Cbar56 = -1.7; a blank line in between.
  const auto hst = read_wamit_hst(kDataDir + "exponents.hst", {2.0, kWater});
  const double rg = kWater.density_kg_per_m3 * kWater.gravity_m_per_s2;
  EXPECT_EQ(hst.entries_read, 9);
  EXPECT_LE(rel(hst.restoring_6x6(2, 2), rg * 4.0 * 2.0), kExactRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(2, 3), rg * 8.0 * 3.0), kExactRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(3, 2), rg * 8.0 * 3.0), kExactRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(2, 4), rg * 8.0 * -0.5), kExactRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(4, 2), rg * 8.0 * -0.5), kExactRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(3, 3), rg * 16.0 * 7.0), kExactRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(3, 5), rg * 16.0 * 1.1), kExactRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(4, 4), rg * 16.0 * 13.0), kExactRelTol);
  EXPECT_LE(rel(hst.restoring_6x6(4, 5), rg * 16.0 * -1.7), kExactRelTol);
  EXPECT_EQ(hst.restoring_6x6(0, 0), 0.0);  // absent entries are zero
  EXPECT_EQ(hst.nondimensional(3, 3), 7.0);
}

TEST(WamitHst, SharedHamsBuoyFileIsAllZeros) {
  // shared/data/hydro/cylinder-buoy/Buoy.hst: HAMS wrote zeros (no hydrostatic input).
  const auto hst = read_wamit_hst(std::string(SPIRAL_TEST_DATA_DIR) + "/hydro/cylinder-buoy/Buoy.hst", {1.0, kWater});
  EXPECT_EQ(hst.entries_read, 36);
  EXPECT_EQ(hst.restoring_6x6.norm(), 0.0);
}

TEST(WamitHst, MalformedFileReportsFileAndLine) {
  const std::string path = kDataDir + "malformed_line4.hst";
  try {
    read_wamit_hst(path, {1.0, kWater});
    FAIL() << "expected FileFormatError";
  } catch (const FileFormatError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 4u);
    EXPECT_NE(std::string(e.what()).find("malformed_line4.hst:4:"), std::string::npos) << e.what();
  }
}

TEST(WamitHst, ParserRejectsBadLinesWithTheirNumbers) {
  struct Case {
    const char* text;
    std::size_t line;
    const char* says;
  };
  const Case cases[] = {
      {"3 3 1.0\n3 3 2.0\n", 2, "given twice"},
      {"3 3 1.0\n\n7 7 1.0\n", 3, "above 6"},
      {"0 3 1.0\n", 1, "1..6"},
      {"3 3\n", 1, "expected 3 fields"},
      {"3 3 1.0 extra\n", 1, "expected 3 fields"},
      {"3.5 3 1.0\n", 1, "integers"},
      {"3 3 nan\n", 1, "finite real"},
      {"\n\n", 0, "no coefficients"},
  };
  for (const auto& c : cases) {
    std::istringstream in(c.text);
    try {
      parse_wamit_hst(in, "inline.hst", {1.0, kWater});
      ADD_FAILURE() << "no error for: " << c.text;
    } catch (const FileFormatError& e) {
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_NE(e.message().find(c.says), std::string::npos) << e.what();
      EXPECT_EQ(e.file(), "inline.hst");
    }
  }
}

TEST(WamitHst, MissingFileNamesIt) {
  const std::string path = kDataDir + "does_not_exist.hst";
  try {
    read_wamit_hst(path, {1.0, kWater});
    FAIL() << "expected FileFormatError";
  } catch (const FileFormatError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 0u);
    EXPECT_NE(std::string(e.what()).find("does_not_exist.hst"), std::string::npos);
  }
}

}  // namespace
}  // namespace spiral::engine
