#include "engine/hull/mean_environmental_loads.hpp"
#include "engine/common/table_range_error.hpp"
#include "engine/hull/heading_rule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace spiral::engine {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// A relative heading this far beyond the end of a table that does not cover
/// the circle is evaluated at the end heading (header, heading rule).
constexpr double kHeadingEndHold_rad = 0.5 * std::numbers::pi / 180.0;

// Linear interpolation bracket: value = (1 - t) v[j0] + t v[j1].
struct Bracket {
  std::size_t j0 = 0;
  std::size_t j1 = 0;
  double t = 0.0;
};

Bracket heading_bracket_in_range(const std::vector<double>& h, double beta, const char* table_name);

// Heading rule documented in the header: periodic when the wrap-around gap is
// no larger than the largest interior gap, otherwise no extrapolation; a
// table may narrow the gaps it interpolates across (MeanDriftTable).
Bracket heading_bracket(const std::vector<double>& h, double beta, const char* table_name,
                        double max_gap_rad = std::numeric_limits<double>::infinity()) {
  const Bracket b = heading_bracket_in_range(h, beta, table_name);
  if (b.j0 == b.j1) return b;
  const double gap = b.j1 > b.j0 ? h[b.j1] - h[b.j0] : h[b.j1] + kTwoPi - h[b.j0];
  if (gap <= max_gap_rad + kHeadingTolerance_rad) return b;
  // Within the heading rule's hold of a tabulated heading: that heading.
  if (b.t * gap <= kHeadingEndHold_rad) return {b.j0, b.j0, 0.0};
  if ((1.0 - b.t) * gap <= kHeadingEndHold_rad) return {b.j1, b.j1, 0.0};
  constexpr double deg = 180.0 / std::numbers::pi;
  throw TableRangeError(fmt::format(
      "{}: relative heading {:.6g} deg lies between the tabulated headings {:.6g} and {:.6g} deg, a gap of {:.6g} "
      "deg wider than the {:.6g} deg the table interpolates across (its data's own spacing: a symmetry image is "
      "not interpolated to; a wave-frame fill can cover the gap)",
      table_name, wrap_0_2pi(beta) * deg, h[b.j0] * deg, h[b.j1] * deg, gap * deg, max_gap_rad * deg));
}

Bracket heading_bracket_in_range(const std::vector<double>& h, double beta, const char* table_name) {
  const std::size_t n = h.size();
  const double first = h.front();
  const double last = h.back();
  const double b = first + wrap_0_2pi(beta - first);  // in [first, first + 2 pi)
  if (b <= last) {
    const auto it = std::upper_bound(h.begin(), h.end(), b);
    if (it == h.end()) return {n - 1, n - 1, 0.0};  // b == last
    const std::size_t j1 = static_cast<std::size_t>(it - h.begin());
    const std::size_t j0 = j1 - 1;
    return {j0, j1, (b - h[j0]) / (h[j1] - h[j0])};
  }
  if (wraps_around(h)) return {n - 1, 0, (b - last) / (first + kTwoPi - last)};
  if (b - last <= kHeadingEndHold_rad) return {n - 1, n - 1, 0.0};
  if (first + kTwoPi - b <= kHeadingEndHold_rad) return {0, 0, 0.0};
  throw TableRangeError(fmt::format(
      "{}: relative heading {:.6g} deg lies outside the tabulated headings {:.6g}..{:.6g} deg "
      "and the table does not cover the circle (no extrapolation in heading)",
      table_name, b * 180.0 / std::numbers::pi, first * 180.0 / std::numbers::pi, last * 180.0 / std::numbers::pi));
}

// Frequency bracket with the end values held outside the table.
Bracket frequency_bracket(const std::vector<double>& w, double omega) {
  const std::size_t n = w.size();
  if (omega <= w.front()) return {0, 0, 0.0};
  if (omega >= w.back()) return {n - 1, n - 1, 0.0};
  const auto it = std::upper_bound(w.begin(), w.end(), omega);
  const std::size_t j1 = static_cast<std::size_t>(it - w.begin());
  const std::size_t j0 = j1 - 1;
  return {j0, j1, (omega - w[j0]) / (w[j1] - w[j0])};
}

double lerp(const std::vector<double>& v, const Bracket& b) { return (1.0 - b.t) * v[b.j0] + b.t * v[b.j1]; }

