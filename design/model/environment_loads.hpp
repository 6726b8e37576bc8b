#pragma once
// Mean (static) environmental loads on the hull for one environment of the
// project: wind and current from the hull's heading-dependent coefficient
// tables, mean wave drift from drift coefficients and the sea spectrum.
// Loads that the environment asks for but the project gives no data for are
// not invented: they are listed in `notes` so the engineer sees what is missing.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "design/project/project.hpp"
#include "engine/analysis/static_equilibrium.hpp"
#include "engine/environment/current_profile.hpp"
#include "engine/environment/wave_spectrum.hpp"
#include "engine/hull/mean_environmental_loads.hpp"

namespace spiral::design {

struct MeanEnvironmentLoad {
  /// Load on the hull (N, N·m, global axes) at a hull offset (yaw matters).
  engine::ExternalLoad load;
  std::vector<std::string> notes;  ///< loads not modelled, and why; the mean drift's heading rule
};

/// The environment's current as an engine profile (global, direction of propagation).
engine::CurrentProfile current_profile_of(const Current& current);
/// The environment's current profile; none when it has no current (or an empty profile).
std::optional<engine::CurrentProfile> current_profile_of(const Environment& environment);

/// The environment's sea spectrum.
engine::WaveSpectrum wave_spectrum_of(const Waves& waves);

/// The hull's mean drift coefficients (from the .12d file or the table),
/// with the images of the hull's declared symmetry and the wave-frame fill
/// the project asks for (hull.mean_drift_headings). Throws
/// engine::FileFormatError for a bad .12d file, InputError
/// (mean_drift_symmetry) for data that contradict the declared symmetry.
engine::MeanDriftTable drift_table_of(const Project& project, const MeanDrift& drift);
/// Throws engine::FileFormatError for a bad .12d file. `drift`: the drift
/// table already read (a case model's); null: read here when needed.
MeanEnvironmentLoad mean_environment_load(const Project& project, const Environment& environment,
                                          std::shared_ptr<const engine::MeanDriftTable> drift = nullptr);

/// A heading outside a table of the hull's data (engine::TableRangeError:
/// RAOs, drift, coefficients) as the input error it is: at the environment's
/// waves.heading_deg, problem `heading_in_database`, `what` naming the data.
[[noreturn]] void heading_error(const Project& project, const std::string& environment, const std::string& what,
                                const std::exception& e);

}  // namespace spiral::design
