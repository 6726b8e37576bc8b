#pragma once
// The OC4-DeepCwind semi-submersible as a low-frequency hull model, from
// shared/data/reference-platforms.md: §1.1 full-system mass and inertia,
// §1.2 hydrostatics (C33, C44 = C55 incl. gravity), §1.5 added mass at the
// 110 s period (surge/pitch coupling A15), §1.8 mooring stiffness (K11, K33,
// K55, K66, K15). The centre of gravity is put on the z axis (x_G = −0.0065 m
// dropped) so that heave is uncoupled — the single-DOF case of §1.8.

#include <Eigen/Core>

#include "engine/analysis/hull_dynamics.hpp"
#include "engine/common/rigid_body.hpp"

namespace spiral::test {

struct Oc4HullData {
  engine::HullDynamicsModel model;
  engine::LinearizedLines lines;
};

inline Oc4HullData oc4_hull_dynamics() {
  using engine::Matrix6d;
  Oc4HullData d;
  const double mass_kg = 1.40751e7;
  const Eigen::Vector3d cog_m(0.0, 0.0, -9.90);
  const Eigen::Matrix3d inertia_cog = Eigen::Vector3d(1.126e10, 1.126e10, 1.228e10).asDiagonal();
  d.model.mass = engine::rigid_body_mass_matrix(mass_kg, cog_m, inertia_cog);

  Matrix6d A = Matrix6d::Zero();
  A.diagonal() << 8.751e6, 8.751e6, 1.5e7, 7.629e9, 7.629e9, 6.434e9;  // A33 as in §1.8
  A(0, 4) = A(4, 0) = -1.077e8;
  A(1, 3) = A(3, 1) = 1.077e8;  // sway-roll mirrors surge-pitch with the opposite sign
  d.model.added_mass = A;

  Matrix6d C = Matrix6d::Zero();
  C(2, 2) = 3.836e6;
  C(3, 3) = C(4, 4) = 9.892e8;
  d.model.hydrostatic_stiffness = C;

  Matrix6d K = Matrix6d::Zero();
  K.diagonal() << 7.08e4, 7.08e4, 1.91e4, 8.73e7, 8.73e7, 1.172e8;
  K(0, 4) = K(4, 0) = -1.072e5;
  K(1, 3) = K(3, 1) = 1.072e5;
  d.lines.stiffness = K;
  return d;
}

}  // namespace spiral::test
