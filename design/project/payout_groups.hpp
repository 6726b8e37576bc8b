#pragma once
// The groups of mooring lines that the pretension optimizer pays out
// together (one design variable each), from `optimization.groups` or the
// default rule of docs/project-format.md: the project's `mooring.groups` in
// order, a group skipped when it shares a line with an earlier one (so a
// catch-all group such as "all" after the clusters adds nothing), and every
// line in no chosen group its own group, named after the line.

#include <string>
#include <vector>

#include "design/project/project.hpp"

namespace spiral::design {

struct PayoutGroup {
  std::string name;
  std::vector<std::size_t> lines;  ///< indices into mooring.lines
  /// Index of the `mooring.groups` entry, or none for a line on its own.
  std::optional<std::size_t> project_group;
};

/// The variables' groups. Names that `optimization.groups` gives but the
/// project does not define are skipped (validation reports them).
std::vector<PayoutGroup> payout_groups(const Project& project);

/// Names of the groups skipped by the default rule (for the study's notes).
std::vector<std::string> skipped_overlapping_groups(const Project& project);

}  // namespace spiral::design
