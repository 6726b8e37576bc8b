#pragma once
// The hull of a project as the engine's analyses need it: hydrostatic and
// gravity restoring about the reference point, the force at rest (buoyancy
// excess the lines must take), and the rigid-body mass matrix.

#include <optional>

#include "design/project/project.hpp"
#include "engine/common/rigid_body.hpp"
#include "engine/analysis/static_equilibrium.hpp"
#include "engine/hull/hydrostatics.hpp"
#include "engine/hull/morison_hull.hpp"
#include "engine/hull/wamit_1.hpp"

namespace spiral::design {

struct HullModel {
  engine::HullStaticModel statics;  ///< restoring (buoyancy + gravity) and rest force
  engine::HydrostaticRestoring restoring;
  engine::Matrix6d mass_matrix = engine::Matrix6d::Zero();  ///< rigid body, about the reference point
  /// A(w), B(w) from hull.hydrodynamics.radiation_file (absent without it).
  std::optional<engine::HydroCoefficients> radiation;
  /// A(w_LF) for the low-frequency equations and natural periods (zero without
  /// radiation data), and the w_LF it was taken at (rad/s).
  engine::Matrix6d low_frequency_added_mass = engine::Matrix6d::Zero();
  double added_mass_frequency_rad_per_s = 0.0;
  /// hydrodynamics.model: morison — the member strips of hull.geometry; their
  /// added mass is then low_frequency_added_mass (frequency independent).
  std::optional<engine::MorisonHull> morison;
};

/// Whether a BEM hull has a first-order wave excitation: a .4 or .3 file,
/// or `excitation: morison_maccamy_fuchs` (its wave-frequency motions).
bool has_wave_excitation(const Project& project);

/// The first-order excitation of the Morison members of hull.geometry with
/// the MacCamy–Fuchs correction (`excitation: morison_maccamy_fuchs`), at
/// the BEM radiation's frequencies and every 10 deg of heading (a spread
/// sea's components come from any direction), body frame.
engine::ExcitationTable morison_excitation_of(const Project& project, const engine::HydroCoefficients& radiation);

/// The Morison members of hull.geometry: each column a vertical member with
/// end faces, each pontoon a member without (closed by the columns it joins),
/// strips of hydrodynamics.strip_length (1 m without hydrodynamics).
engine::MorisonHull morison_hull_of(const Project& project);

/// The WAMIT read options of the project's hydrodynamics (water, ULEN,
/// frequency column, period scale).
engine::WamitReadOptions wamit_options_of(const Project& project, const HullHydrodynamics& h);

/// Builds the hull model. The restoring comes from the WAMIT .hst file when
/// the project gives one (buoyancy terms, as NREL/OpenFAST files hold them)
/// plus the gravity terms of the project's mass, else from the waterplane and
/// volume properties. Throws engine::FileFormatError for a bad .hst file and
/// std::invalid_argument when the displaced volume is missing. With
/// hull.hydrodynamics the .1 file is read (FileFormatError with file and
/// line) and A is taken at added_mass_frequency (default: the lowest
/// frequency in the file, the low-frequency limit the file offers); with
/// model: morison A is the members' strip-theory added mass.
HullModel build_hull_model(const Project& project);

}  // namespace spiral::design
