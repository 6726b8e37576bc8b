#pragma once
// Slowly varying (difference-frequency) wave drift force by Newman's
// approximation from the mean drift coefficients (J. N. Newman, "Second-order,
// slowly-varying forces on vessels in irregular waves", Proc. Int. Symp. on
// Dynamics of Marine Vehicles and Structures in Waves, London 1974; Faltinsen
// 1990 §5.4). The off-diagonal QTF T(w_j, w_k) is replaced by the diagonal,
// T_jk ~ sgn(D) sqrt(|D(w_j)| |D(w_k)|), so that for a realization
// eta = sum a_k cos(theta_k):
//
//   F_i(t) = 2 [sum_j a_j s_ij sqrt|D_i(w_j)| cos theta_j] [sum_k a_k sqrt|D_i(w_k)| cos theta_k]
//
// (s_ij = sign of D_i(w_j), theta_k = w_k t + phi_k − k_k·x0 at the hull
// reference point). This is 2[sum a_k sqrt(D_k) cos theta_k]^2 when D keeps its
// sign, and for any sign pattern its mean is sum a_k^2 D_ik = 2 int S D dw, the
// mean drift load (mean_environmental_loads.hpp) - the sum-frequency part of
// the product (twice the wave frequencies) is kept: it is far above the
// low-frequency natural frequencies and the hull filters it. D_i is taken at
// each component's own heading relative to the (mean) hull yaw psi; the body
// loads are rotated to global axes by psi. Valid when the low-frequency
// natural periods are long against the wave periods (Newman's condition;
// DNV-RP-C205 §7.4, recalled): moored semis and FPSOs in surge, sway, yaw.
#include <vector>

#include "engine/common/eigen_types.hpp"
#include "engine/environment/wave_realization.hpp"
#include "engine/hull/mean_environmental_loads.hpp"

namespace spiral::engine {

struct SlowDriftPlacement {
  double x_m = 0.0;      ///< hull reference point, global
  double y_m = 0.0;
  double yaw_rad = 0.0;  ///< mean hull yaw
};

/// Precomputed per-component weights; evaluate with slow_drift_force.
struct SlowDriftSeries {
  std::vector<double> omega_rad_per_s;
  std::vector<double> phase_rad;                     ///< phi_k − k·x0
  Eigen::Matrix<double, 6, Eigen::Dynamic> weight;   ///< a_k sqrt|D_ik|, body frame
  Eigen::Matrix<double, 6, Eigen::Dynamic> signed_weight;  ///< a_k sgn(D_ik) sqrt|D_ik|
  double yaw_rad = 0.0;
  Vector6d mean_force_b = Vector6d::Zero();  ///< sum a_k^2 D_ik, body frame, N, N·m
};

/// Throws std::invalid_argument for a heading outside the table (heading rule
/// of mean_environmental_loads.hpp).
SlowDriftSeries prepare_slow_drift(const WaveRealization& sea, const MeanDriftTable& table,
                                   const SlowDriftPlacement& placement);

/// F(t), global frame, N, N·m. Allocation-free; cost 2 x components cosines.
Vector6d slow_drift_force(const SlowDriftSeries& series, double t_s);

}  // namespace spiral::engine
