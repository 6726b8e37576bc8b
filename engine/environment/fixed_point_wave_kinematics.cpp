#include "engine/environment/fixed_point_wave_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace spiral::engine {

FixedPointWaveKinematics::FixedPointWaveKinematics(std::shared_ptr<const WaveRealization> sea,
                                                   const std::vector<Eigen::Vector3d>& points, double cutoff,
                                                   double sample_interval_s)
    : sea_(std::move(sea)), interval_s_(sample_interval_s) {
  if (!sea_) throw std::invalid_argument("fixed-point wave kinematics: no sea");
  if (!(cutoff > 0.0 && cutoff < 1.0))
    throw std::invalid_argument("fixed-point wave kinematics: cutoff must be in (0, 1)");
  if (!(sample_interval_s >= 0.0 && std::isfinite(sample_interval_s)))
    throw std::invalid_argument("fixed-point wave kinematics: sample interval must be >= 0 s");
  const auto& c = sea_->components;
  order_.resize(c.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::size_t a, std::size_t b) { return c[a].wavenumber_rad_per_m < c[b].wavenumber_rad_per_m; });
  cos_wt_.resize(c.size());
  sin_wt_.resize(c.size());
  for (std::size_t j : order_) {
    omega_.push_back(c[j].omega_rad_per_s);
    wavenumber_.push_back(c[j].wavenumber_rad_per_m);
    cos_heading_.push_back(c[j].cos_heading);
    sin_heading_.push_back(c[j].sin_heading);
    const double k = c[j].wavenumber_rad_per_m, cb = c[j].cos_heading, sb = c[j].sin_heading;
    k_cc_.push_back(k * cb * cb);
    k_cs_.push_back(k * cb * sb);
    k_ss_.push_back(k * sb * sb);
    k_c_.push_back(k * cb);
    k_s_.push_back(k * sb);
  }
  log_cutoff_ = std::log(cutoff);
  points_.resize(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) set_point(points_[p], points[p]);
}

double FixedPointWaveKinematics::default_sample_interval_s(const WaveRealization& sea) {
  // rms error / rms acceleration = Δ⁴ √(Σ (a ω² c ω⁴)²) / √(Σ (a ω²)²),
  // c = (9/16) / 24: solved for Δ at kSampledAccelerationError.
  constexpr double c = 9.0 / 16.0 / 24.0;
  double error_sq = 0.0, signal_sq = 0.0;
  for (const WaveComponent& w : sea.components) {
    const double acc = w.amplitude_m * w.omega_rad_per_s * w.omega_rad_per_s;
    error_sq += std::pow(acc * c * std::pow(w.omega_rad_per_s, 4), 2);
    signal_sq += acc * acc;
  }
  if (!(error_sq > 0.0)) return kMaxSampleInterval_s;
  const double per_s4 = std::sqrt(error_sq / signal_sq);  // the ratio at Δ = 1 s
  return std::min(kMaxSampleInterval_s, std::pow(kSampledAccelerationError / per_s4, 0.25));
}

double FixedPointWaveKinematics::midpoint_error(const WaveRealization& sea, double top_z_m, double length_m) {
  const double z = std::min(top_z_m, 0.0);
  double error = 0.0, amplitude = 0.0;
  for (const WaveComponent& w : sea.components) {
    const double velocity = w.amplitude_m * w.omega_rad_per_s;
    const double kl = w.wavenumber_rad_per_m * length_m;
    error += velocity * wave_profiles(w, z, sea.water_depth_m).ch_over_sh * kl * kl / 24.0;
    amplitude += velocity * wave_profiles(w, 0.0, sea.water_depth_m).ch_over_sh;
  }
  return amplitude > 0.0 ? error / amplitude : 0.0;
}

void FixedPointWaveKinematics::move_point(std::size_t point, const Eigen::Vector3d& position) {
  if (point >= points_.size()) throw std::out_of_range("fixed-point wave kinematics: no such point");
  Point& pt = points_[point];
  pt.count = 0;  // set_point keeps the amplitude vectors' storage
  ++pt.generation;
  set_point(pt, position);
}

