#pragma once
// The load-case matrix (`load_case_matrix`, docs/project-format.md): each
// entry turns one environment to several headings — every heading of its
// waves, wind and current turned by the same angle, so the sea keeps its
// shape relative to itself (collinear stays collinear) — and makes a load
// case of each, intact and, as asked, with each single mooring line removed.
// A realistic FPS matrix is hundreds of cases (8–12 headings × 2–3
// environments × intact + every line damaged) written in a few lines.
//
// Names are reproducible: environment `<base>@h045` (the heading in whole
// degrees, or as written when not whole), intact case `<base>@h045`,
// damaged case `<base>@h045-without-L3`; generated in entry order, then
// heading order, intact first, then the damaged lines in project order.

#include <string>
#include <vector>

#include "design/project/project.hpp"

namespace spiral::design {

/// `<base>@h<heading>`: the generated environment (and intact case) name.
std::string matrix_case_name(const std::string& base_environment, double heading_rad);

/// The load cases an entry generates (names, environments, damaged lines,
/// conditions), in the order above. `project` gives the line order.
std::vector<LoadCase> matrix_load_cases(const Project& project, const LoadCaseMatrixEntry& entry);

/// Appends the generated environments and load cases of every entry to
/// `project` (the entries must be valid: project_validation checks them).
void expand_load_case_matrix(Project& project);

}  // namespace spiral::design
