#pragma once
// A line (mooring line or riser) attached to the hull, as the coupled static
// analysis sees it: given where its top end is, the force it exerts on the
// hull there and the 3×3 tangent stiffness of that force.
//
// Implementations keep their last solution as a warm start for the next
// call (a workspace, not model data): an equilibrium or stiffness iteration
// moves the top end by small steps, and a warm start cuts each solve to a
// few Newton iterations. One object per analysis; not shared across threads.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/lines/catenary.hpp"

namespace spiral::engine {

/// Response of a line to the position of its top end.
struct LineEndResponse {
  Eigen::Vector3d force_g = Eigen::Vector3d::Zero();  ///< force of the line on the hull, N, global
  /// K = −dF/dx of that force w.r.t. the top-end position, N/m, global.
  Eigen::Matrix3d stiffness_g = Eigen::Matrix3d::Zero();
  double top_tension_N = 0.0;
  int iterations = 0;
};

/// A point of a line's static profile.
struct LineProfilePoint {
  Eigen::Vector3d position_g = Eigen::Vector3d::Zero();  ///< m
  double arc_length_m = 0.0;                             ///< unstretched, from the bottom end (anchor)
  double tension_N = 0.0;                                ///< effective tension
  int segment = 0;                                       ///< index of the segment/section, bottom to top
  bool on_seabed = false;
};

/// How a line at rest meets the seabed.
enum class LineRegime {
  suspended,  ///< no seabed contact
  touchdown,  ///< part of the line lies on the seabed
  slack,      ///< no horizontal tension: a vertical hanging part, the rest on the seabed (catenary lines)
};

const char* to_string(LineRegime regime);  ///< "suspended" | "touchdown" | "slack"

/// The full static state of a line, for results tables and reports.
struct LineState {
  LineEndResponse top;                                       ///< at the hull
  Eigen::Vector3d bottom_force_g = Eigen::Vector3d::Zero();  ///< force of the line on its anchor, N
  double laid_length_m = 0.0;                                ///< unstretched length resting on the seabed
  double touchdown_distance_m = 0.0;                         ///< horizontal, anchor to touchdown point (0: none)
  LineRegime regime = LineRegime::suspended;
  std::vector<LineProfilePoint> profile;
};

class StaticLine {
 public:
  virtual ~StaticLine() = default;
  virtual const std::string& name() const = 0;
  /// Top-end position in the hull body frame, relative to the hull reference point, m.
  virtual const Eigen::Vector3d& attachment_b() const = 0;
  /// Solves the line with its top end at `attachment_g` (global, m). Throws
  /// SolverError naming the line when it cannot.
  virtual LineEndResponse solve(const Eigen::Vector3d& attachment_g) = 0;
  /// The force of the line on the hull alone (N, global), for finite
  /// differences: a line may skip its stiffness. Default: solve().force_g.
  virtual Eigen::Vector3d solve_force(const Eigen::Vector3d& attachment_g) { return solve(attachment_g).force_g; }
  /// The force at `attachment_g` with a tangent stiffness from this or a
  /// recent nearby solve (not necessarily at `attachment_g`): the line
  /// linearized for a predictor, where an exact K is not worth a new
  /// factorisation. Default: solve().
  virtual LineEndResponse linearization(const Eigen::Vector3d& attachment_g) { return solve(attachment_g); }
  /// Solves the line at `attachment_g` and returns its whole state, with
  /// `points_per_segment` + 1 profile points on each segment (ends included).
  virtual LineState state(const Eigen::Vector3d& attachment_g, int points_per_segment) = 0;
  /// The 3×3 stiffness K = −dF/dx of the line solved at `attachment_g` when
  /// the strain changes from that state are carried by `incremental_EA_N`
  /// (one per segment or section, bottom first) instead of the static EA:
  /// fibre ropes' static–dynamic convention (the mean state on the static
  /// EA, the motions about it on the dynamic one; DNV-OS-E301 ch. 2 sec. 2
  /// [2.4]). Default, for a line with no axial model of its own (a
  /// linearization): solve(attachment_g).stiffness_g.
  virtual Eigen::Matrix3d incremental_stiffness_g(const Eigen::Vector3d& attachment_g,
                                                  const std::vector<double>& incremental_EA_N) {
    (void)incremental_EA_N;
    return solve(attachment_g).stiffness_g;
  }
  /// Forgets the warm start (the next solve starts cold).
  virtual void reset() = 0;
  /// Whether one solve costs milliseconds (FE) rather than microseconds
  /// (catenary): the line array solves such lines on several threads.
  virtual bool expensive() const { return false; }
};

/// A quasi-static elastic catenary between a fixed anchor and the hull.
/// Current does not act on it (use the FE line for that).
class CatenaryStaticLine final : public StaticLine {
 public:
  CatenaryStaticLine(std::string name, Eigen::Vector3d anchor_g, Eigen::Vector3d attachment_b,
                     double anchor_height_above_seabed_m, CatenaryLine line, CatenaryOptions options = {});
  const std::string& name() const override { return name_; }
  const Eigen::Vector3d& attachment_b() const override { return attachment_b_; }
  LineEndResponse solve(const Eigen::Vector3d& attachment_g) override;
  LineState state(const Eigen::Vector3d& attachment_g, int points_per_segment) override;
  /// Exact (catenary_incremental_tangent); one EA per segment.
  Eigen::Matrix3d incremental_stiffness_g(const Eigen::Vector3d& attachment_g,
                                          const std::vector<double>& incremental_EA_N) override;
  void reset() override { warm_start_.reset(); }

  /// The line, its last solution and the horizontal direction (anchor ->
  /// fairlead) of the plane it was solved in: what the payout sensitivities
  /// of engine/lines/catenary_payout.hpp need.
  const CatenaryLine& line() const { return line_; }
  const CatenarySolution& last_solution() const { return last_; }
  const Eigen::Vector3d& last_direction_g() const { return last_direction_g_; }

 private:
  std::string name_;
  Eigen::Vector3d anchor_g_;
  Eigen::Vector3d attachment_b_;
  double anchor_height_above_seabed_m_;
  CatenaryLine line_;
  CatenaryOptions options_;
  std::optional<CatenaryGuess> warm_start_;
  CatenarySolution last_;
  Eigen::Vector3d last_direction_g_ = Eigen::Vector3d::UnitX();

  struct Plane {
    double span_m;
    Eigen::Vector3d direction_g;  ///< horizontal unit vector, anchor -> fairlead
  };
  Plane plane_of(const Eigen::Vector3d& attachment_g) const;
  LineEndResponse solve_in_plane(const Plane& plane, double vertical_span_m, const CatenaryOptions& options);
};

/// The 3×3 stiffness of a catenary's fairlead force in global axes from its
/// in-plane tangent d(H, V)/d(XF, ZF): the in-plane terms along the line's
/// horizontal direction e, plus the lateral "string" stiffness H / XF across it
/// (the horizontal force turns with the line when the fairlead moves sideways).
Eigen::Matrix3d catenary_fairlead_stiffness(const Eigen::Matrix2d& tangent_HV_by_XZ, double horizontal_force_N,
                                            double horizontal_span_m, const Eigen::Vector3d& horizontal_direction_g);

}  // namespace spiral::engine