void FixedPointWaveKinematics::set_point(Point& out, const Eigen::Vector3d& x) {
  const auto& c = sea_->components;
  out.position_m = x;
  out.z_m = x.z();
  if (x.z() >= 0.0) return;  // above the still-water level: no kinematics (see the header)
  // e^{k z} >= cutoff  <=>  k <= ln(cutoff) / z: a prefix of the sorted components.
  const double k_max = log_cutoff_ / x.z();
  while (out.count < order_.size() && c[order_[out.count]].wavenumber_rad_per_m <= k_max) ++out.count;
  out.horizontal_c.resize(out.count);
  out.horizontal_s.resize(out.count);
  out.vertical_c.resize(out.count);
  out.vertical_s.resize(out.count);
  max_count_ = std::max(max_count_, out.count);
  out.elevation_c.resize(out.count);
  out.elevation_s.resize(out.count);
  for (std::size_t j = 0; j < out.count; ++j) {
    const WaveComponent& w = c[order_[j]];
    const WaveProfiles f = wave_profiles(w, x.z(), sea_->water_depth_m);
    const double psi = w.phase_rad - w.kx_rad_per_m * x.x() - w.ky_rad_per_m * x.y();
    const double aw = w.amplitude_m * w.omega_rad_per_s;
    out.horizontal_c[j] = aw * f.ch_over_sh * std::cos(psi);
    out.horizontal_s[j] = aw * f.ch_over_sh * std::sin(psi);
    out.vertical_c[j] = aw * f.sh_over_sh * std::cos(psi);
    out.vertical_s[j] = aw * f.sh_over_sh * std::sin(psi);
    out.elevation_c[j] = w.amplitude_m * std::cos(psi);
    out.elevation_s[j] = w.amplitude_m * std::sin(psi);
  }
}

void FixedPointWaveKinematics::time_phases(double t_s, std::size_t count, double* cos_wt, double* sin_wt,
                                           std::size_t first) const {
  for (std::size_t j = first; j < count; ++j) {
    const double wt = omega_[j] * t_s;
    cos_wt[j] = std::cos(wt);
    sin_wt[j] = std::sin(wt);
  }
}

FixedPointWaveKinematics::Slot& FixedPointWaveKinematics::slot(std::int64_t index) const {
  Slot& s = slots_[ring(index)];
  if (s.index == index && !s.at.empty()) return s;
  s.index = index;
  s.at.assign(points_.size(), HeldSample{});
  s.cos_wt.resize(max_count_);
  s.sin_wt.resize(max_count_);
  time_phases(static_cast<double>(index) * interval_s_, max_count_, s.cos_wt.data(), s.sin_wt.data());
  for (std::size_t p = 0; p < points_.size(); ++p) {
    s.at[p].generation = points_[p].generation;
    if (points_[p].count > 0) s.at[p].sample = at_point(points_[p], s.cos_wt.data(), s.sin_wt.data());
  }
  ++full_sums_;
  return s;
}

const FixedPointWaveKinematics::Sample& FixedPointWaveKinematics::held_sample(Slot& s, std::size_t point) const {
  HeldSample& held = s.at[point];
  const Point& pt = points_[point];
  if (held.generation == pt.generation) return held.sample;
  // Moved since the slot was summed: summed anew under the slot's phases,
  // extended if the point now keeps more components than any point did then.
  if (s.cos_wt.size() < pt.count) {
    const std::size_t had = s.cos_wt.size();
    s.cos_wt.resize(pt.count);
    s.sin_wt.resize(pt.count);
    time_phases(static_cast<double>(s.index) * interval_s_, pt.count, s.cos_wt.data(), s.sin_wt.data(), had);
  }
  held.sample = pt.count > 0 ? at_point(pt, s.cos_wt.data(), s.sin_wt.data()) : Sample{};
  held.generation = pt.generation;
  return held.sample;
}

FixedPointWaveKinematics::GridTime FixedPointWaveKinematics::grid_time(double t_s) const {
  const double x = t_s / interval_s_, base = std::floor(x), u = x - base;
  // Cubic Lagrange weights of the nodes −1, 0, 1, 2 at u ∈ [0, 1).
  return {static_cast<std::int64_t>(base) - 1,
          {-u * (u - 1.0) * (u - 2.0) / 6.0, (u + 1.0) * (u - 1.0) * (u - 2.0) / 2.0, -(u + 1.0) * u * (u - 2.0) / 2.0,
           (u + 1.0) * u * (u - 1.0) / 6.0}};
}

