#include "engine/lines/stochastic_drag.hpp"

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <numbers>

namespace spiral::engine {
namespace {

/// The Gaussian beyond this many standard deviations holds < 1e-15.
constexpr double kTruncation = 8.0;

struct GaussLegendreRule {
  std::array<double, kStochasticDragNodes> node{};  ///< on [−1, 1]
  std::array<double, kStochasticDragNodes> weight{};
};

/// Golub & Welsch (Math. Comp. 23, 1969): the Gauss–Legendre nodes are the
/// eigenvalues of the symmetric Jacobi matrix with off-diagonal
/// k / sqrt(4k² − 1), the weights twice the squared first components of
/// its unit eigenvectors.
GaussLegendreRule make_rule() {
  constexpr int n = kStochasticDragNodes;
  Eigen::Matrix<double, n, n> jacobi = Eigen::Matrix<double, n, n>::Zero();
  for (int k = 1; k < n; ++k) jacobi(k, k - 1) = jacobi(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, n, n>> solver(jacobi);
  GaussLegendreRule rule;
  for (int k = 0; k < n; ++k) {
    rule.node[static_cast<std::size_t>(k)] = solver.eigenvalues()(k);
    const double v0 = solver.eigenvectors()(0, k);
    rule.weight[static_cast<std::size_t>(k)] = 2.0 * v0 * v0;
  }
  return rule;
}

const GaussLegendreRule& rule() {
  static const GaussLegendreRule r = make_rule();
  return r;
}

double standard_normal_density(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi); }

/// ∫ f(z) φ(z) dz over [−8, 8] by Gauss–Legendre, the interval split at
/// `kink` when it lies inside (f smooth on either side of it).
template <class F>
Eigen::Matrix2d expectation_over_normal(double kink, F&& f) {
  const GaussLegendreRule& gl = rule();
  std::array<double, 3> bounds{-kTruncation, kink, kTruncation};
  const bool split = kink > -kTruncation && kink < kTruncation;
  if (!split) bounds[1] = kTruncation;
  Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
  for (int piece = 0; piece < (split ? 2 : 1); ++piece) {
    const double lo = bounds[static_cast<std::size_t>(piece)], hi = bounds[static_cast<std::size_t>(piece) + 1];
    const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    for (int k = 0; k < kStochasticDragNodes; ++k) {
      const double z = mid + half * gl.node[static_cast<std::size_t>(k)];
      sum += (gl.weight[static_cast<std::size_t>(k)] * half * standard_normal_density(z)) * f(z);
    }
  }
  return sum;
}

/// |w| I + w wᵀ / |w| in the plane (0 at w = 0, where it is continuous).
Eigen::Matrix2d drag_slope_at(const Eigen::Vector2d& w) {
  const double speed = w.norm();
  if (!(speed > 0.0)) return Eigen::Matrix2d::Zero();
  return speed * Eigen::Matrix2d::Identity() + (w * w.transpose()) / speed;
}

/// E[slope(a + z b)], z ~ N(0, 1): along the line a + z b the slope is
/// smooth except where the line passes closest to w = 0, where it is split.
Eigen::Matrix2d expectation_along(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double bb = b.squaredNorm();
  if (!(bb > 0.0)) return drag_slope_at(a);
  return expectation_over_normal(-a.dot(b) / bb, [&](double z) { return drag_slope_at(a + z * b); });
}

}  // namespace

Eigen::Matrix3d expected_drag_slope(const Eigen::Vector3d& unit_tangent, const Eigen::Vector3d& mean_normal_velocity,
                                    const Eigen::Matrix3d& normal_velocity_covariance) {
  // An orthonormal basis of the normal plane.
  const Eigen::Vector3d& t = unit_tangent;
  Eigen::Index least = 0;
  t.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d e1 = (Eigen::Vector3d::Unit(least) - t(least) * t).normalized();
  Eigen::Matrix<double, 3, 2> plane;
  plane << e1, t.cross(e1);

  const Eigen::Vector2d mean = plane.transpose() * mean_normal_velocity;
  const Eigen::Matrix2d covariance = plane.transpose() * normal_velocity_covariance * plane;
  // Principal axes: the inner integral runs along the major one, the outer
  // across it. Each is split where its integrand has a kink: the inner where
  // its line passes closest to w = 0, the outer where that line passes
  // through it (there the inner result is only C¹). Split so, 16 nodes
  // per piece give the isotropic case to 1e-5.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal(0.5 * (covariance + covariance.transpose()));
  const Eigen::Vector2d sigma = principal.eigenvalues().cwiseMax(0.0).cwiseSqrt();  // ascending
  const Eigen::Vector2d minor_unit = principal.eigenvectors().col(0);
  const Eigen::Vector2d major = sigma(1) * principal.eigenvectors().col(1);
  Eigen::Matrix2d expected;
  if (!(sigma(0) > 0.0)) {
    expected = expectation_along(mean, major);
  } else {
    const Eigen::Vector2d minor = sigma(0) * minor_unit;
    expected = expectation_over_normal(-mean.dot(minor_unit) / sigma(0),
                                       [&](double z) { return expectation_along(mean + z * minor, major); });
  }
  return plane * expected * plane.transpose();
}

}  // namespace spiral::engine
