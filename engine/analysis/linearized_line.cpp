#include "engine/analysis/linearized_line.hpp"

namespace spiral::engine {

LinearizedStaticLine::LinearizedStaticLine(std::string name, Eigen::Vector3d attachment_b,
                                           const Eigen::Vector3d& attachment_g, const LineEndResponse& at)
    : name_(std::move(name)), attachment_b_(std::move(attachment_b)), origin_g_(attachment_g), origin_(at) {}

LineEndResponse LinearizedStaticLine::solve(const Eigen::Vector3d& attachment_g) {
  LineEndResponse r = origin_;
  r.force_g = origin_.force_g - origin_.stiffness_g * (attachment_g - origin_g_);
  r.top_tension_N = r.force_g.norm();
  r.iterations = 0;
  return r;
}

LineState LinearizedStaticLine::state(const Eigen::Vector3d& attachment_g, int /*points_per_segment*/) {
  LineState s;
  s.top = solve(attachment_g);
  // No profile, no regime: only the top response is meaningful.
  return s;
}

}  // namespace spiral::engine
