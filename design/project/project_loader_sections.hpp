#pragma once
// Internal to the project loader (not a public design API): the mapping of
// each section of the project file (format v1, docs/project-format.md) onto
// the schema structs of project.hpp, read through the strict MapReader
// (yaml_map_reader.hpp). One file per group of sections:
//   project_loader_mooring.cpp   site, line_types, mooring
//   project_loader_hull.cpp      hull (hydrostatics, load coefficients, mean
//                                drift, hydrodynamics, geometry)
//   project_loader_risers.cpp    risers and the riser criteria
//   project_loader_cases.cpp     environments, load_cases, criteria, stages
//   project_loader_optimization.cpp  optimization
// and project_loader.cpp reads the top level in file order.

#include <filesystem>
#include <optional>

#include "design/project/project.hpp"
#include "design/project/yaml_map_reader.hpp"

namespace spiral::design::loader_detail {

/// A name in a list of names (`mooring.groups[i].lines`, `optimization.cases`).
void read_name(Context& ctx, const YAML::Node& node, const std::string& path, std::vector<std::string>& out);

Site read_site(MapReader& r);
LineTypeInput read_line_type(MapReader& r);
/// `seabed_z`: the default z of an anchor written in polar form.
Mooring read_mooring(MapReader& r, std::optional<double> seabed_z);

/// `fe: {element_length, touchdown_refinement: {length, element_length}}`;
/// `mesh` holds the default element length on entry.
void read_fe_mesh(MapReader& r, FeMesh& mesh);

/// File references (hydrostatics, hydrodynamics, mean drift, panel mesh)
/// resolve against `base_folder` unless absolute.
Hull read_hull(MapReader& r, const std::filesystem::path& base_folder);

Riser read_riser(MapReader& r);
/// The keys of `criteria.risers` and `risers[i].criteria`, all optional.
RiserCriteriaOverrides read_riser_criteria(MapReader& r);

Environment read_environment(MapReader& r);
LoadCase read_load_case(MapReader& r);
LoadCaseMatrixEntry read_load_case_matrix_entry(MapReader& r);
Criteria read_criteria(MapReader& r);
Stage read_stage(MapReader& r);
Optimization read_optimization(MapReader& r);

}  // namespace spiral::design::loader_detail
