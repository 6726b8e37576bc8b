#pragma once
// The periods and damping of a free-decay record, by the half-cycle
// logarithmic decrement (the model-basin practice, e.g. ITTC Recommended
// Procedure 7.5-02-07-03.1 on floating offshore platform experiments).
//
// Between two successive extremes x_k, x_{k+1} of opposite sign about the
// final position, a linear oscillator with damping ratio ζ decays by
//   |x_{k+1}| / |x_k| = exp(−π ζ / sqrt(1 − ζ²)),
// so ζ = L / sqrt(π² + L²), L = ln(|x_k| / |x_{k+1}|), and the damped
// period is twice the time between them. For a nonlinear (drag, friction)
// system ζ is the equivalent linear damping at that amplitude, reported
// with the mean amplitude of the half cycle.
//
// Errors: std::invalid_argument for series of different lengths or fewer
// than three samples after the start.

#include <span>
#include <vector>

namespace spiral::engine {

/// One half cycle of a free decay: from one extreme to the next.
struct DecayHalfCycle {
  double start_s = 0.0;        ///< time of the first extreme
  double amplitude = 0.0;      ///< mean of |x_k| and |x_{k+1}| (the record's unit)
  double period_s = 0.0;       ///< damped period, 2 (t_{k+1} − t_k)
  double damping_ratio = 0.0;  ///< ζ, fraction of critical
};

/// Extremes of x − `final_position` after `start_s` (the position the
/// decay returns to, e.g. the static equilibrium), and the half cycles
/// between successive extremes of opposite sign whose amplitude exceeds
/// `smallest_amplitude` (below it the record's noise or a slow drift of the
/// mean position would set the decrement).
std::vector<DecayHalfCycle> free_decay_half_cycles(std::span<const double> time_s, std::span<const double> x,
                                                   double final_position, double start_s, double smallest_amplitude);

}  // namespace spiral::engine
