#pragma once
// The riser safe operational zone section of a stage report (DESIGN.md §7,
// §9): a plan view with each riser's allowable-offset polygon, the platform
// zone (their intersection) drawn boldly and every load case's offset
// (intact / damaged, static / extreme), the near/far/cross table per riser,
// the platform zone per direction and the offset check. Reads results only.

#include <optional>
#include <vector>

#include "design/soz/soz.hpp"
#include "report/document.hpp"

namespace spiral::report {

/// `zone` with its static offset checks; `extremes`: MPM offsets of storms
/// (kind extreme); `offset_limit_m`: the project's offset limit circle, if any.
Section soz_section(const design::SozResult& zone, const std::vector<design::OffsetCheck>& extremes,
                    std::optional<double> offset_limit_m);

}  // namespace spiral::report
