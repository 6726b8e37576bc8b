#include "design/analysis/line_hydrodynamics.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/common/rigid_body.hpp"
#include "engine/lines/stochastic_drag.hpp"

namespace spiral::design {
namespace {

/// Fairlead step of the shape derivative: large against the catenary closure
/// (1e-9 m), small against the metres over which the shape changes.
constexpr double kFairleadStep_m = 0.1;
/// Profile points per segment for the node sums (tributary lengths ~ L/40).
constexpr int kPointsPerSegment = 40;

/// Position on a profile at unstretched arc length s (linear between points;
/// the point count may differ between solutions, e.g. with a touchdown point).
Eigen::Vector3d position_at_arc(const std::vector<engine::LineProfilePoint>& profile, double s) {
  if (s <= profile.front().arc_length_m) return profile.front().position_g;
  for (std::size_t j = 1; j < profile.size(); ++j) {
    const double s0 = profile[j - 1].arc_length_m;
    const double s1 = profile[j].arc_length_m;
    if (s <= s1 && s1 > s0) {
      const double u = (s - s0) / (s1 - s0);
      return (1.0 - u) * profile[j - 1].position_g + u * profile[j].position_g;
    }
  }
  return profile.back().position_g;
}

}  // namespace

LineHydrodynamicsResult line_hydrodynamics(LineArrayModel& model, const engine::HullPose& pose,
                                           const std::vector<Eigen::Matrix3d>& covariance, double rho,
                                           const engine::CurrentProfile* current) {
  if (covariance.size() != model.lines.size() || model.designs.size() != model.lines.size()) {
    throw std::invalid_argument("line_hydrodynamics: one covariance per catenary mooring line is needed");
  }
  LineHydrodynamicsResult out;
  for (std::size_t l = 0; l < model.lines.size(); ++l) {
    engine::StaticLine& line = *model.lines[l];
    const Eigen::Vector3d arm = pose.rotation * line.attachment_b();
    const Eigen::Vector3d x_f = pose.reference_point_g + arm;
    const engine::LineState base = line.state(x_f, kPointsPerSegment);
    const std::size_t n = base.profile.size();
    std::vector<Eigen::Matrix3d> J(n, Eigen::Matrix3d::Zero());
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d step = kFairleadStep_m * Eigen::Vector3d::Unit(i);
      const engine::LineState plus = line.state(x_f + step, kPointsPerSegment);
      const engine::LineState minus = line.state(x_f - step, kPointsPerSegment);
      for (std::size_t j = 0; j < n; ++j) {
        const double arc = base.profile[j].arc_length_m;
        J[j].col(i) =
            (position_at_arc(plus.profile, arc) - position_at_arc(minus.profile, arc)) / (2.0 * kFairleadStep_m);
      }
    }
    line.solve(x_f);  // leave the warm start at the equilibrium
    Eigen::Matrix3d A_f = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d B_f = Eigen::Matrix3d::Zero();
    double sigma_sum = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t prev = j == 0 ? 0 : j - 1;
      const std::size_t next = j + 1 == n ? n - 1 : j + 1;
      const double ds = 0.5 * (base.profile[next].arc_length_m - base.profile[prev].arc_length_m);
      if (!(ds > 0.0)) continue;
      Eigen::Vector3d t = base.profile[next].position_g - base.profile[prev].position_g;
      if (t.norm() <= 0.0) continue;
      t.normalize();
      const Eigen::Matrix3d Pn = Eigen::Matrix3d::Identity() - t * t.transpose();
      const auto& type = model.designs[l].segment_types.at(static_cast<std::size_t>(base.profile[j].segment));
      const double d = type.hydrodynamic_diameter_m;
      const Eigen::Matrix3d PJ = Pn * J[j];
      const Eigen::Matrix3d normal_covariance = PJ * covariance[l] * PJ.transpose();
      sigma_sum += std::sqrt(std::max(0.0, normal_covariance.trace()));
      const Eigen::Vector3d u_current =
          current ? Eigen::Vector3d(Pn * engine::current_velocity_g(*current, base.profile[j].position_g.z()))
                  : Eigen::Vector3d::Zero();
      A_f += J[j].transpose() * (rho * type.added_mass_normal * 0.25 * std::numbers::pi * d * d * ds * Pn) * J[j];
      B_f += J[j].transpose() *
             (0.5 * rho * type.drag_normal * d * ds * engine::expected_drag_slope(t, u_current, normal_covariance)) *
             J[j];
    }
    out.line_drag_velocity_std_m_per_s.push_back(n > 0 ? sigma_sum / static_cast<double>(n) : 0.0);
    const Eigen::Matrix<double, 3, 6> T = engine::point_jacobian(arm);
    out.added_mass += T.transpose() * A_f * T;
    out.damping += T.transpose() * B_f * T;
  }
  return out;
}

}  // namespace spiral::design
