#include "design/optimization/smooth_zone.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace spiral::design {

namespace {
constexpr int kSamples = 1440;  // every quarter degree
constexpr double kStep_deg = 360.0 / kSamples;
constexpr double kCheckStep_deg = 0.01;
constexpr double kDegPerRad = 180.0 / std::numbers::pi;

double wrap_deg(double deg) {
  deg = std::fmod(deg, 360.0);
  return deg < 0.0 ? deg + 360.0 : deg;
}
}  // namespace

SmoothZone::SmoothZone(const std::function<double(double)>& allowable_of)
    : values_m_(kSamples), slopes_per_step_(kSamples) {
  for (int i = 0; i < kSamples; ++i) values_m_[static_cast<std::size_t>(i)] = allowable_of(i * kStep_deg);
  // Fritsch–Carlson slopes on the unit-degree grid, periodic: zero at a local
  // extremum, the harmonic mean of the neighbouring secants otherwise.
  for (int i = 0; i < kSamples; ++i) {
    const double left =
        values_m_[static_cast<std::size_t>(i)] - values_m_[static_cast<std::size_t>((i + kSamples - 1) % kSamples)];
    const double right =
        values_m_[static_cast<std::size_t>((i + 1) % kSamples)] - values_m_[static_cast<std::size_t>(i)];
    slopes_per_step_[static_cast<std::size_t>(i)] = left * right <= 0.0 ? 0.0 : 2.0 * left * right / (left + right);
  }
  double excess = 0.0;
  for (double deg = 0.0; deg < 360.0; deg += kCheckStep_deg)
    excess = std::max(excess, raw(deg, nullptr) - allowable_of(deg));
  conservatism_m_ = excess;
}

double SmoothZone::raw(double direction_deg, double* slope_per_deg) const {
  const double u = wrap_deg(direction_deg) / kStep_deg;  // in sample steps
  const int i = std::min(static_cast<int>(std::floor(u)), kSamples - 1);
  const double t = u - i;
  const auto a = static_cast<std::size_t>(i);
  const auto b = static_cast<std::size_t>((i + 1) % kSamples);
  // Cubic Hermite on [i, i+1] (unit interval).
  const double h00 = (1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t);
  const double h10 = t * (1.0 - t) * (1.0 - t);
  const double h01 = t * t * (3.0 - 2.0 * t);
  const double h11 = t * t * (t - 1.0);
  if (slope_per_deg) {
    const double d00 = 6.0 * t * t - 6.0 * t;
    const double d10 = 3.0 * t * t - 4.0 * t + 1.0;
    const double d01 = -d00;
    const double d11 = 3.0 * t * t - 2.0 * t;
    *slope_per_deg =
        (d00 * values_m_[a] + d10 * slopes_per_step_[a] + d01 * values_m_[b] + d11 * slopes_per_step_[b]) / kStep_deg;
  }
  return h00 * values_m_[a] + h10 * slopes_per_step_[a] + h01 * values_m_[b] + h11 * slopes_per_step_[b];
}

double SmoothZone::allowable_m(double direction_rad) const {
  return raw(direction_rad * kDegPerRad, nullptr) - conservatism_m_;
}

double SmoothZone::slope_m_per_rad(double direction_rad) const {
  double slope = 0.0;
  raw(direction_rad * kDegPerRad, &slope);
  return slope * kDegPerRad;
}

}  // namespace spiral::design
