#include "design/project/payout_groups.hpp"

#include <algorithm>

namespace spiral::design {

namespace {

std::optional<std::size_t> line_index(const Project& project, const std::string& name) {
  for (std::size_t i = 0; i < project.mooring.lines.size(); ++i)
    if (project.mooring.lines[i].name == name) return i;
  return std::nullopt;
}

struct Selection {
  std::vector<PayoutGroup> groups;
  std::vector<std::string> skipped;
};

Selection select(const Project& project) {
  Selection out;
  const std::vector<LineGroup>& defined = project.mooring.groups;
  std::vector<std::size_t> chosen;  // indices into mooring.groups
  if (project.optimization && !project.optimization->groups.empty()) {
    for (const std::string& name : project.optimization->groups) {
      const auto it = std::find_if(defined.begin(), defined.end(), [&](const LineGroup& g) { return g.name == name; });
      if (it != defined.end()) chosen.push_back(static_cast<std::size_t>(it - defined.begin()));
    }
  } else {
    for (std::size_t g = 0; g < defined.size(); ++g) chosen.push_back(g);
  }
  const bool explicit_list = project.optimization && !project.optimization->groups.empty();
  std::vector<bool> taken(project.mooring.lines.size(), false);
  for (const std::size_t g : chosen) {
    PayoutGroup group{defined[g].name, {}, g};
    bool overlaps = false;
    for (const std::string& name : defined[g].lines) {
      const std::optional<std::size_t> i = line_index(project, name);
      if (!i) continue;
      overlaps = overlaps || taken[*i];
      group.lines.push_back(*i);
    }
    // An explicit list is checked for overlaps by the validation; the default
    // rule skips a group that repeats lines of an earlier one.
    if ((overlaps && !explicit_list) || group.lines.empty()) {
      out.skipped.push_back(group.name);
      continue;
    }
    for (const std::size_t i : group.lines) taken[i] = true;
    out.groups.push_back(std::move(group));
  }
  for (std::size_t i = 0; i < project.mooring.lines.size(); ++i) {
    if (!taken[i]) out.groups.push_back({project.mooring.lines[i].name, {i}, std::nullopt});
  }
  return out;
}

}  // namespace

std::vector<PayoutGroup> payout_groups(const Project& project) { return select(project).groups; }

std::vector<std::string> skipped_overlapping_groups(const Project& project) { return select(project).skipped; }

}  // namespace spiral::design
