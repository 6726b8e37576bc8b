#pragma once
// Risers of a project as FE static lines, and their static results checked
// against the riser criteria (API RP 2RD / DNV-OS-F201 style, DESIGN.md §6):
// von Mises utilization with the design factor of the load case's condition,
// minimum effective tension (no compression), top tension, top angle,
// flex-joint rotation and minimum bending radius.
//
// The riser's foot (its seabed end) is placed so that at the hull's rest
// position the riser leaves the hang-off at its design top angle: the riser
// as a multi-segment elastic catenary (weight = effective weight, bending
// neglected — it changes the top angle by hundredths of a degree for an
// SCR) solved for its top force on the ray H = V tan θ
// (engine/lines/catenary_top_angle.hpp), which keeps a lazy wave's buoyant
// section suspended; the suspended part must stay above the seabed (a sag
// bend lying on it is a geometry error).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "design/project.hpp"
#include "engine/analysis/fe_static_line.hpp"
#include "engine/environment/current_profile.hpp"
#include "engine/lines/riser_section.hpp"

namespace spiral::design {

struct RiserSectionDesign {
  double length_m = 0.0;
  engine::PipeSectionProperties properties;
  bool steel = true;  ///< wall stresses are checked (scr, lazy-wave; not flexible pipe)
};

struct RiserDesign {
  std::string name;
  RiserKind kind = RiserKind::scr;
  Eigen::Vector3d hang_off_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d foot_g = Eigen::Vector3d::Zero();  ///< seabed end, global
  double azimuth_rad = 0.0;
  double design_top_angle_rad = 0.0;
  /// Sections from the foot to the hang-off (FE order; the project lists them downwards).
  std::vector<RiserSectionDesign> sections;
  double internal_pressure_top_Pa = 0.0;
  double contents_density_top_kg_per_m3 = 0.0;
  RiserCriteria criteria;
  engine::FeLineModel fe_model;
};

/// Section properties, foot position and FE model of a riser. Throws
/// engine::SolverError when no foot position gives the design top angle
/// (riser too short to reach the seabed at that angle, or too long or too
/// buoyant: a buoyant section or the sag bend would lie on the seabed).
RiserDesign riser_design(const Project& project, const Riser& riser);

/// The FE environment of a line of contact diameter `diameter_m` (seabed
/// penalty stiffness = normal_stiffness × diameter, N/m per m) and current.
engine::FeEnvironment fe_environment(const Project& project, const std::optional<engine::CurrentProfile>& current,
                                     double contact_diameter_m);

/// The FE refinement zone of a line or riser mesh: `mesh.touchdown_refinement`
/// centred on the touchdown point of the at-rest static shape, which lies
/// `laid_length_m` (unstretched) from end A; none when no refinement is asked
/// for or nothing lies on the seabed at rest (there is no touchdown to refine).
std::optional<engine::FeRefinementZone> touchdown_refinement_zone(const FeMesh& mesh,
                                                                  double laid_length_m);

std::unique_ptr<engine::FeStaticLine> riser_static_line(const Project& project, const RiserDesign& design,
                                                        const std::optional<engine::CurrentProfile>& current);

/// One criterion of one riser. `utilization` ≤ 1 passes. The minimum
/// effective tension is a floor, checked pass/fail: its utilization is 0 while
/// T_min > limit and 1 + (limit − T_min)/T_top at or below it.
struct RiserCriterionCheck {
  std::string criterion;  ///< von_mises | min_effective_tension | max_top_tension | max_top_angle | flex_joint_rotation | min_bending_radius
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
  int section = 0;  ///< index into the project's Riser::sections (listed from the hang-off down)
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
  std::string kind;
  double top_tension_N = 0.0;
  double top_angle_deg = 0.0;            ///< from vertical
  /// Angle between the top tangent and the flex-joint axis (the at-rest top
  /// tangent at the design top angle in the riser's azimuth plane, fixed to
  /// the hull and turned with it), deg; includes the azimuthal swing.
  double flex_joint_rotation_deg = 0.0;
  double touchdown_distance_m = 0.0;     ///< horizontal, hang-off to touchdown point (0: none)
  double min_effective_tension_N = 0.0;
  double min_effective_tension_arc_m = 0.0;  ///< from the foot
  double max_curvature_per_m = 0.0;
  double min_bending_radius_m = 0.0;     ///< 1 / max curvature
  /// Largest von Mises utilization over the steel sections and where (arc
  /// from the foot); empty when no section has a steel wall (a flexible pipe
  /// is checked by its bending radius and tensions instead).
  std::optional<double> max_von_mises_utilization;
  std::optional<double> max_von_mises_arc_m;
  std::vector<RiserCriterionCheck> checks;
  std::string governing_criterion;       ///< the check with the largest utilization
  double utilization = 0.0;              ///< of the governing check
  bool passes = true;
  std::vector<RiserProfilePoint> profile;  ///< every FE node, foot first
};

/// Post-processes an FE solution of the riser, the hull's rotation
/// `hull_rotation` (body to global) placing its flex-joint axis.
RiserStaticsRow riser_statics_row(const Project& project, const RiserDesign& design,
                                  const engine::FeStaticsResult& solution, DesignCondition condition,
                                  const Eigen::Matrix3d& hull_rotation);

/// The riser's flex-joint axis in the hull body frame: the unit top tangent
/// (pointing down the riser) at the design top angle in its azimuth plane.
Eigen::Vector3d flex_joint_axis_b(const RiserDesign& design);

}  // namespace spiral::design
