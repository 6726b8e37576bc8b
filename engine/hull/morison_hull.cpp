#include "engine/hull/morison_hull.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/common/rigid_body.hpp"

namespace spiral::engine {
namespace {

using Vector3cd = Eigen::Matrix<std::complex<double>, 3, 1>;
constexpr double kPi = std::numbers::pi;

void check_non_negative(double value, int member, const char* what) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(
        fmt::format("Morison hull: member {}: {} must be finite and >= 0, got {}", member, what, value));
  }
}

/// Depth profiles of linear wave theory at z (global, <= 0) per unit
/// amplitude: C = cosh k(z+h)/sinh kh (horizontal velocity), S = sinh
/// k(z+h)/sinh kh (vertical), P = cosh k(z+h)/cosh kh (pressure); written
/// with exponentials so that deep water (kh large or no depth) is e^{kz}.
struct Profiles {
  double C = 0.0, S = 0.0, P = 0.0;
};

Profiles profiles(double k, double z, std::optional<double> depth) {
  const double ekz = std::exp(k * z);
  if (!depth) return {ekz, ekz, ekz};
  const double h = *depth;
  const double reflected = std::exp(-k * (z + 2.0 * h));
  const double e2kh = std::exp(-2.0 * k * h);
  return {(ekz + reflected) / (1.0 - e2kh), (ekz - reflected) / (1.0 - e2kh), (ekz + reflected) / (1.0 + e2kh)};
}

}  // namespace

MorisonHull make_morison_hull(const MorisonHullInput& input) {
  if (!(input.strip_length_m > 0.0)) {
    throw std::invalid_argument(
        fmt::format("Morison hull: strip length must be > 0 m, got {} m", input.strip_length_m));
  }
  MorisonHull hull;
  hull.reference_point_at_rest_g = input.reference_point_at_rest_g;
  const double z_ref = input.reference_point_at_rest_g.z();
  for (std::size_t m = 0; m < input.members.size(); ++m) {
    const MorisonMember& member = input.members[m];
    const int id = static_cast<int>(m);
    const Eigen::Vector3d d = member.end_b_b - member.end_a_b;
    const double length = d.norm();
    if (!(length > 0.0) || !d.allFinite()) {
      throw std::invalid_argument(fmt::format("Morison hull: member {}: its ends must be distinct finite points", id));
    }
    if (!(member.diameter_m > 0.0) || !std::isfinite(member.diameter_m)) {
      throw std::invalid_argument(
          fmt::format("Morison hull: member {}: diameter must be > 0 m, got {} m", id, member.diameter_m));
    }
    check_non_negative(member.drag_coefficient, id, "drag coefficient");
    check_non_negative(member.added_mass_coefficient, id, "added-mass coefficient");
    check_non_negative(member.end_added_mass_coefficient, id, "end added-mass coefficient");
    check_non_negative(member.end_drag_coefficient, id, "end drag coefficient");
    const Eigen::Vector3d t = d / length;
    // Pieces below and above the mean water level (global z = 0 at rest).
    std::vector<double> cuts = {0.0, length};
    const double za = z_ref + member.end_a_b.z();
    const double zb = z_ref + member.end_b_b.z();
    if ((za < 0.0 && zb > 0.0) || (za > 0.0 && zb < 0.0)) {
      cuts.insert(cuts.begin() + 1, length * (0.0 - za) / (zb - za));
    }
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      const double piece = cuts[c + 1] - cuts[c];
      const int n = std::max(1, static_cast<int>(std::ceil(piece / input.strip_length_m - 1e-9)));
      const double ds = piece / n;
      for (int i = 0; i < n; ++i) {
        MorisonStrip s;
        s.center_b = member.end_a_b + t * (cuts[c] + (i + 0.5) * ds);
        s.axis_b = t;
        s.length_m = ds;
        s.diameter_m = member.diameter_m;
        s.drag_coefficient = member.drag_coefficient;
        s.added_mass_coefficient = member.added_mass_coefficient;
        s.submerged_at_rest = z_ref + s.center_b.z() < 0.0;
        s.member = id;
        hull.strips.push_back(s);
      }
    }
    if (member.end_faces) {
      for (const auto& [center, normal] :
           {std::pair{member.end_a_b, Eigen::Vector3d(t)}, std::pair{member.end_b_b, Eigen::Vector3d(-t)}}) {
        MorisonEndFace f;
        f.center_b = center;
        f.inward_normal_b = normal;
        f.radius_m = 0.5 * member.diameter_m;
        f.added_mass_coefficient = member.end_added_mass_coefficient;
        f.drag_coefficient = member.end_drag_coefficient;
        f.submerged_at_rest = z_ref + center.z() < 0.0;
        f.member = id;
        hull.faces.push_back(f);
      }
    }
  }
  return hull;
}

