// The lines' relaxations in the hull's equations (LineRelaxation,
// hull_dynamics.hpp) against the linear frequency response they stand for:
// a hull forced harmonically in surge settles to the amplitude and phase of
//   X = F / (K − ω² M + iω B + Σ_j Δ_j iωτ_j / (1 + iωτ_j))
// (any vibration text for the single-DOF response; the relaxation term is
// the standard linear solid's complex modulus, e.g. Lakes, Viscoelastic
// Materials, ch. 2).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "engine/analysis/hull_dynamics.hpp"

namespace spiral::engine {
namespace {

// Surge only matters here: the other DOFs are stiff and unforced.
HullDynamicsModel surge_hull(double mass_kg) {
  HullDynamicsModel m;
  m.mass = Matrix6d::Identity() * mass_kg;
  m.mass.diagonal().tail<3>().setConstant(mass_kg * 1e3);
  m.hydrostatic_stiffness = Matrix6d::Identity() * 1e9;
  m.hydrostatic_stiffness(0, 0) = 0.0;
  return m;
}

// Three forcing periods around the surge period (about 180 s): the steady
// amplitude and phase of the surge within 0.2 % and 2 mrad of the transfer
// function's (the record's last 4 periods, by projection on sin and cos; the
// integrator's own error is far below).
TEST(HullLineRelaxation, HarmonicSurgeResponseMatchesTheComplexStiffness) {
  const double M = 6e7, K = 7e4, B = 1e5;
  const std::vector<LineRelaxation> relaxations{{Matrix6d::Zero(), 15.0}, {Matrix6d::Zero(), 110.0}};
  LinearizedLines lines;
  lines.stiffness(0, 0) = K;
  lines.damping = Matrix6d::Zero();
  (*lines.damping)(0, 0) = B;
  lines.relaxations = relaxations;
  lines.relaxations[0].stiffness(0, 0) = 0.3 * K;
  lines.relaxations[1].stiffness(0, 0) = 0.5 * K;
  const double force_N = 1e5;
  for (const double period_s : {120.0, 180.0, 300.0}) {
    const double w = 2.0 * std::numbers::pi / period_s;
    HullLoads loads;
    loads.lines = lines;
    loads.external = [=](double t, const Vector6d&, const Vector6d&) {
      Vector6d f = Vector6d::Zero();
      f(0) = force_N * std::sin(w * t);
      return f;
    };
    HullSimulationOptions options;
    const double settle_s = 40.0 * period_s, record_s = 4.0 * period_s, dt = period_s / 200.0;
    for (double t = settle_s; t <= settle_s + record_s + 1e-9; t += dt) options.output_times_s.push_back(t);
    const HullTimeSeries run = simulate_hull(surge_hull(M), loads, Vector6d::Zero(), Vector6d::Zero(), options);

    double s = 0.0, c = 0.0;
    const Eigen::Index n = run.times_s.size() - 1;  // whole periods: drop the repeated end point
    for (Eigen::Index k = 0; k < n; ++k) {
      s += run.position(0, k) * std::sin(w * run.times_s(k));
      c += run.position(0, k) * std::cos(w * run.times_s(k));
    }
    const std::complex<double> measured(2.0 * s / n, 2.0 * c / n);  // x = Re(X) sin + Im(X) cos

    std::complex<double> stiffness(K - w * w * M, w * B);
    for (const LineRelaxation& r : lines.relaxations) {
      const std::complex<double> iwt(0.0, w * r.time_constant_s);
      stiffness += r.stiffness(0, 0) * iwt / (1.0 + iwt);
    }
    // x = Im(X e^{iwt}) for a force Im(F e^{iwt}): X = F / stiffness, i.e.
    // x = |X| sin(wt + arg X) = Re X sin + Im X cos.
    const std::complex<double> expected = force_N / stiffness;
    EXPECT_NEAR(std::abs(measured), std::abs(expected), 2e-3 * std::abs(expected)) << period_s << " s";
    EXPECT_NEAR(std::arg(measured), std::arg(expected), 2e-3) << period_s << " s";
  }
}

}  // namespace
}  // namespace spiral::engine
