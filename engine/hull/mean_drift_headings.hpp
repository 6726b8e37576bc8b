#pragma once
// Mean drift at wave headings a database does not hold: exact images under
// the hull's symmetry, and an explicit, bounded wave-frame fill between the
// headings it then has.
//
// Symmetry. A hull that a rotation R by φ about the vertical, or the mirror
// P: y → −y, maps onto itself is loaded alike by the mapped wave: for the
// rotation D(β + φ) = R D(β) on the force (Fx, Fy) and on the moment
// (Mx, My), heave and yaw unchanged; for the mirror D(−β) = (Fx, −Fy, Fz,
// −Mx, My, −Mz) — a moment is a pseudovector, M' = det(P) P M (any text on
// the symmetry of rigid-body loads, e.g. Newman, Marine Hydrodynamics §6.17
// for the added-mass form of the argument). `rotations` = n and `mirror_xz`
// name the group C_n or D_n (a three-column semi with one column on the
// x-axis: D_3, data at 0° then give 0°, 120° and 240°).
//
// Wave-frame fill (an approximation, named as such where it is used). Between
// two tabulated headings β0 < β < β1 the coefficients are interpolated
// linearly in heading *in the wave frame* — the force and the roll/pitch
// moment turned by −β_j to along/across the wave at each end — and turned
// back by β. It keeps a drift force that points along the waves at both ends
// along the waves at β, with the magnitude interpolated, where interpolating
// body-frame components across 120° would shrink it (to half at 60°). It
// assumes the hull's drift in the wave frame varies linearly between the
// data: true for an axisymmetric hull, an approximation for anything else.
// Its reach is bounded, not its error (the data cannot tell that): only a gap
// between neighbouring tabulated headings (around the circle) no wider than
// `max_span_rad` is filled, so no filled heading lies farther than half of it
// from data; a wider gap stays as the loads treat any table (linear between
// neighbours, no extrapolation past the ends). The filled gaps hold a heading
// every ≤ `step_rad`, so the loads' body-frame interpolation between them
// turns a vector of fixed magnitude with a relative error ≤ 1 − cos(step/2)
// (9.5e-4 at 5°).
//
// Both return a new table that mean_environmental_loads.hpp and
// slow_drift.hpp use as they use a file's; neither extrapolates in frequency.

#include <numbers>

#include "engine/hull/mean_environmental_loads.hpp"

namespace spiral::engine {

/// The hull's symmetry group in the horizontal plane: `rotations`-fold about
/// the vertical axis (1: none), with or without the x–z plane as a mirror.
struct HullSymmetry {
  int rotations = 1;       ///< n ≥ 1: the hull maps onto itself turned by 360°/n
  bool mirror_xz = false;  ///< the hull maps onto itself under y → −y
};

/// `table` with every heading the symmetry maps its headings to. An image
/// that lands on a heading the table already holds (within 1e-6 rad) must
/// agree with it to `relative_tolerance` of the table's largest force (DOFs
/// 1–3) or moment (4–6) coefficient, else the table is not as symmetric as
/// declared: std::invalid_argument naming the heading, the DOF and the
/// difference. Throws std::invalid_argument for rotations < 1.
MeanDriftTable with_symmetry_images(const MeanDriftTable& table, const HullSymmetry& symmetry,
                                    double relative_tolerance = 1e-3);

/// How the wave-frame fill works (header).
struct WaveFrameFill {
  double max_span_rad = 0.0;                         ///< > 0: the widest gap between data filled
  double step_rad = 5.0 * std::numbers::pi / 180.0;  ///< > 0: the largest spacing of filled headings
};

/// `table` with headings at most `fill.step_rad` apart in every gap between
/// neighbouring tabulated headings (around the circle) no wider than
/// `fill.max_span_rad`, by the wave-frame interpolation of the header. A
/// table with one heading has one gap, the whole circle: filled (its
/// wave-frame coefficients held) when max_span ≥ 2π. Throws
/// std::invalid_argument for a non-positive span or step.
MeanDriftTable filled_in_wave_frame(const MeanDriftTable& table, const WaveFrameFill& fill);

}  // namespace spiral::engine
