#include "report/stage_scene.hpp"

#include <cmath>

#include "engine/analysis/line_array.hpp"

namespace spiral::report {

Scene stage_scene(const design::Project& project, const design::StaticCaseResult& result,
                  const std::vector<design::LineStrength>& strengths, double safety_factor,
                  const std::vector<engine::Panel>& hull_panels_b) {
  Scene scene;
  scene.depth_m = project.site.depth_m;
  scene.value_label = "Utilization";
  const engine::HullPose pose = engine::pose_from_offset(project.hull.reference_point_g, result.offset);
  scene.hull.reference_point_g = pose.reference_point_g;
  scene.hull.rotation = pose.rotation;
  scene.hull.geometry = project.hull.geometry;
  scene.hull.panels_b = hull_panels_b;
  if (!project.hull.geometry) {
    // A box of the waterplane area and the draft V / A_wp, with a freeboard of half the draft.
    const double area = project.hull.waterplane_area_m2.value_or(2500.0);
    const double draft = project.hull.displaced_volume_m3.value_or(area * 20.0) / area;
    const double side = std::sqrt(area);
    scene.hull.box_size_m = {side, side, 1.5 * draft};
    scene.hull.box_bottom_b_m = -draft;
  }
  for (const design::LineStaticsRow& row : result.lines) {
    SceneLine line;
    line.name = row.name;
    const design::LineStrength* strength = nullptr;
    for (const auto& s : strengths)
      if (s.name == row.name) strength = &s;
    for (const engine::LineProfilePoint& p : row.profile) {
      line.points_g.push_back(p.position_g);
      const auto seg = static_cast<std::size_t>(p.segment);
      const double mbl = strength && seg < strength->segment_mbl_N.size() ? strength->segment_mbl_N[seg] : 0.0;
      line.values.push_back(mbl > 0.0 ? p.tension_N * safety_factor / mbl : 0.0);
    }
    if (!line.points_g.empty()) {
      scene.anchors_g.push_back(line.points_g.front());
      scene.fairleads_g.push_back(line.points_g.back());
    }
    scene.lines.push_back(std::move(line));
  }
  for (const design::RiserStaticsRow& riser : result.risers) {
    SceneLine line;
    line.name = riser.name;
    // Risers on the same colour scale as the lines, by their own utilization
    // per node: von Mises over the steel wall (API RP 2RD design factor), or
    // for a flexible pipe its curvature against the minimum bending radius.
    const design::Riser* model = nullptr;
    for (const design::Riser& r : project.risers)
      if (r.name == riser.name) model = &r;
    // MBR > 0 when given (validated); 0 stands for none.
    const double mbr_m =
        model ? design::riser_criteria(project.criteria, *model).min_bending_radius_m.value_or(0.0) : 0.0;
    for (const design::RiserProfilePoint& p : riser.profile) {
      line.points_g.push_back(p.position_g);
      double u = p.von_mises_utilization.value_or(0.0);
      if (!p.von_mises_utilization && mbr_m > 0.0) u = p.curvature_per_m * mbr_m;
      line.values.push_back(u);
    }
    line.riser = true;
    scene.lines.push_back(std::move(line));
  }
  return scene;
}

}  // namespace spiral::report
