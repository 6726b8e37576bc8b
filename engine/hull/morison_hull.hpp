#pragma once
// Morison member model of a hull (strip theory) for hulls without a BEM data
// set: circular columns and pontoons/braces cut into strips, each loaded by
// Morison's equation (Morison, O'Brien, Johnson & Schaaf 1950; DNV-RP-C205
// (2010) §6.2), normal to its axis:
//
//   dF = rho (1 + Ca) A a_n ds                 Froude–Krylov + diffraction inertia
//      − rho Ca A v'_n ds                      added mass (in the hull's mass matrix)
//      + 1/2 rho Cd D |u_n − v_n| (u_n − v_n) ds   drag on the relative velocity
//
// with A = pi D^2/4, u the fluid velocity (current + waves), a the wave
// acceleration, v the velocity of the strip centre with the hull, and _n the
// components normal to the member axis. Axial loads act only on the flat end
// faces of columns (pontoon ends are closed by the columns they join):
//
//   F_end = p_dyn A_face n_in                 Froude–Krylov pressure on the face
//         + rho Ca_end V_end a_t − rho Ca_end V_end v'_t   end added mass, V_end = (2/3) pi R^3
//         + 1/2 rho Cd_end A_face |u_t − v_t| (u_t − v_t)  axial (heave-plate) drag
//
// n_in the face normal into the member, _t the axial components. The default
// Ca = 1 is the 2D potential-flow value of a circle and Ca_end = 2/pi that of
// one wetted side of a circular disc (DNV-RP-C205 App. D, Tables D-1 and D-2:
// disc C_A = 2/pi on V_R = 4/3 pi a^3 for both sides, i.e. 2/pi on the
// hemisphere (2/3) pi a^3 for one side); Cd = 1.05 is DNV-RP-C205 §6.7.2's
// post-critical value for a rough (marine-grown, k/D > 1e-2) cylinder. The
// strip model has no radiation damping and no free-surface memory: at short
// waves (kR > ~0.3) diffraction (MacCamy & Fuchs 1954) lowers and shifts the
// inertia force and the model over-predicts it (measured against HAMS in
// tests/validation/engine/hull/morison_hull_test.cpp); the first-order
// excitation can take the MacCamy–Fuchs correction of the columns
// (MorisonDiffraction).
//
// Linear (frequency-domain) quantities use the geometry at rest up to the
// mean water level z = 0 (global z): added mass and first-order excitation
// (morison_excitation, WAMIT e^{iwt} convention as in wamit_3.hpp). The time-
// domain load (morison_load) uses the kinematics with Wheeler stretching of
// wave_realization.hpp at the strip centres (wet when below the instantaneous
// surface, so strips above z = 0 load in crests), the current profile at the
// strip depth (held at the surface value above z = 0), and the relative
// velocity with the hull; the strips are placed at a given pose (the static
// equilibrium: first-order consistent, as a BEM model's RAOs at the mean
// position) and the force is returned in global axes about the reference
// point of that pose.
//
// Errors: std::invalid_argument naming the member and the value.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <complex>
#include <optional>
#include <vector>

#include "engine/common/eigen_types.hpp"
#include "engine/common/seawater.hpp"
#include "engine/environment/current_profile.hpp"
#include "engine/environment/wave_realization.hpp"
#include "engine/hull/wamit_3.hpp"

