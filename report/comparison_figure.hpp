#pragma once
// The four analysis levels' trade-off at a glance (`spiral compare`): per
// level, the horizontal offset's standard deviation and 3-h MPM, the most
// loaded line's dynamic top-tension MPM (mooring line or riser), and the wall-clock
// cost, each bar labelled with its difference against the coupled run (and
// the cost with its speed-up) — the accuracy the simpler levels keep and
// what they save, the comparison DESIGN.md §1 asks the product to show.

#include "design/analysis/level_comparison.hpp"
#include "report/document.hpp"

namespace spiral::report {

/// A 2 × 2 panel figure (id "comparison"); the most loaded line is the one,
/// mooring line or riser, with the largest coupled MPM of the dynamic top
/// tension (else of any level that has one).
Figure comparison_figure(const design::LevelComparison& comparison);

}  // namespace spiral::report
