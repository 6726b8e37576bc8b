// Validation of the mean environmental loads on the hull:
//  - coefficient (OCIMF-form) wind/current loads against hand-evaluated
//    1/2 rho CA V^2 with heading interpolation, sign, and hull-yaw rotation;
//  - mean wave drift: a constant drift coefficient D0 gives exactly
//    F = 2 D0 m0 = D0 Hs^2/8 for Pierson-Moskowitz (closed-form m0 = Hs^2/16),
//    with or without spreading; the variance outside the table matches the PM
//    closed-form cumulative distribution;
//  - the WAMIT .12d reader on shared/data/hydro/oc4-semi/marin_semi.12d,
//    spot-checked against raw numbers of the file, and on malformed text.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/hull/mean_environmental_loads.hpp"
#include "engine/hull/wamit_12d.hpp"
#include "support/expect_near.hpp"

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
// Closed-form products and rotations of exact inputs: round-off only.
constexpr double kRoundOffRelTol = 1e-12;
// Drift integral of a constant D0 over the PM spectrum: the kernel's quadrature
// (Simpson, 4000 intervals, plus the analytic w^-5 tail) reproduces the
// closed-form m0 to ~1e-7; 1e-5 leaves margin (cf. wave_spectrum_test).
constexpr double kIntegrationRelTol = 1e-5;
// Spreading weights sum to 1 to the 16-panel Simpson accuracy per bin (~1e-8).
constexpr double kSpreadingRelTol = 1e-6;
// Share of the variance below/above the table: the node sum assigns the
// Simpson weight of the node nearest the table end to one side; one node
// carries < 1e-3 of m0 here (h = wp/400).
constexpr double kVarianceShareAbsTol = 1e-3;
// Locating a tabulated frequency 2 pi / PER: the reader computes the same
// expression from the same digits, so only round-off separates them.
constexpr double kFrequencyMatch_rad_per_s = 1e-9;

const char* kSemi12d = SPIRAL_SCENARIO_DATA_DIR "/hydro/oc4-semi/marin_semi.12d";

CoefficientTable four_heading_table() {
  // Coefficient x area at 0, 90, 180, 270 deg (relative flow direction, hull frame).
  return {{0.0, 90.0 * kDeg, 180.0 * kDeg, 270.0 * kDeg},
          {100.0, 20.0, -80.0, 20.0},    // CxA, m^2
          {0.0, 300.0, 0.0, -300.0},     // CyA, m^2
          {0.0, 5000.0, 0.0, -5000.0}};  // CmzA, m^3
}

