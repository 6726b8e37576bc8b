#include "engine/hull/hydrostatics.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace spiral::engine {
namespace {

void require(bool condition, const char* field, const char* expectation, double value, const char* unit) {
  if (!condition || !std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("{}: must be {}, got {} {}", field, expectation, value, unit));
  }
}

void require_finite(const Eigen::Vector3d& v, const char* field) {
  if (!v.allFinite()) {
    throw std::invalid_argument(fmt::format("{}: must be finite, got ({}, {}, {}) m", field, v.x(), v.y(), v.z()));
  }
}

void validate(const Seawater& water) {
  require(water.density_kg_per_m3 > 0.0, "water.density_kg_per_m3", "> 0", water.density_kg_per_m3, "kg/m^3");
  require(water.gravity_m_per_s2 > 0.0, "water.gravity_m_per_s2", "> 0", water.gravity_m_per_s2, "m/s^2");
}

// Indices of the 6-DOF vector (0-based: surge 0 ... yaw 5).
constexpr int kHeave = 2, kRoll = 3, kPitch = 4, kYaw = 5;

}  // namespace

Matrix6d buoyancy_restoring(const HydrostaticBody& body, const Seawater& water) {
  validate(water);
  const auto& wp = body.waterplane;
  require(wp.area_m2 >= 0.0, "hydrostatics.waterplane.area_m2", ">= 0", wp.area_m2, "m^2");
  require(wp.second_moment_xx_m4 >= 0.0, "hydrostatics.waterplane.second_moment_xx_m4", ">= 0", wp.second_moment_xx_m4,
          "m^4");
  require(wp.second_moment_yy_m4 >= 0.0, "hydrostatics.waterplane.second_moment_yy_m4", ">= 0", wp.second_moment_yy_m4,
          "m^4");
  require(std::isfinite(wp.product_moment_xy_m4), "hydrostatics.waterplane.product_moment_xy_m4", "finite",
          wp.product_moment_xy_m4, "m^4");
  if (!wp.centroid_m.allFinite()) {
    throw std::invalid_argument("hydrostatics.waterplane.centroid_m: must be finite");
  }
  require(body.displaced_volume_m3 >= 0.0, "hydrostatics.displaced_volume_m3", ">= 0", body.displaced_volume_m3, "m^3");
  require_finite(body.centre_of_buoyancy_m, "hydrostatics.centre_of_buoyancy_m");

  const double rg = water.density_kg_per_m3 * water.gravity_m_per_s2;
  const double V = body.displaced_volume_m3;
  const Eigen::Vector3d& b = body.centre_of_buoyancy_m;
  const double Sx = wp.area_m2 * wp.centroid_m.x();  // ∫ x dA
  const double Sy = wp.area_m2 * wp.centroid_m.y();  // ∫ y dA

  // WAMIT User Manual v7 §3.1 with the body mass set to zero (the rho g terms).
  Matrix6d C = Matrix6d::Zero();
  C(kHeave, kHeave) = rg * wp.area_m2;
  C(kHeave, kRoll) = C(kRoll, kHeave) = rg * Sy;
  C(kHeave, kPitch) = C(kPitch, kHeave) = -rg * Sx;
  C(kRoll, kRoll) = rg * (wp.second_moment_xx_m4 + V * b.z());
  C(kRoll, kPitch) = C(kPitch, kRoll) = -rg * wp.product_moment_xy_m4;
  C(kRoll, kYaw) = -rg * V * b.x();
  C(kPitch, kPitch) = rg * (wp.second_moment_yy_m4 + V * b.z());
  C(kPitch, kYaw) = -rg * V * b.y();
  return C;
}

Matrix6d gravity_restoring(const BodyMass& mass, double gravity_m_per_s2) {
  require(mass.mass_kg >= 0.0, "mass.mass_kg", ">= 0", mass.mass_kg, "kg");
  require(gravity_m_per_s2 > 0.0, "gravity_m_per_s2", "> 0", gravity_m_per_s2, "m/s^2");
  require_finite(mass.centre_of_gravity_m, "mass.centre_of_gravity_m");
  const double mg = mass.mass_kg * gravity_m_per_s2;
  const Eigen::Vector3d& G = mass.centre_of_gravity_m;
  // WAMIT User Manual v7 §3.1, the m g terms: a rotation raises or lowers the
  // CG, so the weight's moment about the reference point changes by
  // -m g z_g (roll, pitch) and, for an off-centre CG, couples to yaw.
  Matrix6d C = Matrix6d::Zero();
  C(kRoll, kRoll) = -mg * G.z();
  C(kPitch, kPitch) = -mg * G.z();
  C(kRoll, kYaw) = mg * G.x();
  C(kPitch, kYaw) = mg * G.y();
  return C;
}

HydrostaticRestoring hydrostatic_restoring(const Matrix6d& buoyancy_6x6, double displaced_volume_m3,
                                           const Eigen::Vector3d& centre_of_buoyancy_m, const BodyMass& mass,
                                           const Seawater& water) {
  validate(water);
  if (!buoyancy_6x6.allFinite()) {
    throw std::invalid_argument("hydrostatics.buoyancy_6x6: must be finite");
  }
  require(displaced_volume_m3 >= 0.0, "hydrostatics.displaced_volume_m3", ">= 0", displaced_volume_m3, "m^3");
  require_finite(centre_of_buoyancy_m, "hydrostatics.centre_of_buoyancy_m");

  HydrostaticRestoring r;
  r.buoyancy_6x6 = buoyancy_6x6;
  r.gravity_6x6 = gravity_restoring(mass, water.gravity_m_per_s2);
  r.total_6x6 = r.buoyancy_6x6 + r.gravity_6x6;

  // Rest-position load about the reference point: buoyancy rho g V up at B,
  // weight m g down at G (moment = r x F with F = (0, 0, F_z)).
  const double buoyancy_N = water.density_kg_per_m3 * water.gravity_m_per_s2 * displaced_volume_m3;
  const double weight_N = mass.mass_kg * water.gravity_m_per_s2;
  const Eigen::Vector3d& B = centre_of_buoyancy_m;
  const Eigen::Vector3d& G = mass.centre_of_gravity_m;
  r.rest_force(kHeave) = buoyancy_N - weight_N;
  r.rest_force(kRoll) = buoyancy_N * B.y() - weight_N * G.y();
  r.rest_force(kPitch) = -(buoyancy_N * B.x() - weight_N * G.x());

  if (buoyancy_N > 0.0) {
    r.metacentric_height_transverse_m = r.total_6x6(kRoll, kRoll) / buoyancy_N;
    r.metacentric_height_longitudinal_m = r.total_6x6(kPitch, kPitch) / buoyancy_N;
  }
  return r;
}

HydrostaticRestoring hydrostatic_restoring(const HydrostaticBody& body, const BodyMass& mass, const Seawater& water) {
  return hydrostatic_restoring(buoyancy_restoring(body, water), body.displaced_volume_m3, body.centre_of_buoyancy_m,
                               mass, water);
}

Vector6d linear_hydrostatic_load(const HydrostaticRestoring& restoring, const Vector6d& displacement) {
  if (!displacement.allFinite()) {
    throw std::invalid_argument("linear_hydrostatic_load: displacement must be finite");
  }
  // First-order Taylor expansion about the rest position (WAMIT §3.1 / Faltinsen
  // 1990 ch. 2): F = F0 - C xi.
  return restoring.rest_force - restoring.total_6x6 * displacement;
}

}  // namespace spiral::engine
