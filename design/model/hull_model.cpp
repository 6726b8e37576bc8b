#include "design/model/hull_model.hpp"

#include <list>
#include <mutex>
#include <numbers>
#include <string>
#include <utility>
#include <vector>
#include <stdexcept>

#include "engine/hull/wamit_hst.hpp"

namespace spiral::design {

engine::WamitReadOptions wamit_options_of(const Project& project, const HullHydrodynamics& h) {
  engine::WamitReadOptions options;
  options.frequency_column = h.frequency_column == FrequencyColumnKind::period
                                 ? engine::FrequencyColumn::period_s
                                 : engine::FrequencyColumn::angular_frequency;
  options.ulen_m = h.ulen_m;
  options.period_scale = h.period_scale;
  options.water = {project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2};
  return options;
}

bool has_wave_excitation(const Project& project) {
  const auto& h = project.hull.hydrodynamics;
  return h && h->model == HullHydrodynamicsModel::bem &&
         (h->rao_file || h->excitation_file || h->excitation == ExcitationSource::morison_maccamy_fuchs);
}

namespace {

/// Every number the Morison excitation table depends on, as bytes: equal
/// keys give bit-identical tables.
std::string excitation_key(const engine::MorisonHull& hull, const engine::Seawater& water, std::optional<double> depth,
                           const std::vector<double>& omegas) {
  std::vector<double> v;
  const auto add3 = [&v](const Eigen::Vector3d& x) { v.insert(v.end(), x.data(), x.data() + 3); };
  for (const engine::MorisonStrip& s : hull.strips) {
    add3(s.center_b);
    add3(s.axis_b);
    v.insert(v.end(), {s.length_m, s.diameter_m, s.drag_coefficient, s.added_mass_coefficient,
                       s.submerged_at_rest ? 1.0 : 0.0, static_cast<double>(s.member)});
  }
  v.push_back(-1.0);  // strips | faces
  for (const engine::MorisonEndFace& f : hull.faces) {
    add3(f.center_b);
    add3(f.inward_normal_b);
    v.insert(v.end(), {f.radius_m, f.added_mass_coefficient, f.drag_coefficient, f.submerged_at_rest ? 1.0 : 0.0,
                       static_cast<double>(f.member)});
  }
  add3(hull.reference_point_at_rest_g);
  v.insert(v.end(), {water.density_kg_per_m3, water.gravity_m_per_s2, depth ? 1.0 : 0.0, depth.value_or(0.0)});
  v.insert(v.end(), omegas.begin(), omegas.end());
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
}

}  // namespace

engine::ExcitationTable morison_excitation_of(const Project& project, const engine::HydroCoefficients& radiation) {
  constexpr int kHeadings = 36;
  const engine::MorisonHull hull = morison_hull_of(project);
  const engine::Seawater water{project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2};
  // Every case model of a run builds the same hull, and the table (36
  // headings × the radiation frequencies, each a sum over the strips with
  // MacCamy–Fuchs Bessel factors) was a quarter of a 3-h S-C storm's time:
  // kept per process by its inputs, the last few of them.
  static std::mutex mutex;
  static std::list<std::pair<std::string, engine::ExcitationTable>> computed;
  constexpr std::size_t kKept = 4;
  const std::string key = excitation_key(hull, water, project.site.depth_m, radiation.omega_rad_per_s);
  {
    std::lock_guard lock(mutex);
    for (const auto& [k, table] : computed)
      if (k == key) return table;
  }
  std::vector<double> headings(kHeadings);
  for (int i = 0; i < kHeadings; ++i) headings[static_cast<std::size_t>(i)] = 2.0 * std::numbers::pi * i / kHeadings;
  engine::ExcitationTable table = engine::morison_excitation_table(
      hull, water, project.site.depth_m, radiation.omega_rad_per_s, headings, engine::MorisonDiffraction::maccamy_fuchs,
      "hull.geometry (Morison members, MacCamy-Fuchs)");
  std::lock_guard lock(mutex);
  // Two tasks starting together may both have computed it: keep one entry.
  for (const auto& [k, kept] : computed)
    if (k == key) return table;
  computed.emplace_front(key, table);
  if (computed.size() > kKept) computed.pop_back();
  return table;
}

engine::MorisonHull morison_hull_of(const Project& project) {
  const Hull& hull = project.hull;
  if (!hull.geometry) {
    throw std::invalid_argument("hull.geometry is needed for the Morison member model");
  }
  engine::MorisonHullInput input;
  input.reference_point_at_rest_g = hull.reference_point_g;
  if (hull.hydrodynamics) input.strip_length_m = hull.hydrodynamics->strip_length_m;
  for (const HullColumn& c : hull.geometry->columns) {
    engine::MorisonMember m;
    m.end_a_b = {c.center_b.x(), c.center_b.y(), c.z_bottom_m};
    m.end_b_b = {c.center_b.x(), c.center_b.y(), c.z_top_m};
    m.diameter_m = c.diameter_m;
    m.drag_coefficient = c.coefficients.drag;
    m.added_mass_coefficient = c.coefficients.added_mass;
    m.end_faces = true;
    m.end_added_mass_coefficient = c.end_added_mass;
    m.end_drag_coefficient = c.end_drag;
    input.members.push_back(m);
  }
  for (const HullPontoon& p : hull.geometry->pontoons) {
    engine::MorisonMember m;
    m.end_a_b = p.from_b;
    m.end_b_b = p.to_b;
    m.diameter_m = p.diameter_m;
    m.drag_coefficient = p.coefficients.drag;
    m.added_mass_coefficient = p.coefficients.added_mass;
    input.members.push_back(m);
  }
  return engine::make_morison_hull(input);
}

HullModel build_hull_model(const Project& project) {
  const Hull& hull = project.hull;
  const engine::Seawater water{project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2};
  const engine::BodyMass mass{hull.mass_kg, hull.center_of_gravity_b};
  if (!hull.displaced_volume_m3 || !hull.center_of_buoyancy_b) {
    throw std::invalid_argument(
        "hull.displaced_volume (m^3) and hull.center_of_buoyancy (m) are needed for the static "
        "balance of buoyancy, weight and line loads");
  }

  HullModel model;
  if (hull.hydrostatics_file) {
    const auto hst = engine::read_wamit_hst(*hull.hydrostatics_file, {1.0, water});
    model.restoring = engine::hydrostatic_restoring(hst.restoring_6x6, *hull.displaced_volume_m3,
                                                    *hull.center_of_buoyancy_b, mass, water);
  } else {
    engine::HydrostaticBody body;
    body.waterplane.area_m2 = hull.waterplane_area_m2.value_or(0.0);
    if (hull.waterplane_inertia_m4) {
      body.waterplane.second_moment_xx_m4 = hull.waterplane_inertia_m4->x();
      body.waterplane.second_moment_yy_m4 = hull.waterplane_inertia_m4->y();
    }
    body.displaced_volume_m3 = *hull.displaced_volume_m3;
    body.centre_of_buoyancy_m = *hull.center_of_buoyancy_b;
    model.restoring = engine::hydrostatic_restoring(body, mass, water);
  }
  model.statics.reference_point_at_rest_g = hull.reference_point_g;
  model.statics.hydrostatic_stiffness = model.restoring.total_6x6;
  model.statics.rest_force = model.restoring.rest_force;

  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  if (hull.inertia_kg_m2) {
    inertia = *hull.inertia_kg_m2;
  } else if (hull.radii_of_gyration_m) {
    inertia.diagonal() = hull.mass_kg * hull.radii_of_gyration_m->cwiseProduct(*hull.radii_of_gyration_m);
  }
  model.mass_matrix = engine::rigid_body_mass_matrix(hull.mass_kg, hull.center_of_gravity_b, inertia);
  if (hull.hydrodynamics && hull.hydrodynamics->model == HullHydrodynamicsModel::morison) {
    model.morison = morison_hull_of(project);
    model.low_frequency_added_mass = engine::morison_added_mass(*model.morison, project.site.water_density_kg_per_m3);
  } else if (hull.hydrodynamics) {
    model.radiation =
        engine::read_wamit_1(hull.hydrodynamics->radiation_file, wamit_options_of(project, *hull.hydrodynamics));
    model.added_mass_frequency_rad_per_s =
        hull.hydrodynamics->added_mass_frequency_rad_per_s.value_or(model.radiation->omega_rad_per_s.front());
    model.low_frequency_added_mass = engine::added_mass_at(*model.radiation, model.added_mass_frequency_rad_per_s);
  }
  return model;
}

}  // namespace spiral::design
