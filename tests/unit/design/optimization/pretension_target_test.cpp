// Target-pretension mode on both shipped scenarios: every line of every
// group reaches its target at rest to 0.1 % (the solve converges to 1e-8).

#include "design/optimization/pretension_target.hpp"

#include <gtest/gtest.h>

#include "design/model/mooring_model.hpp"
#include "engine/lines/catenary_payout.hpp"

namespace spiral::design {
namespace {

void check_targets(const std::string& scenario, double factor) {
  ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/" + scenario);
  p.project.optimization = Optimization{};
  const std::vector<LineTypeProperties> types = resolve_line_types(p.project);
  // Each group's target: `factor` times the pretension of its first line now.
  for (const GroupVariable& g : group_variables(p.project)) {
    const MooringLine& first = *std::find_if(p.project.mooring.lines.begin(), p.project.mooring.lines.end(),
                                             [&](const MooringLine& l) { return l.name == g.lines.front(); });
    const double now =
        engine::solve_catenary(catenary_of(p.project, first, types), catenary_geometry_at_rest(p.project, first))
            .fairlead_tension_N;
    p.project.optimization->target_pretension.push_back({g.name, factor * now});
  }
  const TargetPretensionResult r = solve_target_pretensions(p.project);
  ASSERT_EQ(r.lines.size(), p.project.mooring.lines.size());
  for (const TargetPretensionRow& row : r.lines) {
    const MooringLine& line = *std::find_if(p.project.mooring.lines.begin(), p.project.mooring.lines.end(),
                                            [&](const MooringLine& l) { return l.name == row.line; });
    // Independent check: the line with the payout, solved at rest.
    const double reached =
        engine::solve_catenary(engine::with_payout(catenary_of(p.project, line, types), row.payout_m),
                               catenary_geometry_at_rest(p.project, line))
            .fairlead_tension_N;
    EXPECT_NEAR(reached, row.target_N, 1e-3 * row.target_N) << scenario << " " << row.line;
    EXPECT_NEAR(reached, row.target_N, 1e-7 * row.target_N) << scenario << " " << row.line;
  }
}

TEST(PretensionTarget, DefaultScenarioLinesReachTheirTargets) {
  check_targets("deepwater-fps.yaml", 1.10);
  check_targets("deepwater-fps.yaml", 0.92);
}

TEST(PretensionTarget, Oc4LinesReachTheirTargets) {
  check_targets("oc4-semisubmersible.yaml", 1.15);
  check_targets("oc4-semisubmersible.yaml", 0.90);
}

TEST(PretensionTarget, UnreachableTargetNamesTheLine) {
  ValidatedProject p = load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  p.project.optimization = Optimization{};
  p.project.optimization->payout_limit_pct = 0.1;  // ± 0.8 m
  p.project.optimization->target_pretension = {{"all", 3.0e6}};
  try {
    solve_target_pretensions(p.project);
    FAIL() << "expected SolverError";
  } catch (const engine::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("line L1 (group all)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("above the tension"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spiral::design