Matrix6d morison_added_mass(const MorisonHull& hull, double rho) {
  Matrix6d A = Matrix6d::Zero();
  for (const MorisonStrip& s : hull.strips) {
    if (!s.submerged_at_rest) continue;
    const double m = rho * s.added_mass_coefficient * 0.25 * kPi * s.diameter_m * s.diameter_m * s.length_m;
    const Eigen::Matrix3d normal = Eigen::Matrix3d::Identity() - s.axis_b * s.axis_b.transpose();
    const auto J = point_jacobian(s.center_b);
    A += m * J.transpose() * normal * J;
  }
  for (const MorisonEndFace& f : hull.faces) {
    if (!f.submerged_at_rest) continue;
    const double m = rho * f.added_mass_coefficient * (2.0 / 3.0) * kPi * std::pow(f.radius_m, 3);
    const auto J = point_jacobian(f.center_b);
    A += m * J.transpose() * (f.inward_normal_b * f.inward_normal_b.transpose()) * J;
  }
  return A;
}

std::complex<double> maccamy_fuchs_factor(double x) {
  if (!(x > 0.0)) throw std::invalid_argument(fmt::format("MacCamy-Fuchs factor: kR must be > 0, got {}", x));
  // J1' = J0 − J1/x, Y1' = Y0 − Y1/x (Abramowitz & Stegun 9.1.27).
  const double dJ1 = std::cyl_bessel_j(0.0, x) - std::cyl_bessel_j(1.0, x) / x;
  const double dY1 = std::cyl_neumann(0.0, x) - std::cyl_neumann(1.0, x) / x;
  const std::complex<double> i(0.0, 1.0);
  return -2.0 * i / (kPi * x * x * std::complex<double>(dJ1, -dY1));
}

