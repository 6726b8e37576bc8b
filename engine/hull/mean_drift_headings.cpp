#include "engine/hull/mean_drift_headings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/hull/heading_rule.hpp"

namespace spiral::engine {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDeg = 180.0 / std::numbers::pi;
/// Headings this close are the same heading (the heading rule's tolerance).
constexpr double kSameHeading_rad = kHeadingTolerance_rad;

double wrapped(double angle) { return wrap_0_2pi(angle, kSameHeading_rad); }

/// The six DOFs' coefficients at one heading: frequencies × DOF.
using Coefficients = Eigen::Matrix<double, Eigen::Dynamic, 6>;

Coefficients at_heading(const MeanDriftTable& t, std::size_t j) {
  Coefficients c = Coefficients::Zero(static_cast<Eigen::Index>(t.omega_rad_per_s.size()), 6);
  for (std::size_t i = 0; i < 6; ++i)
    if (t.present[i]) c.col(static_cast<Eigen::Index>(i)) = t.coefficient[i].col(static_cast<Eigen::Index>(j));
  return c;
}

/// Turned by `angle` about the vertical: the force (1, 2) and the roll/pitch
/// moment (4, 5) as horizontal vectors; heave and yaw are unchanged.
Coefficients turned(const Coefficients& c, double angle) {
  const double cs = std::cos(angle), sn = std::sin(angle);
  Coefficients out = c;
  for (const Eigen::Index x : {0, 3}) {
    out.col(x) = cs * c.col(x) - sn * c.col(x + 1);
    out.col(x + 1) = sn * c.col(x) + cs * c.col(x + 1);
  }
  return out;
}

/// Under y → −y: sway, roll and yaw change sign (force a vector, moment a pseudovector).
Coefficients mirrored(Coefficients c) {
  for (const Eigen::Index i : {1, 3, 5}) c.col(i) = -c.col(i);
  return c;
}

/// A table of `like`'s frequencies from (heading, coefficients) pairs.
MeanDriftTable assembled(const MeanDriftTable& like, std::vector<std::pair<double, Coefficients>> entries,
                         double max_interpolation_gap_rad) {
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  MeanDriftTable out;
  out.omega_rad_per_s = like.omega_rad_per_s;
  out.present = like.present;
  // A turned force or moment has both horizontal components.
  for (const std::size_t x : {0u, 3u}) out.present[x] = out.present[x + 1] = like.present[x] || like.present[x + 1];
  const auto rows = static_cast<Eigen::Index>(out.omega_rad_per_s.size());
  const auto cols = static_cast<Eigen::Index>(entries.size());
  for (std::size_t i = 0; i < 6; ++i) out.coefficient[i] = Eigen::MatrixXd::Zero(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j) {
    out.headings_rad.push_back(entries[static_cast<std::size_t>(j)].first);
    for (std::size_t i = 0; i < 6; ++i)
      if (out.present[i])
        out.coefficient[i].col(j) = entries[static_cast<std::size_t>(j)].second.col(static_cast<Eigen::Index>(i));
  }
  out.max_interpolation_gap_rad = max_interpolation_gap_rad;
  return out;
}

/// The widest gap the loads interpolate `t` across (mean_environmental_loads'
/// heading rule: the interior gaps, and the wrap-around one when the table
/// is periodic by that rule), at most the table's own limit.
double interpolated_gap(const MeanDriftTable& t) {
  return std::min(widest_interpolated_gap(t.headings_rad), t.max_interpolation_gap_rad);
}

double largest_abs(const MeanDriftTable& t, std::size_t first_dof) {
  double m = 0.0;
  for (std::size_t i = first_dof; i < first_dof + 3; ++i)
    if (t.present[i]) m = std::max(m, t.coefficient[i].cwiseAbs().maxCoeff());
  return m;
}

}  // namespace

