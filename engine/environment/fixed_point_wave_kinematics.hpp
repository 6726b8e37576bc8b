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
// (kinematics at the nodes' initial positions, Hall 2015). The lines take
// the gradients as well and carry each value to where the line now is, to
// first order (the error (k Δ)²/2), and move a point when it has drifted
// far enough for that to matter (move_point).
//
// Profiles: linear theory (DNV-RP-C205 §3.2.2) with Wheeler stretching
// (§3.2.3) to second order in k Δz about the point's z (evaluate() says
// how), η from the point's kept components; a point above the instantaneous
// surface is dry (zero), as is one above the still-water level at rest.
// Components whose depth profile has decayed below `cutoff` of its surface
// value are left out of a point's sum, and a point where all of them have
// is flagged still.
//
// Sampled in time (`sample_interval_s` > 0): the sums are taken at the grid
// times i Δ only, kept for the last few, and a time between is the cubic
// Lagrange interpolant of the four grid samples around it — what MoorDyn v2
// does with its wave-kinematics time series (WaveKin 2/3, Hall). A
// component of frequency ω errs by at most c (ω Δ)⁴ of its amplitude,
// c = (9/16)/24 (the Lagrange remainder on the middle interval); the
// default interval holds the rms error of the acceleration, summed over the
// components, to 1e-2 of the rms acceleration: ω_max Δ ≈ 1.07 for a JONSWAP
// sea cut at 5 ω_p, Δ ≈ 0.50 s at Tp 14 s, where an IDA step of the coupled
// storm is ≈ 0.08 s. 1e-3 (Δ 0.28 s) moved no statistic of the deep-water
// storms by more than 0.02 % against it (lc1 600 s, lc5 300 s, 2026-12-08)
// and cost 1.8× the sums. The wet/dry test is
// exact in form: η is interpolated as well and a point above it is dry; a
// point dry at any of the four samples (the kinematics jump to zero there,
// which no polynomial follows) is summed directly at t. A moved point's
// held samples are summed anew when they are next used, under the phases the
// slot keeps: a point that moves at every output costs one sum per grid
// sample it is read at, not one sin/cos per component and held sample.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "engine/environment/wave_realization.hpp"

namespace spiral::engine {

class FixedPointWaveKinematics {
 public:
  /// `points`: global positions (z up from the still-water level).
  /// `sample_interval_s`: 0 sums at every time asked; > 0 samples the sums
  /// on that grid and interpolates between (see above).
  FixedPointWaveKinematics(std::shared_ptr<const WaveRealization> sea, const std::vector<Eigen::Vector3d>& points,
                           double cutoff = 1e-3, double sample_interval_s = 0.0);

  /// The grid interval at which the interpolated acceleration's rms error
  /// is kSampledAccelerationError of the rms acceleration (see above), at
  /// most kMaxSampleInterval_s.
  static double default_sample_interval_s(const WaveRealization& sea);
  static constexpr double kSampledAccelerationError = 1e-2;
  static constexpr double kMaxSampleInterval_s = 1.0;
  double sample_interval_s() const { return interval_s_; }

  /// How far one point's velocity may stand for a straight piece of line
  /// `length_m` long whose highest point is at `top_z_m`: the mean over the
  /// piece of each component's depth profile and phase differs from their
  /// value at its middle by at most (k ℓ)²/24 of it (the mean of e^{k x}
  /// over ±ℓ/2 is sinh(kℓ/2)/(kℓ/2) = 1 + (kℓ)²/24 + …, and of e^{i k x}
  /// likewise), so this returns Σ a ω f_h(top) (k ℓ)²/24 / Σ a ω: the error
  /// bound as a fraction of the sea's velocity amplitude at the still-water
  /// level.
  static double midpoint_error(const WaveRealization& sea, double top_z_m, double length_m);

  /// How the dynamic FE lines use the points (engine/lines/fe_dynamic_line.hpp,
  /// fluid_at): each Gauss point takes its point's value carried to where it
  /// is by the gradients, to first order, and a point moves when it has
  /// drifted this far. The term left out is (k Δ)²/2 of a component, 7e-4 at
  /// a 13 s wave's k = 0.024 rad/m (the 0.5 m jumps before the gradients
  /// erred by k Δ: 0.012 rad). Each move sums the point anew and is a
  /// (second-order) jump in the forcing: deep-water lc1 storm, 600 s, 7,506
  /// steps at 0.5 m, 7,594 at 2 m, every statistic the same within 0.03 %
  /// (docs/decisions/global-analysis-mesh.md).
  static constexpr double kLinePointDrift_m = 2.0;
  /// An element of a line takes the sea at its five Gauss points instead of
  /// its midpoint where the midpoint would err by more than this fraction of
  /// the sea's velocity amplitude at the still-water level (midpoint_error):
  /// in a Tp 14 s sea the top 40 m element below the −28 m fairleads
  /// (1.4–2.3e-2), not the next (≈ 6e-3); shorter seas reach deeper.
  /// Deep-water lc1, 600 s, against the own meshes at 0.03 of the
  /// tolerances: the mooring tensions' std within 0.17 % (0.07 % at 1e-3:
  /// four elements a line, +9 % of the dynamics' instructions; 0.39 % with
  /// midpoints only) (docs/decisions/global-analysis-mesh.md).
  static constexpr double kWaveZoneMidpointError = 1e-2;

