#pragma once
// The hull of a project as the engine's analyses need it: hydrostatic and
// gravity restoring about the reference point, the force at rest (buoyancy
// excess the lines must take), and the rigid-body mass matrix.

#include "design/project.hpp"
#include "engine/analysis/rigid_body.hpp"
#include "engine/analysis/static_equilibrium.hpp"
#include "engine/hull/hydrostatics.hpp"

namespace spiral::design {

struct HullModel {
  engine::HullStaticModel statics;      ///< restoring (buoyancy + gravity) and rest force
  engine::HydrostaticRestoring restoring;
  engine::Matrix6d mass_matrix = engine::Matrix6d::Zero();  ///< rigid body, about the reference point
};

/// Builds the hull model. The restoring comes from the WAMIT .hst file when
/// the project gives one (buoyancy terms, as NREL/OpenFAST files hold them)
/// plus the gravity terms of the project's mass, else from the waterplane and
/// volume properties. Throws engine::FileFormatError for a bad .hst file and
/// std::invalid_argument when the displaced volume is missing.
HullModel build_hull_model(const Project& project);

}  // namespace spiral::design
