#pragma once
// Properties of the ambient sea water used by hydrostatic kernels.
// Defaults are the project's reference values (shared/data/reference-platforms.md,
// "Conventions": rho = 1025 kg/m^3, g = 9.80665 m/s^2 (standard gravity)).

namespace spiral::engine {

struct Seawater {
  double density_kg_per_m3 = 1025.0;  ///< > 0
  double gravity_m_per_s2 = 9.80665;  ///< > 0
};

}  // namespace spiral::engine
