// Validation of the WAMIT-format readers of frequency-dependent hull data:
//  - .1 (added mass, radiation damping): OC4-DeepCwind marin_semi.1 against
//    shared/data/reference-platforms.md §1.5 (period column, ULEN = 1 m,
//    rho = 1025 kg/m^3) and HAMS Buoy.1 (angular-frequency column) against the
//    raw file numbers with the WAMIT dimensionalisation written out;
//  - .3 (excitation) on HAMS Buoy.3, .4 (RAO) on a small synthetic file,
//    heading/frequency interpolation and the out-of-range heading error;
//  - malformed lines and missing files.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/hull/wamit_1.hpp"
#include "engine/hull/wamit_3.hpp"
#include "support/expect_near.hpp"

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr double kRho = 1025.0;
constexpr double kG = 9.80665;
// reference-platforms.md §1.5 prints 4 significant figures: half a unit in the
// 4th figure is at most 5e-4 of the value (mantissa >= 1).
constexpr double kFourSignificantFiguresRelTol = 5e-4;
// Products of file digits with exact constants: round-off only.
constexpr double kRoundOffRelTol = 1e-12;
// Periods are printed with 6 significant digits (0.125664E+03).
constexpr double kPrintedPeriodRelTol = 1e-5;
// Phases are printed with 7 significant digits (9.000000E+01 deg).
constexpr double kPrintedPhaseTol_deg = 1e-5;

const char* kSemi1 = SPIRAL_SCENARIO_DATA_DIR "/hydro/oc4-semi/marin_semi.1";
const char* kBuoy1 = SPIRAL_TEST_DATA_DIR "/hydro/cylinder-buoy/Buoy.1";
const char* kBuoy3 = SPIRAL_TEST_DATA_DIR "/hydro/cylinder-buoy/Buoy.3";

WamitReadOptions period_options(double ulen_m = 1.0) {
  WamitReadOptions o;
  o.frequency_column = FrequencyColumn::period_s;
  o.ulen_m = ulen_m;
  o.water = {kRho, kG};
  return o;
}

WamitReadOptions frequency_options(double ulen_m = 1.0) {
  WamitReadOptions o = period_options(ulen_m);
  o.frequency_column = FrequencyColumn::angular_frequency;
  return o;
}

// ------------------------------------------------------------------- .1 OC4

TEST(Wamit1, Oc4SemiLongestPeriodMatchesReferenceTable) {
  const auto c = read_wamit_1(kSemi1, period_options());
  ASSERT_EQ(c.omega_rad_per_s.size(), 498u);  // distinct periods in the file
  EXPECT_FALSE(c.added_mass_infinite.has_value());
  EXPECT_FALSE(c.added_mass_zero.has_value());
  for (std::size_t i = 1; i < c.omega_rad_per_s.size(); ++i) {
    ASSERT_GT(c.omega_rad_per_s[i], c.omega_rad_per_s[i - 1]);
  }
  // Longest period 628.319 s is the lowest frequency, first in the table.
  EXPECT_REL_NEAR(c.omega_rad_per_s.front(), 2.0 * kPi / 628.319, kRoundOffRelTol);
  const Matrix6d& A = c.added_mass.front();
  EXPECT_REL_NEAR(A(0, 0), 8.740e6, kFourSignificantFiguresRelTol);
  EXPECT_REL_NEAR(A(2, 2), 1.537e7, kFourSignificantFiguresRelTol);
  EXPECT_REL_NEAR(A(4, 4), 7.627e9, kFourSignificantFiguresRelTol);
  EXPECT_REL_NEAR(A(5, 5), 6.430e9, kFourSignificantFiguresRelTol);
  EXPECT_REL_NEAR(A(0, 4), -1.076e8, kFourSignificantFiguresRelTol);
  // Written out from the file line "0.628319E+03 1 5 -1.049620E+05 -1.030536E-01":
  // A15 = rho L^4 Abar, B15 = rho L^4 w Bbar (one rotational index: k = 4).
  const double w = 2.0 * kPi / 628.319;
  EXPECT_REL_NEAR(A(0, 4), kRho * -1.049620e5, kRoundOffRelTol);
  EXPECT_REL_NEAR(c.damping.front()(0, 4), kRho * w * -1.030536e-1, kRoundOffRelTol);
  // Entries the file omits (e.g. 1-2) are zero.
  EXPECT_EQ(A(0, 1), 0.0);
}

