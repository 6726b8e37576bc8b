#include "engine/analysis/fairlead_velocity.hpp"

#include "engine/analysis/line_array.hpp"

namespace spiral::engine {

std::vector<Eigen::Matrix3d> fairlead_velocity_covariance(std::span<const Eigen::Vector3d> fairleads_b,
                                                          const Eigen::Vector3d& reference_point,
                                                          const Eigen::Matrix<double, 6, Eigen::Dynamic>& motion,
                                                          double dt_s) {
  std::vector<Eigen::Matrix3d> out(fairleads_b.size(), Eigen::Matrix3d::Zero());
  const Eigen::Index n = motion.cols();
  if (n < 3) return out;
  for (std::size_t l = 0; l < fairleads_b.size(); ++l) {
    const Eigen::Vector3d arm_b = fairleads_b[l];
    const auto fairlead = [&](Eigen::Index k) {
      const HullPose pose = pose_from_offset(reference_point, motion.col(k));
      return Eigen::Vector3d(pose.reference_point_g + pose.rotation * arm_b);
    };
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    for (Eigen::Index k = 1; k + 1 < n; ++k) {
      const Eigen::Vector3d v = (fairlead(k + 1) - fairlead(k - 1)) / (2.0 * dt_s);
      mean += v;
      second += v * v.transpose();
    }
    const double m = static_cast<double>(n - 2);
    mean /= m;
    out[l] = second / m - mean * mean.transpose();
  }
  return out;
}

}  // namespace spiral::engine