MeanDriftTable with_symmetry_images(const MeanDriftTable& table, const HullSymmetry& symmetry,
                                    double relative_tolerance) {
  validate_mean_drift_table(table);
  if (symmetry.rotations < 1)
    throw std::invalid_argument(fmt::format("hull symmetry: rotations must be >= 1, got {}", symmetry.rotations));
  if (symmetry.rotations == 1 && !symmetry.mirror_xz) return table;
  const double force_scale = largest_abs(table, 0);
  const double moment_scale = largest_abs(table, 3);

  std::vector<std::pair<double, Coefficients>> entries;
  const auto add = [&](double heading, Coefficients c) {
    const double h = wrapped(heading);
    for (auto& [at, existing] : entries) {
      const double apart = std::abs(std::remainder(at - h, kTwoPi));
      if (apart > kSameHeading_rad) continue;
      // The same heading reached twice: the data must agree with their image.
      for (Eigen::Index i = 0; i < 6; ++i) {
        const double scale = i < 3 ? force_scale : moment_scale;
        const double difference = (existing.col(i) - c.col(i)).cwiseAbs().maxCoeff();
        if (difference > relative_tolerance * scale) {
          throw std::invalid_argument(fmt::format(
              "mean drift table: not symmetric as declared ({}-fold{}): at heading {:.6g} deg DOF {} differs from "
              "its image by {:.4g} ({:.3g} % of the table's largest {} coefficient, tolerance {:.3g} %)",
              symmetry.rotations, symmetry.mirror_xz ? ", mirror x-z" : "", h * kDeg, i + 1, difference,
              100.0 * difference / scale, i < 3 ? "force" : "moment", 100.0 * relative_tolerance));
        }
      }
      return;
    }
    entries.emplace_back(h, std::move(c));
  };
  // The data first, so that an image never replaces a tabulated value.
  for (std::size_t j = 0; j < table.headings_rad.size(); ++j) add(table.headings_rad[j], at_heading(table, j));
  for (std::size_t j = 0; j < table.headings_rad.size(); ++j) {
    const double beta = table.headings_rad[j];
    const Coefficients c = at_heading(table, j);
    for (int k = 0; k < symmetry.rotations; ++k) {
      const double phi = kTwoPi * k / symmetry.rotations;
      add(beta + phi, turned(c, phi));
      if (symmetry.mirror_xz) add(-beta + phi, turned(mirrored(c), phi));
    }
  }
  return assembled(table, std::move(entries), table.headings_rad.size() > 1 ? interpolated_gap(table) : 0.0);
}

MeanDriftTable filled_in_wave_frame(const MeanDriftTable& table, const WaveFrameFill& fill) {
  validate_mean_drift_table(table);
  if (!(fill.max_span_rad > 0.0) || !(fill.step_rad > 0.0)) {
    throw std::invalid_argument(
        fmt::format("wave-frame fill: span and step must be > 0 rad, got {} and {}", fill.max_span_rad, fill.step_rad));
  }
  const std::size_t n = table.headings_rad.size();
  std::vector<std::pair<double, Coefficients>> entries;
  for (std::size_t j = 0; j < n; ++j) entries.emplace_back(table.headings_rad[j], at_heading(table, j));
  // Each gap to the next heading around the circle (a single heading: the circle).
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t next = (j + 1) % n;
    const double from = table.headings_rad[j];
    double gap = table.headings_rad[next] - from;
    if (next <= j) gap += kTwoPi;
    if (gap > fill.max_span_rad + kSameHeading_rad) continue;
    const int pieces = static_cast<int>(std::ceil(gap / fill.step_rad - 1e-9));
    // Along and across the waves at both ends.
    const Coefficients start = turned(at_heading(table, j), -from);
    const Coefficients end = turned(at_heading(table, next), -(from + gap));
    for (int k = 1; k < pieces; ++k) {
      const double t = static_cast<double>(k) / pieces;
      const double beta = from + t * gap;
      entries.emplace_back(wrapped(beta), turned((1.0 - t) * start + t * end, beta));
    }
  }
  return assembled(table, std::move(entries), std::max(fill.step_rad, n > 1 ? interpolated_gap(table) : 0.0));
}

}  // namespace spiral::engine
