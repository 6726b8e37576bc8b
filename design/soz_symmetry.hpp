#pragma once
// Risers whose safe operational zones are the same zone turned about the
// vertical (soz.hpp: same design, criteria and hang-off depth, azimuths a
// whole number of grid steps apart, no current on an FE riser, no hull
// rotation). Used by compute_soz.

#include <vector>

#include "design/soz.hpp"

namespace spiral::design {

/// Per riser, the index of an earlier riser whose zone is its zone turned by
/// `shift[r]` grid steps (of `n_directions`), or −1 when it must be solved.
std::vector<int> soz_rotation_sources(const Project& project, const std::vector<RiserDesign>& risers,
                                      const SozConditions& conditions, const SozOptions& options,
                                      int n_directions, std::vector<int>& shift);

}  // namespace spiral::design