Vector6cd morison_excitation(const MorisonHull& hull, const Seawater& water, std::optional<double> depth, double omega,
                             double heading, MorisonDiffraction diffraction) {
  if (!(omega > 0.0)) {
    throw std::invalid_argument(fmt::format("Morison excitation: frequency must be > 0 rad/s, got {}", omega));
  }
  const double k = solve_dispersion({omega, depth, water.gravity_m_per_s2}).wavenumber_rad_per_m;
  const double rho = water.density_kg_per_m3;
  const double cb = std::cos(heading);
  const double sb = std::sin(heading);
  const std::complex<double> i(0.0, 1.0);
  const double z_ref = hull.reference_point_at_rest_g.z();
  // Incident wave per unit amplitude, eta = e^{i(wt − k (x cos b + y sin b))}
  // (wamit_3.hpp), x, y from the reference point; a = i w u.
  struct Flow {
    Vector3cd acceleration;
    std::complex<double> pressure;
  };
  auto flow_at = [&](const Eigen::Vector3d& r_b) {
    const double z = z_ref + r_b.z();
    const Profiles p = profiles(k, z, depth);
    const std::complex<double> phase = std::exp(-i * (k * (r_b.x() * cb + r_b.y() * sb)));
    Flow f;
    f.acceleration << i * omega * omega * p.C * cb * phase, i * omega * omega * p.C * sb * phase,
        -omega * omega * p.S * phase;
    f.pressure = rho * water.gravity_m_per_s2 * p.P * phase;
    return f;
  };
  Vector6cd X = Vector6cd::Zero();
  auto add = [&X](const Eigen::Vector3d& r, const Vector3cd& F) {
    X.head<3>() += F;
    // Real r x complex F by parts (Eigen's complex cross() conjugates).
    const Eigen::Vector3d re = r.cross(Eigen::Vector3d(F.real()));
    const Eigen::Vector3d im = r.cross(Eigen::Vector3d(F.imag()));
    X.tail<3>() += re.cast<std::complex<double>>() + std::complex<double>(0.0, 1.0) * im.cast<std::complex<double>>();
  };
  const bool maccamy_fuchs = diffraction == MorisonDiffraction::maccamy_fuchs;
  // The factor depends on the diameter alone at this frequency, and a hull
  // has a few diameters over many strips: each computed once (four Bessel
  // functions per strip were 13 % of a wave-frequency coupled run's profile).
  std::vector<std::pair<double, std::complex<double>>> factor_by_diameter;
  const auto column_factor = [&](double diameter_m) {
    for (const auto& [d, factor] : factor_by_diameter)
      if (d == diameter_m) return factor;
    return factor_by_diameter.emplace_back(diameter_m, maccamy_fuchs_factor(0.5 * k * diameter_m)).second;
  };
  // A member within 1e-6 rad of the vertical is a column for the correction.
  const auto vertical = [](const Eigen::Vector3d& axis) { return std::abs(axis.z()) > 1.0 - 1e-12; };
  for (const MorisonStrip& s : hull.strips) {
    if (!s.submerged_at_rest) continue;
    const Flow f = flow_at(s.center_b);
    const Vector3cd t = s.axis_b.cast<std::complex<double>>();
    const Vector3cd a_n = f.acceleration - t * t.dot(f.acceleration);  // t real: dot = t^T a
    const double mass = rho * (1.0 + s.added_mass_coefficient) * 0.25 * kPi * s.diameter_m * s.diameter_m * s.length_m;
    const std::complex<double> scale = maccamy_fuchs && vertical(s.axis_b) ? column_factor(s.diameter_m) : 1.0;
    add(s.center_b, scale * mass * a_n);
  }
  for (const MorisonEndFace& face : hull.faces) {
    if (!face.submerged_at_rest) continue;
    const Flow f = flow_at(face.center_b);
    const Vector3cd n = face.inward_normal_b.cast<std::complex<double>>();
    const double R = face.radius_m;
    const double area = kPi * R * R;
    const double end_mass = rho * face.added_mass_coefficient * (2.0 / 3.0) * kPi * std::pow(R, 3);
    if (maccamy_fuchs && vertical(face.inward_normal_b)) {
      // The incident pressure p_c e^{−i k·ξ} over the disc |ξ| <= R about the
      // centre: ∫ dA = π R² 2 J1(kR)/(kR), ∫ ξ dA = −2π i R² J2(kR)/k ê
      // (ê = (cos β, sin β, 0), the direction of propagation; Abramowitz &
      // Stegun 9.1.21 for the integral over the angle). The first moment
      // gives the face a moment (∫ p ξ dA) × n about its centre. The end
      // added-mass inertia takes the same disc average of the incident
      // acceleration (at the centre alone it would cancel the averaged
      // pressure earlier still).
      const double x = k * R;
      const double mean = 2.0 * std::cyl_bessel_j(1.0, x) / x;
      const Eigen::Vector3d e(cb, sb, 0.0);
      const std::complex<double> first_moment =
          -2.0 * kPi * std::complex<double>(0.0, 1.0) * R * R * std::cyl_bessel_j(2.0, x) / k;
      add(face.center_b, mean * (f.pressure * area * n + end_mass * n * n.dot(f.acceleration)));
      const Eigen::Vector3d arm = e.cross(face.inward_normal_b);
      X.tail<3>() += f.pressure * first_moment * arm.cast<std::complex<double>>();
    } else {
      add(face.center_b, f.pressure * area * n + end_mass * n * n.dot(f.acceleration));
    }
  }
  return X;
}

WaveTransferTable morison_excitation_table(const MorisonHull& hull, const Seawater& water, std::optional<double> depth,
                                           const std::vector<double>& omegas, const std::vector<double>& headings,
                                           MorisonDiffraction diffraction, const std::string& file) {
  WaveTransferTable table;
  table.quantity = TransferQuantity::excitation;
  table.omega_rad_per_s = omegas;
  table.headings_rad = headings;
  table.file = file;
  const auto rows = static_cast<Eigen::Index>(headings.size());
  const auto cols = static_cast<Eigen::Index>(omegas.size());
  for (auto& v : table.values) v = Eigen::MatrixXcd::Zero(rows, cols);
  table.dof_present.fill(true);
  for (Eigen::Index h = 0; h < rows; ++h) {
    for (Eigen::Index w = 0; w < cols; ++w) {
      const Vector6cd X = morison_excitation(hull, water, depth, omegas[static_cast<std::size_t>(w)],
                                             headings[static_cast<std::size_t>(h)], diffraction);
      for (int dof = 0; dof < 6; ++dof) table.values[static_cast<std::size_t>(dof)](h, w) = X(dof);
    }
  }
  return table;
}

