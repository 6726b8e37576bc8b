#pragma once
// From the project (validated, SI) to the engine's mooring model: line types
// resolved to physical properties, segments to catenary segments with their
// submerged weights, clumps and buoys to joint loads.

#include <string>
#include <vector>

#include "design/line_properties.hpp"
#include "design/project.hpp"
#include "engine/analysis/mooring_statics.hpp"

namespace spiral::design {

/// What the design layer keeps beside each engine line: the properties of
/// every segment, for utilization against the segment's own MBL.
struct MooringLineDesign {
  std::string name;
  std::vector<LineTypeProperties> segment_types;  ///< one per segment, anchor -> fairlead
};

struct MooringDesignModel {
  engine::MooringSystemModel system;
  std::vector<MooringLineDesign> lines;  ///< same order as system.lines
};

/// Resolves every line type of the project (by name).
std::vector<LineTypeProperties> resolve_line_types(const Project& project);

/// Builds the mooring model of the project. `excluded_line`, when not empty,
/// names a line to leave out (damaged condition). Throws std::invalid_argument
/// for an unknown line name (the validation pass has caught the rest).
MooringDesignModel build_mooring_model(const Project& project, const std::string& excluded_line = {});

}  // namespace spiral::design
