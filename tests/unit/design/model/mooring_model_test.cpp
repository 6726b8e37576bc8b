// The project's mooring lines as engine lines: an FE line's mesh follows its
// `fe` map, including the refinement around the at-rest touchdown point.
#include "design/model/mooring_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "design/project/project_loader.hpp"
#include "engine/analysis/fe_static_line.hpp"

namespace spiral::design {
namespace {

// Node spacing is whole elements of at most the target length; round-off of
// the arc-length sums on a 835 m line stays far below a micrometre.
constexpr double kMeshSlack_m = 1e-6;

const engine::FeStaticLine& fe_line(const LineArrayModel& model, const std::string& name) {
  for (const auto& line : model.lines) {
    if (line->name() == name) return dynamic_cast<const engine::FeStaticLine&>(*line);
  }
  throw std::runtime_error("no line " + name);
}

TEST(MooringModel, FeLineIsRefinedAroundItsAtRestTouchdown) {
  // Format sample, line L3: OC4 chain (835.35 m), model fe, 8 m elements,
  // refined to 2 m over 100 m around the TDP.
  Project project = load_project(std::string(SPIRAL_SOURCE_DIR) + "/tests/data/format-sample.yaml");
  LineArrayOptions options;
  options.include_risers = false;
  const LineArrayModel refined = build_line_array(project, options);
  const engine::FeStaticLine& line = fe_line(refined, "L3");
  ASSERT_TRUE(line.model().refinement.has_value());
  const engine::FeRefinementZone zone = *line.model().refinement;
  EXPECT_DOUBLE_EQ(zone.length_m, 100.0);
  EXPECT_DOUBLE_EQ(zone.element_length_m, 2.0);

  // The zone is centred on the at-rest catenary's touchdown point.
  const auto& l3 = project.mooring.lines[2];
  const Eigen::Vector3d fairlead_g = project.hull.reference_point_g + l3.fairlead_b;
  const auto catenary = catenary_of(project, l3, resolve_line_types(project));
  const double laid_m = engine::solve_catenary(catenary, {(fairlead_g - l3.anchor_g).head<2>().norm(),
                                                          fairlead_g.z() - l3.anchor_g.z(), 0.0})
                            .laid_length_m;
  ASSERT_GT(laid_m, 0.0);
  EXPECT_NEAR(zone.start_arc_length_m + 0.5 * zone.length_m, laid_m, kMeshSlack_m);

  // Inside the zone the elements are no longer than 2 m, outside 8 m.
  const std::vector<double> mesh = engine::fe_line_mesh(line.model());
  for (std::size_t i = 1; i < mesh.size(); ++i) {
    const double mid = 0.5 * (mesh[i - 1] + mesh[i]);
    const bool inside = mid > zone.start_arc_length_m && mid < zone.start_arc_length_m + zone.length_m;
    EXPECT_LE(mesh[i] - mesh[i - 1], (inside ? 2.0 : 8.0) + kMeshSlack_m) << "element " << i;
  }

  // Without the refinement the mesh is the uniform 8 m one: fewer nodes.
  project.mooring.lines[2].fe.touchdown_refinement.reset();
  const LineArrayModel uniform = build_line_array(project, options);
  const std::vector<double> uniform_mesh = engine::fe_line_mesh(fe_line(uniform, "L3").model());
  EXPECT_FALSE(fe_line(uniform, "L3").model().refinement.has_value());
  EXPECT_GT(mesh.size(), uniform_mesh.size() + 30);  // 100 m at 2 m instead of 8 m: ≈ 37 more nodes
  RecordProperty("nodes_refined", static_cast<int>(mesh.size()));
  RecordProperty("nodes_uniform", static_cast<int>(uniform_mesh.size()));

  // The FE solution at rest touches down inside the refined zone.
  engine::FeStaticLine solved = line;
  solved.solve(fairlead_g);
  ASSERT_TRUE(solved.last_result()->touchdown.has_value());
  const double tdp_m = solved.last_result()->touchdown->arc_length_m;
  EXPECT_GT(tdp_m, zone.start_arc_length_m);
  EXPECT_LT(tdp_m, zone.start_arc_length_m + zone.length_m);
}

}  // namespace
}  // namespace spiral::design
