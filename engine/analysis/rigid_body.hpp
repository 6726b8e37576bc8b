#pragma once
// Rigid-body kinematics of the hull. DOF order (DESIGN.md §4): surge, sway,
// heave, roll, pitch, yaw. Rotations are the Tait–Bryan angles roll (about x),
// pitch (about y), yaw (about z) composed as R = Rz(yaw)·Ry(pitch)·Rx(roll),
// mapping body-frame vectors to the global frame — valid for large yaw.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace spiral::engine {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// Rotation body -> global for (roll, pitch, yaw) in rad.
inline Eigen::Matrix3d rotation_matrix(const Eigen::Vector3d& roll_pitch_yaw_rad) {
  return (Eigen::AngleAxisd(roll_pitch_yaw_rad.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(roll_pitch_yaw_rad.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll_pitch_yaw_rad.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

/// Global position of a body-frame point for a hull whose reference point sits
/// at `reference_point_g` at rest and is displaced by `offset` (6 DOF, m and rad).
inline Eigen::Vector3d body_point_to_global(const Eigen::Vector3d& reference_point_g,
                                            const Vector6d& offset,
                                            const Eigen::Vector3d& point_b) {
  return reference_point_g + offset.head<3>() + rotation_matrix(offset.tail<3>()) * point_b;
}

}  // namespace spiral::engine
