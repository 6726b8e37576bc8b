#pragma once
// From the project (validated, SI) to the engine's static line array: line
// types resolved to physical properties, segments to catenary segments with
// their submerged weights, clumps and buoys to joint loads.

#include <memory>
#include <string>
#include <vector>

#include "design/project/line_properties.hpp"
#include "design/project/project.hpp"
#include "design/model/riser_model.hpp"
#include "engine/analysis/static_line.hpp"
#include "engine/environment/current_profile.hpp"

namespace spiral::design {

/// What the design layer keeps beside each engine line: the properties of
/// every segment, for utilization against the segment's own MBL.
struct MooringLineDesign {
  std::string name;
  std::vector<LineTypeProperties> segment_types;  ///< one per segment, anchor -> fairlead
};

/// The lines attached to the hull, ready for the engine's static analyses:
/// the mooring lines first (in project order), then the risers.
/// Each engine line holds its warm start: one model per analysis thread.
struct LineArrayModel {
  Eigen::Vector3d reference_point_g = Eigen::Vector3d::Zero();  ///< hull reference point at rest
  std::vector<std::unique_ptr<engine::StaticLine>> lines;
  std::vector<MooringLineDesign> designs;  ///< the mooring lines, lines[0 .. designs.size())
  std::vector<RiserDesign> risers;         ///< the risers, lines[designs.size() ..)
};

struct LineArrayOptions {
  std::string excluded_line;                      ///< damaged condition: this mooring line is removed
  std::optional<engine::CurrentProfile> current;  ///< acts on FE lines (mooring `model: fe`, risers)
  bool include_risers = true;
  /// With a `current`: every mooring line is an FE line carrying it, whatever
  /// its `model` (a catenary has no current drag). The S-C levels' static
  /// case (Corrêa & Jacob; Cruces Girón et al.): the mean offset and the 6x6
  /// K are those of the current-loaded lines. Without a current it changes
  /// nothing: each line keeps its own model (a catenary is exact there).
  bool lines_carry_current = false;
  /// The FE lines' solver settings (mooring `model: fe` lines and risers).
  engine::FeStaticsOptions fe_statics;
};

/// The resolved type named `name`; std::invalid_argument if there is none.
const LineTypeProperties& find_type(const std::vector<LineTypeProperties>& types, const std::string& name);

/// Resolves every line type of the project (by name).
std::vector<LineTypeProperties> resolve_line_types(const Project& project);

/// Where a line's fairlead is relative to its anchor with the hull at its
/// rest position, in the catenary's plane: the geometry pretension is
/// defined at (hull fixed, still water).
engine::CatenaryGeometry catenary_geometry_at_rest(const Project& project, const MooringLine& line);

/// The line's pretension — its fairlead tension with the hull at rest, in
/// still water, as its catenary — with `payout_m` added to its top segment.
/// Throws engine::SolverError when the line cannot be solved there.
double pretension_at_rest_N(const Project& project, const MooringLine& line,
                            const std::vector<LineTypeProperties>& types, double payout_m = 0.0);

/// The engine catenary of one project line.
engine::CatenaryLine catenary_of(const Project& project, const MooringLine& line,
                                 const std::vector<LineTypeProperties>& types);

/// The mooring lines of the project as quasi-static catenaries (every line,
/// whatever its `model`: the quick look of `spiral statics`). `excluded_line`,
/// when not empty, names a line to leave out. Throws std::invalid_argument
/// for an unknown line name. `types`: the project's resolved line types (a
/// case model holds them); without them they are resolved here.
LineArrayModel build_mooring_model(const Project& project, const std::vector<LineTypeProperties>& types,
                                   const std::string& excluded_line = {});
LineArrayModel build_mooring_model(const Project& project, const std::string& excluded_line = {});

/// The FE model of one mooring line: per segment its EA, mass, submerged
/// weight, Morison drag and added-mass coefficients on the volume-equivalent
/// diameter (displaced area π d²/4), and the line's mesh.
engine::FeLineModel fe_line_model(const Project& project, const MooringLine& line,
                                  const std::vector<LineTypeProperties>& types);

/// Every line attached to the hull for the coupled static analysis: mooring
/// lines as catenaries or FE lines (`model`; all FE with
/// `options.lines_carry_current` and a current), risers as FE lines with bending.
LineArrayModel build_line_array(const Project& project, const std::vector<LineTypeProperties>& types,
                                const LineArrayOptions& options);
LineArrayModel build_line_array(const Project& project, const LineArrayOptions& options);

}  // namespace spiral::design
