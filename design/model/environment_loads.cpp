#include "design/model/environment_loads.hpp"

#include <fmt/format.h>

#include <numbers>

#include "design/project/project_validation.hpp"
#include "engine/environment/wind.hpp"
#include "engine/hull/mean_drift_headings.hpp"
#include "engine/hull/mean_environmental_loads.hpp"
#include "engine/hull/wamit_12d.hpp"

namespace spiral::design {

namespace {

engine::CoefficientTable table_of(const HullLoadCoefficients& c) {
  return {c.headings_rad, c.surge_m2, c.sway_m2, c.yaw_m3};
}

}  // namespace

namespace {

/// The data as given: the .12d file's diagonal or the project's table.
engine::MeanDriftTable drift_data_of(const Project& project, const MeanDrift& drift) {
  if (const auto* file = std::get_if<MeanDriftFile>(&drift)) {
    return engine::read_wamit_12d_mean_drift(file->file, project.site.water_density_kg_per_m3,
                                             project.site.gravity_m_per_s2, file->ulen_m, file->period_scale);
  }
  const auto& t = std::get<design::MeanDriftTable>(drift);
  engine::MeanDriftTable table;
  table.omega_rad_per_s = t.frequencies_rad_per_s;
  table.headings_rad = t.headings_rad;
  const auto fill = [&](int dof, const std::vector<std::vector<double>>& rows) {
    Eigen::MatrixXd m(t.frequencies_rad_per_s.size(), t.headings_rad.size());
    for (std::size_t j = 0; j < rows.size(); ++j)
      for (std::size_t k = 0; k < rows[j].size(); ++k)
        m(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = rows[j][k];
    table.coefficient[static_cast<std::size_t>(dof)] = m;
    table.present[static_cast<std::size_t>(dof)] = true;
  };
  fill(0, t.surge_N_per_m2);
  fill(1, t.sway_N_per_m2);
  fill(5, t.yaw_N_m_per_m2);
  for (int dof : {2, 3, 4}) {
    table.coefficient[static_cast<std::size_t>(dof)] = Eigen::MatrixXd::Zero(
        static_cast<Eigen::Index>(t.frequencies_rad_per_s.size()), static_cast<Eigen::Index>(t.headings_rad.size()));
  }
  return table;
}

}  // namespace

engine::MeanDriftTable drift_table_of(const Project& project, const MeanDrift& drift) {
  const MeanDriftHeadings& rule = project.hull.mean_drift_headings;
  engine::MeanDriftTable table = drift_data_of(project, drift);
  try {
    table = engine::with_symmetry_images(table, {rule.symmetry_rotations, rule.symmetry_mirror_xz});
  } catch (const std::invalid_argument& e) {
    throw InputError({make_issue(project, "hull.mean_drift.symmetry", "mean_drift_symmetry", e.what())});
  }
  if (rule.wave_frame_fill_max_span_rad)
    table = engine::filled_in_wave_frame(table, {.max_span_rad = *rule.wave_frame_fill_max_span_rad});
  return table;
}

engine::CurrentProfile current_profile_of(const Current& current) {
  // The project lists the profile from the surface down; the engine wants z increasing.
  engine::CurrentProfile profile;
  profile.heading_rad = current.heading_rad;
  for (auto it = current.profile.rbegin(); it != current.profile.rend(); ++it) {
    profile.z_m.push_back(it->z_m);
    profile.speed_m_per_s.push_back(it->speed_m_per_s);
  }
  return profile;
}

engine::WaveSpectrum wave_spectrum_of(const Waves& waves) {
  if (waves.spectrum == WaveSpectrum::pierson_moskowitz) {
    return engine::make_pierson_moskowitz_spectrum(waves.hs_m, waves.tp_s);
  }
  return engine::make_jonswap_spectrum({waves.hs_m, waves.tp_s, waves.gamma});
}

std::optional<engine::CurrentProfile> current_profile_of(const Environment& environment) {
  if (!environment.current || environment.current->profile.empty()) return std::nullopt;
  return current_profile_of(*environment.current);
}

MeanEnvironmentLoad mean_environment_load(const Project& project, const Environment& environment,
                                          std::shared_ptr<const engine::MeanDriftTable> drift) {
  MeanEnvironmentLoad result;
  const Hull& hull = project.hull;

  std::optional<engine::CoefficientTable> wind_table;
  double wind_speed_at_table_height = 0.0;
  double wind_heading = 0.0;
  if (environment.wind && environment.wind->speed_m_per_s > 0.0) {
    if (hull.wind_coefficients) {
      wind_table = table_of(*hull.wind_coefficients);
      // The table's speed is the 1-hour mean at its reference height
      // (ISO 19901-1 / NPD profile from the 10 m speed).
      wind_speed_at_table_height = engine::mean_wind_speed_m_per_s(
          {environment.wind->speed_m_per_s, hull.wind_coefficients->reference_height_m});
      wind_heading = environment.wind->heading_rad;
    } else {
      result.notes.push_back(
          fmt::format("wind {:.1f} m/s: no hull.wind_coefficients in the project, wind load on the hull not modelled",
                      environment.wind->speed_m_per_s));
    }
  }

  std::optional<engine::CoefficientTable> current_table;
  const std::optional<engine::CurrentProfile> current = current_profile_of(environment);
  if (current) {
    if (hull.current_coefficients) {
      current_table = table_of(*hull.current_coefficients);
    } else {
      result.notes.push_back(
          "current: no hull.current_coefficients in the project, current load on the hull not modelled");
    }
  }

  std::shared_ptr<const engine::MeanDriftIntegral> drift_integral;
  if (environment.waves) {
    if (hull.mean_drift) {
      const std::shared_ptr<const engine::MeanDriftTable> drift_table =
          drift ? std::move(drift)
                : std::make_shared<const engine::MeanDriftTable>(drift_table_of(project, *hull.mean_drift));
      engine::MeanDriftInput input;
      input.spectrum = wave_spectrum_of(*environment.waves);
      input.wave_heading_rad = environment.waves->heading_rad;
      if (environment.waves->spreading_s) {
        input.spreading = engine::DirectionalSpreading{engine::SpreadingForm::cos_2s, *environment.waves->spreading_s};
      }
      drift_integral = std::make_shared<const engine::MeanDriftIntegral>(*drift_table, input);
      // The heading rule is the project's choice; every result it enters says so.
      const MeanDriftHeadings& rule = hull.mean_drift_headings;
      if (rule.symmetry_rotations > 1 || rule.symmetry_mirror_xz) {
        result.notes.push_back(fmt::format(
            "mean drift: the data's headings extended by the hull's {}-fold symmetry{} (hull.mean_drift.symmetry)",
            rule.symmetry_rotations, rule.symmetry_mirror_xz ? " with the x-z plane as a mirror" : ""));
      }
      if (rule.wave_frame_fill_max_span_rad) {
        result.notes.push_back(
            fmt::format("mean drift: interpolated in the wave frame across gaps between headings up to {:.0f} deg, an "
                        "approximation (hull.mean_drift.wave_frame_fill)",
                        *rule.wave_frame_fill_max_span_rad * 180.0 / std::numbers::pi));
      }
    } else {
      result.notes.push_back(
          fmt::format("waves Hs {:.1f} m: no hull.mean_drift in the project, mean wave drift not modelled",
                      environment.waves->hs_m));
    }
  }

  const double air_density = project.site.air_density_kg_per_m3;
  const double water_density = project.site.water_density_kg_per_m3;
  result.load = [=](const engine::Vector6d& offset) {
    engine::Vector6d load = engine::Vector6d::Zero();
    const double yaw = offset(5);
    if (wind_table)
      load += engine::wind_load(*wind_table, wind_speed_at_table_height, wind_heading, yaw, air_density).load_g;
    if (current_table) load += engine::current_load(*current_table, *current, water_density, yaw).load_g;
    if (drift_integral) load += drift_integral->load(yaw).load_g;
    return load;
  };
  return result;
}

void heading_error(const Project& project, const std::string& environment, const std::string& what,
                   const std::exception& e) {
  std::string path = "waves.heading_deg";
  for (std::size_t i = 0; i < project.environments.size(); ++i)
    if (project.environments[i].name == environment) path = fmt::format("environments[{}].waves.heading_deg", i);
  throw InputError({make_issue(project, path, "heading_in_database", fmt::format("{}: {}", what, e.what()))});
}

}  // namespace spiral::design
