#pragma once
// The dynamics section of a stage report: the S-C storm of one load case —
// time series of surge, sway, yaw and the horizontal offset, their Welch
// spectra, the quasi-static fairlead tension of the most loaded line, the
// statistics table (mean, std, extremes, MPM) with the level and the
// wall-clock cost, and the dynamic checks. Reads results only.

#include "design/stage_dynamics.hpp"
#include "report/document.hpp"

namespace spiral::report {

Section dynamics_section(const design::StageDynamics& dynamics, const std::string& code);

/// Figures and tables of one storm, for sections that show several (ids carry `id_prefix`).
std::vector<Block> storm_blocks(const design::StageDynamics& dynamics, const std::string& id_prefix);

}  // namespace spiral::report
