#pragma once
// Fixed-size Eigen types of the 6-DOF rigid-body world (DOF order: surge,
// sway, heave, roll, pitch, yaw — DESIGN.md §4).
#include <Eigen/Core>

namespace spiral::engine {
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
}  // namespace spiral::engine