MorisonLoad morison_load(const MorisonHull& hull, const MorisonFlow& flow, const Eigen::Vector3d& reference_g,
                         const Eigen::Matrix3d& rotation, double t_s, const Vector6d& velocity) {
  const double rho = flow.water_density_kg_per_m3;
  const Eigen::Vector3d v = velocity.head<3>();
  const Eigen::Vector3d w = velocity.tail<3>();
  MorisonLoad out;
  struct Fluid {
    bool wet = false;
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
    Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
    double pressure = 0.0;
  };
  auto fluid_at = [&](const Eigen::Vector3d& p_g) {
    Fluid f;
    if (p_g.z() > flow.highest_crest_m) return f;
    if (flow.sea != nullptr) {
      const WaveKinematics kin = wave_kinematics(*flow.sea, p_g, t_s);
      if (!kin.wet) return f;
      f.velocity = kin.velocity_m_per_s;
      f.acceleration = kin.acceleration_m_per_s2;
      f.pressure = kin.dynamic_pressure_Pa;
    } else if (p_g.z() > 0.0) {
      return f;
    }
    f.wet = true;
    if (flow.current != nullptr) f.velocity += current_velocity_g(*flow.current, std::min(0.0, p_g.z()));
    return f;
  };
  auto add = [&out](const Eigen::Vector3d& arm, const Eigen::Vector3d& F) {
    out.force.head<3>() += F;
    out.force.tail<3>() += arm.cross(F);
  };
  for (const MorisonStrip& s : hull.strips) {
    const Eigen::Vector3d arm = rotation * s.center_b;
    const Eigen::Vector3d t = rotation * s.axis_b;
    const Eigen::Vector3d centre = reference_g + arm;
    // Vertical extent of the strip (axis and section): the wetted fraction
    // grows continuously as the surface rises through it, so the force has no
    // jumps when a strip wets or dries (a jump would stall the integrator).
    const double half_height =
        0.5 * s.length_m * std::abs(t.z()) + 0.5 * s.diameter_m * std::sqrt(std::max(0.0, 1.0 - t.z() * t.z()));
    const double z_low = centre.z() - half_height;
    if (z_low > flow.highest_crest_m) continue;
    const double eta = flow.sea != nullptr ? surface_elevation_m(*flow.sea, centre.x(), centre.y(), t_s) : 0.0;
    const double wet = std::clamp((eta - z_low) / (2.0 * half_height), 0.0, 1.0);
    if (wet == 0.0) continue;
    // Kinematics at the centre of the wetted part.
    const Eigen::Vector3d point(centre.x(), centre.y(), std::min(centre.z(), z_low + wet * half_height));
    const Fluid f = fluid_at(point);
    if (!f.wet) continue;
    ++out.wet_strips;
    const Eigen::Vector3d relative = f.velocity - (v + w.cross(arm));
    const Eigen::Vector3d u_n = relative - t * t.dot(relative);
    const Eigen::Vector3d a_n = f.acceleration - t * t.dot(f.acceleration);
    const double area = 0.25 * kPi * s.diameter_m * s.diameter_m;
    add(arm, wet * (rho * (1.0 + s.added_mass_coefficient) * area * s.length_m * a_n +
                    0.5 * rho * s.drag_coefficient * s.diameter_m * s.length_m * u_n.norm() * u_n));
  }
  for (const MorisonEndFace& face : hull.faces) {
    const Eigen::Vector3d arm = rotation * face.center_b;
    const Fluid f = fluid_at(reference_g + arm);
    if (!f.wet) continue;
    const Eigen::Vector3d n = rotation * face.inward_normal_b;
    const Eigen::Vector3d relative = f.velocity - (v + w.cross(arm));
    const double u_t = n.dot(relative);
    const double area = kPi * face.radius_m * face.radius_m;
    const double end_mass = rho * face.added_mass_coefficient * (2.0 / 3.0) * kPi * std::pow(face.radius_m, 3);
    add(arm, (f.pressure * area + end_mass * n.dot(f.acceleration) +
              0.5 * rho * face.drag_coefficient * area * std::abs(u_t) * u_t) *
                 n);
  }
  return out;
}

}  // namespace spiral::engine
