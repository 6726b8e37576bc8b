#include "engine/analysis/mooring_statics.hpp"

#include <cmath>

#include <fmt/format.h>

namespace spiral::engine {

namespace {

// Below this horizontal span (m) the line is taken as vertical and its
// horizontal direction as the one from anchor to fairlead at rest; the
// horizontal force of such a line is zero by symmetry anyway.
constexpr double kVerticalLineSpan_m = 1e-9;

}  // namespace

MooringStaticResult solve_mooring_statics(const MooringSystemModel& system, const Vector6d& offset,
                                          const CatenaryOptions& options,
                                          const MooringStaticResult* warm_start) {
  MooringStaticResult result;
  result.lines.reserve(system.lines.size());
  const Eigen::Matrix3d rotation = rotation_matrix(offset.tail<3>());
  const Eigen::Vector3d reference_g = system.reference_point_g + offset.head<3>();

  for (std::size_t i = 0; i < system.lines.size(); ++i) {
    const MooringLineModel& model = system.lines[i];
    MooringLineState state;
    const Eigen::Vector3d arm_g = rotation * model.fairlead_b;
    state.fairlead_g = reference_g + arm_g;

    const Eigen::Vector3d chord = state.fairlead_g - model.anchor_g;
    const double horizontal_span = std::hypot(chord.x(), chord.y());
    if (horizontal_span > kVerticalLineSpan_m) {
      state.horizontal_direction_g = Eigen::Vector3d(chord.x(), chord.y(), 0.0) / horizontal_span;
    } else {
      const Eigen::Vector3d rest =
          system.reference_point_g + model.fairlead_b - model.anchor_g;
      const double rest_span = std::hypot(rest.x(), rest.y());
      state.horizontal_direction_g = Eigen::Vector3d::UnitX();
      if (rest_span > kVerticalLineSpan_m) {
        state.horizontal_direction_g = Eigen::Vector3d(rest.x(), rest.y(), 0.0) / rest_span;
      }
    }

    CatenaryGeometry geometry;
    geometry.horizontal_span_m = horizontal_span;
    geometry.vertical_span_m = chord.z();
    geometry.anchor_height_above_seabed_m = model.anchor_height_above_seabed_m;

    std::optional<CatenaryGuess> guess;
    if (warm_start != nullptr && i < warm_start->lines.size()) {
      const CatenarySolution& previous = warm_start->lines[i].solution;
      guess = CatenaryGuess{previous.fairlead_horizontal_N, previous.fairlead_vertical_N};
    }

    try {
      state.solution = solve_catenary(model.line, geometry, options, guess);
    } catch (const SolverError& error) {
      throw SolverError(fmt::format("mooring line '{}': {}", model.name, error.what()),
                        error.diagnostics());
    }

    const CatenarySolution& s = state.solution;
    // The line pulls the fairlead horizontally towards the anchor and down by V_F;
    // it pulls the anchor towards the fairlead and up by V_A.
    state.fairlead_force_g = -s.fairlead_horizontal_N * state.horizontal_direction_g -
                             s.fairlead_vertical_N * Eigen::Vector3d::UnitZ();
    state.anchor_force_g = s.anchor_horizontal_N * state.horizontal_direction_g +
                           s.anchor_vertical_N * Eigen::Vector3d::UnitZ();

    result.hull_force.head<3>() += state.fairlead_force_g;
    result.hull_force.tail<3>() += arm_g.cross(state.fairlead_force_g);
    result.lines.push_back(std::move(state));
  }
  return result;
}

}  // namespace spiral::engine
