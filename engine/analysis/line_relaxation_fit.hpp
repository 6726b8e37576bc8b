#pragma once
// A time-domain form of the lines' low-frequency dynamic stiffness for the
// hull's equations: K_dyn(ω) − K_dyn(0) (6×6, the lines' end impedances
// mapped to the hull, engine/lines/fe_line_impedance.hpp) fitted over a band
// of frequencies by
//   iω B − ω² A + Σ_j Δ_j iωτ_j / (1 + iωτ_j),
// a dashpot B, an added mass A and P relaxations (LineRelaxation in hull_dynamics.hpp), the
// time constants τ_j chosen on a logarithmic grid (1 s to 3000 s, 40
// values; for P = 2 every pair a factor 2.3 or more apart) and B, A, Δ_j by
// linear least squares for each choice, each entry of the 6×6 matrices
// apart, every frequency weighted by the caller (1 / ‖K_dyn(ω)‖: relative).
// B, A and Δ_j are made symmetric positive semi-definite (negative
// eigenvalues set to zero: a passive model whatever the data), and the
// choice kept is the one whose passive model has the least residual.
// The same form as a rational fit of a radiation kernel (e.g. Perez & Fossen,
// Ocean Eng. 2008) with real poles, which a current-restrained line's
// relaxation has.
//
// Errors: std::invalid_argument for fewer than 2 frequencies, lengths that
// differ, a frequency <= 0, or P outside 1..2.

#include <complex>
#include <span>
#include <vector>

#include "engine/analysis/hull_dynamics.hpp"

namespace spiral::engine {

using Matrix6cd = Eigen::Matrix<std::complex<double>, 6, 6>;

struct LineRelaxationFit {
  Matrix6d damping = Matrix6d::Zero();      ///< B, N·s/m …
  Matrix6d added_mass = Matrix6d::Zero();   ///< A, kg …
  std::vector<LineRelaxation> relaxations;  ///< P of them, τ ascending
  /// ‖model − data‖ / ‖data‖ over the band, each frequency weighted as fitted.
  double relative_residual = 0.0;
};

/// `dynamic_minus_static[k]` = K_dyn(ω_k) − K_dyn(0) at `omegas_rad_per_s[k]` (> 0).
LineRelaxationFit fit_line_relaxation(std::span<const double> omegas_rad_per_s,
                                      std::span<const Matrix6cd> dynamic_minus_static, std::span<const double> weights,
                                      int poles);

}  // namespace spiral::engine
