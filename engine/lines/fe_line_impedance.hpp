#pragma once
// The dynamic stiffness of a dynamic FE line at its top end (end B): the
// force the line puts on its support for a small harmonic motion of that
// end about a static state, in the frequency domain.
//
// The line's equations (fe_line_dynamics.hpp) linearized about the static
// state q0 (at rest, v = 0): with M the mass (structural + added), C = ∂G/∂v
// (the drag on the velocity relative to the current, axial and seabed
// damping) and K = ∂G/∂q (the static tangent and the drag's dependence on
// the line's direction), G the net nodal force, a motion Q e^{iωt} obeys
// D(ω) Q = δG with D = K + iω C + ω² M. End A is held, end B moves by X;
// the free DOFs carry no net force, so the force on the support changes by
//   δF_B = (D_BB − D_Bf D_ff⁻¹ D_fB) X = −K_dyn(ω) X,
// and K_dyn(0) is the line's condensed static end stiffness (the FE statics'
// with the current drag). Re K_dyn(ω) is the line's stiffness at ω, Im
// K_dyn(ω) / ω its damping. A line restrained by a strong current is not
// quasi-static at low frequency: its current-loaded shape relaxes through
// the water with a time constant of the order of the surge period, so
// Re K_dyn grows with ω (docs/decisions/enhanced-sc-accuracy.md).
//
// The drag is linearized about the current (the slope of the steady drag,
// the line at rest) or, given the velocity covariance of end B's motion
// (its low- and wave-frequency motion together), stochastically about it:
// the expected slope of the normal drag |w| w over the Gaussian normal
// relative velocity at each Gauss point, the line following end B
// quasi-statically (stochastic_drag.hpp). A line swept by the hull's wave-
// frequency motion damps a slow motion more than the current alone does —
// in a mild current (OC4: 0.5 m/s, the fairleads' WF velocity std ~1 m/s)
// several times more.
// Seabed friction, regularized at rest, would enter as a stiff dashpot: it
// is left out (the caller gives an environment without friction for lines
// with a laid part).
//
// Errors: SolverError for invalid input (as FeLineDynamics) or a singular
// system.

#include <Eigen/Core>
#include <complex>
#include <span>
#include <vector>

#include "engine/lines/fe_line_dynamics.hpp"

namespace spiral::engine {

using Matrix3cd = Eigen::Matrix<std::complex<double>, 3, 3>;

/// K_dyn(ω) (N/m, complex; global axes) of `model` about the static solution
/// `state` (end B at its last node) in `environment`, at each ω (rad/s, >= 0);
/// the drag linearized on end B's motion of velocity covariance
/// `end_B_velocity_covariance` ((m/s)², global; zero: about the current).
std::vector<Matrix3cd> end_B_dynamic_stiffness(
    const FeLineModel& model, const FeDynamicEnvironment& environment, const FeStaticsResult& state,
    std::span<const double> omegas_rad_per_s,
    const Eigen::Matrix3d& end_B_velocity_covariance = Eigen::Matrix3d::Zero());

}  // namespace spiral::engine
