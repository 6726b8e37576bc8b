#include "design/project/validated_project.hpp"

#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "design/project/load_case_matrix.hpp"
#include "design/project/project_loader.hpp"
#include "design/project/project_validation.hpp"

namespace spiral::design {

ValidatedProject load_validated_project(const std::filesystem::path& file,
                                        const std::optional<std::filesystem::path>& data_folder) {
  return validate_loaded_project(load_project(file, data_folder));
}

ValidatedProject validate_loaded_project(Project parsed) {
  ValidatedProject result;
  result.project = std::move(parsed);
  const Project& project = result.project;

  std::vector<InputIssue> issues;
  LineCheckTable check_table;
  for (std::size_t i = 0; i < project.line_types.size(); ++i) {
    const LineTypeInput& input = project.line_types[i];
    try {
      LineTypeProperties properties =
          resolve_line_type(input, project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2);
      check_table[input.name] = {properties.axial_stiffness_N, properties.breaking_load_N,
                                 properties.submerged_weight_N_per_m};
      result.line_types.push_back(std::move(properties));
    } catch (const std::invalid_argument& error) {
      issues.push_back(make_issue(project, fmt::format("line_types[{}]", i), "line_type_resolvable", error.what()));
    }
  }
  for (InputIssue& issue : check_project(project, check_table)) issues.push_back(std::move(issue));
  if (!issues.empty()) throw InputError(std::move(issues));
  if (!project.load_case_matrix.empty()) {
    // The generated environments and cases are checked like written ones (a
    // turned sea may leave the hull's drift data, say); their issues name them.
    expand_load_case_matrix(result.project);
    Project expanded = result.project;  // the matrix is checked already; its names are now taken by itself
    expanded.load_case_matrix.clear();
    for (InputIssue& issue : check_project(expanded, check_table)) issues.push_back(std::move(issue));
    if (!issues.empty()) throw InputError(std::move(issues));
  }
  return result;
}

}  // namespace spiral::design
