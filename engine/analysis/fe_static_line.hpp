#pragma once
// A finite-element line (mooring line or riser) as a StaticLine of the
// coupled static analysis: end A fixed (anchor, riser foot), end B at the hull
// attachment. Unlike the catenary it carries current drag and bending.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/analysis/static_line.hpp"
#include "engine/lines/fe_line_statics.hpp"

namespace spiral::engine {

/// The section (index into model.sections, end A first) each node of an FE
/// solution lies in; a node on a joint belongs to the section below it.
std::vector<int> node_sections(const FeLineModel& model, const FeStaticsResult& result);

class FeStaticLine final : public StaticLine {
 public:
  FeStaticLine(std::string name, Eigen::Vector3d end_A_g, Eigen::Vector3d attachment_b, FeLineModel model,
               FeEnvironment environment, FeStaticsOptions options = {});
  const std::string& name() const override { return name_; }
  const Eigen::Vector3d& attachment_b() const override { return attachment_b_; }
  /// Warm-started from the last converged solve (kept after a failed one);
  /// at the attachment of the last solve it returns that solution as is (a
  /// re-solve there would return it, to round-off). The stiffness is exact
  /// there, unless set_stiffness_reuse_distance allows an earlier one.
  LineEndResponse solve(const Eigen::Vector3d& attachment_g) override;
  /// From now on solve() may return, with the force at its attachment, the
  /// end-B stiffness of the most recent solve that computed one (its own or
  /// an adopted line's) if that was within `distance_m` of it: no Jacobian
  /// and factorisation, for callers that use the stiffness as a Newton
  /// tangent only. 0 (the default): always the exact stiffness.
  void set_stiffness_reuse_distance(double distance_m) { stiffness_reuse_distance_m_ = distance_m; }
  /// Without the end-B stiffness (its Jacobian factorisation is most of a warm solve).
  Eigen::Vector3d solve_force(const Eigen::Vector3d& attachment_g) override;
  /// The force there and the end-B stiffness of the last solve that computed one.
  LineEndResponse linearization(const Eigen::Vector3d& attachment_g) override;
  /// The FE nodes are the profile (`points_per_segment` is not used: the mesh sets the resolution).
  LineState state(const Eigen::Vector3d& attachment_g, int points_per_segment) override;
  /// Takes `solution` (with its end-B stiffness, if it has one) as this line's solve at
  /// `attachment_g`, as if solved there: the next solve at that attachment
  /// returns it, others start warm from it. It must come from a line with the
  /// same model, environment and anchor (e.g. another case's line with the
  /// same environment). Throws
  /// std::invalid_argument if its mesh size differs from this model's.
  void adopt(const Eigen::Vector3d& attachment_g, FeStaticsResult solution);
  /// adopt() of `source`'s last solve, with the end-B stiffness of its most
  /// recent solve that computed one (see set_stiffness_reuse_distance).
  /// `source` must have a last solve.
  void adopt(const FeStaticLine& source);
  /// fe_line_incremental_end_B_stiffness at the solve there; one EA per section.
  Eigen::Matrix3d incremental_stiffness_g(const Eigen::Vector3d& attachment_g,
                                          const std::vector<double>& incremental_EA_N) override;
  void reset() override {
    last_.reset();
    warm_.reset();
    recent_stiffness_.reset();
  }
  bool expensive() const override { return true; }
  /// The full FE solution of the last solve (curvature, bending moment per node).
  const FeStaticsResult* last_result() const { return last_.get(); }
  /// Where end B was for last_result() (meaningless without one).
  const Eigen::Vector3d& last_attachment_g() const { return last_attachment_g_; }
  const FeLineModel& model() const { return model_; }
  const Eigen::Vector3d& end_A_g() const { return end_A_g_; }

 private:
  std::string name_;
  Eigen::Vector3d end_A_g_;
  Eigen::Vector3d attachment_b_;
  FeLineModel model_;
  FeEnvironment environment_;
  FeStaticsOptions options_;
  /// Solves at attachment_g unless last_ already holds that solution (with
  /// the stiffness if `stiffness`).
  const FeStaticsResult& solve_at(const Eigen::Vector3d& attachment_g, bool stiffness);
  /// Makes `solution` (converged at `attachment_g`) the last solve and the warm start.
  const FeStaticsResult& keep(const Eigen::Vector3d& attachment_g, FeStaticsResult solution);

  std::shared_ptr<const FeStaticsResult> last_;  ///< of the last solve; empty after a failure
  Eigen::Vector3d last_attachment_g_ = Eigen::Vector3d::Zero();
  std::optional<Eigen::Matrix3d> recent_stiffness_;  ///< end-B stiffness of the last solve that computed one
  Eigen::Vector3d recent_stiffness_at_g_ = Eigen::Vector3d::Zero();  ///< where end B was for it
  double stiffness_reuse_distance_m_ = 0.0;
  /// The last converged solve (the warm start): last_ itself, or kept
  /// through a failed solve.
  std::shared_ptr<const FeStaticsResult> warm_;
};

}  // namespace spiral::engine
