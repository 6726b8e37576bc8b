#pragma once
// Risers whose safe operational zones follow from another riser's zone — or
// from the other half of their own — by an isometry of the horizontal plane:
// a rotation about the vertical or a reflection in a vertical plane. Used by
// compute_soz to solve each distinct zone once.

#include <vector>

#include "design/soz/soz.hpp"

namespace spiral::design {

/// How a riser's zone is obtained on the direction grid (n directions).
struct SozZoneMap {
  /// Riser whose zone this one copies; −1: this riser is solved.
  int source = -1;
  /// Copy by reflection (else rotation): direction k is the source's
  /// direction `index` − k (mod n); by rotation it is k − `index`.
  bool mirrored = false;
  int index = 0;
  /// For a solved riser that is its own mirror image (the plane through its
  /// foot and hang-off falls on the grid): direction k equals direction
  /// `self_mirror_index` − k (mod n), so only the half from the mirror plane
  /// anticlockwise is solved. −1: no such symmetry.
  int self_mirror_index = -1;
};

/// Per riser (in order), how its zone is found. Nothing is shared when
/// `options.exploit_symmetry` is off, a current acts on an FE riser, or the
/// hull is rotated.
std::vector<SozZoneMap> soz_zone_maps(const Project& project, const std::vector<RiserDesign>& risers,
                                      const SozConditions& conditions, const SozOptions& options, int n_directions);

/// Whether direction k of a self-mirror riser is in the solved half:
/// its angle from the mirror plane, anticlockwise, is within [0°, 180°].
bool soz_in_solved_half(int k, int self_mirror_index, int n_directions);

}  // namespace spiral::design
