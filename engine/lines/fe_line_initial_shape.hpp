#pragma once
// Default starting shape for the FE line statics: the inextensible catenary
// of the line's mean weight in the vertical plane through its ends, lying on
// the seabed from end A when A is on the seabed (Irvine, "Cable Structures"
// 1981, §1.2: suspended cable with supports at unequal levels), or a straight
// line when the line is shorter than its chord, has no net weight, or its
// ends are vertically aligned. It only has to be close enough for Newton.

#include <functional>

#include <Eigen/Core>

#include "engine/lines/fe_line_statics.hpp"

namespace spiral::engine {

struct InitialShape {
  /// Position (global, m) as a function of unstretched arc length from end A.
  std::function<Eigen::Vector3d(double)> position_m;
  /// Horizontal tension of that catenary, N (0 for the straight line): seeds
  /// the nodal stretch |r'| = 1 + T/EA, so that Newton starts with a tensioned
  /// (non-singular) cable instead of a slack one.
  double horizontal_tension_N = 0.0;
};

InitialShape default_initial_shape(const FeLineModel& model, const FeEnvironment& environment,
                                   const Eigen::Vector3d& end_A_m, const Eigen::Vector3d& end_B_m);

}  // namespace spiral::engine
