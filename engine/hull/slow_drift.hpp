#pragma once
// Slowly varying (difference-frequency) wave drift force by Newman's
// approximation from the mean drift coefficients (J. N. Newman, "Second-order,
// slowly-varying forces on vessels in irregular waves", Proc. Int. Symp. on
// Dynamics of Marine Vehicles and Structures in Waves, London 1974; Faltinsen
// 1990 §5.4). The off-diagonal difference-frequency QTF is replaced by the
// diagonal, T_jk ~ s_j sqrt(|D(w_j)| |D(w_k)|), s_j = sgn D(w_j), and only the
// difference-frequency terms are kept:
//
//   F_i(t) = sum_j sum_k a_j a_k T_jk cos(theta_j − theta_k)
//          = Re{ Z_s(t) conj(Z(t)) },
//   Z(t)   = sum_k a_k sqrt|D_i(w_k)| e^{i theta_k},   Z_s: the same with s_k,
//
// theta_k = w_k t + phi_k − k_k·x0 at the hull reference point. When D keeps
// its sign this is |Z|², the slowly varying part of 2[sum a_k sqrt(D_k)
// cos theta_k]² (the squared form also holds sum-frequency terms at twice the
// wave frequencies, which the diagonal approximation does not describe and the
// low-frequency hull filters out; dropping them keeps the integrator's step
// long). For any sign pattern the mean is sum a_k² D_ik = 2 int S D dw, the
// mean drift load (mean_environmental_loads.hpp). D_i is taken at each
// component's own heading relative to the (mean) hull yaw psi; the body loads
// are rotated to global axes by psi. Valid when the low-frequency natural
// periods are long against the wave periods (Newman's condition): moored
// semis and FPSOs in surge, sway and yaw.
#include <vector>

#include "engine/common/eigen_types.hpp"
#include "engine/environment/wave_realization.hpp"
#include "engine/hull/mean_environmental_loads.hpp"

namespace spiral::engine {

struct SlowDriftPlacement {
  double x_m = 0.0;  ///< hull reference point, global
  double y_m = 0.0;
  double yaw_rad = 0.0;  ///< mean hull yaw
};

/// Precomputed per-component weights; evaluate with slow_drift_force.
struct SlowDriftSeries {
  std::vector<double> omega_rad_per_s;
  std::vector<double> phase_rad;                           ///< phi_k − k·x0
  Eigen::Matrix<double, 6, Eigen::Dynamic> weight;         ///< a_k sqrt|D_ik|, body frame
  Eigen::Matrix<double, 6, Eigen::Dynamic> signed_weight;  ///< a_k sgn(D_ik) sqrt|D_ik|
  double yaw_rad = 0.0;
  Vector6d mean_force_b = Vector6d::Zero();  ///< sum a_k^2 D_ik, body frame, N, N·m
};

/// Throws std::invalid_argument for a heading outside the table (heading rule
/// of mean_environmental_loads.hpp).
SlowDriftSeries prepare_slow_drift(const WaveRealization& sea, const MeanDriftTable& table,
                                   const SlowDriftPlacement& placement);

/// F(t), global frame, N, N·m. Allocation-free; cost: one cos and sin per component.
Vector6d slow_drift_force(const SlowDriftSeries& series, double t_s);

}  // namespace spiral::engine
