// The stochastic linearization of the normal drag (engine/lines/stochastic_drag)
// against its closed forms and a Monte Carlo estimate.
#include "engine/lines/stochastic_drag.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace spiral::engine {
namespace {

const Eigen::Vector3d kTangent = Eigen::Vector3d(1.0, 0.0, 2.0).normalized();

/// Two unit vectors spanning the plane normal to kTangent.
Eigen::Vector3d normal_a() { return kTangent.cross(Eigen::Vector3d::UnitY()).normalized(); }
Eigen::Vector3d normal_b() { return kTangent.cross(normal_a()); }

/// E|U + v|, v ~ N(0, sigma²) (the folded normal's mean).
double folded_mean(double U, double sigma) {
  return sigma * std::sqrt(2.0 / std::numbers::pi) * std::exp(-U * U / (2.0 * sigma * sigma)) +
         U * std::erf(U / (sigma * std::numbers::sqrt2));
}

// A line that does not move in a current meets the steady drag's slope:
// d(|u| u)/du = |u| I + u uᵀ/|u|, 2U along the current, U across it, and
// nothing along its own tangent.
TEST(StochasticDrag, ALineAtRestInACurrentMeetsTheSteadySlope) {
  const double U = 1.3;
  const Eigen::Matrix3d D = expected_drag_slope(kTangent, U * normal_a(), Eigen::Matrix3d::Zero());
  EXPECT_NEAR(normal_a().dot(D * normal_a()), 2.0 * U, 1e-14);
  EXPECT_NEAR(normal_b().dot(D * normal_b()), U, 1e-14);
  EXPECT_NEAR((D * kTangent).norm(), 0.0, 1e-14);
}

// Motion in one normal direction, no current: Borgman's sqrt(8/pi) sigma
// along it (2 E|v|) and E|v| = sqrt(2/pi) sigma across it. Tolerance 1e-7:
// the 16-node rule on each side of the kink (measured 2e-10 here, 8e-9 with
// the current below).
TEST(StochasticDrag, OneDirectionOfMotionGivesBorgmanAlongItAndHalfAcross) {
  const double sigma = 0.4;
  const Eigen::Matrix3d S = sigma * sigma * normal_a() * normal_a().transpose();
  const Eigen::Matrix3d D = expected_drag_slope(kTangent, Eigen::Vector3d::Zero(), S);
  EXPECT_NEAR(normal_a().dot(D * normal_a()), std::sqrt(8.0 / std::numbers::pi) * sigma, 1e-7 * sigma);
  EXPECT_NEAR(normal_b().dot(D * normal_b()), std::sqrt(2.0 / std::numbers::pi) * sigma, 1e-7 * sigma);
  EXPECT_NEAR(normal_a().dot(D * normal_b()), 0.0, 1e-12);
}

// Motion along a current of comparable speed: the folded normal's mean,
// 2 E|U + v| along, E|U + v| across.
TEST(StochasticDrag, MotionAlongTheCurrentGivesTheFoldedNormalMean) {
  const double U = 0.7, sigma = 0.5;
  const Eigen::Matrix3d S = sigma * sigma * normal_a() * normal_a().transpose();
  const Eigen::Matrix3d D = expected_drag_slope(kTangent, U * normal_a(), S);
  EXPECT_NEAR(normal_a().dot(D * normal_a()), 2.0 * folded_mean(U, sigma), 1e-7 * U);
  EXPECT_NEAR(normal_b().dot(D * normal_b()), folded_mean(U, sigma), 1e-7 * U);
}

// Isotropic motion in the normal plane, no current: |w| is Rayleigh,
// E|w| = sigma sqrt(pi/2), and E[w wᵀ/|w|] = ½ E|w| I, so D = 1.5 E|w| P_n.
// The quadrature's kink at w = 0 is in the middle of both axes here.
TEST(StochasticDrag, IsotropicMotionGivesThreeHalvesOfTheRayleighMean) {
  const double sigma = 0.9;
  const Eigen::Matrix3d Pn = Eigen::Matrix3d::Identity() - kTangent * kTangent.transpose();
  const Eigen::Matrix3d D = expected_drag_slope(kTangent, Eigen::Vector3d::Zero(), sigma * sigma * Pn);
  const Eigen::Matrix3d exact = 1.5 * sigma * std::sqrt(std::numbers::pi / 2.0) * Pn;
  EXPECT_LE((D - exact).norm(), 1e-5 * exact.norm());
}

// Tangential parts of the current or the motion do not enter; the result is
// symmetric and positive semi-definite.
TEST(StochasticDrag, TangentialPartsAreIgnoredAndTheResultIsSymmetric) {
  const Eigen::Vector3d u = 0.6 * normal_a() - 0.2 * normal_b();
  Eigen::Matrix3d S;
  S << 0.3, 0.1, -0.05, 0.1, 0.2, 0.02, -0.05, 0.02, 0.25;
  const Eigen::Matrix3d Pn = Eigen::Matrix3d::Identity() - kTangent * kTangent.transpose();
  const Eigen::Matrix3d D = expected_drag_slope(kTangent, u, Pn * S * Pn);
  const Eigen::Matrix3d with_tangential = expected_drag_slope(kTangent, u + 2.0 * kTangent, S);
  EXPECT_LE((D - with_tangential).norm(), 1e-13 * D.norm());
  EXPECT_LE((D - D.transpose()).norm(), 1e-14 * D.norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(D);
  EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-14 * D.norm());
}

// A general case — a current at an angle to anisotropic, correlated motion
// whose spread straddles w = 0 — against the mean of a million samples
// (their standard error ≈ 4e-4 of the result; tolerance 2e-3).
TEST(StochasticDrag, AGeneralCaseAgreesWithMonteCarlo) {
  const Eigen::Vector3d u = 0.3 * normal_a() - 0.2 * normal_b();
  const Eigen::Matrix3d L = 0.5 * normal_a() * normal_a().transpose() + 0.3 * normal_b() * normal_a().transpose() +
                            0.25 * normal_b() * normal_b().transpose();  // S = L Lᵀ
  const Eigen::Matrix3d D = expected_drag_slope(kTangent, u, L * L.transpose());
  std::mt19937_64 rng(7);
  std::normal_distribution<double> z;
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  constexpr int samples = 1000000;
  const Eigen::Matrix3d Pn = Eigen::Matrix3d::Identity() - kTangent * kTangent.transpose();
  for (int k = 0; k < samples; ++k) {
    const Eigen::Vector3d w = u + L * Eigen::Vector3d(z(rng), z(rng), z(rng));
    const double speed = w.norm();
    sum += speed * Pn + w * w.transpose() / speed;
  }
  const Eigen::Matrix3d monte_carlo = sum / samples;
  EXPECT_LE((D - monte_carlo).norm(), 2e-3 * monte_carlo.norm()) << D << "\n\n" << monte_carlo;
}

}  // namespace
}  // namespace spiral::engine