TEST(Wamit1, Oc4SemiInterpolatesAt110s) {
  const auto c = read_wamit_1(kSemi1, period_options());
  const Matrix6d A = added_mass_at(c, 2.0 * kPi / 110.0);
  EXPECT_REL_NEAR(A(0, 0), 8.751e6, kFourSignificantFiguresRelTol);
  EXPECT_REL_NEAR(A(2, 2), 1.516e7, kFourSignificantFiguresRelTol);
  EXPECT_REL_NEAR(A(4, 4), 7.629e9, kFourSignificantFiguresRelTol);
  EXPECT_REL_NEAR(A(5, 5), 6.434e9, kFourSignificantFiguresRelTol);
  EXPECT_REL_NEAR(A(0, 4), -1.077e8, kFourSignificantFiguresRelTol);
  // Linear in w between the bracketing rows 125.664 s and 104.720 s.
  const double w0 = 2.0 * kPi / 125.664;
  const double w1 = 2.0 * kPi / 104.720;
  std::size_t j = 0;
  while (c.omega_rad_per_s[j] < w1 - 1e-9) ++j;
  ASSERT_REL_NEAR(c.omega_rad_per_s[j - 1], w0, kPrintedPeriodRelTol);
  const double s = (2.0 * kPi / 110.0 - c.omega_rad_per_s[j - 1]) / (c.omega_rad_per_s[j] - c.omega_rad_per_s[j - 1]);
  const Matrix6d expected = (1.0 - s) * c.added_mass[j - 1] + s * c.added_mass[j];
  EXPECT_EIGEN_REL_NEAR(A, expected, kRoundOffRelTol);
  // Held at the ends.
  EXPECT_EIGEN_REL_NEAR(added_mass_at(c, 1e-6), c.added_mass.front(), 0.0);
  EXPECT_EIGEN_REL_NEAR(damping_at(c, 100.0), c.damping.back(), 0.0);
  EXPECT_THROW(added_mass_at(c, std::nan("")), std::invalid_argument);
}

// ------------------------------------------------------------------ .1 HAMS

TEST(Wamit1, BuoyFrequencyColumnDimensionalisation) {
  const auto c = read_wamit_1(kBuoy1, frequency_options());
  ASSERT_EQ(c.omega_rad_per_s.size(), 30u);
  EXPECT_REL_NEAR(c.omega_rad_per_s.front(), 0.2, kRoundOffRelTol);
  EXPECT_REL_NEAR(c.omega_rad_per_s.back(), 6.0, kRoundOffRelTol);
  // File line "2.000000E-01 1 1 1.739347E-01 2.930294E-09": A11 = rho Abar, B11 = rho w Bbar.
  EXPECT_REL_NEAR(c.added_mass[0](0, 0), kRho * 1.739347e-1, kRoundOffRelTol);
  EXPECT_REL_NEAR(c.damping[0](0, 0), kRho * 0.2 * 2.930294e-9, kRoundOffRelTol);
  // "2.000000E-01 3 3 9.689767E-02 2.981663E-04"
  EXPECT_REL_NEAR(c.damping[0](2, 2), kRho * 0.2 * 2.981663e-4, kRoundOffRelTol);
  // With ULEN = 2 m the exponents show: k = 3 (1,1), 4 (1,5), 5 (4,4).
  const auto c2 = read_wamit_1(kBuoy1, frequency_options(2.0));
  EXPECT_REL_NEAR(c2.added_mass[0](0, 0), kRho * 8.0 * 1.739347e-1, kRoundOffRelTol);
  EXPECT_REL_NEAR(c2.added_mass[0](0, 4), kRho * 16.0 * -4.810507e-2, kRoundOffRelTol);
  EXPECT_REL_NEAR(c2.added_mass[0](3, 3), kRho * 32.0 * 1.668259e-2, kRoundOffRelTol);
  EXPECT_REL_NEAR(c2.damping[0](0, 4), kRho * 16.0 * 0.2 * -7.940947e-10, kRoundOffRelTol);
}