void require_finite(double value, const char* what, const char* unit) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("{} must be finite ({}), got {}", what, unit, value));
  }
}

}  // namespace

void validate_coefficient_table(const CoefficientTable& t) {
  const std::size_t n = t.headings_rad.size();
  if (n == 0) throw std::invalid_argument("coefficient table: no headings");
  if (t.Cx_m2.size() != n || t.Cy_m2.size() != n || t.Cmz_m3.size() != n) {
    throw std::invalid_argument(fmt::format("coefficient table: {} headings but {} Cx_m2, {} Cy_m2, {} Cmz_m3 values",
                                            n, t.Cx_m2.size(), t.Cy_m2.size(), t.Cmz_m3.size()));
  }
  for (std::size_t j = 0; j < n; ++j) {
    const double h = t.headings_rad[j];
    if (!(h >= 0.0 && h < kTwoPi)) {
      throw std::invalid_argument(
          fmt::format("coefficient table: headings_rad[{}] must be in [0, 2 pi) rad, got {} rad", j, h));
    }
    if (j > 0 && !(h > t.headings_rad[j - 1])) {
      throw std::invalid_argument(
          fmt::format("coefficient table: headings_rad must be strictly increasing, got {} rad after {} rad", h,
                      t.headings_rad[j - 1]));
    }
    if (!std::isfinite(t.Cx_m2[j]) || !std::isfinite(t.Cy_m2[j]) || !std::isfinite(t.Cmz_m3[j])) {
      throw std::invalid_argument(fmt::format("coefficient table: non-finite coefficient at heading {} rad", h));
    }
  }
}

CoefficientLoadResult coefficient_load(const CoefficientTable& table, const CoefficientLoadInput& in) {
  validate_coefficient_table(table);
  if (!(in.fluid_density_kg_per_m3 > 0.0) || !std::isfinite(in.fluid_density_kg_per_m3)) {
    throw std::invalid_argument(
        fmt::format("coefficient load: fluid density must be > 0 kg/m^3, "
                    "got {} kg/m^3",
                    in.fluid_density_kg_per_m3));
  }
  require_finite(in.flow_velocity_g.x(), "coefficient load: flow velocity x", "m/s");
  require_finite(in.flow_velocity_g.y(), "coefficient load: flow velocity y", "m/s");
  require_finite(in.hull_yaw_rad, "coefficient load: hull yaw", "rad");

  CoefficientLoadResult r;
  r.speed_m_per_s = std::hypot(in.flow_velocity_g.x(), in.flow_velocity_g.y());
  const double direction = r.speed_m_per_s > 0.0 ? std::atan2(in.flow_velocity_g.y(), in.flow_velocity_g.x()) : 0.0;
  r.relative_heading_rad = wrap_0_2pi(direction - in.hull_yaw_rad);
  if (r.speed_m_per_s == 0.0) return r;  // no flow, no load (and no heading to look up)
  const Bracket b = heading_bracket(table.headings_rad, r.relative_heading_rad, "coefficient table");
  r.coefficients << lerp(table.Cx_m2, b), lerp(table.Cy_m2, b), lerp(table.Cmz_m3, b);
  // OCIMF form: F = 1/2 rho (C A)(beta) V|V|, V = |V| >= 0 (direction carried by beta).
  const double q = 0.5 * in.fluid_density_kg_per_m3 * r.speed_m_per_s * r.speed_m_per_s;
  r.load_b(0) = q * r.coefficients(0);
  r.load_b(1) = q * r.coefficients(1);
  r.load_b(5) = q * r.coefficients(2);
  r.load_g = yaw_body_to_global(r.load_b, in.hull_yaw_rad);
  return r;
}

CoefficientLoadResult current_load(const CoefficientTable& table, const CurrentProfile& current,
                                   double water_density_kg_per_m3, double hull_yaw_rad, double reference_z_m) {
  if (!(reference_z_m <= 0.0)) {
    throw std::invalid_argument(
        fmt::format("current load: reference depth z must be <= 0 m (at or below the mean water level), got "
                    "{} m",
                    reference_z_m));
  }
  return coefficient_load(table, {water_density_kg_per_m3, current_velocity_g(current, reference_z_m), hull_yaw_rad});
}

