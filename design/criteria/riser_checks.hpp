#pragma once
// The static results of a riser checked against the riser criteria (API RP
// 2RD / DNV-OS-F201 style, DESIGN.md §6): von Mises utilization with the
// design factor of the load case's condition, minimum effective tension (no
// compression), top tension, top angle, flex-joint rotation and minimum
// bending radius.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "design/model/riser_model.hpp"
#include "engine/lines/fe_line_statics.hpp"

namespace spiral::design {

/// One criterion of one riser. `utilization` ≤ 1 passes. The minimum
/// effective tension is a floor, checked pass/fail: its utilization is 0 while
/// T_min > limit and 1 + (limit − T_min)/T_top at or below it.
struct RiserCriterionCheck {
  std::string criterion;  ///< von_mises | min_effective_tension | max_top_tension | max_top_angle | flex_joint_rotation
                          ///< | min_bending_radius
  double value = 0.0;     ///< in `unit`
  double limit = 0.0;     ///< in `unit`
  std::string unit;
  double utilization = 0.0;
  bool passes = true;
};

/// The riser results at one FE node (foot first).
struct RiserProfilePoint {
  Eigen::Vector3d position_g = Eigen::Vector3d::Zero();  ///< m, global
  double arc_length_m = 0.0;                             ///< unstretched, from the foot
  int section = 0;         ///< index into the project's Riser::sections (listed from the hang-off down)
  bool on_seabed = false;  ///< at or before the touchdown point
  double effective_tension_N = 0.0;
  /// True wall tension T_w = T_e + p_i A_i − p_e A_o (Sparks 1984), with the
  /// contents and sea pressures at the node.
  double wall_tension_N = 0.0;
  double bending_moment_N_m = 0.0;  ///< |EI κ|
  double curvature_per_m = 0.0;     ///< |κ|
  /// Steel sections only: the largest von Mises stress over the wall's four
  /// extreme points and its utilization (design factor of the condition).
  std::optional<double> von_mises_Pa;
  std::optional<double> von_mises_utilization;
};

struct RiserStaticsRow {
  std::string name;
  RiserKind kind = RiserKind::scr;
  double top_tension_N = 0.0;
  double top_angle_deg = 0.0;  ///< from vertical
  /// Angle between the top tangent and the flex-joint axis (the at-rest top
  /// tangent at the design top angle in the riser's azimuth plane, fixed to
  /// the hull and turned with it), deg; includes the azimuthal swing.
  double flex_joint_rotation_deg = 0.0;
  double touchdown_distance_m = 0.0;  ///< horizontal, hang-off to touchdown point (0: none)
  double min_effective_tension_N = 0.0;
  double min_effective_tension_arc_m = 0.0;  ///< from the foot
  double max_curvature_per_m = 0.0;
  double min_bending_radius_m = 0.0;  ///< 1 / max curvature
  /// Largest von Mises utilization over the steel sections and where (arc
  /// from the foot); empty when no section has a steel wall (a flexible pipe
  /// is checked by its bending radius and tensions instead).
  std::optional<double> max_von_mises_utilization;
  std::optional<double> max_von_mises_arc_m;
  std::vector<RiserCriterionCheck> checks;
  std::string governing_criterion;  ///< the check with the largest utilization
  double utilization = 0.0;         ///< of the governing check
  bool passes = true;
  std::vector<RiserProfilePoint> profile;  ///< every FE node, foot first
};

/// The profile of the riser named `name` among `risers`; null when it is not
/// there (a start for that riser's FE statics at the same ends, dynamic_riser).
const std::vector<RiserProfilePoint>* riser_profile(const std::vector<RiserStaticsRow>& risers,
                                                    const std::string& name);

/// Post-processes an FE solution of the riser, the hull's rotation
/// `hull_rotation` (body to global) placing its flex-joint axis.
RiserStaticsRow riser_statics_row(const Project& project, const RiserDesign& design,
                                  const engine::FeStaticsResult& solution, DesignCondition condition,
                                  const Eigen::Matrix3d& hull_rotation);

/// The riser's flex-joint axis in the hull body frame: the unit top tangent
/// (pointing down the riser) at the design top angle in its azimuth plane.
Eigen::Vector3d flex_joint_axis_b(const RiserDesign& design);

}  // namespace spiral::design
