// Project loader, section hull: mass and inertia, hydrostatics, wind and
// current coefficients, mean drift, hydrodynamics and member geometry
// (project_loader_sections.hpp).

#include <fmt/format.h>

#include <span>
#include <string>
#include <string_view>

#include "design/project/project_loader_sections.hpp"

namespace spiral::design::loader_detail {
namespace {

std::filesystem::path resolve(const std::string& file, const std::filesystem::path& base_folder) {
  const std::filesystem::path path(file);
  return path.is_absolute() ? path : base_folder / path;
}

/// `{headings_deg, surge, sway, yaw}`; equal lengths are checked in validation.
void read_load_coefficients(MapReader& r, HullLoadCoefficients& c) {
  assign(c.headings_rad, r.angles("headings", kRequired));
  assign(c.surge_m2, r.numbers("surge", "m^2", kRequired));
  assign(c.sway_m2, r.numbers("sway", "m^2", kRequired));
  assign(c.yaw_m3, r.numbers("yaw", "m^3", kRequired));
}

/// `symmetry: {rotations, mirror_xz}` and `wave_frame_fill: {max_span_deg}`,
/// beside either form of the data.
MeanDriftHeadings read_mean_drift_headings(MapReader& r) {
  MeanDriftHeadings h;
  r.map("symmetry", kOptional, [&](MapReader& s) {
    assign(h.symmetry_rotations, s.integer("rotations", kOptional));
    assign(h.symmetry_mirror_xz, s.boolean("mirror_xz", kOptional));
  });
  r.map("wave_frame_fill", kOptional, [&](MapReader& f) {
    if (const auto span = f.angle("max_span", kRequired)) h.wave_frame_fill_max_span_rad = *span;
  });
  return h;
}

/// Either `{file, ulen}` (WAMIT .12d) or a table `{headings_deg, frequencies,
/// surge, sway, yaw}`; the presence of `file` chooses.
MeanDrift read_mean_drift(MapReader& r, const std::filesystem::path& base_folder) {
  static constexpr std::string_view kTableKeys[] = {"headings_deg", "frequencies", "surge", "sway", "yaw"};
  if (r.has("file")) {
    MeanDriftFile f;
    if (const auto file = r.text("file", kRequired)) f.file = resolve(*file, base_folder);
    assign(f.ulen_m, r.number("ulen", "m", kOptional));
    assign(f.period_scale, r.number("period_scale", "-", kOptional));
    for (const auto key : kTableKeys) {
      const auto node = r.child(key, kOptional);
      if (!node) continue;
      r.context().add(node->Mark(), r.path_of(key),
                      fmt::format("give either file (WAMIT .12d) or a table (headings_deg, "
                                  "frequencies, surge, sway, yaw), not both; got {} with file",
                                  key),
                      "conflicting_keys");
    }
    return f;
  }
  r.child("file", kOptional);  // known key, for suggestions
  for (const char* key : {"ulen", "period_scale"}) {
    if (const auto node = r.child(key, kOptional)) {
      r.context().add(node->Mark(), r.path_of(key), "applies to a WAMIT file (file: path.12d) only, got a table",
                      "key_not_applicable");
    }
  }
  MeanDriftTable t;
  assign(t.headings_rad, r.angles("headings", kRequired));
  assign(t.frequencies_rad_per_s, r.numbers("frequencies", "rad/s", kRequired));
  assign(t.surge_N_per_m2, r.number_rows("surge", "N/m^2", kRequired));
  assign(t.sway_N_per_m2, r.number_rows("sway", "N/m^2", kRequired));
  assign(t.yaw_N_m_per_m2, r.number_rows("yaw", "N m/m^2", kRequired));
  return t;
}

HullHydrodynamics read_hull_hydrodynamics(MapReader& r, const std::filesystem::path& base_folder) {
  static const EnumTable<FrequencyColumnKind> kColumns = {
      {"period", FrequencyColumnKind::period}, {"angular_frequency", FrequencyColumnKind::angular_frequency}};
  static const EnumTable<HullHydrodynamicsModel> kModels = {{"bem", HullHydrodynamicsModel::bem},
                                                            {"morison", HullHydrodynamicsModel::morison}};
  static const EnumTable<ExcitationSource> kExcitationSources = {
      {"files", ExcitationSource::files}, {"morison_maccamy_fuchs", ExcitationSource::morison_maccamy_fuchs}};
  static const EnumTable<RadiationModel> kRadiationModels = {{"low_frequency", RadiationModel::low_frequency},
                                                             {"memory", RadiationModel::memory}};
  // Keys of one model only: given with the other, key_not_applicable.
  static constexpr std::string_view kBemKeys[] = {"radiation_file",       "frequency_column", "ulen",
                                                  "period_scale",         "excitation_file",  "rao_file",
                                                  "added_mass_frequency", "radiation",        "memory_duration",
                                                  "memory_time_step",     "excitation"};
  static constexpr std::string_view kMorisonKeys[] = {"strip_length"};
  HullHydrodynamics h;
  assign(h.model, r.enumeration("model", kModels, kOptional));
  const bool morison = h.model == HullHydrodynamicsModel::morison;
  for (const auto key :
       morison ? std::span<const std::string_view>(kBemKeys) : std::span<const std::string_view>(kMorisonKeys)) {
    if (const auto node = r.child(key, kOptional)) {
      r.context().add(
          node->Mark(), r.path_of(key),
          fmt::format("applies to model: {} only, got model: {}", morison ? "bem" : "morison", to_string(h.model)),
          "key_not_applicable");
    }
  }
  if (morison) {
    assign(h.strip_length_m, r.number("strip_length", "m", kOptional));
  } else {
    if (const auto file = r.text("radiation_file", kRequired)) h.radiation_file = resolve(*file, base_folder);
    assign(h.frequency_column, r.enumeration("frequency_column", kColumns, kOptional));
    assign(h.ulen_m, r.number("ulen", "m", kOptional));
    assign(h.period_scale, r.number("period_scale", "-", kOptional));
    if (const auto file = r.text("excitation_file", kOptional)) h.excitation_file = resolve(*file, base_folder);
    if (const auto file = r.text("rao_file", kOptional)) h.rao_file = resolve(*file, base_folder);
    assign(h.excitation, r.enumeration("excitation", kExcitationSources, kOptional));
    h.added_mass_frequency_rad_per_s = r.number("added_mass_frequency", "rad/s", kOptional);
    assign(h.radiation, r.enumeration("radiation", kRadiationModels, kOptional));
    assign(h.memory_duration_s, r.number("memory_duration", "s", kOptional));
    assign(h.memory_time_step_s, r.number("memory_time_step", "s", kOptional));
  }
  assign(h.linear_damping, r.vector<6>("linear_damping", "N s/m, N m s/rad", kOptional));
  assign(h.quadratic_damping, r.vector<6>("quadratic_damping", "N s^2/m^2, N m s^2/rad^2", kOptional));
  return h;
}

void read_member_coefficients(MapReader& r, MemberCoefficients& c) {
  assign(c.drag, r.number("drag", "-", kOptional));
  assign(c.added_mass, r.number("added_mass", "-", kOptional));
}

HullGeometry read_hull_geometry(MapReader& r, const std::filesystem::path& base_folder) {
  HullGeometry g;
  if (const auto file = r.text("panel_mesh", kOptional)) g.panel_mesh = resolve(*file, base_folder);
  r.list_of_maps("columns", kOptional, [&](MapReader& c) {
    HullColumn column;
    assign(column.center_b, c.vector<2>("center", "m", kRequired));
    assign(column.z_bottom_m, c.number("z_bottom", "m", kRequired));
    assign(column.z_top_m, c.number("z_top", "m", kRequired));
    assign(column.diameter_m, c.number("diameter", "m", kRequired));
    read_member_coefficients(c, column.coefficients);
    assign(column.end_added_mass, c.number("end_added_mass", "-", kOptional));
    assign(column.end_drag, c.number("end_drag", "-", kOptional));
    g.columns.push_back(column);
  });
  r.list_of_maps("pontoons", kOptional, [&](MapReader& p) {
    HullPontoon pontoon;
    assign(pontoon.from_b, p.position("from", kRequired));
    assign(pontoon.to_b, p.position("to", kRequired));
    assign(pontoon.diameter_m, p.number("diameter", "m", kRequired));
    read_member_coefficients(p, pontoon.coefficients);
    g.pontoons.push_back(pontoon);
  });
  return g;
}

}  // namespace

Hull read_hull(MapReader& r, const std::filesystem::path& base_folder) {
  Hull hull;
  assign(hull.reference_point_g, r.position("reference_point", kRequired));
  assign(hull.mass_kg, r.number("mass", "kg", kRequired));
  assign(hull.center_of_gravity_b, r.position("center_of_gravity", kRequired));
  hull.radii_of_gyration_m = r.vector<3>("radii_of_gyration", "m", kOptional);
  if (const auto node = r.child("inertia", kOptional)) {
    // [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz], kg m^2 about the CoG.
    const std::string path = r.path_of("inertia");
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    if (node->IsSequence() && node->size() == 6) {
      if (const auto v = to_vector<6>(r.context(), *node, path, "kg m^2")) {
        inertia << (*v)[0], (*v)[3], (*v)[4], (*v)[3], (*v)[1], (*v)[5], (*v)[4], (*v)[5], (*v)[2];
        hull.inertia_kg_m2 = inertia;
      }
    } else if (const auto v = to_vector<3>(r.context(), *node, path, "kg m^2")) {
      inertia.diagonal() = *v;
      hull.inertia_kg_m2 = inertia;
    }
  }
  if (r.has("radii_of_gyration") == r.has("inertia")) {
    r.context().add(r.mark(), r.path_of("radii_of_gyration"),
                    "give exactly one of radii_of_gyration (m) or inertia (kg m^2), about the CoG",
                    r.has("inertia") ? "conflicting_keys" : "missing_key");
  }
  hull.displaced_volume_m3 = r.number("displaced_volume", "m^3", kOptional);
  hull.center_of_buoyancy_b = r.position("center_of_buoyancy", kOptional);
  hull.waterplane_area_m2 = r.number("waterplane_area", "m^2", kOptional);
  hull.waterplane_inertia_m4 = r.vector<2>("waterplane_inertia", "m^4", kOptional);
  if (const auto file = r.text("hydrostatics_file", kOptional)) {
    hull.hydrostatics_file = resolve(*file, base_folder);
  }
  r.map("wind_coefficients", kOptional, [&](MapReader& w) {
    WindCoefficients c;
    read_load_coefficients(w, c);
    assign(c.reference_height_m, w.number("reference_height", "m", kOptional));
    hull.wind_coefficients = c;
  });
  r.map("current_coefficients", kOptional, [&](MapReader& w) {
    HullLoadCoefficients c;
    read_load_coefficients(w, c);
    hull.current_coefficients = c;
  });
  r.map("mean_drift", kOptional, [&](MapReader& d) {
    hull.mean_drift_headings = read_mean_drift_headings(d);
    hull.mean_drift = read_mean_drift(d, base_folder);
  });
  r.map("hydrodynamics", kOptional,
        [&](MapReader& d) { hull.hydrodynamics = read_hull_hydrodynamics(d, base_folder); });
  r.map("geometry", kOptional, [&](MapReader& g) { hull.geometry = read_hull_geometry(g, base_folder); });
  return hull;
}

}  // namespace spiral::design::loader_detail
