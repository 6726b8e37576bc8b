#pragma once
// The platform safe operational zone as a smooth function of direction, for
// the pretension optimizer's offset constraint ρ / A(θ) ≤ 1: the zone the
// checks use (soz.hpp: per riser a polar polygon, linear in angle between
// grid directions; the platform the smallest of them) has kinks at every
// grid direction and wherever the governing riser changes, where a gradient
// method's constraint would have no derivative.
//
// Construction: the platform zone is sampled every 0.25° and interpolated
// by a periodic monotone cubic (Fritsch & Carlson, SIAM J. Numer. Anal. 17,
// 1980: C¹, no overshoot beyond the neighbouring samples); the curve is then
// lowered by its largest excess over the polygon zone found on a 0.01° grid,
// so that a point inside the smooth zone is inside the checked zone. The
// lowering is reported (`conservatism_m`): it comes from the kinks where the
// governing riser changes, and is a few decimetres on the default scenario's
// 15° screening zone (of allowable offsets above 100 m).

#include <functional>
#include <vector>

namespace spiral::design {

class SmoothZone {
 public:
  /// `allowable_of(direction_deg)`: the zone as checked (m), periodic in 360°.
  explicit SmoothZone(const std::function<double(double)>& allowable_of);

  /// Allowable offset (m) in direction θ (rad, CCW from +x).
  double allowable_m(double direction_rad) const;
  /// dA/dθ, m/rad.
  double slope_m_per_rad(double direction_rad) const;
  /// How far the interpolant was lowered to stay inside the checked zone, m.
  double conservatism_m() const { return conservatism_m_; }

 private:
  std::vector<double> values_m_;         ///< every 0.25 deg from 0
  std::vector<double> slopes_per_step_;  ///< m per sample step
  double conservatism_m_ = 0.0;

  double raw(double direction_deg, double* slope_per_deg) const;
};

}  // namespace spiral::design
