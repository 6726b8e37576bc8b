#pragma once
// Equivalent (stochastic) linearization of a line's normal Morison drag.
//
// Per unit length the normal drag is f = k |w| w, k = ½ ρ Cd d, with w the
// normal relative velocity (current minus line). For a Gaussian w the
// least-squares linear replacement of f about its mean is the expected
// Jacobian, E[∂f/∂w] (Atalik & Utku, "Stochastic linearization of
// multi-degree-of-freedom non-linear systems", Earthquake Eng. Struct. Dyn.
// 4, 1976; for one component and zero mean it is Borgman's sqrt(8/π) σ,
// Borgman 1967):
//   D = E[ |w| P_n + w wᵀ / |w| ],  w ~ N(u_n, S_n),
// u_n the normal current, S_n the covariance of the line's normal velocity,
// P_n the projector on the normal plane. D is the damping a small extra
// line velocity meets, per unit k: it carries the current (2U along the
// normal current, U across it, for U ≫ σ), the direction of the motion
// (a line swept in one direction: 2 E|w| along it, E|w| across it) and their
// correlation — which a single scalar σ per node cannot.
//
// The expectation is a two-dimensional quadrature on the principal axes of
// S_n (8 standard deviations each way), Gauss–Legendre (Golub & Welsch 1969
// nodes) on pieces split where the integrand has a kink: |w| is not smooth
// at w = 0, and a rule across the kink converges as a power of the node
// count (Gauss–Hermite, 32 nodes: 1.3 % off on a one-dimensional motion).
// Split, 16 nodes per piece give the closed forms the tests check to 1e-5.

#include <Eigen/Core>

namespace spiral::engine {

/// Gauss–Legendre nodes per piece of each axis of the quadrature.
inline constexpr int kStochasticDragNodes = 16;

/// E[|w| P_n + w wᵀ/|w|] (m/s) for w ~ N(mean_normal_velocity,
/// normal_velocity_covariance) in the plane normal to `unit_tangent`: both are
/// projected on that plane first (a tangential part is ignored). Symmetric,
/// positive semi-definite, zero along the tangent.
Eigen::Matrix3d expected_drag_slope(const Eigen::Vector3d& unit_tangent, const Eigen::Vector3d& mean_normal_velocity,
                                    const Eigen::Matrix3d& normal_velocity_covariance);

}  // namespace spiral::engine
