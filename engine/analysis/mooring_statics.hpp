#pragma once
// Quasi-static mooring restoring force on the hull: every line solved as a
// multi-segment elastic catenary (engine/lines/catenary.hpp) between its
// anchor and the fairlead at the displaced hull position, and the line forces
// summed into a 6-DOF force about the hull reference point.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/analysis/rigid_body.hpp"
#include "engine/lines/catenary.hpp"

namespace spiral::engine {

/// One mooring line between a fixed anchor and a fairlead on the hull.
struct MooringLineModel {
  std::string name;
  Eigen::Vector3d anchor_g = Eigen::Vector3d::Zero();    ///< m, global frame
  Eigen::Vector3d fairlead_b = Eigen::Vector3d::Zero();  ///< m, body frame (relative to the hull reference point)
  double anchor_height_above_seabed_m = 0.0;             ///< 0: anchor on the seabed (contact possible)
  CatenaryLine line;
};

struct MooringSystemModel {
  Eigen::Vector3d reference_point_g = Eigen::Vector3d::Zero();  ///< hull reference point at rest, m
  std::vector<MooringLineModel> lines;
};

/// A line's static state at one hull position.
struct MooringLineState {
  CatenarySolution solution;
  Eigen::Vector3d fairlead_g = Eigen::Vector3d::Zero();        ///< m
  Eigen::Vector3d fairlead_force_g = Eigen::Vector3d::Zero();  ///< force of the line on the hull, N
  Eigen::Vector3d anchor_force_g = Eigen::Vector3d::Zero();    ///< force of the line on the anchor, N
  Eigen::Vector3d horizontal_direction_g = Eigen::Vector3d::UnitX();  ///< unit, anchor -> fairlead
};

struct MooringStaticResult {
  std::vector<MooringLineState> lines;  ///< in the order of MooringSystemModel::lines
  /// Sum of the line forces on the hull (N) and their moments about the
  /// displaced hull reference point (N·m), global axes, DOF order surge..yaw.
  Vector6d hull_force = Vector6d::Zero();
};

/// Solves every line for the hull displaced by `offset` (m, rad; DOF order of
/// DESIGN.md §4). `warm_start`, when given, must come from the same system and
/// seeds each line's Newton iteration. Throws SolverError naming the line.
MooringStaticResult solve_mooring_statics(const MooringSystemModel& system, const Vector6d& offset,
                                          const CatenaryOptions& options = {},
                                          const MooringStaticResult* warm_start = nullptr);

}  // namespace spiral::engine
