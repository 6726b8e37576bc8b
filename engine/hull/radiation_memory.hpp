#pragma once
// Radiation memory of a hull from its frequency-domain added mass and damping
// (a WAMIT .1 table): the infinite-frequency added mass A(inf) and the
// retardation kernel K(t) of Cummins' equation (Cummins 1962),
//
//   (M + A(inf)) q'' + int_0^t K(t - s) q'(s) ds + ... = F,
//   K(t) = (2/pi) int_0^inf B(w) cos(w t) dw,
//
// with A(inf) from the file's zero-period row when it has one, else from
// Ogilvie's relation (Ogilvie 1964)
//
//   A(w) = A(inf) - (1/w) int_0^inf K(t) sin(w t) dt,
//
// evaluated with the kernel as the simulation uses it (truncated at t_max) and
// averaged over the tabulated frequencies with w t_max >= 2 pi (at least one
// period of sin(w t) inside the kernel; lower frequencies amplify the
// truncation by 1/w). Then the hull's effective added mass at w in the time
// domain, A(inf) + (1/w) int_0^t_max K sin, is the least-squares match of the
// table over that band; the spread is returned as a diagnostic.
//
// The data must allow it (else RadiationDataError, a std::invalid_argument,
// saying what is missing):
//   * B(w) must have decayed at both ends of the table, in every diagonal DOF
//     with damping: B_ii at the first and last frequency <= tail_ratio_limit
//     x max_w B_ii. The kernel takes B = 0 beyond the last frequency and B
//     linear from B(0) = 0 (a floating body radiates no waves at zero
//     frequency) to the first one; a table that stops where B is still large
//     (a HAMS run to 6 rad/s of a small cylinder, whose damping peaks at 5.2
//     rad/s) would put a step into the transform and ringing into K(t).
//   * The frequency spacing must resolve the kernel duration: the trapezoid
//     cosine sum over a grid of spacing dw is periodic in t with 2 pi / dw, so
//     t_max <= pi / max(dw) (the kernel sees no alias of itself).
//   * At least 8 frequencies.
//
// Units: SI as in HydroCoefficients (kg, kg m, kg m^2; damping N s/m ...);
// the kernel in N/(m/s)/s (translations) etc.

#include <span>
#include <stdexcept>

#include "engine/hull/retardation_kernel.hpp"
#include "engine/hull/wamit_1.hpp"

namespace spiral::engine {

/// The data cannot give a radiation memory (message says why).
class RadiationDataError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct RadiationMemoryInput {
  double duration_s = 60.0;  ///< t_max of the kernel, > time_step_s (OpenFAST HydroDyn RdtnTMax 60 s)
  double time_step_s = 0.1;  ///< kernel and velocity-history step, > 0
  /// Largest B_ii(w_end) / max_w B_ii accepted at either end of the table;
  /// 5 %: the step at w_max then puts at most ~B(w_max)/(pi t) of ringing into
  /// K(t), a few % of B(w) in the kernel's cosine transform (measured on OC4 in
  /// tests/validation/engine/hull/radiation_memory_test.cpp).
  double tail_ratio_limit = 0.05;
};

struct RadiationMemory {
  RetardationKernel kernel;
  Matrix6d added_mass_infinite = Matrix6d::Zero();
  bool added_mass_infinite_from_file = false;  ///< true: the file's PER = 0 row
  // diagnostics
  /// B_ii(w_end) / max B_ii, the larger of both ends, per DOF (0 without damping).
  Vector6d tail_ratio = Vector6d::Zero();
  /// Ogilvie band: frequencies used for the A(inf) estimate, rad/s.
  double ogilvie_omega_min_rad_per_s = 0.0;
  std::size_t ogilvie_frequencies = 0;
  /// Largest |A(inf) + (1/w) int K sin − A(w)|_ii / |A(inf)|_ii over the band, per DOF.
  Vector6d ogilvie_max_deviation = Vector6d::Zero();
};

/// Builds A(inf) and K(t) from `radiation` (see the header comment). Throws
/// RadiationDataError when the data do not allow it, std::invalid_argument for
/// input out of range.
RadiationMemory make_radiation_memory(const HydroCoefficients& radiation, const RadiationMemoryInput& input);

/// int_0^t_max K(t) cos(w t) dt of the kernel as tabulated (K linear between
/// samples, integrated exactly per interval): should give B(w) back.
Matrix6d kernel_cosine_transform(const RetardationKernel& kernel, double omega_rad_per_s);

/// int_0^t_max K(t) sin(w t) dt, same rule; w > 0.
Matrix6d kernel_sine_transform(const RetardationKernel& kernel, double omega_rad_per_s);

}  // namespace spiral::engine
