#pragma once
// Statistics of the fairlead velocities that a hull motion record imposes,
// for the enhanced semi-coupled line damping (design/analysis/line_hydrodynamics.hpp).

#include <span>
#include <vector>

#include <Eigen/Core>

namespace spiral::engine {

/// Fairlead velocity covariance (global, 3x3) per fairlead (body-frame position in `fairleads_b`) from a motion
/// record (central differences of the fairlead positions).
std::vector<Eigen::Matrix3d> fairlead_velocity_covariance(std::span<const Eigen::Vector3d> fairleads_b,
                                                          const Eigen::Vector3d& reference_point,
                                                          const Eigen::Matrix<double, 6, Eigen::Dynamic>& motion,
                                                          double dt_s);

}  // namespace spiral::engine
