#include "design/optimization/pretension_target.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "design/model/mooring_model.hpp"
#include "engine/common/stopwatch.hpp"
#include "engine/lines/catenary_payout.hpp"

namespace spiral::design {

TargetPretensionResult solve_target_pretensions(const Project& project) {
  engine::Stopwatch start;
  if (!project.optimization || project.optimization->target_pretension.empty()) {
    InputIssue issue;
    issue.file = project.source_file;
    issue.path = "optimization.target_pretension";
    issue.message = "the project gives no target pretensions (optimization.target_pretension: [{group, tension}])";
    issue.problem = "target_pretension_given";
    throw InputError({issue});
  }
  const std::vector<LineTypeProperties> types = resolve_line_types(project);
  const std::vector<GroupVariable> groups = group_variables(project);
  TargetPretensionResult result;
  result.project = project.name;
  for (const PretensionTarget& target : project.optimization->target_pretension) {
    const GroupVariable& group =
        *std::find_if(groups.begin(), groups.end(), [&](const GroupVariable& g) { return g.name == target.group; });
    for (const std::string& name : group.lines) {
      const MooringLine& line = mooring_line(project, name);
      const engine::CatenaryGeometry at_rest = catenary_geometry_at_rest(project, line);
      const engine::CatenaryLine catenary = catenary_of(project, line, types);
      TargetPretensionRow row;
      row.line = name;
      row.group = group.name;
      row.target_N = target.tension_N;
      row.pretension_before_N = pretension_at_rest_N(project, line, types);
      try {
        const engine::PayoutForTension solved =
            engine::payout_for_fairlead_tension(catenary, at_rest, target.tension_N, {group.min_m, group.max_m});
        row.payout_m = solved.payout_m;
        row.pretension_after_N = solved.fairlead_tension_N;
        row.iterations = solved.iterations;
      } catch (const engine::SolverError& error) {
        throw engine::SolverError(fmt::format("line {} (group {}): {}", name, group.name, error.what()));
      }
      row.top_segment_after_m = line.segments.back().length_m + row.payout_m;
      result.lines.push_back(std::move(row));
    }
  }
  result.wall_s = start.seconds();
  return result;
}

}  // namespace spiral::design
