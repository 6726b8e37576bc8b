#pragma once
// Enhanced semi-coupled (DESIGN.md §1): the mooring lines' damping and added
// mass reduced to 6x6 matrices at the hull reference point. An approximation,
// after the idea of W. C. Webster ("Mooring-induced damping", Ocean
// Engineering 22(6), 1995: the line's drag over its quasi-static motion damps
// the hull) and of the enhanced S-C of Cruces Girón, Corrêa, Jacob et al.
// (Marine Structures 39, 2014), in this form:
//
// 1) Shape derivative. For each catenary line at its equilibrium fairlead
//    position x_f, the quasi-static profile r_j (points at fixed unstretched
//    arc length s_j) is solved at x_f ± h e_i (h = 0.1 m, central
//    differences; the perturbed profiles are read at the same arc lengths by
//    linear interpolation): J_j = d r_j / d x_f (3x3). The line is assumed to move
//    quasi-statically with the fairlead (no line dynamics, no current).
// 2) Per node, with the normal projector P_n = I − t tᵀ (t the unit tangent),
//    tributary length ds_j, hydrodynamic diameter d, Cd, Ca of its segment:
//      added mass  a_j = rho Ca (pi d²/4) ds_j P_n
//      damping     b_j = ½ rho Cd d ds_j D_j
//    D_j the Morison drag |w| w linearized stochastically for the node's
//    Gaussian normal relative velocity w ~ N(u_n, P_n J_j S_f J_jᵀ P_n) —
//    u_n the normal current at the node, S_f the covariance of the fairlead
//    velocity (global, 3x3) — as the expected Jacobian
//    E[|w| P_n + w wᵀ/|w|] (engine/lines/stochastic_drag.hpp; Atalik &
//    Utku 1976; Borgman's sqrt(8/pi) sigma for one direction without
//    current): 2U along and U across the normal current for a line that
//    hardly moves, and for a line swept in one direction by the waves twice
//    the damping along that direction as across it. S_f is supplied by the
//    caller (the analysis takes it from a first plain S-C run of the same
//    case: one fixed-point iteration). A line in a 1.5 m/s current is damped
//    several times more than by its own motion.
// 3) Fairlead matrices A_f = sum J_jᵀ a_j J_j, B_f = sum J_jᵀ b_j J_j, mapped
//    to the hull by the fairlead arm a (global): delta x_f = du − [a×] dtheta,
//    T = [I, −[a×]], A_6 = Tᵀ A_f T, B_6 = Tᵀ B_f T, summed over the lines.
// Limits: the in-line (tangential) drag and inertia, the current's effect
// on the line's shape, the risers' damping, and the lines' own dynamic
// amplification (important for deep-water lines at wave frequency) are
// neglected; the result is symmetric positive semi-definite by
// construction. The risers were tried the same way (FE lines in the
// current, their quasi-static shape derivative) and not kept: a 2,000 m SCR
// does not follow its hang-off quasi-statically down its length, the
// derivative overstates the deep part's motion, and the default scenario's
// lc1 came out over-damped (surge std 15 % below coupled, against 4.5 %
// above without them; docs/decisions/enhanced-sc-accuracy.md).
#include <vector>

#include "design/model/mooring_model.hpp"
#include "engine/analysis/line_array.hpp"
#include "engine/environment/current_profile.hpp"

namespace spiral::design {

struct LineHydrodynamicsResult {
  engine::Matrix6d added_mass = engine::Matrix6d::Zero();  ///< kg, kg·m, kg·m²
  engine::Matrix6d damping = engine::Matrix6d::Zero();     ///< N·s/m, N·m·s/rad …
  std::vector<double> line_drag_velocity_std_m_per_s;      ///< mean sigma over the nodes, per line
};

/// `model` holds catenary mooring lines only (build_mooring_model);
/// `fairlead_velocity_covariance` one 3x3 (m²/s², global) per line of model.
/// `current`: the case's profile (nullptr: none).
LineHydrodynamicsResult line_hydrodynamics(LineArrayModel& model, const engine::HullPose& pose,
                                           const std::vector<Eigen::Matrix3d>& fairlead_velocity_covariance,
                                           double water_density_kg_per_m3,
                                           const engine::CurrentProfile* current = nullptr);

}  // namespace spiral::design
