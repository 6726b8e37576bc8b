#pragma once
// The OC4 semi with a steady current and wind on the hull (coefficient
// tables), one payout group per line: a small, fast problem for the
// optimization tests.

#include <numbers>
#include <string>

#include "design/project/validated_project.hpp"

namespace spiral::design::testing {

/// The OC4 CoG sits 6.5 mm aft of the CoB (ref: mass-weighted); `symmetric`
/// puts it on the CoB's vertical so that the hull has no pitch trim and the
/// moored system the exact 120° symmetry of its lines.
inline ValidatedProject oc4_optimization_project(double current_m_per_s, double heading_deg, bool symmetric = false) {
  constexpr double kDegToRad = std::numbers::pi / 180.0;
  ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  HullLoadCoefficients c;
  c.headings_rad = {0.0, 90.0 * kDegToRad, 180.0 * kDegToRad, 270.0 * kDegToRad};
  c.surge_m2 = {3000.0, 0.0, -3000.0, 0.0};
  c.sway_m2 = {0.0, 3000.0, 0.0, -3000.0};
  c.yaw_m3 = {0.0, 0.0, 0.0, 0.0};
  p.project.hull.current_coefficients = c;
  if (symmetric) p.project.hull.center_of_gravity_b.head<2>().setZero();
  Environment environment;
  environment.name = "steady-current";
  environment.current = Current{heading_deg * kDegToRad, {{0.0, current_m_per_s}, {-200.0, current_m_per_s}}};
  p.project.environments.push_back(environment);
  p.project.load_cases = {{"still", "still-water", std::nullopt, DesignCondition::extreme},
                          {"current", "steady-current", std::nullopt, DesignCondition::extreme},
                          {"current-damaged-L1", "steady-current", std::string("L1"), DesignCondition::survival}};
  p.project.mooring.groups.clear();
  p.project.optimization = Optimization{};
  p.project.optimization->payout_limit_pct = 1.5;  // ± 12.5 m of 835 m
  return p;
}

}  // namespace spiral::design::testing