bool FixedPointWaveKinematics::interpolate_point(std::size_t point, const std::array<Slot*, 4>& slots,
                                                 const std::array<double, 4>& w, Eigen::Vector3d& velocity,
                                                 Eigen::Vector3d& acceleration, Gradients* gradients) const {
  std::array<const Sample*, 4> at{};
  for (int k = 0; k < 4; ++k) {
    at[k] = &held_sample(*slots[k], point);
    if (!at[k]->wet) return false;
  }
  double eta = 0.0;
  for (int k = 0; k < 4; ++k) eta += w[k] * at[k]->eta_m;
  if (points_[point].z_m > eta) return true;  // dry between wet samples: under a trough
  for (int k = 0; k < 4; ++k) {
    velocity += w[k] * at[k]->velocity;
    acceleration += w[k] * at[k]->acceleration;
  }
  if (gradients != nullptr) {
    for (int k = 0; k < 4; ++k) {
      gradients->velocity_per_s += w[k] * at[k]->gradients.velocity_per_s;
      gradients->acceleration_per_s2 += w[k] * at[k]->gradients.acceleration_per_s2;
    }
  }
  return true;
}

void FixedPointWaveKinematics::evaluate(double t_s, std::vector<Eigen::Vector3d>& velocity,
                                        std::vector<Eigen::Vector3d>& acceleration,
                                        std::vector<Gradients>* gradients) const {
  velocity.assign(points_.size(), Eigen::Vector3d::Zero());
  acceleration.assign(points_.size(), Eigen::Vector3d::Zero());
  if (gradients != nullptr) gradients->assign(points_.size(), Gradients{});
  const auto take = [&](std::size_t p, const Sample& sum) {
    velocity[p] = sum.velocity;
    acceleration[p] = sum.acceleration;
    if (gradients != nullptr) (*gradients)[p] = sum.gradients;
  };
  if (interval_s_ > 0.0) {
    const GridTime g = grid_time(t_s);
    const std::array<Slot*, 4> slots = {&slot(g.first), &slot(g.first + 1), &slot(g.first + 2), &slot(g.first + 3)};
    bool phases_at_t = false;  // cos_wt_, sin_wt_ hold the phases at t_s (for points summed directly)
    for (std::size_t p = 0; p < points_.size(); ++p) {
      if (points_[p].count == 0) continue;
      if (interpolate_point(p, slots, g.weights, velocity[p], acceleration[p],
                            gradients != nullptr ? &(*gradients)[p] : nullptr))
        continue;
      if (!phases_at_t) time_phases(t_s, max_count_, cos_wt_.data(), sin_wt_.data());
      phases_at_t = true;
      take(p, at_point(points_[p], cos_wt_.data(), sin_wt_.data()));
    }
    return;
  }
  time_phases(t_s, max_count_, cos_wt_.data(), sin_wt_.data());
  ++full_sums_;
  for (std::size_t p = 0; p < points_.size(); ++p) {
    if (points_[p].count > 0) take(p, at_point(points_[p], cos_wt_.data(), sin_wt_.data()));
  }
}

void FixedPointWaveKinematics::evaluate_point(double t_s, std::size_t point, Eigen::Vector3d& velocity,
                                              Eigen::Vector3d& acceleration, Gradients* gradients) const {
  velocity.setZero();
  acceleration.setZero();
  if (gradients != nullptr) *gradients = Gradients{};
  const Point& pt = points_[point];
  if (pt.count == 0) return;
  if (interval_s_ > 0.0) {
    // From the grid when its four samples are held (an output time inside
    // the last step's): the same kinematics the residual saw.
    const GridTime g = grid_time(t_s);
    std::array<Slot*, 4> slots{};
    bool held = true;
    for (int k = 0; k < 4; ++k) {
      slots[k] = &slots_[ring(g.first + k)];
      held = held && slots[k]->index == g.first + k && !slots[k]->at.empty();
    }
    if (held && interpolate_point(point, slots, g.weights, velocity, acceleration, gradients)) return;
  }
  thread_local std::vector<double> cos_wt, sin_wt;
  cos_wt.resize(pt.count);
  sin_wt.resize(pt.count);
  time_phases(t_s, pt.count, cos_wt.data(), sin_wt.data());
  const Sample sum = at_point(pt, cos_wt.data(), sin_wt.data());
  velocity = sum.velocity;
  acceleration = sum.acceleration;
  if (gradients != nullptr) *gradients = sum.gradients;
}

