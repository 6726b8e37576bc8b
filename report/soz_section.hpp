#pragma once
// The riser safe operational zone section of a stage report (DESIGN.md §7,
// §9): a plan view with each riser's allowable-offset polygon, the platform
// zone (their intersection) drawn boldly and every load case's offset
// (intact / damaged, static / extreme), the near/far/cross table per riser,
// the platform zone per direction and the offset check. Reads results only.

#include "design/static_stage.hpp"
#include "report/document.hpp"

namespace spiral::report {

/// Requires results.soz. `offset_limit_m`: the project's offset limit circle, if any.
Section soz_section(const design::StaticStageResults& results, std::optional<double> offset_limit_m);

}  // namespace spiral::report
