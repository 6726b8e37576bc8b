#pragma once
// Linear (Airy) wave velocity and acceleration of a realization at a fixed
// set of points, for the dynamic FE lines: each element takes the
// kinematics at its midpoint, a point the line moves when the element has
// drifted from it (fe_line_dynamics.hpp).
//
// Why fixed points: a direct sum over the realization's components (2200
// for a short-crested 3-h sea: 200 frequencies × 11 directions) at every
// Gauss point and Newton iteration costs several times the whole line
// residual (docs/decisions/coupled-dynamics-performance.md). At a fixed point
// x0 the phase of each component splits into a time part and a space part,
//   cos(ω t − k·x0 + φ) = cos ω t · cos ψ − sin ω t · sin ψ,  ψ = φ − k·x0,
// so the amplitudes a ω f(z0) cos ψ, a ω f(z0) sin ψ are computed once and
// each time costs one sin/cos per component for all points plus ≈ 20
// multiply-adds per component and point. The error of holding a point
// fixed is the phase k Δ of the element's excursion Δ from it: for the
// points' static positions k σ ≈ 0.03 rad/m × 1–3 m = 0.03–0.1 rad in the
// deep-water storm (surge std 1.1 m) — MoorDyn's original approach
// (kinematics at the nodes' initial positions, Hall 2015); the lines move a
// point when its element has drifted from it (move_point).
//
// Profiles: linear theory (DNV-RP-C205 §3.2.2) with Wheeler stretching
// (§3.2.3) to second order in k Δz about the point's z (evaluate() says
// how), η from the point's kept components; a point above the instantaneous
// surface is dry (zero), as is one above the still-water level at rest.
// Components whose depth profile has decayed below `cutoff` of its surface
// value are left out of a point's sum, and a point where all of them have
// is flagged still.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/environment/wave_realization.hpp"

namespace spiral::engine {

class FixedPointWaveKinematics {
 public:
  /// `points`: global positions (z up from the still-water level).
  FixedPointWaveKinematics(std::shared_ptr<const WaveRealization> sea, const std::vector<Eigen::Vector3d>& points,
                           double cutoff = 1e-3);

  std::size_t size() const { return points_.size(); }
  /// Where a point's kinematics are evaluated (global).
  const Eigen::Vector3d& position(std::size_t point) const { return points_[point].position_m; }
  /// Moves a point: its amplitudes are computed anew at `position` (one
  /// sin/cos pair and depth profile per component it keeps). Not while
  /// another thread evaluates this object.
  void move_point(std::size_t point, const Eigen::Vector3d& position);
  /// True where no component reaches the point (deep, or above the water).
  bool still(std::size_t point) const { return points_[point].count == 0; }

  /// Velocity and local acceleration at every point at time t (global).
  void evaluate(double t_s, std::vector<Eigen::Vector3d>& velocity_m_per_s,
                std::vector<Eigen::Vector3d>& acceleration_m_per_s2) const;
  /// The same at one point only (its own sin/cos of ω t: for a single
  /// element's forces at a time the line is not otherwise evaluated at).
  void evaluate_point(double t_s, std::size_t point, Eigen::Vector3d& velocity_m_per_s,
                      Eigen::Vector3d& acceleration_m_per_s2) const;

 private:
  struct Point {
    std::size_t count = 0;                           // components kept: the first `count` by wavenumber
    std::vector<double> horizontal_c, horizontal_s;  // a ω f_h cos ψ, a ω f_h sin ψ
    std::vector<double> vertical_c, vertical_s;      // a ω f_v cos ψ, a ω f_v sin ψ
    std::vector<double> elevation_c, elevation_s;    // a cos ψ, a sin ψ
    double z_m = 0.0;
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  };
  void set_point(Point& out, const Eigen::Vector3d& position);
  /// cos ω_j t, sin ω_j t of the first `count` (sorted) components.
  void time_phases(double t_s, std::size_t count, double* cos_wt, double* sin_wt) const;
  void at_point(const Point& pt, const double* cos_wt, const double* sin_wt, Eigen::Vector3d& velocity,
                Eigen::Vector3d& acceleration) const;

  std::shared_ptr<const WaveRealization> sea_;
  std::vector<std::size_t> order_;                                      // components by increasing wavenumber
  std::vector<double> omega_, wavenumber_, cos_heading_, sin_heading_;  // in that order
  std::vector<Point> points_;
  std::size_t max_count_ = 0;  // the most components any point keeps (or kept)
  double log_cutoff_ = 0.0;
  mutable std::vector<double> cos_wt_, sin_wt_;  // per component (sorted), of the last t
};

}  // namespace spiral::engine
