// Mean drift at headings the data do not hold (engine/hull/mean_drift_headings):
// the images under the hull's symmetry are the data turned and mirrored
// exactly; the loads do not interpolate across gaps the images open; a
// table that is not symmetric as declared is refused; the wave-frame fill
// reproduces an axisymmetric hull's drift at every heading and reaches no
// farther than it is allowed; and on the OC4 semi's .12d (heading 0 only) the
// D3 images at 120 and 240 deg are the 0 deg force turned.
#include "engine/hull/mean_drift_headings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/common/table_range_error.hpp"
#include "engine/hull/wamit_12d.hpp"

namespace spiral::engine {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// Rotations and sums of exact inputs: round-off only.
constexpr double kRoundOff = 1e-12;

/// Surge 10 + w, pitch 3, heave 2 at the given headings: a drift along the
/// waves, turned with each heading (an axisymmetric hull), at two frequencies.
MeanDriftTable axisymmetric_table(const std::vector<double>& headings_deg) {
  MeanDriftTable t;
  t.omega_rad_per_s = {0.5, 1.0};
  for (std::size_t i = 0; i < 6; ++i) {
    t.coefficient[i] = Eigen::MatrixXd::Zero(2, static_cast<Eigen::Index>(headings_deg.size()));
    t.present[i] = true;
  }
  for (std::size_t j = 0; j < headings_deg.size(); ++j) {
    const double b = headings_deg[j] * kDeg;
    t.headings_rad.push_back(b);
    for (Eigen::Index k = 0; k < 2; ++k) {
      const double along = 10.0 + t.omega_rad_per_s[static_cast<std::size_t>(k)];
      const auto col = static_cast<Eigen::Index>(j);
      t.coefficient[0](k, col) = along * std::cos(b);
      t.coefficient[1](k, col) = along * std::sin(b);
      t.coefficient[2](k, col) = 2.0;
      // A pitch moment about the axis across the waves: (−sin b, cos b) × 3.
      t.coefficient[3](k, col) = -3.0 * std::sin(b);
      t.coefficient[4](k, col) = 3.0 * std::cos(b);
    }
  }
  return t;
}

Vector6d axisymmetric_at(double heading_rad, double omega) {
  const double along = 10.0 + omega;
  Vector6d d;
  d << along * std::cos(heading_rad), along * std::sin(heading_rad), 2.0, -3.0 * std::sin(heading_rad),
      3.0 * std::cos(heading_rad), 0.0;
  return d;
}

TEST(MeanDriftSymmetry, ThreeFoldWithMirrorTurnsTheZeroDegreeDataTo120And240) {
  const MeanDriftTable d3 = with_symmetry_images(axisymmetric_table({0.0}), {3, true});
  ASSERT_EQ(d3.headings_rad.size(), 3u);
  EXPECT_NEAR(d3.headings_rad[1], 120.0 * kDeg, kRoundOff);
  EXPECT_NEAR(d3.headings_rad[2], 240.0 * kDeg, kRoundOff);
  for (const double h : {0.0, 120.0, 240.0})
    for (const double w : {0.5, 1.0})
      EXPECT_LT((mean_drift_coefficients(d3, w, h * kDeg) - axisymmetric_at(h * kDeg, w)).norm(), kRoundOff) << h;
  // Between the images the table does not interpolate (its data had no gap),
  // except within the heading rule's 0.5 deg hold.
  EXPECT_THROW(mean_drift_coefficients(d3, 0.5, 45.0 * kDeg), TableRangeError);
  EXPECT_LT((mean_drift_coefficients(d3, 0.5, 120.3 * kDeg) - axisymmetric_at(120.0 * kDeg, 0.5)).norm(), kRoundOff);
}

TEST(MeanDriftSymmetry, MirrorMapsAHeadingToItsNegativeWithSwayRollAndYawReversed) {
  MeanDriftTable t = axisymmetric_table({30.0});
  t.coefficient[5].setConstant(0.7);  // a yaw moment at 30 deg
  const MeanDriftTable m = with_symmetry_images(t, {1, true});
  ASSERT_EQ(m.headings_rad.size(), 2u);
  EXPECT_NEAR(m.headings_rad[1], 330.0 * kDeg, kRoundOff);
  const Vector6d at30 = mean_drift_coefficients(m, 1.0, 30.0 * kDeg);
  const Vector6d at330 = mean_drift_coefficients(m, 1.0, 330.0 * kDeg);
  Vector6d expected = at30;
  expected(1) = -at30(1);
  expected(3) = -at30(3);
  expected(5) = -at30(5);
  EXPECT_LT((at330 - expected).norm(), kRoundOff);
}

TEST(MeanDriftSymmetry, AnImageThatContradictsTheDataIsRefused) {
  // A sway force at 0 deg cannot be: the mirror y -> -y maps 0 deg onto itself.
  MeanDriftTable t = axisymmetric_table({0.0});
  t.coefficient[1].setConstant(0.5);  // 4.5 % of the largest force coefficient
  try {
    with_symmetry_images(t, {3, true});
    FAIL() << "an asymmetric table was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("not symmetric as declared"), std::string::npos) << what;
    EXPECT_NE(what.find("heading 0 deg DOF 2"), std::string::npos) << what;
  }
  // Without the mirror the same data are a consistent C3 table.
  EXPECT_EQ(with_symmetry_images(t, {3, false}).headings_rad.size(), 3u);
  EXPECT_THROW(with_symmetry_images(t, {0, false}), std::invalid_argument);
}

TEST(MeanDriftWaveFrameFill, ReproducesAnAxisymmetricHullAtEveryHeading) {
  const MeanDriftTable filled =
      filled_in_wave_frame(with_symmetry_images(axisymmetric_table({0.0}), {3, true}), {120.0 * kDeg, 5.0 * kDeg});
  EXPECT_EQ(filled.headings_rad.size(), 72u);
  EXPECT_NEAR(filled.max_interpolation_gap_rad, 5.0 * kDeg, kRoundOff);
  double worst = 0.0;
  for (double h = 0.0; h < 360.0; h += 0.25) {
    const Vector6d d = mean_drift_coefficients(filled, 1.0, h * kDeg);
    const Vector6d exact = axisymmetric_at(h * kDeg, 1.0);
    worst = std::max(worst, (d - exact).norm() / exact.norm());
    // On a filled heading the fill is exact (the wave-frame values are equal).
    if (std::fmod(h, 5.0) == 0.0) {
      EXPECT_LT((d - exact).norm(), 1e-11) << h;
    }
  }
  // Between filled headings the body-frame interpolation of a turning vector:
  // at most 1 - cos(2.5 deg) of its size.
  EXPECT_LT(worst, 1.0 - std::cos(2.5 * kDeg));
  EXPECT_GT(worst, 0.1 * (1.0 - std::cos(2.5 * kDeg)));
}

TEST(MeanDriftWaveFrameFill, FillsOnlyTheGapsItMaySpan) {
  // Data at 0 and 90 deg (a 90 deg gap and a 270 deg one back round): a span
  // of 100 deg fills the first; beyond 90 deg the table ends as it did.
  const MeanDriftTable t = axisymmetric_table({0.0, 90.0});
  const MeanDriftTable filled = filled_in_wave_frame(t, {100.0 * kDeg, 5.0 * kDeg});
  EXPECT_EQ(filled.headings_rad.size(), 19u);
  EXPECT_LT((mean_drift_coefficients(filled, 0.5, 45.0 * kDeg) - axisymmetric_at(45.0 * kDeg, 0.5)).norm(), 1e-11);
  EXPECT_THROW(mean_drift_coefficients(filled, 0.5, 180.0 * kDeg), TableRangeError);
  // A single heading held around the whole circle: the axisymmetric assumption.
  const MeanDriftTable held = filled_in_wave_frame(axisymmetric_table({0.0}), {360.0 * kDeg, 5.0 * kDeg});
  EXPECT_LT((mean_drift_coefficients(held, 1.0, 200.0 * kDeg) - axisymmetric_at(200.0 * kDeg, 1.0)).norm(), 1e-11);
  EXPECT_THROW(filled_in_wave_frame(t, {0.0, 5.0 * kDeg}), std::invalid_argument);
}

TEST(MeanDriftSymmetry, Oc4SemiImagesAreTheZeroDegreeForceTurned) {
  // marin_semi.12d holds heading 0 only; the OC4 hull (columns at 60, 180,
  // 300 deg) is D3 with the x-z plane a mirror. Its sway at 0 deg is WAMIT
  // round-off (1e-5 of surge), well inside the 1e-3 consistency tolerance.
  const MeanDriftTable data =
      read_wamit_12d_mean_drift(SPIRAL_SCENARIO_DATA_DIR "/hydro/oc4-semi/marin_semi.12d", 1025.0, 9.80665, 1.0);
  const MeanDriftTable d3 = with_symmetry_images(data, {3, true});
  ASSERT_EQ(d3.headings_rad.size(), 3u);
  for (const double w : {0.3, 0.6, 1.0}) {
    const Vector6d at0 = mean_drift_coefficients(data, w, 0.0);
    const Vector6d at120 = mean_drift_coefficients(d3, w, 120.0 * kDeg);
    EXPECT_NEAR(at120(0), at0(0) * std::cos(120.0 * kDeg) - at0(1) * std::sin(120.0 * kDeg),
                kRoundOff * std::abs(at0(0)));
    EXPECT_NEAR(at120(1), at0(0) * std::sin(120.0 * kDeg) + at0(1) * std::cos(120.0 * kDeg),
                kRoundOff * std::abs(at0(0)));
    EXPECT_EQ(at120(2), at0(2));
  }
}

}  // namespace
}  // namespace spiral::engine
