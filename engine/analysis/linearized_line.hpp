#pragma once
// A line replaced by its first-order response about one top-end position:
// f(x) = f₀ − K₀ (x − x₀). Used where an expensive line (an FE riser) must
// be evaluated thousands of times over small hull motions — the pretension
// optimizer's inner iterations — and is re-linearized from the full model
// between them (design/optimization/scenario_model.hpp). The error of the
// force is second order in |x − x₀| (the curvature of the line's response,
// which for a riser changes over tens of metres of offset).

#include <string>

#include "engine/analysis/static_line.hpp"

namespace spiral::engine {

class LinearizedStaticLine final : public StaticLine {
 public:
  /// The response `at` of a line at top-end position `attachment_g`.
  LinearizedStaticLine(std::string name, Eigen::Vector3d attachment_b, const Eigen::Vector3d& attachment_g,
                       const LineEndResponse& at);
  const std::string& name() const override { return name_; }
  const Eigen::Vector3d& attachment_b() const override { return attachment_b_; }
  LineEndResponse solve(const Eigen::Vector3d& attachment_g) override;
  /// The top only: the linearization carries no profile.
  LineState state(const Eigen::Vector3d& attachment_g, int points_per_segment) override;
  void reset() override {}

 private:
  std::string name_;
  Eigen::Vector3d attachment_b_;
  Eigen::Vector3d origin_g_;
  LineEndResponse origin_;
};

}  // namespace spiral::engine