TEST(CoefficientLoads, HeadOnFlowGivesDragAlongTheFlow) {
  // 2 m/s current along +x, hull yaw 0: Fx = 1/2 x 1025 x 100 x 2^2 = 205000 N.
  const auto r = coefficient_load(four_heading_table(), {1025.0, {2.0, 0.0, 0.0}, 0.0});
  Vector6d expected = Vector6d::Zero();
  expected(0) = 205000.0;
  EXPECT_EIGEN_REL_NEAR(r.load_g, expected, kRoundOffRelTol);
  EXPECT_EIGEN_REL_NEAR(r.load_b, expected, kRoundOffRelTol);
  EXPECT_EQ(r.relative_heading_rad, 0.0);
  // Reversed flow (beta = 180 deg): CxA = -80 pushes towards -x, along the flow (V|V| sign).
  const auto back = coefficient_load(four_heading_table(), {1025.0, {-2.0, 0.0, 0.0}, 0.0});
  EXPECT_REL_NEAR(back.load_g(0), -0.5 * 1025.0 * 80.0 * 4.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(back.relative_heading_rad, kPi, kRoundOffRelTol);
}

TEST(CoefficientLoads, InterpolatesLinearlyInHeadingIncludingTheWrap) {
  // Flow towards 45 deg: halfway between the 0 and 90 deg rows.
  const double V = 1.5;
  const double q = 0.5 * 1025.0 * V * V;
  const auto r =
      coefficient_load(four_heading_table(), {1025.0, {V * std::cos(45 * kDeg), V * std::sin(45 * kDeg), 0.0}, 0.0});
  EXPECT_REL_NEAR(r.load_b(0), q * 60.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(r.load_b(1), q * 150.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(r.load_b(5), q * 2500.0, kRoundOffRelTol);
  // Towards 315 deg: halfway between 270 and 360 (= 0) deg rows, across the wrap.
  const auto w =
      coefficient_load(four_heading_table(), {1025.0, {V * std::cos(-45 * kDeg), V * std::sin(-45 * kDeg), 0.0}, 0.0});
  EXPECT_REL_NEAR(w.relative_heading_rad, 315.0 * kDeg, kRoundOffRelTol);
  EXPECT_REL_NEAR(w.load_b(0), q * 60.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(w.load_b(1), q * -150.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(w.load_b(5), q * -2500.0, kRoundOffRelTol);
}

TEST(CoefficientLoads, HullYawRotatesTheRelativeHeadingAndTheLoad) {
  // Flow towards global +y (90 deg) on a hull yawed 90 deg: beta = 0 in the hull
  // frame, so F_b = (205000, 0) and F_g = Rz(90 deg) F_b = (0, 205000).
  const auto r = coefficient_load(four_heading_table(), {1025.0, {0.0, 2.0, 0.0}, 90.0 * kDeg});
  EXPECT_REL_NEAR_SCALE(r.relative_heading_rad, 0.0, kRoundOffRelTol, 2.0 * kPi);
  EXPECT_REL_NEAR(r.load_b(0), 205000.0, kRoundOffRelTol);
  EXPECT_REL_NEAR_SCALE(r.load_g(0), 0.0, kRoundOffRelTol, 205000.0);
  EXPECT_REL_NEAR(r.load_g(1), 205000.0, kRoundOffRelTol);
  // Flow towards +x on a hull yawed 90 deg: beta = 270 deg, beam flow from the
  // hull's port side: CyA(270) = -300 -> F_b,y = -q 300 (towards body -y = global +x).
  const auto beam = coefficient_load(four_heading_table(), {1025.0, {2.0, 0.0, 0.0}, 90.0 * kDeg});
  EXPECT_REL_NEAR(beam.relative_heading_rad, 270.0 * kDeg, kRoundOffRelTol);
  EXPECT_REL_NEAR(beam.load_b(1), -0.5 * 1025.0 * 4.0 * 300.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(beam.load_g(0), 0.5 * 1025.0 * 4.0 * 300.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(beam.load_g(5), -0.5 * 1025.0 * 4.0 * 5000.0, kRoundOffRelTol);
}

TEST(CoefficientLoads, CurrentUsesTheReferenceDepthAndWindTheGivenSpeed) {
  const CurrentProfile current{{-200.0, 0.0}, {0.5, 1.5}, 0.0};
  // Surface current 1.5 m/s by default; 1.0 m/s at z = -100 m.
  EXPECT_REL_NEAR(current_load(four_heading_table(), current, 1025.0, 0.0).load_g(0), 0.5 * 1025.0 * 100.0 * 1.5 * 1.5,
                  kRoundOffRelTol);
  EXPECT_REL_NEAR(current_load(four_heading_table(), current, 1025.0, 0.0, -100.0).load_g(0),
                  0.5 * 1025.0 * 100.0 * 1.0 * 1.0, kRoundOffRelTol);
  // Wind 40 m/s towards 90 deg, hull yaw 0: beta = 90 deg, Fy = 1/2 1.225 300 40^2.
  const auto wind = wind_load(four_heading_table(), 40.0, 90.0 * kDeg, 0.0);
  EXPECT_REL_NEAR(wind.load_b(1), 0.5 * 1.225 * 300.0 * 1600.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(wind.load_b(0), 0.5 * 1.225 * 20.0 * 1600.0, kRoundOffRelTol);
  // No flow, no load.
  EXPECT_EQ(wind_load(four_heading_table(), 0.0, 1.0, 0.3).load_g, Vector6d::Zero());
  // Table checks.
  CoefficientTable bad = four_heading_table();
  bad.headings_rad[2] = 7.0;
  EXPECT_THROW(coefficient_load(bad, {1025.0, {1.0, 0.0, 0.0}, 0.0}), std::invalid_argument);
}

// Constant D0 for surge and sway (N/m^2) and a yaw value (N m/m^2), headings 0..345 deg.
MeanDriftTable constant_drift_table(double D0) {
  MeanDriftTable t;
  t.omega_rad_per_s = {0.2, 0.5, 1.0, 2.0};
  for (int j = 0; j < 24; ++j) t.headings_rad.push_back(15.0 * j * kDeg);
  for (int i : {0, 1, 5}) {
    t.present[static_cast<std::size_t>(i)] = true;
    t.coefficient[static_cast<std::size_t>(i)] = Eigen::MatrixXd::Constant(4, 24, D0 * (i + 1));
  }
  return t;
}

TEST(MeanWaveDrift, ConstantCoefficientGivesTwiceD0TimesM0) {
  const double D0 = 5000.0;  // N/m^2
  const double Hs = 6.0;
  MeanDriftInput in;
  in.spectrum = make_pierson_moskowitz_spectrum(Hs, 10.0);
  in.wave_heading_rad = 0.0;
  const auto r = mean_wave_drift_load(constant_drift_table(D0), in);
  // F = 2 D0 m0 = D0 Hs^2 / 8 (PM: m0 = Hs^2/16 exactly).
  EXPECT_REL_NEAR(r.load_b(0), D0 * Hs * Hs / 8.0, kIntegrationRelTol);
  EXPECT_REL_NEAR(r.load_b(1), 2.0 * D0 * Hs * Hs / 8.0, kIntegrationRelTol);
  EXPECT_REL_NEAR(r.load_b(5), 6.0 * D0 * Hs * Hs / 8.0, kIntegrationRelTol);
  EXPECT_EQ(r.load_b(2), 0.0);
  EXPECT_REL_NEAR(r.m0_m2, Hs * Hs / 16.0, kIntegrationRelTol);
  // JONSWAP: 2 D0 m0 with the spectrum's own m0 (A_gamma makes m0 ~ Hs^2/16 only).
  in.spectrum = make_jonswap_spectrum({Hs, 10.0, 3.3});
  const auto j = mean_wave_drift_load(constant_drift_table(D0), in);
  EXPECT_REL_NEAR(j.load_b(0), 2.0 * D0 * spectral_moments(in.spectrum).m0_m2, kIntegrationRelTol);
}

TEST(MeanWaveDrift, SpreadingAndHullYaw) {
  const double D0 = 5000.0;
  const double Hs = 6.0;
  MeanDriftInput in;
  in.spectrum = make_pierson_moskowitz_spectrum(Hs, 10.0);
  in.wave_heading_rad = 30.0 * kDeg;
  in.hull_yaw_rad = 30.0 * kDeg;
  in.spreading = DirectionalSpreading{SpreadingForm::cos_2s, 8.0};
  in.spreading_directions = 21;
  const auto r = mean_wave_drift_load(constant_drift_table(D0), in);
  // The weights sum to 1: the constant-D0 answer is unchanged in the hull frame...
  EXPECT_REL_NEAR(r.load_b(0), D0 * Hs * Hs / 8.0, kSpreadingRelTol);
  EXPECT_EQ(r.directions.size(), 21u);
  // ...and rotated by the hull yaw into the global frame.
  const double c = std::cos(30.0 * kDeg);
  const double s = std::sin(30.0 * kDeg);
  EXPECT_REL_NEAR(r.load_g(0), c * r.load_b(0) - s * r.load_b(1), kRoundOffRelTol);
  EXPECT_REL_NEAR(r.load_g(1), s * r.load_b(0) + c * r.load_b(1), kRoundOffRelTol);
  EXPECT_EQ(r.load_g(5), r.load_b(5));
}

TEST(MeanWaveDrift, TheIntegralAtTheTableHeadingsGivesTheLoadAtAnyYaw) {
  // A table that varies in frequency and heading, a spread JONSWAP sea: the
  // prepared integral at a yaw between the table's headings against the
  // direct sum 2 Σ_dir w_dir Σ_i w_i D(w_i, beta_dir − yaw) over the same
  // quadrature nodes, with D from the table's own bilinear interpolation.
  MeanDriftTable t;
  t.omega_rad_per_s = {0.2, 0.5, 0.8, 1.2, 2.0};
  for (int j = 0; j < 12; ++j) t.headings_rad.push_back(30.0 * j * kDeg);
  for (int i : {0, 1, 5}) {
    auto& c = t.coefficient[static_cast<std::size_t>(i)];
    c.resize(5, 12);
    for (int k = 0; k < 5; ++k)
      for (int j = 0; j < 12; ++j)
        c(k, j) = 1000.0 * (i + 1) * t.omega_rad_per_s[static_cast<std::size_t>(k)] *
                  std::cos(t.headings_rad[static_cast<std::size_t>(j)] + 0.3 * i);
    t.present[static_cast<std::size_t>(i)] = true;
  }
  MeanDriftInput in;
  in.spectrum = make_jonswap_spectrum({7.0, 11.0, 3.3});
  in.wave_heading_rad = 20.0 * kDeg;
  in.spreading = DirectionalSpreading{SpreadingForm::cos_2s, 6.0};
  in.spreading_directions = 9;
  const MeanDriftIntegral integral(t, in);

  SpectrumQuadratureOptions options;
  options.min_upper_limit_rad_per_s = t.omega_rad_per_s.back();
  const SpectrumQuadrature q = spectrum_quadrature(in.spectrum, options);
  for (double yaw_deg : {0.0, 7.5, 43.0, -101.0}) {
    const double yaw = yaw_deg * kDeg;
    Vector6d direct = Vector6d::Zero();
    for (const SpreadingDirection& dir : discretise_spreading(*in.spreading, in.wave_heading_rad, 9)) {
      const double beta = dir.heading_rad - yaw;
      for (Eigen::Index i = 0; i < q.omega_rad_per_s.size(); ++i)
        direct += 2.0 * dir.weight * q.weight_m2(i) * mean_drift_coefficients(t, q.omega_rad_per_s(i), beta);
      direct += 2.0 * dir.weight * q.tail_m0_m2 * mean_drift_coefficients(t, q.tail_start_rad_per_s, beta);
    }
    const MeanDriftResult r = integral.load(yaw);
    for (int i : {0, 1, 5}) EXPECT_REL_NEAR(r.load_b(i), direct(i), kRoundOffRelTol) << yaw_deg << " deg, DOF " << i;
    // The one-call form is the same.
    in.hull_yaw_rad = yaw;
    EXPECT_EQ(mean_wave_drift_load(t, in).load_g, r.load_g);
  }
}

TEST(MeanWaveDrift, ReportsTheVarianceOutsideTheTableAndHoldsTheEnds) {
  // PM cumulative distribution: int_0^w S dw / m0 = exp(-1.25 (wp/w)^4).
  const WaveSpectrum pm = make_pierson_moskowitz_spectrum(4.0, 8.0);
  const double wp = pm.peak_rad_per_s();
  MeanDriftTable t;
  t.omega_rad_per_s = {0.7, 1.2};  // straddles wp = 0.785 rad/s
  t.headings_rad = {0.0};
  t.present[0] = true;
  t.coefficient[0] = Eigen::MatrixXd(2, 1);
  t.coefficient[0] << 1000.0, 3000.0;
  MeanDriftInput in;
  in.spectrum = pm;
  const auto r = mean_wave_drift_load(t, in);
  const double below = std::exp(-1.25 * std::pow(wp / 0.7, 4));
  const double above = 1.0 - std::exp(-1.25 * std::pow(wp / 1.2, 4));
  EXPECT_NEAR(r.variance_fraction_below_table, below, kVarianceShareAbsTol);
  EXPECT_NEAR(r.variance_fraction_above_table, above, kVarianceShareAbsTol);
  // Held ends: the drift lies between 2 m0 D(first) and 2 m0 D(last).
  EXPECT_GT(r.load_b(0), 2.0 * r.m0_m2 * 1000.0);
  EXPECT_LT(r.load_b(0), 2.0 * r.m0_m2 * 3000.0);
  // Single-heading table: only that heading; anything else is refused.
  in.wave_heading_rad = 10.0 * kDeg;
  EXPECT_THROW(mean_wave_drift_load(t, in), std::invalid_argument);
  in.hull_yaw_rad = 10.0 * kDeg;  // relative heading back to 0
  EXPECT_NO_THROW(mean_wave_drift_load(t, in));
}

TEST(MeanWaveDrift, InterpolatesInFrequencyAndHeading) {
  MeanDriftTable t;
  t.omega_rad_per_s = {0.5, 1.0};
  t.headings_rad = {0.0, 30.0 * kDeg};  // half-circle style table: no wrap
  t.present[0] = true;
  t.coefficient[0] = Eigen::MatrixXd(2, 2);
  t.coefficient[0] << 100.0, 200.0,  // w = 0.5
      300.0, 400.0;                  // w = 1.0
  // w = 0.75, beta = 15 deg: bilinear mean 250.
  EXPECT_REL_NEAR(mean_drift_coefficients(t, 0.75, 15.0 * kDeg)(0), 250.0, kRoundOffRelTol);
  // Held ends in frequency.
  EXPECT_REL_NEAR(mean_drift_coefficients(t, 3.0, 0.0)(0), 300.0, kRoundOffRelTol);
  EXPECT_REL_NEAR(mean_drift_coefficients(t, 0.1, 30.0 * kDeg)(0), 200.0, kRoundOffRelTol);
  // Outside the heading range of a table that does not cover the circle.
  EXPECT_THROW(mean_drift_coefficients(t, 0.75, 90.0 * kDeg), std::invalid_argument);
}

TEST(WamitQtf12d, MeanDriftDiagonalOfTheOc4Semi) {
  const double rho = 1025.0;
  const double g = 9.80665;
  const MeanDriftTable t = read_wamit_12d_mean_drift(kSemi12d, rho, g, 1.0);
  // 56 periods from 2.0944 s to 25.133 s, one heading (0 deg), all six DOFs.
  ASSERT_EQ(t.omega_rad_per_s.size(), 56u);
  ASSERT_EQ(t.headings_rad.size(), 1u);
  EXPECT_EQ(t.headings_rad[0], 0.0);
  for (bool p : t.present) EXPECT_TRUE(p);
  EXPECT_REL_NEAR(t.omega_rad_per_s.front(), 2.0 * kPi / 25.133, kRoundOffRelTol);
  EXPECT_REL_NEAR(t.omega_rad_per_s.back(), 2.0 * kPi / 2.0944, kRoundOffRelTol);
  const auto row_of = [&](double period_s) {
    for (std::size_t k = 0; k < t.omega_rad_per_s.size(); ++k) {
      if (std::abs(t.omega_rad_per_s[k] - 2.0 * kPi / period_s) < kFrequencyMatch_rad_per_s) {
        return static_cast<Eigen::Index>(k);
      }
    }
    ADD_FAILURE() << "period " << period_s << " s not in the table";
    return Eigen::Index{0};
  };
  // Line 4411: "0.62832E+01 0.62832E+01 0.0 0.0 1 3.12197E+00 ... RE 3.12197E+00":
  // surge force, k = 1: D = rho g ULEN RE = 1025 x 9.80665 x 1 x 3.12197 N/m^2.
  EXPECT_REL_NEAR(t.coefficient[0](row_of(6.2832), 0), 1025.0 * 9.80665 * 1.0 * 3.12197, kRoundOffRelTol);
  // Line 4413: same period, I = 5 (pitch moment), RE 1.30159E+01, k = 2:
  // D = rho g ULEN^2 RE = 1025 x 9.80665 x 1^2 x 13.0159 N m/m^2.
  EXPECT_REL_NEAR(t.coefficient[4](row_of(6.2832), 0), 1025.0 * 9.80665 * 1.0 * 13.0159, kRoundOffRelTol);
  // Line 1621: PER 12.566 s, I = 1, RE -6.68055E-02 (a negative surge drift in
  // the long-wave range, as printed).
  EXPECT_REL_NEAR(t.coefficient[0](row_of(12.566), 0), 1025.0 * 9.80665 * -6.68055e-2, kRoundOffRelTol);
  // ULEN scaling: forces ~ ULEN, moments ~ ULEN^2.
  const MeanDriftTable t2 = read_wamit_12d_mean_drift(kSemi12d, rho, g, 2.0);
  EXPECT_REL_NEAR(t2.coefficient[0](row_of(6.2832), 0), 2.0 * t.coefficient[0](row_of(6.2832), 0), kRoundOffRelTol);
  EXPECT_REL_NEAR(t2.coefficient[4](row_of(6.2832), 0), 4.0 * t.coefficient[4](row_of(6.2832), 0), kRoundOffRelTol);
}

std::string format_error_of(const std::string& text) {
  std::istringstream in(text);
  try {
    parse_wamit_12d_mean_drift(in, "bad.12d", 1025.0, 9.80665, 1.0);
  } catch (const FileFormatError& e) {
    return e.what();
  }
  return "no FileFormatError";
}

TEST(WamitQtf12d, MalformedFilesNameFileAndLine) {
  const std::string good =
      "  10.0 10.0 0.0 0.0 1 2.0 0.0 2.0 0.0\n"
      "  10.0  8.0 0.0 0.0 1 1.0 9.0 0.9 0.1\n"
      "   8.0  8.0 0.0 0.0 1 3.0 0.0 3.0 0.0\n";
  {
    std::istringstream in("NEMOH Numeric Output -- title line\n" + good);
    const auto t = parse_wamit_12d_mean_drift(in, "ok.12d", 1000.0, 10.0, 1.0);
    ASSERT_EQ(t.omega_rad_per_s.size(), 2u);
    EXPECT_REL_NEAR(t.coefficient[0](0, 0), 1000.0 * 10.0 * 2.0, kRoundOffRelTol);  // T = 10 s
    EXPECT_REL_NEAR(t.coefficient[0](1, 0), 1000.0 * 10.0 * 3.0, kRoundOffRelTol);  // T = 8 s
    EXPECT_FALSE(t.present[1]);
  }
  EXPECT_NE(format_error_of(good + "  8.0 8.0 0.0 0.0 1 3.0 0.0 abc 0.0\n").find("bad.12d:4:"), std::string::npos);
  EXPECT_NE(format_error_of(good + "  8.0 8.0 0.0\n").find("bad.12d:4: expected 9 fields"), std::string::npos);
  EXPECT_NE(format_error_of(good + "  8.0 8.0 0.0 0.0 7 3.0 0.0 3.0 0.0\n").find("bad.12d:4:"), std::string::npos);
  // A DOF given at one period only: incomplete diagonal (whole-file problem, line 0).
  EXPECT_NE(format_error_of(good + "  8.0 8.0 0.0 0.0 2 3.0 0.0 3.0 0.0\n")
                .find("bad.12d: incomplete mean drift diagonal: I = 2"),
            std::string::npos);
  // Conflicting repeat of a diagonal entry.
  EXPECT_NE(format_error_of(good + "  8.0 8.0 0.0 0.0 1 3.5 0.0 3.5 0.0\n").find("bad.12d:4:"), std::string::npos);
  EXPECT_NE(format_error_of("").find("no diagonal"), std::string::npos);
  EXPECT_THROW(read_wamit_12d_mean_drift("/nonexistent/x.12d", 1025.0, 9.80665, 1.0), FileFormatError);
}

}  // namespace
}  // namespace spiral::engine
