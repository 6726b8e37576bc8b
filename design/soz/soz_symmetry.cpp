// soz_symmetry.hpp: which risers share a zone, turned about the vertical or
// mirrored in a vertical plane. The problem of an FE riser at a hull offset —
// gravity, a flat seabed with isotropic (axial) friction, an isotropic pipe,
// the criteria incl. a flex-joint axis that lies in the riser's azimuth
// plane — is invariant under every isometry of the horizontal plane as long
// as nothing directional acts: no current, no hull roll/pitch/yaw. If an
// isometry Q carries riser a (its foot-to-hang-off vector and azimuth) onto
// riser b, then b at hull offset x is a at Qᵀx, so b's zone is a's mapped by
// Q. On the direction grid the copy is exact when Q maps grid directions onto
// grid directions: a rotation by a whole number of steps, or a reflection in
// a plane at a whole number of half steps. A riser mirrored onto itself (in
// the plane of its foot and hang-off) has a zone symmetric about that plane.
#include "design/soz/soz_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Angles count as whole grid steps to this relative precision (the criterion
// the step itself passes, validate_soz_options).
constexpr double kStepDivisionTolerance = 1e-9;
// Placements (foot-to-hang-off vectors, both derived from the same design
// data) agree to round-off; this relative bound accepts them.
constexpr double kPlacementTolerance = 1e-6;

const Riser* project_riser(const Project& project, const std::string& name) {
  const auto it =
      std::find_if(project.risers.begin(), project.risers.end(), [&](const Riser& r) { return r.name == name; });
  return it == project.risers.end() ? nullptr : &*it;
}

/// `angle_deg` as a whole number of grid steps (mod n), if it is one.
std::optional<int> whole_steps(double angle_deg, double step_deg, int n) {
  const double steps = angle_deg / step_deg;
  if (std::abs(steps - std::round(steps)) > kStepDivisionTolerance * std::max(1.0, std::abs(steps))) {
    return std::nullopt;
  }
  return static_cast<int>(((std::lround(steps) % n) + n) % n);
}

/// The riser's placement: the horizontal vector from its foot to its hang-off
/// at zero offset, its heights and its azimuth (the flex-joint plane).
struct Placement {
  Eigen::Vector2d foot_to_hang_off;
  double angle_deg = 0.0;  ///< direction of foot_to_hang_off
  double azimuth_deg = 0.0;
  double hang_off_z = 0.0, foot_z = 0.0;
};

Placement placement_of(const Project& project, const RiserDesign& d) {
  Placement p;
  const Eigen::Vector3d hang_off_g = project.hull.reference_point_g + d.hang_off_b;
  p.foot_to_hang_off = (hang_off_g - d.foot_g).head<2>();
  p.angle_deg = std::atan2(p.foot_to_hang_off.y(), p.foot_to_hang_off.x()) * kRadToDeg;
  p.azimuth_deg = d.azimuth_rad * kRadToDeg;
  p.hang_off_z = hang_off_g.z();
  p.foot_z = d.foot_g.z();
  return p;
}

Eigen::Vector2d turned(const Eigen::Vector2d& v, double angle_deg) {
  const double a = angle_deg / kRadToDeg;
  return {std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y()};
}

/// Reflection in the vertical plane at `axis_deg`.
Eigen::Vector2d mirrored(const Eigen::Vector2d& v, double axis_deg) {
  const double a = 2.0 * axis_deg / kRadToDeg;
  return {std::cos(a) * v.x() + std::sin(a) * v.y(), std::sin(a) * v.x() - std::cos(a) * v.y()};
}

bool same_vector(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - b).norm() <= kPlacementTolerance * std::max(1.0, a.norm());
}

/// Angles equal modulo 360°.
bool same_angle(double a_deg, double b_deg) {
  const double d = std::remainder(a_deg - b_deg, 360.0);
  return std::abs(d) <= kStepDivisionTolerance * 360.0;
}

bool same_design(const Project& project, const RiserDesign& a, const RiserDesign& b) {
  const Riser* pa = project_riser(project, a.name);
  const Riser* pb = project_riser(project, b.name);
  if (!pa || !pb) return false;
  return a.kind == b.kind && pa->sections == pb->sections && pa->top_angle_rad == pb->top_angle_rad &&
         pa->internal_pressure_Pa == pb->internal_pressure_Pa && pa->fe == pb->fe && a.criteria == b.criteria &&
         a.fe_model == b.fe_model && a.design_top_angle_rad == b.design_top_angle_rad;
}

}  // namespace

bool soz_in_solved_half(int k, int self_mirror_index, int n_directions) {
  if (self_mirror_index < 0) return true;
  const int j = ((2 * k - self_mirror_index) % (2 * n_directions) + 2 * n_directions) % (2 * n_directions);
  return j <= n_directions;
}

std::vector<SozZoneMap> soz_zone_maps(const Project& project, const std::vector<RiserDesign>& risers,
                                      const SozConditions& conditions, const SozOptions& options, int n_directions) {
  std::vector<SozZoneMap> maps(risers.size());
  const double step_deg = options.step_deg;
  // The catenary screening model carries no current: it stays symmetric.
  const bool current = conditions.current && options.model == SozModel::fe;
  if (!options.exploit_symmetry || current || !conditions.rotation_rad.isZero(0.0)) return maps;
  std::vector<Placement> placements;
  for (const RiserDesign& d : risers) placements.push_back(placement_of(project, d));
  for (std::size_t r = 0; r < risers.size(); ++r) {
    const Placement& b = placements[r];
    for (std::size_t q = 0; q < r && maps[r].source < 0; ++q) {
      const Placement& a = placements[q];
      if (maps[q].source >= 0 || a.hang_off_z != b.hang_off_z || a.foot_z != b.foot_z ||
          !same_design(project, risers[q], risers[r])) {
        continue;
      }
      // Rotation by α: b = a turned by α, azimuth too.
      const double alpha_deg = b.angle_deg - a.angle_deg;
      if (const auto shift = whole_steps(alpha_deg, step_deg, n_directions);
          shift && same_vector(turned(a.foot_to_hang_off, alpha_deg), b.foot_to_hang_off) &&
          same_angle(a.azimuth_deg + alpha_deg, b.azimuth_deg)) {
        maps[r] = {static_cast<int>(q), false, *shift, -1};
        break;
      }
      // Reflection in the plane at β, 2β = angle_a + angle_b: b = a mirrored.
      const double two_beta_deg = a.angle_deg + b.angle_deg;
      if (const auto m = whole_steps(two_beta_deg, step_deg, n_directions);
          m && same_vector(mirrored(a.foot_to_hang_off, 0.5 * two_beta_deg), b.foot_to_hang_off) &&
          same_angle(two_beta_deg - a.azimuth_deg, b.azimuth_deg)) {
        maps[r] = {static_cast<int>(q), true, *m, -1};
      }
    }
    if (maps[r].source >= 0) continue;
    // Its own mirror image in the plane of its foot and hang-off, when the
    // azimuth (the flex-joint plane) lies in it too.
    const double two_axis_deg = 2.0 * b.angle_deg;
    if (const auto m = whole_steps(two_axis_deg, step_deg, n_directions);
        m && same_angle(2.0 * b.azimuth_deg, two_axis_deg)) {
      maps[r].self_mirror_index = *m;
    }
  }
  return maps;
}

}  // namespace spiral::design
