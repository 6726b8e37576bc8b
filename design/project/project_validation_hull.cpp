// Validation of the section hull: mass and inertia, hydrostatics, the load
// coefficient and mean drift tables, hydrodynamics and member geometry
// (project_validation_checks.hpp).

#include <fmt/format.h>

#include <numbers>
#include <utility>
#include <variant>

#include "design/project/project_validation_checks.hpp"

namespace spiral::design::validation_detail {
namespace {

/// Headings of a table: at least `minimum` of them, each in [0, 360) deg,
/// strictly increasing (periodic interpolation needs an ordered circle).
void check_headings(Reporter& r, const std::string& at, const std::vector<double>& headings_rad, std::size_t minimum) {
  const char* c = "headings_valid";
  if (headings_rad.size() < minimum) {
    r.fail(at, c, fmt::format("needs at least {} headings, got {}", minimum, headings_rad.size()));
  }
  for (std::size_t k = 0; k < headings_rad.size(); ++k) {
    const double deg = headings_rad[k] * kRadToDeg;
    const std::string kat = fmt::format("{}[{}]", at, k);
    if (!(headings_rad[k] >= 0.0 && headings_rad[k] < 2.0 * std::numbers::pi)) {
      r.fail(kat, c, fmt::format("must be in [0, 360) deg, got {:.6g} deg", deg));
    } else if (k > 0 && !(headings_rad[k] > headings_rad[k - 1])) {
      r.fail(kat, c,
             fmt::format("headings must increase strictly, got {:.6g} deg after {:.6g} deg", deg,
                         headings_rad[k - 1] * kRadToDeg));
    }
  }
}

/// The list at `at` must have `expected` values, one per entry of `axis`.
void check_length(Reporter& r, const std::string& at, std::size_t size, std::size_t expected, const char* axis) {
  if (size != expected) {
    r.fail(at, "table_lengths_match",
           fmt::format("must have one value per entry of {} ({}), got {}", axis, expected, size));
  }
}

void check_load_coefficients(Reporter& r, const std::string& at, const HullLoadCoefficients& c) {
  check_headings(r, at + ".headings_deg", c.headings_rad, 2);
  const std::size_t n = c.headings_rad.size();
  check_length(r, at + ".surge", c.surge_m2.size(), n, "headings_deg");
  check_length(r, at + ".sway", c.sway_m2.size(), n, "headings_deg");
  check_length(r, at + ".yaw", c.yaw_m3.size(), n, "headings_deg");
}

void check_mean_drift_table(Reporter& r, const std::string& at, const MeanDriftTable& t) {
  check_headings(r, at + ".headings_deg", t.headings_rad, 2);
  const auto& f = t.frequencies_rad_per_s;
  if (f.empty()) r.fail(at + ".frequencies", "frequencies_valid", "needs at least one frequency");
  for (std::size_t k = 0; k < f.size(); ++k) {
    const std::string kat = fmt::format("{}.frequencies[{}]", at, k);
    if (!(f[k] > 0.0)) {
      r.fail(kat, "frequencies_valid", fmt::format("must be > 0 rad/s, got {} rad/s", f[k]));
    } else if (k > 0 && !(f[k] > f[k - 1])) {
      r.fail(kat, "frequencies_valid",
             fmt::format("frequencies must increase strictly, got {} rad/s after {} rad/s", f[k], f[k - 1]));
    }
  }
  for (const auto& [key, rows] : {std::pair{".surge", &t.surge_N_per_m2}, std::pair{".sway", &t.sway_N_per_m2},
                                  std::pair{".yaw", &t.yaw_N_m_per_m2}}) {
    check_length(r, at + key, rows->size(), t.headings_rad.size(), "headings_deg (rows)");
    for (std::size_t i = 0; i < rows->size(); ++i) {
      check_length(r, fmt::format("{}{}[{}]", at, key, i), (*rows)[i].size(), f.size(), "frequencies");
    }
  }
}

void check_member_coefficients(Reporter& r, const std::string& at, const MemberCoefficients& c) {
  at_least(r, at + ".drag", c.drag, 0.0, "", "coefficient_non_negative");
  at_least(r, at + ".added_mass", c.added_mass, 0.0, "", "coefficient_non_negative");
}

void check_hull_geometry(Reporter& r, const HullGeometry& g) {
  if (g.columns.empty() && g.pontoons.empty() && !g.panel_mesh) {
    r.fail("hull.geometry", "hull_geometry_members", "needs at least one column, pontoon or a panel_mesh");
  }
  if (g.panel_mesh) check_file(r, "hull.geometry.panel_mesh", *g.panel_mesh);
  for (std::size_t i = 0; i < g.columns.size(); ++i) {
    const HullColumn& c = g.columns[i];
    const std::string at = fmt::format("hull.geometry.columns[{}]", i);
    positive(r, at + ".diameter", c.diameter_m, "m", "hull_value_positive");
    if (!(c.z_top_m > c.z_bottom_m)) {
      r.fail(at + ".z_top", "column_top_above_bottom",
             fmt::format("must be above z_bottom {} m, got {} m", c.z_bottom_m, c.z_top_m));
    }
    check_member_coefficients(r, at, c.coefficients);
    at_least(r, at + ".end_added_mass", c.end_added_mass, 0.0, "", "coefficient_non_negative");
    at_least(r, at + ".end_drag", c.end_drag, 0.0, "", "coefficient_non_negative");
  }
  for (std::size_t i = 0; i < g.pontoons.size(); ++i) {
    const HullPontoon& p = g.pontoons[i];
    const std::string at = fmt::format("hull.geometry.pontoons[{}]", i);
    positive(r, at + ".diameter", p.diameter_m, "m", "hull_value_positive");
    check_member_coefficients(r, at, p.coefficients);
    if (!((p.to_b - p.from_b).norm() > 0.0)) {
      r.fail(at + ".to", "pontoon_length_positive",
             fmt::format("must differ from `from`, got both at [{}, {}, {}] m", p.to_b.x(), p.to_b.y(), p.to_b.z()));
    }
  }
}

void check_hull_hydrodynamics(Reporter& r, const Hull& hull) {
  const HullHydrodynamics& h = *hull.hydrodynamics;
  const std::string at = "hull.hydrodynamics";
  if (h.model == HullHydrodynamicsModel::morison) {
    positive(r, at + ".strip_length", h.strip_length_m, "m", "hull_value_positive");
    if (!hull.geometry || (hull.geometry->columns.empty() && hull.geometry->pontoons.empty())) {
      r.fail(at + ".model", "morison_needs_geometry",
             "model: morison builds the members from hull.geometry, which has none");
    }
  } else {
    check_file(r, at + ".radiation_file", h.radiation_file);
    if (h.excitation == ExcitationSource::morison_maccamy_fuchs) {
      if (h.excitation_file || h.rao_file) {
        r.fail(at + ".excitation", "excitation_source_conflict",
               fmt::format("morison_maccamy_fuchs computes the excitation from hull.geometry; the {} gives it too: "
                           "keep one",
                           h.excitation_file ? "excitation_file" : "rao_file"));
      }
      if (!hull.geometry || (hull.geometry->columns.empty() && hull.geometry->pontoons.empty())) {
        r.fail(at + ".excitation", "morison_needs_geometry",
               "morison_maccamy_fuchs builds the members from hull.geometry, which has none");
      }
    }
  }
  if (h.excitation_file) check_file(r, at + ".excitation_file", *h.excitation_file);
  if (h.rao_file) check_file(r, at + ".rao_file", *h.rao_file);
  positive(r, at + ".ulen", h.ulen_m, "m", "hull_value_positive");
  positive(r, at + ".period_scale", h.period_scale, "", "hull_value_positive");
  positive(r, at + ".added_mass_frequency", h.added_mass_frequency_rad_per_s, "rad/s", "hull_value_positive");
  positive(r, at + ".memory_time_step", h.memory_time_step_s, "s", "hull_value_positive");
  if (!(h.memory_duration_s > h.memory_time_step_s)) {
    r.fail(at + ".memory_duration", "memory_duration_above_step",
           fmt::format("must be above memory_time_step {} s, got {} s", h.memory_time_step_s, h.memory_duration_s));
  }
  for (int k = 0; k < 6; ++k) {
    at_least(r, fmt::format("{}.linear_damping[{}]", at, k), h.linear_damping[k], 0.0, k < 3 ? "N s/m" : "N m s/rad",
             "hull_damping_non_negative");
    at_least(r, fmt::format("{}.quadratic_damping[{}]", at, k), h.quadratic_damping[k], 0.0,
             k < 3 ? "N s^2/m^2" : "N m s^2/rad^2", "hull_damping_non_negative");
  }
}

}  // namespace

void check_hull(const Project& p, Reporter& r) {
  const Hull& h = p.hull;
  positive(r, "hull.mass", h.mass_kg, "kg", "hull_value_positive");
  if (h.radii_of_gyration_m) {
    for (int k = 0; k < 3; ++k) {
      positive(r, fmt::format("hull.radii_of_gyration[{}]", k), (*h.radii_of_gyration_m)[k], "m",
               "hull_value_positive");
    }
  }
  if (h.inertia_kg_m2) {
    for (int k = 0; k < 3; ++k) {
      positive(r, fmt::format("hull.inertia[{}]", k), (*h.inertia_kg_m2)(k, k), "kg m^2", "hull_value_positive");
    }
  }
  const bool all_values =
      h.displaced_volume_m3 && h.center_of_buoyancy_b && h.waterplane_area_m2 && h.waterplane_inertia_m4;
  if (!all_values && !h.hydrostatics_file) {
    r.fail("hull", "hull_hydrostatics_complete",
           "give displaced_volume, center_of_buoyancy, waterplane_area and waterplane_inertia, or "
           "a hydrostatics_file (.hst)");
  }
  positive(r, "hull.displaced_volume", h.displaced_volume_m3, "m^3", "hull_value_positive");
  positive(r, "hull.waterplane_area", h.waterplane_area_m2, "m^2", "hull_value_positive");
  if (h.waterplane_inertia_m4) {
    for (int k = 0; k < 2; ++k) {
      positive(r, fmt::format("hull.waterplane_inertia[{}]", k), (*h.waterplane_inertia_m4)[k], "m^4",
               "hull_value_positive");
    }
  }
  if (h.hydrostatics_file) check_file(r, "hull.hydrostatics_file", *h.hydrostatics_file);
  if (h.wind_coefficients) {
    check_load_coefficients(r, "hull.wind_coefficients", *h.wind_coefficients);
    positive(r, "hull.wind_coefficients.reference_height", h.wind_coefficients->reference_height_m, "m",
             "hull_value_positive");
  }
  if (h.current_coefficients) {
    check_load_coefficients(r, "hull.current_coefficients", *h.current_coefficients);
  }
  if (h.mean_drift) {
    const MeanDriftHeadings& rule = h.mean_drift_headings;
    if (rule.symmetry_rotations < 1 || rule.symmetry_rotations > 360) {
      r.fail("hull.mean_drift.symmetry.rotations", "hull_value_positive",
             fmt::format("must be 1 (none) to 360, the n of an n-fold symmetry, got {}", rule.symmetry_rotations));
    }
    if (const auto& span = rule.wave_frame_fill_max_span_rad;
        span && !(*span > 0.0 && *span <= 2.0 * std::numbers::pi + 1e-12)) {
      r.fail("hull.mean_drift.wave_frame_fill.max_span_deg", "hull_value_positive",
             fmt::format("must be in (0, 360] deg, got {} deg", *span * 180.0 / std::numbers::pi));
    }
    if (const auto* f = std::get_if<MeanDriftFile>(&*h.mean_drift)) {
      check_file(r, "hull.mean_drift.file", f->file);
      positive(r, "hull.mean_drift.ulen", f->ulen_m, "m", "hull_value_positive");
      positive(r, "hull.mean_drift.period_scale", f->period_scale, "", "hull_value_positive");
    } else {
      check_mean_drift_table(r, "hull.mean_drift", std::get<MeanDriftTable>(*h.mean_drift));
    }
  }
  if (h.hydrodynamics) check_hull_hydrodynamics(r, h);
  if (h.geometry) check_hull_geometry(r, *h.geometry);
}

}  // namespace spiral::design::validation_detail