CoefficientLoadResult wind_load(const CoefficientTable& table, double wind_speed_m_per_s, double wind_heading_rad,
                                double hull_yaw_rad, double air_density_kg_per_m3) {
  if (!(wind_speed_m_per_s >= 0.0) || !std::isfinite(wind_speed_m_per_s)) {
    throw std::invalid_argument(fmt::format("wind load: wind speed must be >= 0 m/s, got {} m/s", wind_speed_m_per_s));
  }
  require_finite(wind_heading_rad, "wind load: wind heading", "rad");
  const Eigen::Vector3d v(wind_speed_m_per_s * std::cos(wind_heading_rad),
                          wind_speed_m_per_s * std::sin(wind_heading_rad), 0.0);
  CoefficientLoadResult r = coefficient_load(table, {air_density_kg_per_m3, v, hull_yaw_rad});
  // A zero speed has no direction of its own: report the stated heading.
  r.relative_heading_rad = wrap_0_2pi(wind_heading_rad - hull_yaw_rad);
  return r;
}

void validate_mean_drift_table(const MeanDriftTable& t) {
  const std::size_t nw = t.omega_rad_per_s.size();
  const std::size_t nb = t.headings_rad.size();
  if (nw == 0 || nb == 0) {
    throw std::invalid_argument(
        fmt::format("mean drift table: needs >= 1 frequency and heading, got {} and {}", nw, nb));
  }
  for (std::size_t k = 0; k < nw; ++k) {
    const double w = t.omega_rad_per_s[k];
    if (!(w > 0.0) || !std::isfinite(w) || (k > 0 && !(w > t.omega_rad_per_s[k - 1]))) {
      throw std::invalid_argument(
          fmt::format("mean drift table: frequencies must be > 0 rad/s and strictly increasing, got "
                      "omega[{}] = {} rad/s",
                      k, w));
    }
  }
  for (std::size_t j = 0; j < nb; ++j) {
    const double h = t.headings_rad[j];
    if (!std::isfinite(h) || (j > 0 && !(h > t.headings_rad[j - 1]))) {
      throw std::invalid_argument(
          fmt::format("mean drift table: headings must be finite and strictly increasing, got heading[{}] = "
                      "{} rad",
                      j, h));
    }
  }
  if (t.headings_rad.back() - t.headings_rad.front() > kTwoPi + kHeadingTolerance_rad) {
    throw std::invalid_argument("mean drift table: headings span more than 2 pi rad");
  }
  if (!(t.max_interpolation_gap_rad >= 0.0))
    throw std::invalid_argument("mean drift table: the widest gap interpolated across must be >= 0 rad");
  bool any = false;
  for (std::size_t i = 0; i < 6; ++i) {
    if (!t.present[i]) continue;
    any = true;
    const auto& c = t.coefficient[i];
    if (static_cast<std::size_t>(c.rows()) != nw || static_cast<std::size_t>(c.cols()) != nb) {
      throw std::invalid_argument(
          fmt::format("mean drift table: DOF {} coefficients are {}x{}, expected {}x{} (frequencies x "
                      "headings)",
                      i + 1, c.rows(), c.cols(), nw, nb));
    }
    if (!c.allFinite()) {
      throw std::invalid_argument(fmt::format("mean drift table: DOF {} has non-finite coefficients", i + 1));
    }
  }
  if (!any) throw std::invalid_argument("mean drift table: no DOF has coefficients");
}

namespace {

Vector6d interpolate_drift(const MeanDriftTable& t, const Bracket& fw, const Bracket& fb) {
  Vector6d d = Vector6d::Zero();
  for (std::size_t i = 0; i < 6; ++i) {
    if (!t.present[i]) continue;
    const auto& c = t.coefficient[i];
    const auto at = [&](std::size_t k, const Bracket& b) {
      return (1.0 - b.t) * c(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(b.j0)) +
             b.t * c(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(b.j1));
    };
    d(static_cast<Eigen::Index>(i)) = (1.0 - fw.t) * at(fw.j0, fb) + fw.t * at(fw.j1, fb);
  }
  return d;
}

}  // namespace

Vector6d mean_drift_coefficients(const MeanDriftTable& table, double omega, double relative_heading_rad) {
  validate_mean_drift_table(table);
  require_finite(omega, "mean drift: frequency", "rad/s");
  require_finite(relative_heading_rad, "mean drift: relative heading", "rad");
  return interpolate_drift(
      table, frequency_bracket(table.omega_rad_per_s, omega),
      heading_bracket(table.headings_rad, relative_heading_rad, "mean drift table", table.max_interpolation_gap_rad));
}

