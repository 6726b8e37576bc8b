// The radiation memory convolution of hull_dynamics.hpp against a fine
// quadrature of the same integral: with the velocity history up to date
// (the S-C driver stops at every kernel step) and lagging by several steps
// (the coupled driver stores it at its output times).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/analysis/hull_dynamics.hpp"

namespace spiral::engine {
namespace {

constexpr double kStep_s = 0.1;
constexpr double kDecay_s = 1.0;  // K(t) = exp(-t / 1 s) I: decayed (to 2.5e-3) at its 6 s end, as a real kernel
constexpr double kOmega = 0.3;    // a low-frequency motion, rad/s

RetardationKernel exponential_kernel() {
  RetardationKernel k;
  k.time_step_s = kStep_s;
  k.values.setZero(36, 61);  // 6 s
  for (Eigen::Index j = 0; j < k.values.cols(); ++j) {
    const double value = std::exp(-kStep_s * static_cast<double>(j) / kDecay_s);
    for (int d = 0; d < 6; ++d) k.values(7 * d, j) = value;
  }
  return k;
}

double velocity(double t) { return t >= 0.0 ? std::sin(kOmega * t) : 0.0; }

/// int_0^6 exp(-tau) v(t - tau) dtau by Simpson's rule on 60,000 intervals.
double reference_force(double t) {
  const int n = 60000;
  const double h = 6.0 / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double tau = h * i;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += w * std::exp(-tau / kDecay_s) * velocity(t - tau);
  }
  return sum * h / 3.0;
}

VelocityHistory history_until(double t_last) {
  VelocityHistory h;
  h.time_step_s = kStep_s;
  h.count = static_cast<Eigen::Index>(std::floor(t_last / kStep_s + 1e-9)) + 1;
  h.velocities.resize(6, h.count);
  for (Eigen::Index k = 0; k < h.count; ++k)
    h.velocities.col(k).setConstant(velocity(kStep_s * static_cast<double>(k)));
  return h;
}

// The trapezoid on a 0.1 s grid of a kernel decaying over 1 s errs by
// ~h²/12 of the integrand's curvature (K'' = K): ~1e-3 of the force of a
// steady velocity; the linear join over a 0.55 s lag adds v'' s² / 8 ≈ 3e-3
// of the velocity amplitude over the kernel's first half second (40 % of its
// area): ~1e-3 more.
TEST(RadiationMemoryForce, MatchesTheConvolutionWithTheHistoryUpToDateOrLagging) {
  const RetardationKernel kernel = exponential_kernel();
  for (const double t : {10.03, 17.4, 23.07}) {
    const Vector6d v = Vector6d::Constant(velocity(t));
    const double expected = reference_force(t);
    // Errors scale with the velocity amplitude (1 m/s) times the kernel's
    // area (1 s): the force of a steady unit velocity.
    const double scale = 1.0;
    const Vector6d up_to_date = radiation_memory_force(kernel, history_until(t), t, v);
    const Vector6d lagging = radiation_memory_force(kernel, history_until(t - 0.55), t, v);
    EXPECT_NEAR(up_to_date(0), expected, 2e-3 * scale) << "t = " << t;
    EXPECT_NEAR(lagging(0), expected, 4e-3 * scale) << "t = " << t;
    EXPECT_EQ(lagging(0), lagging(5)) << "every DOF the same";
  }
}

}  // namespace
}  // namespace spiral::engine
