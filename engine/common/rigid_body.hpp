#pragma once
// Rigid-body kinematics of the hull. DOF order (DESIGN.md §4): surge, sway,
// heave, roll, pitch, yaw. Rotations are the Tait–Bryan angles roll (about x),
// pitch (about y), yaw (about z) composed as R = Rz(yaw)·Ry(pitch)·Rx(roll),
// mapping body-frame vectors to the global frame — valid for large yaw.

#include <cmath>

#include <Eigen/Core>

#include "engine/common/eigen_types.hpp"
#include <Eigen/Geometry>

namespace spiral::engine {

/// Rotation body -> global for (roll, pitch, yaw) in rad.
inline Eigen::Matrix3d rotation_matrix(const Eigen::Vector3d& roll_pitch_yaw_rad) {
  return (Eigen::AngleAxisd(roll_pitch_yaw_rad.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(roll_pitch_yaw_rad.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll_pitch_yaw_rad.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

/// ω = T(angles) d(roll, pitch, yaw) for R = Rz(yaw)·Ry(pitch)·Rx(roll): the
/// small global rotation of Euler-angle increments, columns Rz Ry e_x, Rz e_y,
/// e_z (Fossen 2011, §2.2.1, in the global frame). Singular at pitch ±90°.
inline Eigen::Matrix3d euler_rate_to_global(const Eigen::Vector3d& roll_pitch_yaw_rad) {
  const double cp = std::cos(roll_pitch_yaw_rad(1)), sp = std::sin(roll_pitch_yaw_rad(1));
  const double cy = std::cos(roll_pitch_yaw_rad(2)), sy = std::sin(roll_pitch_yaw_rad(2));
  Eigen::Matrix3d t;
  t << cy * cp, -sy, 0.0, sy * cp, cy, 0.0, -sp, 0.0, 1.0;
  return t;
}

/// Global position of a body-frame point for a hull whose reference point sits
/// at `reference_point_g` at rest and is displaced by `offset` (6 DOF, m and rad).
inline Eigen::Vector3d body_point_to_global(const Eigen::Vector3d& reference_point_g, const Vector6d& offset,
                                            const Eigen::Vector3d& point_b) {
  return reference_point_g + offset.head<3>() + rotation_matrix(offset.tail<3>()) * point_b;
}

}  // namespace spiral::engine

namespace spiral::engine {

/// A 6-DOF load in hull axes turned to global axes by the hull's yaw ψ
/// (rad): the horizontal force (Fx, Fy) and the heel moments (Mx, My)
/// rotate about z, Fz and Mz do not. Roll and pitch are taken as small.
inline Vector6d yaw_body_to_global(const Vector6d& load_b, double yaw_rad) {
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  Vector6d g = load_b;
  g(0) = c * load_b(0) - s * load_b(1);
  g(1) = s * load_b(0) + c * load_b(1);
  g(3) = c * load_b(3) - s * load_b(4);
  g(4) = s * load_b(3) + c * load_b(4);
  return g;
}

/// [a×], the matrix of the cross product: [a×] b = a × b. A small rotation
/// θ moves a body point at arm a by θ × a = −[a×] θ.
inline Eigen::Matrix3d cross_product_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

/// J = [I, −[r×]]: the small rigid-body motion (translation, rotation) of
/// the reference point → the motion of the body point at arm r (global
/// axes), and by its transpose a force at that point → the force and moment
/// about the reference point; Jᵀ K J carries a point's 3×3 stiffness (or
/// damping, mass) to the body's 6×6.
inline Eigen::Matrix<double, 3, 6> point_jacobian(const Eigen::Vector3d& r) {
  Eigen::Matrix<double, 3, 6> J;
  J << Eigen::Matrix3d::Identity(), -cross_product_matrix(r);
  return J;
}

/// The 6×6 rigid-body mass matrix about the reference point (body axes =
/// global axes at rest) of a body of mass m with its centre of gravity at
/// r_g and inertia tensor I_g about the centre of gravity:
///   [ m I        −m [r_g×]           ]
///   [ m [r_g×]   I_g − m [r_g×][r_g×] ]   (Fossen 2011, §3.3; parallel axes)
inline Matrix6d rigid_body_mass_matrix(double mass_kg, const Eigen::Vector3d& center_of_gravity_m,
                                       const Eigen::Matrix3d& inertia_about_cog_kg_m2) {
  const Eigen::Matrix3d s = cross_product_matrix(center_of_gravity_m);
  Matrix6d m;
  m.topLeftCorner<3, 3>() = mass_kg * Eigen::Matrix3d::Identity();
  m.topRightCorner<3, 3>() = -mass_kg * s;
  m.bottomLeftCorner<3, 3>() = mass_kg * s;
  m.bottomRightCorner<3, 3>() = inertia_about_cog_kg_m2 - mass_kg * s * s;
  return m;
}

}  // namespace spiral::engine
