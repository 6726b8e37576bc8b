#pragma once
// Mooring lines and risers under a given hull motion history (`spiral lines
// --motion`): what MoorDyn's standalone driver and OrcaFlex's "vessel motion
// from a time history" do — the line and riser analysis with motions from
// another program (or from an earlier spiral run).
//
// Every selected mooring line and riser is a dynamic FE line
// (line_dynamics.hpp: FE statics with the load case's current, polyester at
// its dynamic EA, seabed contact with damping and friction, risers with
// bending), its fairlead or hang-off following the hull motion: a natural
// cubic spline through the fairlead positions at the history's own times
// (continuous velocity and acceleration), built up from the pose of the
// first sample by a quintic ramp. The lines see the load case's current and,
// unless switched off, the case's seeded sea (linear wave kinematics at a
// point per element that follows its midpoint to 0.5 m). The sea of a seed is the one `spiral analyze`
// makes for the same case, seed and duration: a motion written by analyze
// meets the waves that made it; a motion from another program meets a sea of
// the same spectrum but not its phases (a note says so).
//
// Recorded at every output time: mooring lines — fairlead and anchor
// tension, the anchor's uplift angle (the line's pull above the horizontal),
// the laid length (arc from the anchor to the last seabed contact); risers —
// the riser criteria of riser_checks.hpp evaluated on the dynamic state
// (top tension and angle, flex-joint rotation, touchdown distance, minimum
// effective tension, bending radius, von Mises) with the case's design
// condition, and each criterion's worst time.
//
// Errors: InputError (unknown case, line, or a request value out of range,
// named by its request argument), engine::SolverError naming the line.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "design/analysis/line_dynamics.hpp"
#include "design/criteria/riser_checks.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {

struct MotionLinesRequest {
  std::string load_case;                            ///< current, waves, damaged line and design condition
  std::vector<double> motion_times_s;               ///< strictly increasing, >= 2
  Eigen::Matrix<double, 6, Eigen::Dynamic> motion;  ///< hull offset at each time, m, rad
  std::vector<std::string> motion_notes;            ///< what the history's reader noted (kept in the result's notes)
  std::vector<std::string> lines;     ///< mooring lines and risers by name (`lines`); empty: every intact one
  double output_step_s = 0.5;         ///< > 0 (`output_step_s`)
  double ramp_s = 20.0;               ///< build-up, >= 0 and shorter than the motion (`ramp_s`)
  bool waves_on_lines = true;         ///< the case's seeded sea on the lines
  std::optional<std::uint64_t> seed;  ///< of the sea; empty: the load case's seed
  double tolerance_scale = 1.0;       ///< integrator tolerances × this (a reference run: < 1)
  /// Called with the fraction done (0..1) as the lines advance, from their
  /// threads; may be empty. An exception it throws stops the run.
  std::function<void(double)> progress;
};

/// One mooring line's record, one value per output time.
struct MooringLineMotionRecord {
  std::string name;
  std::vector<double> fairlead_tension_N;
  std::vector<double> anchor_tension_N;
  std::vector<double> anchor_uplift_deg;  ///< angle of the line's pull on the anchor above the horizontal
  std::vector<double> laid_length_m;      ///< arc from the anchor to the last seabed contact (0: none)
  double fairlead_mbl_N = 0.0;            ///< of the fairlead segment (the dynamic tension check)
  engine::IdaStatistics solver;
  double wall_s = 0.0;
};

/// A riser criterion over the record: its largest utilization and when.
struct RiserCriterionExtreme {
  RiserCriterionCheck worst;  ///< the check at the worst time
  double time_s = 0.0;
};

/// One riser's record, one value per output time.
struct RiserMotionRecord {
  std::string name;
  std::vector<double> top_tension_N;
  std::vector<double> top_angle_deg;
  std::vector<double> flex_joint_rotation_deg;
  std::vector<double> touchdown_distance_m;  ///< horizontal, hang-off to touchdown (0: none)
  std::vector<double> min_effective_tension_N;
  std::vector<double> min_bending_radius_m;
  std::vector<double> max_von_mises_utilization;  ///< empty when no section has a steel wall
  std::vector<double> utilization;                ///< of the governing criterion at each time
  /// Every criterion's worst over the statistics window (after the ramp), in riser_checks order.
  std::vector<RiserCriterionExtreme> extremes;
  engine::IdaStatistics solver;
  double wall_s = 0.0;
};

struct MotionLinesResult {
  std::string case_name;
  std::string environment;
  DesignCondition condition = DesignCondition::extreme;
  std::string damaged_line;  ///< "" intact
  std::uint64_t seed = 1;
  bool waves_on_lines = false;
  std::vector<double> times_s;
  Eigen::Matrix<double, 6, Eigen::Dynamic> motion;  ///< the history at the output times (spline), m, rad
  double ramp_s = 0.0;
  double statistics_from_s = 0.0;  ///< first time of the statistics window: the end of the ramp
  std::vector<MooringLineMotionRecord> lines;
  std::vector<RiserMotionRecord> risers;
  std::vector<std::string> notes;
  double wall_s = 0.0;
};

MotionLinesResult run_motion_lines(const ValidatedProject& project, const MotionLinesRequest& request);

}  // namespace spiral::design
