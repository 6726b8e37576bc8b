// The half-cycle logarithmic decrement (engine/numerics/free_decay) on the
// exact free decay of a linear oscillator.
#include "engine/numerics/free_decay.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace spiral::engine {
namespace {

/// x(t) = x_f + A e^{−ζ ω t} cos(ω_d t) after `release_s`, x_f before (a
/// record whose decay starts at the release), sampled every dt.
struct Record {
  std::vector<double> t, x;
};
Record damped_oscillation(double zeta, double period_s, double amplitude, double final_position, double release_s,
                          double dt_s, double duration_s) {
  const double omega_d = 2.0 * std::numbers::pi / period_s;
  const double omega = omega_d / std::sqrt(1.0 - zeta * zeta);
  Record r;
  for (double t = 0.0; t <= duration_s + 1e-9; t += dt_s) {
    const double s = t - release_s;
    r.t.push_back(t);
    r.x.push_back(final_position +
                  (s < 0.0 ? amplitude
                           : amplitude * std::exp(-zeta * omega * s) *
                                 (std::cos(omega_d * s) + zeta * omega / omega_d * std::sin(omega_d * s))));
  }
  return r;
}

// A lightly and a heavily damped oscillator: every half cycle gives back
// the damped period and ζ. Tolerances: the extremes are refined by a
// parabola through three samples 0.5 s apart on a 150 s period (error
// ~(ω dt)⁴ in the value, ~1e-3 s in the time).
TEST(FreeDecay, TheHalfCycleDecrementGivesBackPeriodAndDampingRatio) {
  for (const double zeta : {0.05, 0.6}) {
    const Record r = damped_oscillation(zeta, 150.0, 10.0, 41.9, 300.0, 0.5, 2400.0);
    const std::vector<DecayHalfCycle> cycles = free_decay_half_cycles(r.t, r.x, 41.9, 300.0, 1e-3);
    ASSERT_GE(cycles.size(), zeta < 0.1 ? 10u : 2u) << zeta;
    for (const DecayHalfCycle& c : cycles) {
      EXPECT_NEAR(c.period_s, 150.0, 0.05) << zeta << " at " << c.start_s;
      EXPECT_NEAR(c.damping_ratio, zeta, 2e-4) << zeta << " at " << c.start_s;
    }
    EXPECT_NEAR(cycles.front().start_s, 300.0, 1e-9) << "the first extreme is the release";
  }
}

// Half cycles stop where the amplitude falls below the threshold given.
TEST(FreeDecay, HalfCyclesBelowTheSmallestAmplitudeAreLeftOut) {
  const Record r = damped_oscillation(0.1, 100.0, 1.0, 0.0, 0.0, 0.25, 2000.0);
  for (const DecayHalfCycle& c : free_decay_half_cycles(r.t, r.x, 0.0, 0.0, 0.2)) EXPECT_GT(c.amplitude, 0.2);
  EXPECT_LT(free_decay_half_cycles(r.t, r.x, 0.0, 0.0, 0.2).size(),
            free_decay_half_cycles(r.t, r.x, 0.0, 0.0, 0.01).size());
}

TEST(FreeDecay, TooShortARecordIsAnError) {
  const std::vector<double> t{0.0, 1.0, 2.0}, x{1.0, 0.0, -1.0};
  EXPECT_THROW(free_decay_half_cycles(t, x, 0.0, 1.5, 0.0), std::invalid_argument);
  EXPECT_THROW(free_decay_half_cycles(t, std::vector<double>{1.0, 2.0}, 0.0, 0.0, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