  std::size_t size() const { return points_.size(); }
  /// Where a point's kinematics are evaluated (global).
  const Eigen::Vector3d& position(std::size_t point) const { return points_[point].position_m; }
  /// Moves a point: its amplitudes are computed anew at `position` (one
  /// sin/cos pair and depth profile per component it keeps); its held
  /// samples are summed anew where next read. Not while another thread
  /// evaluates this object.
  void move_point(std::size_t point, const Eigen::Vector3d& position);
  /// How many times the sums over every point were taken (direct
  /// evaluations, or grid samples when sampled in time).
  long full_sums() const { return full_sums_; }
  /// True where no component reaches the point (deep, or above the water).
  bool still(std::size_t point) const { return points_[point].count == 0; }

  /// ∂u_i/∂x_j and ∂a_i/∂x_j at a point (symmetric: the flow is
  /// irrotational; trace 0: incompressible), of the unstretched linear
  /// fields: u(p + d) = u(p) + G_u d + O((k d)²) for a position near the
  /// point, which is how a line follows its element between moves.
  struct Gradients {
    Eigen::Matrix3d velocity_per_s = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d acceleration_per_s2 = Eigen::Matrix3d::Zero();
  };

  /// Velocity and local acceleration at every point at time t (global),
  /// and their gradients if asked for.
  void evaluate(double t_s, std::vector<Eigen::Vector3d>& velocity_m_per_s,
                std::vector<Eigen::Vector3d>& acceleration_m_per_s2, std::vector<Gradients>* gradients = nullptr) const;
  /// The same at one point only (its own sin/cos of ω t: for a single
  /// element's forces at a time the line is not otherwise evaluated at).
  void evaluate_point(double t_s, std::size_t point, Eigen::Vector3d& velocity_m_per_s,
                      Eigen::Vector3d& acceleration_m_per_s2, Gradients* gradients = nullptr) const;

 private:
  struct Point {
    std::size_t count = 0;                           // components kept: the first `count` by wavenumber
    std::vector<double> horizontal_c, horizontal_s;  // a ω f_h cos ψ, a ω f_h sin ψ
    std::vector<double> vertical_c, vertical_s;      // a ω f_v cos ψ, a ω f_v sin ψ
    std::vector<double> elevation_c, elevation_s;    // a cos ψ, a sin ψ
    double z_m = 0.0;
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
    std::uint64_t generation = 0;  // moves so far: a held sample of an older one is stale
  };
  // The sums at one point and time: velocity, acceleration, η, and whether
  // the point is below η.
  struct Sample {
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero(), acceleration = Eigen::Vector3d::Zero();
    Gradients gradients;
    double eta_m = 0.0;
    bool wet = false;
  };
  // A held sample and the generation of the point it was summed for.
  struct HeldSample {
    Sample sample;
    std::uint64_t generation = 0;
  };
  // The samples of every point at the grid time index · Δ, and the time
  // phases they were summed under (for the points moved since).
  struct Slot {
    std::int64_t index = std::numeric_limits<std::int64_t>::min();
    std::vector<HeldSample> at;
    std::vector<double> cos_wt, sin_wt;  // of the first max_count_ components when filled
  };
  // Eight slots: the four of a time and the last ones IDA may step back to.
  static constexpr std::int64_t kSlots = 8;
  static std::size_t ring(std::int64_t index) { return static_cast<std::size_t>(((index % kSlots) + kSlots) % kSlots); }

  // The four grid nodes around a time (first … first + 3, t between the
  // middle two) and their interpolation weights there.
  struct GridTime {
    std::int64_t first = 0;
    std::array<double, 4> weights{};
  };
  GridTime grid_time(double t_s) const;

  void set_point(Point& out, const Eigen::Vector3d& position);
  /// cos ω_j t, sin ω_j t of the (sorted) components first … count − 1.
  void time_phases(double t_s, std::size_t count, double* cos_wt, double* sin_wt, std::size_t first = 0) const;
  Sample at_point(const Point& pt, const double* cos_wt, const double* sin_wt) const;
  /// The slot of grid index `index`, summed if it is not held.
  Slot& slot(std::int64_t index) const;
  /// The sample of a point in a held slot, summed anew if the point has
  /// moved since it was taken.
  const Sample& held_sample(Slot& s, std::size_t point) const;
  /// Adds the kinematics of one point interpolated from four slots (weights
  /// w) to velocity and acceleration (zero where it is dry); false, adding
  /// nothing, where a sample is dry: the caller sums at t.
  bool interpolate_point(std::size_t point, const std::array<Slot*, 4>& slots, const std::array<double, 4>& w,
                         Eigen::Vector3d& velocity, Eigen::Vector3d& acceleration, Gradients* gradients) const;

  std::shared_ptr<const WaveRealization> sea_;
  std::vector<std::size_t> order_;                                      // components by increasing wavenumber
  std::vector<double> omega_, wavenumber_, cos_heading_, sin_heading_;  // in that order
  std::vector<double> k_cc_, k_cs_, k_ss_, k_c_, k_s_;  // k cos²β, k cos β sin β, k sin²β, k cos β, k sin β
  std::vector<Point> points_;
  std::size_t max_count_ = 0;  // the most components any point keeps (or kept)
  double log_cutoff_ = 0.0;
  mutable std::vector<double> cos_wt_, sin_wt_;  // per component (sorted), of the last t
  double interval_s_ = 0.0;
  mutable std::array<Slot, kSlots> slots_;  // grid index i in slots_[i mod kSlots]
  mutable long full_sums_ = 0;
};

}  // namespace spiral::engine