TEST(Wamit1, LimitRowsMayOmitDamping) {
  std::istringstream text(
      "  -1.0  1 1  2.0\n"
      "   0.0  1 1  1.5\n"
      "   0.0  3 3  4.0  0.0\n"
      "  10.0  1 1  1.8  0.25\n");
  const auto c = parse_wamit_1(text, "limits.1", period_options());
  ASSERT_TRUE(c.added_mass_zero && c.added_mass_infinite);
  EXPECT_EQ((*c.added_mass_zero)(0, 0), kRho * 2.0);
  EXPECT_EQ((*c.added_mass_infinite)(0, 0), kRho * 1.5);
  EXPECT_EQ((*c.added_mass_infinite)(2, 2), kRho * 4.0);
  ASSERT_EQ(c.omega_rad_per_s.size(), 1u);
  EXPECT_REL_NEAR(c.damping[0](0, 0), kRho * (2.0 * kPi / 10.0) * 0.25, kRoundOffRelTol);
}

TEST(Wamit1, MalformedLineNamesFileAndLine) {
  std::istringstream text(
      "  10.0  1 1  1.8  0.25\n"
      "\n"
      "  10.0  1 x  1.8  0.25\n");
  try {
    parse_wamit_1(text, "bad.1", period_options());
    FAIL() << "expected FileFormatError";
  } catch (const FileFormatError& e) {
    EXPECT_EQ(e.file(), "bad.1");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_NE(std::string(e.what()).find("bad.1:3:"), std::string::npos) << e.what();
  }
  std::istringstream missing_b("  10.0  1 1  1.8\n");
  EXPECT_THROW(parse_wamit_1(missing_b, "b.1", period_options()), FileFormatError);
  std::istringstream twice("  10.0  1 1  1.8 0.1\n  10.0  1 1  1.8 0.1\n");
  EXPECT_THROW(parse_wamit_1(twice, "twice.1", period_options()), FileFormatError);
  std::istringstream dof7("  10.0  1 7  1.8 0.1\n");
  EXPECT_THROW(parse_wamit_1(dof7, "dof7.1", period_options()), FileFormatError);
}

TEST(Wamit1, MissingFileAndBadOptions) {
  try {
    read_wamit_1("/nonexistent/hull.1", period_options());
    FAIL() << "expected FileFormatError";
  } catch (const FileFormatError& e) {
    EXPECT_EQ(e.line(), 0u);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/hull.1"), std::string::npos);
  }
  EXPECT_THROW(read_wamit_1(kSemi1, period_options(0.0)), std::invalid_argument);
}

// ------------------------------------------------------------------- .3 HAMS

TEST(Wamit3, BuoyExcitationDimensionalisationAndPhase) {
  const auto x = read_wamit_3(kBuoy3, frequency_options());
  ASSERT_EQ(x.omega_rad_per_s.size(), 30u);
  ASSERT_EQ(x.headings_rad.size(), 1u);
  EXPECT_EQ(x.headings_rad[0], 0.0);
  const double rho_g = kRho * kG;
  // "2.000000E-01 0.0 1 1.693418E-03 9.000000E+01 1.193575E-11 1.693418E-03":
  // X1 = rho g L^2 (RE + i IM): surge leads the crest by 90 deg (inertia force).
  EXPECT_REL_NEAR(x.values[0](0, 0).imag(), rho_g * 1.693418e-3, kRoundOffRelTol);
  EXPECT_REL_NEAR(x.values[0](0, 0).real(), rho_g * 1.193575e-11, kRoundOffRelTol);
  EXPECT_NEAR(std::arg(x.values[0](0, 0)) / kDeg, 90.0, kPrintedPhaseTol_deg);
  // "... 3 3.823694E-01 1.822382E-04 3.823694E-01 1.216186E-06": heave ~ in phase.
  EXPECT_REL_NEAR(x.values[2](0, 0).real(), rho_g * 3.823694e-1, kRoundOffRelTol);
  // Moment (m = 3) with ULEN = 2 m: "... 5 ... -3.238429E-12 -4.590587E-04".
  const auto x2 = read_wamit_3(kBuoy3, frequency_options(2.0));
  EXPECT_REL_NEAR(x2.values[4](0, 0).imag(), rho_g * 8.0 * -4.590587e-4, kRoundOffRelTol);
  EXPECT_REL_NEAR(x2.values[0](0, 0).imag(), rho_g * 4.0 * 1.693418e-3, kRoundOffRelTol);
  // Interpolation in w (between 0.2 and 0.4 rad/s), heading on the single row.
  const Vector6cd mid = transfer_at(x, 0.3, 0.0);
  const std::complex<double> expected = 0.5 * (x.values[2](0, 0) + x.values[2](0, 1));
  EXPECT_REL_NEAR(mid(2).real(), expected.real(), kRoundOffRelTol);
  EXPECT_REL_NEAR(mid(2).imag(), expected.imag(), kRoundOffRelTol);
  // A full turn is the same heading.
  EXPECT_NO_THROW(transfer_at(x, 0.3, 2.0 * kPi));
  try {
    transfer_at(x, 0.3, 10.0 * kDeg);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("heading 10 deg outside the database range [0, 0] deg"), std::string::npos)
        << e.what();
  }
}

