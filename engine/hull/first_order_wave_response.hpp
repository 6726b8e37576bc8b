#pragma once
// First-order (wave-frequency) hull loads and motions in a realised sea:
// the time series of the WAMIT transfer functions (excitation .3, motion RAO .4)
// driven by the components of a WaveRealization.
//
//   F_i(t) = sum_k Re{ X_i(w_k, b_k - psi) A_k e^{i w_k t} },
//   A_k    = a_k e^{i (phi_k - k_k (x0 cos b_k + y0 sin b_k))}
// A_k is the complex amplitude of the incident wave of component k at the hull
// reference point (x0, y0), so that this is exactly WAMIT's definition
// F = Re{X A e^{iwt}} (phase = lead over the wave elevation at the body origin,
// engine/hull/wamit_3.hpp) summed over components: with a single component
// F_i(t) = |X_i| a cos(w t + phi + arg X_i) at the origin.
// psi is the hull's (mean) yaw: the table is entered with the body-relative
// heading b_k - psi and the body-frame result is rotated to the global frame
// (force and moment 3-vectors by Rz(psi); for motions the small-rotation vector
// likewise). Yaw is held fixed: no encounter-frequency or large-yaw effects.
//
// Frequencies outside the table use its end values (wamit_3.hpp transfer_at);
// `variance_share_outside_table` reports how much of the sea's variance that
// concerns. Headings outside the table throw std::invalid_argument (from
// transfer_at) at preparation. Components of zero amplitude are skipped.

#include <Eigen/Core>
#include <vector>

#include "engine/common/eigen_types.hpp"
#include "engine/environment/wave_realization.hpp"
#include "engine/hull/wamit_3.hpp"

namespace spiral::engine {

struct HullWavePlacement {
  double x_m = 0.0;      ///< hull reference point (WAMIT body origin), global x
  double y_m = 0.0;      ///< global y
  double yaw_rad = 0.0;  ///< hull yaw, CCW about +z
};

/// Precomputed complex coefficients; evaluate with evaluate_first_order.
struct FirstOrderWaveSeries {
  TransferQuantity quantity = TransferQuantity::excitation;
  std::vector<double> omega_rad_per_s;
  std::vector<Vector6cd> coefficient;         ///< C_k, global frame: value(t) = sum Re{C_k e^{i w_k t}}
  double variance_share_outside_table = 0.0;  ///< of sum a_k^2/2, components with w outside the table
};

FirstOrderWaveSeries prepare_first_order_series(const WaveRealization& sea, const WaveTransferTable& table,
                                                const HullWavePlacement& placement);

/// Load (N, N m) or motion (m, rad) 6-vector at time t, global frame. Allocation-free.
Vector6d evaluate_first_order(const FirstOrderWaveSeries& series, double t_s);

/// 6 x n matrix, one column per time.
Eigen::Matrix<double, 6, Eigen::Dynamic> evaluate_first_order_many(const FirstOrderWaveSeries& series,
                                                                   const Eigen::VectorXd& times_s);

}  // namespace spiral::engine
