#pragma once
// The state-independent low-frequency forcing of a hull time-domain run (the
// slow drift of engine/hull/slow_drift.hpp and the wind gust of
// engine/environment/wind_realization.hpp), tabulated once and interpolated
// in the integrator's right-hand side.

#include <cmath>

#include <Eigen/Core>

#include "engine/environment/wind_realization.hpp"
#include "engine/hull/slow_drift.hpp"

namespace spiral::engine {

/// The slow drift (rows 0-5, global, N, N·m) and the wind gust (row 6, m/s)
/// are functions of time only: tabulated once on a uniform grid by the phasor
/// recurrence e^{i w (t + dt)} = e^{i w t} e^{i w dt} (a complex product per
/// component instead of a sine and cosine), then read in the right-hand side
/// by Catmull-Rom interpolation (C1 in time, so the Adams steps stay long).
class ForcingTable {
 public:
  /// Grid step of the tabulated state-independent forcing: Catmull-Rom
  /// interpolation errs by ~(w dt)^4/... of a component's amplitude, below 1e-3
  /// for the slow drift (difference frequencies < 2 rad/s) and ~1 % only at the
  /// 1 Hz end of the wind gust, where the hull does not respond.
  static constexpr double kStep_s = 0.1;

  /// Either series may be null (its rows stay zero).
  ForcingTable(const SlowDriftSeries* drift, const WindRealization* gust, double duration_s);

  /// Rows 0-5: the slow-drift force (N, N·m, global); row 6: the gust, m/s.
  Eigen::Matrix<double, 7, 1> at(double t) const {
    const double s = t / kStep_s + 1.0;  // column j holds t = (j − 1) dt
    const auto j = static_cast<Eigen::Index>(std::floor(s));
    if (j < 1 || j + 2 >= values_.cols()) return exact(t);
    const double u = s - static_cast<double>(j);
    const auto p0 = values_.col(j - 1), p1 = values_.col(j), p2 = values_.col(j + 1), p3 = values_.col(j + 2);
    return p1 + 0.5 * u * ((p2 - p0) + u * ((2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) + u * (3.0 * (p1 - p2) + p3 - p0)));
  }

 private:
  Eigen::Matrix<double, 7, 1> exact(double t) const;
  void tabulate_drift(const SlowDriftSeries& d);
  void tabulate_gust(const WindRealization& w);

  const SlowDriftSeries* drift_;
  const WindRealization* gust_;
  Eigen::Matrix<double, 7, Eigen::Dynamic> values_;
};

}  // namespace spiral::engine
