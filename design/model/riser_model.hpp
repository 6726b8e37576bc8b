#pragma once
// Risers of a project as FE static lines (their checks against the riser
// criteria: design/criteria/riser_checks.hpp).
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

#include "design/project/project.hpp"
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
std::optional<engine::FeRefinementZone> touchdown_refinement_zone(const FeMesh& mesh, double laid_length_m);

/// The riser as a static line of the line array, in `current`, solved with `options`.
std::unique_ptr<engine::FeStaticLine> riser_static_line(const Project& project, const RiserDesign& design,
                                                        const std::optional<engine::CurrentProfile>& current,
                                                        const engine::FeStaticsOptions& options = {});

}  // namespace spiral::design
