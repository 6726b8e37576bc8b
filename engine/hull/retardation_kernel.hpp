#pragma once
// The radiation-memory (retardation) kernel of Cummins' equation, built from a
// hull's frequency-domain radiation damping. A property of the hull's
// hydrodynamic data, so it lives with them; the time-domain hull equations
// (engine/analysis/hull_dynamics.hpp) convolve it with the velocity history.

#include <span>

#include <Eigen/Core>

#include "engine/common/eigen_types.hpp"

namespace spiral::engine {

/// Radiation-memory kernel of Cummins' equation (Cummins 1962; Ogilvie 1964):
///   K(t) = (2/pi) int_0^inf B(w) cos(w t) dw,
/// tabulated at t_j = j·dt, j = 0..n−1, t_max = (n−1)·dt.
struct RetardationKernel {
  double time_step_s = 0.0;  ///< dt of the table and of the stored velocity history
  Eigen::MatrixXd values;    ///< 36 × n: column j is K(t_j) flattened column-major, N/(m/s)/s …

  Eigen::Index size() const { return values.cols(); }
  double duration_s() const { return time_step_s * static_cast<double>(size() - 1); }
  Matrix6d at_index(Eigen::Index j) const { return Eigen::Map<const Matrix6d>(values.col(j).data()); }
};

/// Builds K(t) from the frequency-domain radiation damping B(w_i) (6×6 each,
/// w strictly increasing, rad/s) by the trapezoidal rule over the given
/// frequencies; B is taken as zero beyond the last frequency (truncation: the
/// table should reach the frequency where B has decayed). Cost: n_t × n_w × 36.
/// Throws std::invalid_argument for fewer than 2 frequencies, unsorted or
/// negative frequencies, non-positive time step or duration.
RetardationKernel make_retardation_kernel(std::span<const double> frequencies_rad_s, std::span<const Matrix6d> damping,
                                          double time_step_s, double duration_s);

}  // namespace spiral::engine
