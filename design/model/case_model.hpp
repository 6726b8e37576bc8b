#pragma once
// What every analysis of one load case is built from, built once per case and
// shared by its static case, its hull dynamics and its dynamic lines: the
// hull with its data files read once (.hst, .1, and the .12d in waves), the
// resolved line types, the case's environment and current. Before it, a
// coupled run built the hull (and read the WAMIT files) up to four times and
// resolved the line types in four places (issue 13).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "design/model/hull_model.hpp"
#include "design/project/line_properties.hpp"
#include "design/project/project.hpp"
#include "engine/environment/current_profile.hpp"
#include "engine/hull/mean_environmental_loads.hpp"

namespace spiral::design {

struct CaseModel {
  /// The load case and its environment (both null: still water, no load case).
  /// They point into the project, which outlives every analysis of it.
  const LoadCase* load_case = nullptr;
  const Environment* environment = nullptr;
  std::optional<engine::CurrentProfile> current;  ///< the environment's profile, if it has one
  std::shared_ptr<const HullModel> hull;
  std::shared_ptr<const std::vector<LineTypeProperties>> line_types;
  /// The hull's mean drift coefficients (hull.mean_drift) when the case has
  /// waves and the project the data; null otherwise.
  std::shared_ptr<const engine::MeanDriftTable> drift;
};

/// The model of `load_case` (none: still water). Throws what
/// find_load_case and build_hull_model throw (InputError for an unknown case,
/// engine::FileFormatError for a bad data file).
CaseModel build_case_model(const Project& project, const std::optional<std::string>& load_case);

}  // namespace spiral::design
