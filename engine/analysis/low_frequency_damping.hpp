#pragma once
// The hull's low-frequency damping in the horizontal plane, as an equivalent
// linear oscillator per degree of freedom: how much of critical damping the
// model gives its slow-drift resonances.
//
// A moored floater's slow surge, sway and yaw are resonant at periods of
// 60–300 s, where radiation damping has vanished; their response grows as
// 1/sqrt(ζ) under the broad-band slow-drift force (Faltinsen, Sea Loads on
// Ships and Offshore Structures, 1990, ch. 5), so a model with next to no
// damping there — a hull without viscous damping, lines reduced without
// their drag — gives a resonant response that no measurement would show.
// This says so, from the run itself.
//
// Per DOF d, uncoupled from the others (the slow modes of a spread-moored
// hull are nearly so):
//   B_d = −E[∂F_d/∂q̇_d]   over the record's samples, every velocity-dependent
//                          force of the hull's equations at the sampled state
//                          (linear, quadratic and line damping, current and
//                          wind drag on the relative velocity, Morison
//                          members): the stochastic linearization of
//                          Atalik & Utku (1976), which for b |q̇| q̇ gives
//                          sqrt(8/π) σ b;
//   K_d = −E[∂F_d/∂q_d]   likewise (lines, hydrostatics, the current's and
//                          wind's yaw moments);
// plus each line relaxation (Zener element, hull_dynamics.hpp) at the
// natural frequency ω: stiffness Δ (ωτ)²/(1 + (ωτ)²) and damping
// Δ τ/(1 + (ωτ)²); ω = sqrt(K_d / M_d) with M_d = (M + A + A_lines)_dd.
// ζ = B_d / (2 M_d ω). The radiation memory is left out: B(ω) → 0 at these
// periods.

#include <span>
#include <vector>

#include "engine/analysis/hull_dynamics.hpp"

namespace spiral::engine {

/// One DOF's equivalent linear oscillator.
struct DofDamping {
  int dof = 0;                    ///< 0..5 (surge, sway, heave, roll, pitch, yaw)
  double mass = 0.0;              ///< M_d, kg or kg·m²
  double stiffness = 0.0;         ///< K_d, N/m or N·m/rad
  double damping = 0.0;           ///< B_d, N·s/m or N·m·s/rad
  double natural_period_s = 0.0;  ///< 2π/ω; 0 when K_d <= 0 (no restoring)
  double damping_ratio = 0.0;     ///< ζ = B_d / (2 M_d ω); 0 when K_d <= 0
};

/// The equivalent linear oscillator of each of `dofs` over a simulated
/// record (simulate_hull's positions and velocities at its output times),
/// from at most `samples` of its states spread evenly over it.
/// Throws std::invalid_argument on an empty record or a DOF out of range.
std::vector<DofDamping> low_frequency_damping(const HullEquations& equations, const HullTimeSeries& record,
                                              std::span<const int> dofs, int samples = 256);

}  // namespace spiral::engine