MeanDriftIntegral::MeanDriftIntegral(const MeanDriftTable& table, const MeanDriftInput& in)
    : headings_rad_(table.headings_rad), max_interpolation_gap_rad_(table.max_interpolation_gap_rad) {
  validate_mean_drift_table(table);
  require_finite(in.wave_heading_rad, "mean drift: wave heading", "rad");

  MeanDriftResult& r = without_load_;
  if (in.spreading) {
    r.directions = discretise_spreading(*in.spreading, in.wave_heading_rad, in.spreading_directions);
  } else {
    r.directions = {{in.wave_heading_rad, 1.0}};
  }

  // Raise the quadrature limit to the table's last frequency so that the
  // analytic tail lies where D is held constant (exact for the w^-5 tail).
  SpectrumQuadratureOptions options = in.quadrature;
  options.min_upper_limit_rad_per_s = std::max(options.min_upper_limit_rad_per_s, table.omega_rad_per_s.back());
  const SpectrumQuadrature q = spectrum_quadrature(in.spectrum, options);
  const Eigen::Index nodes = q.omega_rad_per_s.size();

  r.m0_m2 = q.weight_m2.sum() + q.tail_m0_m2;
  double below = 0.0;
  double above = q.tail_m0_m2;
  for (Eigen::Index i = 0; i < nodes; ++i) {
    if (q.omega_rad_per_s(i) < table.omega_rad_per_s.front()) below += q.weight_m2(i);
    if (q.omega_rad_per_s(i) > table.omega_rad_per_s.back()) above += q.weight_m2(i);
  }
  r.variance_fraction_below_table = below / r.m0_m2;
  r.variance_fraction_above_table = above / r.m0_m2;

  // Frequency brackets do not depend on the heading: compute them once.
  std::vector<Bracket> fw(static_cast<std::size_t>(nodes) + 1);
  for (Eigen::Index i = 0; i < nodes; ++i) {
    fw[static_cast<std::size_t>(i)] = frequency_bracket(table.omega_rad_per_s, q.omega_rad_per_s(i));
  }
  fw.back() = frequency_bracket(table.omega_rad_per_s, q.tail_start_rad_per_s);

  // Faltinsen (1990) ch. 5 / Newman (1974): F = 2 int S(w) D(w, beta) dw, at
  // each table heading (a bracket on the heading itself, t = 0).
  const auto headings = static_cast<Eigen::Index>(table.headings_rad.size());
  at_heading_ = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, headings);
  for (Eigen::Index j = 0; j < headings; ++j) {
    const Bracket on_heading{static_cast<std::size_t>(j), static_cast<std::size_t>(j), 0.0};
    Vector6d integral = Vector6d::Zero();
    for (Eigen::Index i = 0; i < nodes; ++i) {
      if (q.weight_m2(i) == 0.0) continue;
      integral += q.weight_m2(i) * interpolate_drift(table, fw[static_cast<std::size_t>(i)], on_heading);
    }
    integral += q.tail_m0_m2 * interpolate_drift(table, fw.back(), on_heading);
    at_heading_.col(j) = 2.0 * integral;
  }
}

MeanDriftResult MeanDriftIntegral::load(double hull_yaw_rad) const {
  require_finite(hull_yaw_rad, "mean drift: hull yaw", "rad");
  MeanDriftResult r = without_load_;
  for (const SpreadingDirection& dir : r.directions) {
    if (dir.weight == 0.0) continue;
    const Bracket fb =
        heading_bracket(headings_rad_, dir.heading_rad - hull_yaw_rad, "mean drift table", max_interpolation_gap_rad_);
    r.load_b += dir.weight * ((1.0 - fb.t) * at_heading_.col(static_cast<Eigen::Index>(fb.j0)) +
                              fb.t * at_heading_.col(static_cast<Eigen::Index>(fb.j1)));
  }
  r.load_g = yaw_body_to_global(r.load_b, hull_yaw_rad);
  return r;
}

MeanDriftResult mean_wave_drift_load(const MeanDriftTable& table, const MeanDriftInput& in) {
  return MeanDriftIntegral(table, in).load(in.hull_yaw_rad);
}

}  // namespace spiral::engine
