#pragma once
// The dynamics section of a stage report: the S-C storm of one load case —
// time series of surge, sway, yaw and the horizontal offset, their Welch
// spectra, the quasi-static fairlead tension of the most loaded line, the
// statistics table (mean, std, extremes, MPM) with the level and the
// wall-clock cost, and the dynamic checks. Reads results only.

#include "design/stages/stage_dynamics.hpp"
#include "report/document.hpp"
#include "report/plot.hpp"

namespace spiral::report {

Section dynamics_section(const design::StageDynamics& dynamics, const std::string& code);

/// Figures and tables of one storm, for sections that show several (ids carry `id_prefix`).
std::vector<Block> storm_blocks(const design::StageDynamics& dynamics, const std::string& id_prefix);

/// A time series thinned for the page: the min and max of each of at most
/// 1500 bins, in time order (every peak stays visible), times `scale`.
Series time_envelope(const std::vector<double>& t, const std::vector<double>& v, double scale);
/// Output steps per plotted bin of a record of `samples` samples.
std::size_t envelope_bin_samples(std::size_t samples);

/// Plots in panels of one figure, `cols` per row.
Figure plot_panels(std::string id, std::string caption, double aspect, std::vector<Plot> plots, int cols);

}  // namespace spiral::report