namespace spiral::engine {

/// One circular member, body frame (origin at the hull reference point).
struct MorisonMember {
  Eigen::Vector3d end_a_b = Eigen::Vector3d::Zero();  ///< m
  Eigen::Vector3d end_b_b = Eigen::Vector3d::Zero();  ///< m, distinct from end_a_b
  double diameter_m = 0.0;                            ///< > 0
  double drag_coefficient = 1.05;                     ///< Cd normal, >= 0
  double added_mass_coefficient = 1.0;                ///< Ca normal, >= 0
  bool end_faces = false;                             ///< flat end faces loaded (columns: true)
  double end_added_mass_coefficient = 0.0;            ///< Ca_end on (2/3) pi R^3 per face, >= 0
  double end_drag_coefficient = 0.0;                  ///< Cd_end on pi R^2 per face, >= 0
};

struct MorisonHullInput {
  std::vector<MorisonMember> members;
  Eigen::Vector3d reference_point_at_rest_g = Eigen::Vector3d::Zero();  ///< m
  double strip_length_m = 1.0;                                          ///< target strip length along each member, > 0
};

/// A strip: a short cylinder of length ds at its centre (body frame).
struct MorisonStrip {
  Eigen::Vector3d center_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_b = Eigen::Vector3d::UnitZ();  ///< unit
  double length_m = 0.0;
  double diameter_m = 0.0;
  double drag_coefficient = 0.0;
  double added_mass_coefficient = 0.0;
  bool submerged_at_rest = false;  ///< centre below z = 0 with the hull at rest
  int member = 0;
};

/// A flat circular end face of a column.
struct MorisonEndFace {
  Eigen::Vector3d center_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d inward_normal_b = Eigen::Vector3d::UnitZ();  ///< unit, into the member
  double radius_m = 0.0;
  double added_mass_coefficient = 0.0;
  double drag_coefficient = 0.0;
  bool submerged_at_rest = false;
  int member = 0;
};

struct MorisonHull {
  std::vector<MorisonStrip> strips;
  std::vector<MorisonEndFace> faces;
  Eigen::Vector3d reference_point_at_rest_g = Eigen::Vector3d::Zero();
};

/// Cuts every member into strips no longer than strip_length_m, with a strip
/// boundary at the mean water level where a member crosses it. Validates the
/// input.
MorisonHull make_morison_hull(const MorisonHullInput& input);

/// Added mass about the reference point (6x6, kg, kg m, kg m^2) of the parts
/// below z = 0 at rest: sum over strips rho Ca A ds J^T (I − t t^T) J and over
/// submerged faces rho Ca_end V_end J^T t t^T J, J = [I, −[r]x] the rigid-body
/// velocity at r.
Matrix6d morison_added_mass(const MorisonHull& hull, double water_density_kg_per_m3);

/// How the first-order excitation treats members that are large against the
/// wave length.
enum class MorisonDiffraction {
  /// Strip theory as it is: good for kR < ~0.3 (the long-wave limit).
  none,
  /// Vertical members (columns): each strip's inertia force scaled by the
  /// MacCamy–Fuchs factor of its radius (maccamy_fuchs_factor), and each
  /// horizontal end face loaded by the incident pressure integrated over the
  /// disc instead of taken at its centre (force × 2 J1(kR)/(kR), and the
  /// moment of the pressure's variation across it). Other members and the
  /// faces' added-mass inertia keep strip theory. The large columns of a
  /// semi-submersible are what this is for: the strip model over-predicts
  /// their inertia by tens of per cent at wave frequencies.
  maccamy_fuchs,
};

/// MacCamy & Fuchs (1954): the horizontal wave force per unit length on a
/// vertical circular cylinder of radius R in linear waves over its long-wave
/// value (Morison inertia with C_M = 2), in the WAMIT e^{iwt} convention:
///   r(kR) = −2i / (π (kR)² H1'(kR)*),  H1' = J1' + i Y1'   (Hankel, first kind)
/// (conjugate of the e^{−iwt} form 2i / (π (kR)² H1'(kR)), Chakrabarti,
/// Hydrodynamics of Offshore Structures, 1987, §6.5). |r| → 1 and arg r → 0
/// as kR → 0; |r| = 2/(π (kR)² |H1'|) is C_M(kR)/2, and r lags the long-wave
/// force by atan(J1'/Y1'). Throws std::invalid_argument for kR <= 0.
std::complex<double> maccamy_fuchs_factor(double k_times_radius);

/// First-order wave excitation per unit amplitude (N/m, N m/m) in the WAMIT
/// convention (F = Re{X A e^{iwt}}, phase relative to the wave at the
/// reference point), hull at rest, parts below z = 0: inertia
/// rho (1 + Ca) A ds a_n per strip, pressure and end added-mass inertia per
/// face, with the diffraction correction asked for. heading_rad: direction of
/// propagation in the body frame.
Vector6cd morison_excitation(const MorisonHull& hull, const Seawater& water, std::optional<double> water_depth_m,
                             double omega_rad_per_s, double heading_rad,
                             MorisonDiffraction diffraction = MorisonDiffraction::none);

/// The excitation on a grid (frequencies ascending and > 0, headings
/// ascending), as a `.3` file would give it (wamit_3.hpp), `file` naming its
/// origin for messages.
WaveTransferTable morison_excitation_table(const MorisonHull& hull, const Seawater& water,
                                           std::optional<double> water_depth_m,
                                           const std::vector<double>& omega_rad_per_s,
                                           const std::vector<double>& headings_rad, MorisonDiffraction diffraction,
                                           const std::string& file);

/// What the time-domain load needs besides the hull.
struct MorisonFlow {
  const WaveRealization* sea = nullptr;     ///< empty: no waves
  const CurrentProfile* current = nullptr;  ///< empty: no current
  double water_density_kg_per_m3 = 1025.0;
  /// Strips and faces whose centre is above this height (global z) are never
  /// wet: the largest possible crest sum_k a_k (0 without waves).
  double highest_crest_m = 0.0;
};

struct MorisonLoad {
  Vector6d force = Vector6d::Zero();  ///< global axes, about the pose's reference point, N, N m
  int wet_strips = 0;
};

/// The Morison load at time t on the hull placed at (pose_reference_point_g,
/// pose_rotation) and moving with `velocity` (q' in the DOF order: m/s,
/// rad/s; small-angle rates as angular velocity): inertia from the wave
/// acceleration (added mass excluded: it is in the mass matrix), pressure on
/// the faces, drag on the relative velocity current + waves − hull.
MorisonLoad morison_load(const MorisonHull& hull, const MorisonFlow& flow,
                         const Eigen::Vector3d& pose_reference_point_g, const Eigen::Matrix3d& pose_rotation,
                         double t_s, const Vector6d& velocity);

}  // namespace spiral::engine