TEST(Wamit3, BilinearInHeadingAndFrequency) {
  // Two periods x two headings, heave only; RE/IM are used, MOD/PHA not.
  std::istringstream text(
      "10.0   0.0 3  0 0  1.0  0.0\n"
      "10.0  90.0 3  0 0  3.0  2.0\n"
      " 5.0   0.0 3  0 0  5.0  0.0\n"
      " 5.0  90.0 3  0 0  7.0  4.0\n");
  const auto x = parse_wamit_3(text, "grid.3", period_options());
  const double w0 = 2.0 * kPi / 10.0;
  const double w1 = 2.0 * kPi / 5.0;
  const double rho_g = kRho * kG;
  const Vector6cd v = transfer_at(x, 0.25 * w0 + 0.75 * w1, 30.0 * kDeg);
  // Bilinear: heading weight 1/3, frequency weight 3/4.
  const double re = (2.0 / 3.0) * (0.25 * 1.0 + 0.75 * 5.0) + (1.0 / 3.0) * (0.25 * 3.0 + 0.75 * 7.0);
  const double im = (1.0 / 3.0) * (0.25 * 2.0 + 0.75 * 4.0);
  EXPECT_REL_NEAR(v(2).real(), rho_g * re, kRoundOffRelTol);
  EXPECT_REL_NEAR(v(2).imag(), rho_g * im, kRoundOffRelTol);
  EXPECT_EQ(v(0), std::complex<double>(0.0, 0.0));  // absent DOF
  EXPECT_FALSE(x.dof_present[0]);
  // -30 deg wraps to 330 deg, outside [0, 90].
  EXPECT_THROW(transfer_at(x, w0, -30.0 * kDeg), std::invalid_argument);
  // A gap in the grid is an error.
  std::istringstream gap(
      "10.0   0.0 3  0 0  1.0  0.0\n"
      "10.0  90.0 3  0 0  3.0  2.0\n"
      " 5.0   0.0 3  0 0  5.0  0.0\n");
  EXPECT_THROW(parse_wamit_3(gap, "gap.3", period_options()), FileFormatError);
  std::istringstream bad("10.0   0.0 3  0 0  1.0\n");
  try {
    parse_wamit_3(bad, "bad.3", period_options());
    FAIL();
  } catch (const FileFormatError& e) {
    EXPECT_EQ(e.line(), 1u);
  }
  EXPECT_THROW(read_wamit_3("/nonexistent/hull.3", period_options()), FileFormatError);
}

TEST(Wamit4, RotationsScaleWithOneOverUlen) {
  std::istringstream text(
      "10.0 0.0 1  0 0  0.9  0.1\n"
      "10.0 0.0 5  0 0  0.3 -0.2\n");
  const auto r = parse_wamit_4(text, "hull.4", period_options(4.0));
  EXPECT_EQ(r.quantity, TransferQuantity::motion_rao);
  // Translations m/m unchanged; rotations xi/A = xibar / L rad/m.
  EXPECT_EQ(r.values[0](0, 0), std::complex<double>(0.9, 0.1));
  EXPECT_EQ(r.values[4](0, 0), std::complex<double>(0.3 / 4.0, -0.2 / 4.0));
}

}  // namespace
}  // namespace spiral::engine
