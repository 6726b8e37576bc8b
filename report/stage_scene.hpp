#pragma once
// The 3D scene of a stage's static result: the hull at the case's
// equilibrium pose, every mooring line as its computed profile coloured by
// code utilization along it (T · SF / MBL of the segment the point is on),
// risers, anchors and fairleads.

#include <vector>

#include "design/project/project.hpp"
#include "design/analysis/static_case.hpp"
#include "design/stages/static_stage.hpp"
#include "report/scene.hpp"

namespace spiral::report {

/// `safety_factor` is the case's mooring safety factor (design::CaseCheck);
/// `hull_panels_b`: the hull's panel mesh (StaticStageResults::hull_panels_b), drawn when not empty.
Scene stage_scene(const design::Project& project, const design::StaticCaseResult& result,
                  const std::vector<design::LineStrength>& strengths, double safety_factor,
                  const std::vector<engine::Panel>& hull_panels_b = {});

}  // namespace spiral::report
