#pragma once
// Linear hydrostatic and gravity restoring of a floating rigid body.
//
// Frame and DOF: body reference point (the hull reference point of
// DESIGN.md §4), axes aligned with the global frame at rest, z up, origin of z
// at the mean water level when the reference point lies on it (it need not).
// DOF order surge, sway, heave, roll, pitch, yaw; rotations in rad.
// Restoring force F = -C xi for a small displacement xi about the rest position.
//
// Formulation: WAMIT User Manual v7, §3.1 "Hydrostatic data" (the C_ij below,
// restated by Newman, "Marine Hydrodynamics" (1977) ch. 6 and Faltinsen,
// "Sea Loads on Ships and Offshore Structures" (1990) ch. 2, restoring
// coefficients). Section numbers throughout are recalled, not re-read;
// the formulas were checked against the box-barge closed form and the OC4
// numbers (tests/validation/engine/hull/hydrostatics_test.cpp):
//   C33 = rho g A_wp
//   C34 = C43 =  rho g  S_y          (S_y = ∫ y dA = A_wp y_f)
//   C35 = C53 = -rho g  S_x          (S_x = ∫ x dA = A_wp x_f)
//   C44 = rho g (S_yy + V z_b) - m g z_g      (S_yy = ∫ y^2 dA)
//   C45 = C54 = -rho g S_xy                   (S_xy = ∫ x y dA)
//   C46 = -rho g V x_b + m g x_g
//   C55 = rho g (S_xx + V z_b) - m g z_g      (S_xx = ∫ x^2 dA)
//   C56 = -rho g V y_b + m g y_g
//   all others zero (C64 = C65 = 0: the matrix is not symmetric in general).
// The waterplane integrals are about the reference point's axes, not the
// waterplane centroid.
//
// Split used here (and why two matrices):
//  - buoyancy/waterplane part (`buoyancy_6x6`): every term with rho g, i.e.
//    what the WAMIT formulas give with m = 0. This is the convention of the
//    NREL/OpenFAST .hst files (J. Jonkman, OpenFAST issue #1471: "the
//    hydrostatic restoring included in the WAMIT data should only account for
//    buoyancy effects, not the contribution of system mass/weight") and of
//    the OC4 report's "C44 = -3.776e8" (reference-platforms §1.2). Note that
//    WAMIT itself writes the gravity terms into .hst when the .frc file gives
//    a CG off the origin and a mass (IALTFRC); know which kind of file you have.
//  - gravity part (`gravity_6x6`): -m g z_g on C44, C55; +m g x_g on C46;
//    +m g y_g on C56.
//  - total = buoyancy + gravity: the free-floating body's restoring.
//
// Valid for small rotations about the rest position (linear, wall-sided in the
// waterplane). Large-angle hydrostatics (deck-edge immersion, non-wall-sided
// hulls, GZ curves) need a panel or member model: not in scope here.

#include <Eigen/Core>

#include "engine/common/eigen_types.hpp"

#include "engine/common/seawater.hpp"

namespace spiral::engine {

/// Waterplane of the body at rest, integrals about the reference point's axes.
struct WaterplaneProperties {
  double area_m2 = 0.0;  ///< A_wp = ∫ dA, >= 0
  /// Centroid (x_f, y_f) of the waterplane relative to the reference point, m.
  /// Zero (the default) drops the heave-roll/pitch couplings C34, C35.
  Eigen::Vector2d centroid_m = Eigen::Vector2d::Zero();
  double second_moment_xx_m4 = 0.0;   ///< S_yy = ∫ y^2 dA (roll), >= 0
  double second_moment_yy_m4 = 0.0;   ///< S_xx = ∫ x^2 dA (pitch), >= 0
  double product_moment_xy_m4 = 0.0;  ///< S_xy = ∫ x y dA
};

/// Hydrostatic data of the body at rest.
struct HydrostaticBody {
  WaterplaneProperties waterplane;
  double displaced_volume_m3 = 0.0;                                ///< V, >= 0
  Eigen::Vector3d centre_of_buoyancy_m = Eigen::Vector3d::Zero();  ///< (x_b, y_b, z_b) from the ref point
};

/// Mass and centre of gravity of the floating system (hull + ballast + topsides).
struct BodyMass {
  double mass_kg = 0.0;                                           ///< m, >= 0
  Eigen::Vector3d centre_of_gravity_m = Eigen::Vector3d::Zero();  ///< (x_g, y_g, z_g) from the ref point
};

struct HydrostaticRestoring {
  Matrix6d buoyancy_6x6 = Matrix6d::Zero();  ///< rho g terms only (NREL .hst convention), SI
  Matrix6d gravity_6x6 = Matrix6d::Zero();   ///< m g terms only
  Matrix6d total_6x6 = Matrix6d::Zero();     ///< buoyancy + gravity
  /// Forces and moments about the reference point at rest (xi = 0) from
  /// buoyancy and weight together: F3 = rho g V - m g (> 0: buoyancy excess that
  /// the mooring and riser vertical loads must take), F4 = rho g V y_b - m g y_g,
  /// F5 = -(rho g V x_b - m g x_g); F1 = F2 = F6 = 0. N, N m.
  Vector6d rest_force = Vector6d::Zero();
  /// Transverse and longitudinal metacentric heights GM = C44 / (rho g V),
  /// C55 / (rho g V) of the total matrix when the body floats freely
  /// (m = rho V); with other loads present they are just the normalised
  /// stiffness. 0 when V = 0.
  double metacentric_height_transverse_m = 0.0;
  double metacentric_height_longitudinal_m = 0.0;
};

/// Buoyancy/waterplane restoring (WAMIT §3.1 formulas with m = 0).
/// Throws std::invalid_argument for negative area, volume or second moments.
Matrix6d buoyancy_restoring(const HydrostaticBody& body, const Seawater& water = {});

/// Gravity restoring of a mass at its CG (the m g terms of WAMIT §3.1).
/// Throws std::invalid_argument for a negative mass or gravity.
Matrix6d gravity_restoring(const BodyMass& mass, double gravity_m_per_s2 = 9.80665);

/// Total restoring = buoyancy + gravity, and the rest-position force.
HydrostaticRestoring hydrostatic_restoring(const HydrostaticBody& body, const BodyMass& mass,
                                           const Seawater& water = {});

/// Same from a buoyancy matrix read elsewhere (e.g. an NREL-convention .hst,
/// see wamit_hst.hpp) plus the body's displaced volume and centre of buoyancy
/// for the rest force.
HydrostaticRestoring hydrostatic_restoring(const Matrix6d& buoyancy_6x6, double displaced_volume_m3,
                                           const Eigen::Vector3d& centre_of_buoyancy_m, const BodyMass& mass,
                                           const Seawater& water = {});

/// Linearised hydrostatic + gravity load at a displaced position:
///   F(xi) = rest_force - total_6x6 xi
/// (xi = surge, sway, heave in m; roll, pitch, yaw in rad). Accurate for small
/// rotations and heave within the wall-sided part of the hull; for larger
/// motions use a panel/member model (not in scope). Throws std::invalid_argument
/// for a non-finite displacement.
Vector6d linear_hydrostatic_load(const HydrostaticRestoring& restoring, const Vector6d& displacement);

}  // namespace spiral::engine
