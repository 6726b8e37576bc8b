// soz_symmetry.hpp: which risers share a zone turned about the vertical.
// The problem of an FE riser at a hull offset — gravity, a flat seabed with
// isotropic (axial) friction, the criteria incl. a flex-joint axis that
// turns with the azimuth — is invariant under a rotation about the vertical
// as long as nothing directional acts: no current, no hull roll/pitch/yaw.
// Two risers that differ only by azimuth then have zones that are turned
// copies; on the direction grid the copy is exact when the azimuths differ
// by a whole number of steps.
#include "design/soz_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Azimuth differences count as whole grid steps to this relative precision
// (the criterion the step itself passes, validate_soz_options).
constexpr double kStepDivisionTolerance = 1e-9;

const Riser* project_riser(const Project& project, const std::string& name) {
  const auto it = std::find_if(project.risers.begin(), project.risers.end(),
                               [&](const Riser& r) { return r.name == name; });
  return it == project.risers.end() ? nullptr : &*it;
}

}  // namespace

std::vector<int> soz_rotation_sources(const Project& project, const std::vector<RiserDesign>& risers,
                                      const SozConditions& conditions, const SozOptions& options,
                                      int n_directions, std::vector<int>& shift) {
  std::vector<int> source(risers.size(), -1);
  shift.assign(risers.size(), 0);
  const double step_deg = options.step_deg;
  // The catenary screening model carries no current: it stays symmetric.
  const bool current = conditions.current && options.model == SozModel::fe;
  if (current || !conditions.rotation_rad.isZero(0.0)) return source;
  for (std::size_t r = 0; r < risers.size(); ++r) {
    const RiserDesign& a = risers[r];
    const Riser* pa = project_riser(project, a.name);
    for (std::size_t q = 0; q < r && pa; ++q) {
      const RiserDesign& b = risers[q];
      const Riser* pb = project_riser(project, b.name);
      if (source[q] >= 0 || !pb) continue;
      const bool same_design = a.kind == b.kind && pa->sections == pb->sections &&
                               pa->top_angle_rad == pb->top_angle_rad &&
                               pa->internal_pressure_Pa == pb->internal_pressure_Pa && pa->fe == pb->fe &&
                               a.hang_off_b.z() == b.hang_off_b.z() && a.criteria == b.criteria &&
                               a.fe_model == b.fe_model && a.design_top_angle_rad == b.design_top_angle_rad;
      if (!same_design) continue;
      const double steps = (a.azimuth_rad - b.azimuth_rad) * kRadToDeg / step_deg;
      if (std::abs(steps - std::round(steps)) > kStepDivisionTolerance * std::max(1.0, std::abs(steps))) continue;
      // The foot relative to the hang-off, turned: same placement (it is
      // derived from the same design, so this holds to round-off).
      const double turn = a.azimuth_rad - b.azimuth_rad;
      const Eigen::Vector2d fa = (a.foot_g - a.hang_off_b).head<2>(), fb = (b.foot_g - b.hang_off_b).head<2>();
      const Eigen::Vector2d fb_turned(std::cos(turn) * fb.x() - std::sin(turn) * fb.y(),
                                      std::sin(turn) * fb.x() + std::cos(turn) * fb.y());
      if ((fa - fb_turned).norm() > 1e-6 * fa.norm() || a.foot_g.z() != b.foot_g.z()) continue;
      source[r] = static_cast<int>(q);
      shift[r] = static_cast<int>(((std::lround(steps) % n_directions) + n_directions) % n_directions);
      break;
    }
  }
  return source;
}


}  // namespace spiral::design