FixedPointWaveKinematics::Sample FixedPointWaveKinematics::at_point(const Point& pt, const double* cos_wt,
                                                                    const double* sin_wt) const {
  const std::optional<double>& h = sea_->water_depth_m;
  // Wheeler stretching (DNV-RP-C205 §3.2.3): the profiles at
  // z' = (z − η) h / (h + η) (deep water z − η), η from the point's kept
  // components; f(z') = f(z + Δz) to second order in k Δz (cosh' = k sinh):
  // f_h(z') ≈ (1 + ½ k²Δz²) f_h + k Δz f_v, f_v(z') ≈ (1 + ½ k²Δz²) f_v + k Δz f_h,
  // error (k Δz)³/6 ≤ (k a)³/6 — 1e-3 at a steepness k a of 0.18.
  double eta = 0.0;
  for (std::size_t j = 0; j < pt.count; ++j) eta += pt.elevation_c[j] * cos_wt[j] - pt.elevation_s[j] * sin_wt[j];
  Sample out;
  out.eta_m = eta;
  if (pt.z_m > eta) return out;  // in a trough above the surface: dry
  out.wet = true;
  const double z_stretched = h ? (pt.z_m - eta) * *h / (*h + eta) : pt.z_m - eta;
  const double dz = z_stretched - pt.z_m;
  double ux = 0.0, uy = 0.0, uz = 0.0, ax = 0.0, ay = 0.0, az = 0.0;
  // The gradients' six independent sums each (∂θ/∂x = −k cos β,
  // ∂θ/∂y = −k sin β, f_h' = k f_v, f_v' = k f_h, with the stretched
  // profiles): ∂u_x/∂x = Σ k cos²β ŷ_h, ∂u_x/∂y = Σ k cos β sin β ŷ_h,
  // ∂u_y/∂y = Σ k sin²β ŷ_h, ∂u_x/∂z = ∂u_z/∂x = Σ k cos β x̂_v,
  // ∂u_y/∂z = Σ k sin β x̂_v, ∂u_z/∂z = −Σ k ŷ_h; the acceleration's are
  // their time derivatives (ŷ_h' = ω x̂_h, x̂_v' = −ω ŷ_v).
  double gxx = 0.0, gxy = 0.0, gyy = 0.0, gxz = 0.0, gyz = 0.0, gzz = 0.0;
  double hxx = 0.0, hxy = 0.0, hyy = 0.0, hxz = 0.0, hyz = 0.0, hzz = 0.0;
  for (std::size_t j = 0; j < pt.count; ++j) {
    const double C = cos_wt[j], S = sin_wt[j], omega = omega_[j];
    const double kdz = wavenumber_[j] * dz, same = 1.0 + 0.5 * kdz * kdz;
    // θ = ω t + ψ (η = a cos θ): cos θ = C cos ψ − S sin ψ, sin θ = S cos ψ + C sin ψ.
    const double xh = pt.horizontal_c[j] * C - pt.horizontal_s[j] * S;  // a ω f_h cos θ
    const double yh = pt.horizontal_c[j] * S + pt.horizontal_s[j] * C;  // a ω f_h sin θ
    const double xv = pt.vertical_c[j] * C - pt.vertical_s[j] * S;
    const double yv = pt.vertical_c[j] * S + pt.vertical_s[j] * C;
    // The stretched a ω f cos θ, a ω f sin θ (x̂_h, ŷ_h, x̂_v, ŷ_v).
    const double u_h = same * xh + kdz * xv;
    const double yh_s = same * yh + kdz * yv;
    const double xv_s = same * xv + kdz * xh;
    const double yv_s = same * yv + kdz * yh;
    const double du_h = -omega * yh_s;
    ux += u_h * cos_heading_[j];
    uy += u_h * sin_heading_[j];
    ax += du_h * cos_heading_[j];
    ay += du_h * sin_heading_[j];
    uz -= yv_s;
    az -= omega * xv_s;
    gxx += k_cc_[j] * yh_s;
    gxy += k_cs_[j] * yh_s;
    gyy += k_ss_[j] * yh_s;
    gxz += k_c_[j] * xv_s;
    gyz += k_s_[j] * xv_s;
    gzz -= wavenumber_[j] * yh_s;
    const double wxh = omega * u_h, wyv = omega * yv_s;
    hxx += k_cc_[j] * wxh;
    hxy += k_cs_[j] * wxh;
    hyy += k_ss_[j] * wxh;
    hxz -= k_c_[j] * wyv;
    hyz -= k_s_[j] * wyv;
    hzz -= wavenumber_[j] * wxh;
  }
  out.velocity = {ux, uy, uz};
  out.acceleration = {ax, ay, az};
  out.gradients.velocity_per_s << gxx, gxy, gxz, gxy, gyy, gyz, gxz, gyz, gzz;
  out.gradients.acceleration_per_s2 << hxx, hxy, hxz, hxy, hyy, hyz, hxz, hyz, hzz;
  return out;
}

}  // namespace spiral::engine
