#include "engine/environment/current_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spiral::engine {

void validate_current_profile(const CurrentProfile& p) {
  if (p.z_m.empty()) {
    throw std::invalid_argument("current profile: the (z, speed) table is empty");
  }
  if (p.z_m.size() != p.speed_m_per_s.size()) {
    throw std::invalid_argument(fmt::format("current profile: z_m has {} values but speed_m_per_s has {}", p.z_m.size(),
                                            p.speed_m_per_s.size()));
  }
  if (!std::isfinite(p.heading_rad)) {
    throw std::invalid_argument(fmt::format("current profile: heading must be finite (rad), got {}", p.heading_rad));
  }
  for (std::size_t i = 0; i < p.z_m.size(); ++i) {
    if (!std::isfinite(p.z_m[i])) {
      throw std::invalid_argument(fmt::format("current profile: z_m[{}] must be finite (m), got {}", i, p.z_m[i]));
    }
    if (i > 0 && !(p.z_m[i] > p.z_m[i - 1])) {
      throw std::invalid_argument(
          fmt::format("current profile: z_m must be strictly increasing, got z_m[{}] = {} m after {} m", i, p.z_m[i],
                      p.z_m[i - 1]));
    }
    if (!(p.speed_m_per_s[i] >= 0.0) || !std::isfinite(p.speed_m_per_s[i])) {
      throw std::invalid_argument(
          fmt::format("current profile: speed_m_per_s[{}] must be >= 0 m/s, got {} m/s", i, p.speed_m_per_s[i]));
    }
  }
}

Eigen::Vector3d current_velocity_g(const CurrentProfile& p, double z_m) {
  validate_current_profile(p);
  if (!std::isfinite(z_m)) {
    throw std::invalid_argument(fmt::format("current profile: query z must be finite (m), got {}", z_m));
  }
  double speed = 0.0;
  const auto& z = p.z_m;
  if (z_m <= z.front()) {
    speed = p.speed_m_per_s.front();  // held below the deepest point
  } else if (z_m >= z.back()) {
    speed = p.speed_m_per_s.back();  // held above the top point
  } else {
    const auto upper = std::upper_bound(z.begin(), z.end(), z_m);
    const std::size_t i = static_cast<std::size_t>(upper - z.begin());  // z[i-1] <= z_m < z[i]
    const double t = (z_m - z[i - 1]) / (z[i] - z[i - 1]);
    speed = (1.0 - t) * p.speed_m_per_s[i - 1] + t * p.speed_m_per_s[i];
  }
  return {speed * std::cos(p.heading_rad), speed * std::sin(p.heading_rad), 0.0};
}

CurrentProfile power_law_current_profile(const PowerLawCurrentInput& in) {
  if (!(in.surface_speed_m_per_s >= 0.0) || !std::isfinite(in.surface_speed_m_per_s)) {
    throw std::invalid_argument(
        fmt::format("power-law current: surface speed must be >= 0 m/s, got {} m/s", in.surface_speed_m_per_s));
  }
  if (!(in.water_depth_m > 0.0) || !std::isfinite(in.water_depth_m)) {
    throw std::invalid_argument(
        fmt::format("power-law current: water depth must be > 0 m, got {} m", in.water_depth_m));
  }
  if (!(in.exponent > 0.0) || !std::isfinite(in.exponent)) {
    throw std::invalid_argument(fmt::format("power-law current: exponent must be > 0, got {}", in.exponent));
  }
  if (in.points < 2) {
    throw std::invalid_argument(fmt::format("power-law current: points must be >= 2, got {}", in.points));
  }
  CurrentProfile p;
  p.heading_rad = in.heading_rad;
  const double h = in.water_depth_m;
  for (int k = 0; k < in.points; ++k) {
    // Evenly spaced from the seabed up; the last point is exactly z = 0.
    const double z = k + 1 == in.points ? 0.0 : -h + h * k / (in.points - 1);
    p.z_m.push_back(z);
    // OpenFAST Current.f90 sub-surface current: V0 ((z + h)/h)^(1/7).
    p.speed_m_per_s.push_back(in.surface_speed_m_per_s * std::pow((z + h) / h, in.exponent));
  }
  return p;
}

}  // namespace spiral::engine
