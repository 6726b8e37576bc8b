// Validation of the low-frequency hull integrator against closed-form linear
// vibration results (any vibration text, e.g. Thomson & Dahleh, Theory of
// Vibration with Applications, ch. 2–3): free-decay period and logarithmic
// decrement (heave and yaw single-DOF; the coupled surge and pitch modes
// against the damped eigenvalues of the state-space matrix), modal periods of the coupled OC4
// model, energy conservation, resonance growth and damped steady state, equilibrium at rest, and
// the Cummins radiation memory against its equivalent linear damping.
//
// Time resolution: outputs every 0.05 s and crossing times interpolated
// linearly between samples; at a zero crossing of a sinusoid the curvature is
// zero, so the interpolation error is O((w dt)^3) ~ 1e-6 of a period.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/analysis/hull_dynamics.hpp"
#include "engine/numerics/statistics.hpp"
#include "support/expect_near.hpp"
#include "support/oc4_hull_dynamics.hpp"

namespace spiral::engine {
namespace {

constexpr double kPi = std::numbers::pi;

std::string sci(double x) {
  std::ostringstream s;
  s.precision(3);
  s << std::scientific << x;
  return s.str();
}
constexpr double kOutputStep_s = 0.05;

// Brief's acceptance band for the period; the integration (rtol 1e-8) and the
// crossing interpolation are each below 1e-5 of a period, so 0.5 % is loose.
constexpr double kPeriodRelTol = 5e-3;
// What the integrator actually delivers on the period (measured ~1e-6):
// guards against a silent loss of accuracy.
constexpr double kPeriodTightRelTol = 1e-4;
// Brief's band for the logarithmic decrement; sampled peaks (dt = 0.05 s) err
// by <= (w dt/2)^2/2 = 4e-5 in amplitude, i.e. ~1e-4 of delta.
constexpr double kDecrementRelTol = 2e-2;
// What the integrator and the peak sampling deliver on the decrement
// (measured 3e-6 on the coupled modes): guards against a silent loss.
constexpr double kDecrementTightRelTol = 1e-3;
// Energy drift over 20 periods (brief: 1e-6). Energy is a global quantity:
// with the hull defaults (rtol 1e-10) the drift is 7e-7, too close to the
// bound, so the energy test runs at rtol 1e-11 and atol scaled alike
// (measured 9e-8, 1.3x the steps).
constexpr double kEnergyDriftRelTol = 1e-6;
constexpr double kEnergyTestRelativeTolerance = 1e-11;
// Resonance: numerical vs closed-form response, relative to the final amplitude.
constexpr double kResonanceRelTol = 1e-5;
// Equilibrium hold: S-C lines at q0 without external force for 3 h.
constexpr double kEquilibriumDrift_m = 1e-9;

struct Oscillation {
  double period_s = 0.0;
  double log_decrement = 0.0;
};

// Period from the mean spacing of up-crossings of `level`, decrement from the
// mean ln-ratio of successive cycle maxima measured from `level`.
Oscillation measure(const Eigen::Matrix<double, 6, Eigen::Dynamic>& series, int dof, double level) {
  std::vector<double> x(static_cast<std::size_t>(series.cols()));
  for (Eigen::Index k = 0; k < series.cols(); ++k) x[static_cast<std::size_t>(k)] = series(dof, k);
  const auto t = upcrossing_times_s(x, kOutputStep_s, level);
  Oscillation o;
  if (t.size() >= 2) o.period_s = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  const auto peaks = cycle_maxima(x, level);
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i + 1 < peaks.size(); ++i) {
    if (peaks[i + 1] - level <= 0.0) break;
    sum += std::log((peaks[i] - level) / (peaks[i + 1] - level));
    ++n;
  }
  if (n > 0) o.log_decrement = sum / n;
  return o;
}

// OC4 heave, single DOF: M 1.40751e7 + A33 1.5e7 kg, K 3.836e6 + 1.91e4 N/m.
constexpr double kHeaveMass_kg = 1.40751e7 + 1.5e7;
constexpr double kHeaveStiffness_N_m = 3.836e6 + 1.91e4;
const double kHeavePeriod_s = 2.0 * kPi * std::sqrt(kHeaveMass_kg / kHeaveStiffness_N_m);

TEST(HullFreeDecay, HeaveUndampedPeriodIsTheOc4NaturalPeriod) {
  const auto oc4 = test::oc4_hull_dynamics();
  EXPECT_NEAR(kHeavePeriod_s, 17.26, 0.01);  // reference-platforms §1.8: 17.24 s (A(T) iterated)
  const auto run = free_decay(oc4.model, oc4.lines, 2, 1.0, 20.0 * kHeavePeriod_s, kOutputStep_s);
  const auto o = measure(run.position, 2, 0.0);
  EXPECT_REL_NEAR(o.period_s, kHeavePeriod_s, kPeriodRelTol);
  EXPECT_REL_NEAR(o.period_s, kHeavePeriod_s, kPeriodTightRelTol);
  // Heave is uncoupled: the other DOFs stay at rest.
  EXPECT_LT(run.position.topRows(2).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(run.position.bottomRows(3).cwiseAbs().maxCoeff(), 1e-12);
  RecordProperty("heave_period_rel_error", sci(o.period_s / kHeavePeriod_s - 1.0));
}

TEST(HullFreeDecay, HeaveLinearDampingGivesDampedPeriodAndDecrement) {
  auto oc4 = test::oc4_hull_dynamics();
  constexpr double zeta = 0.05;
  oc4.model.linear_damping(2, 2) = 2.0 * zeta * std::sqrt(kHeaveStiffness_N_m * kHeaveMass_kg);
  const auto run = free_decay(oc4.model, oc4.lines, 2, 2.0, 12.0 * kHeavePeriod_s, kOutputStep_s);
  const auto o = measure(run.position, 2, 0.0);
  // omega_d = omega_n sqrt(1 - zeta^2): the damped period is 0.125 % longer.
  const double damped_period = kHeavePeriod_s / std::sqrt(1.0 - zeta * zeta);
  EXPECT_REL_NEAR(o.period_s, damped_period, kPeriodRelTol);
  EXPECT_REL_NEAR(o.period_s, damped_period, kPeriodTightRelTol);
  const double delta = 2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta);
  EXPECT_REL_NEAR(o.log_decrement, delta, kDecrementRelTol);
  RecordProperty("damped_period_rel_error", sci(o.period_s / damped_period - 1.0));
  RecordProperty("decrement_rel_error", sci(o.log_decrement / delta - 1.0));
}

// Yaw is uncoupled in this model (diagonal yaw mass, added mass and
// stiffness): the single-DOF result holds as for heave.
TEST(HullFreeDecay, YawLinearDampingGivesDampedPeriodAndDecrement) {
  auto oc4 = test::oc4_hull_dynamics();
  const double mass = oc4.model.mass(5, 5) + oc4.model.added_mass(5, 5);
  const double stiffness = oc4.lines.stiffness(5, 5);
  constexpr double zeta = 0.05;
  oc4.model.linear_damping(5, 5) = 2.0 * zeta * std::sqrt(stiffness * mass);
  const double period = 2.0 * kPi * std::sqrt(mass / stiffness);
  EXPECT_NEAR(period, 79.4, 0.5);  // reference-platforms §1.8 single-DOF estimate
  const auto run = free_decay(oc4.model, oc4.lines, 5, 0.05, 8.0 * period, kOutputStep_s);
  const auto o = measure(run.position, 5, 0.0);
  const double damped_period = period / std::sqrt(1.0 - zeta * zeta);
  EXPECT_REL_NEAR(o.period_s, damped_period, kPeriodTightRelTol);
  const double delta = 2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta);
  EXPECT_REL_NEAR(o.log_decrement, delta, kDecrementRelTol);
  EXPECT_REL_NEAR(o.log_decrement, delta, kDecrementTightRelTol);
  EXPECT_LT(run.position.topRows(5).cwiseAbs().maxCoeff(), 1e-12);  // nothing else moves
  RecordProperty("yaw_decrement_rel_error", sci(o.log_decrement / delta - 1.0));
}

// Surge and pitch are coupled (CoG below the reference point, A15, K15), so a
// diagonal damping does not give each its single-DOF decrement. The oracle
// is the damped eigenproblem of the state-space matrix
//   [0, I; −(M + A)^-1 (C + K), −(M + A)^-1 B],
// eigenvalues lambda = −sigma ± i w_d: started on the real part of one
// complex mode (displacement Re v, velocity Re lambda v), the hull moves as
// Re(v e^{lambda t}) — every DOF at w_d, each cycle maximum e^{sigma T_d}
// below the one before: decrement 2 pi sigma / w_d, period 2 pi / w_d.
// Damping: 5 % of critical in surge and in pitch, each from its diagonal.
TEST(HullFreeDecay, CoupledSurgePitchModesDecayAtTheirDampedEigenvalues) {
  auto oc4 = test::oc4_hull_dynamics();
  const Matrix6d M = oc4.model.mass + oc4.model.added_mass;
  const Matrix6d K = oc4.model.hydrostatic_stiffness + oc4.lines.stiffness;
  constexpr double zeta = 0.05;
  for (const int d : {0, 4}) {
    oc4.model.linear_damping(d, d) = 2.0 * zeta * std::sqrt(K(d, d) * M(d, d));
  }
  const Matrix6d Minv = M.inverse();
  Eigen::Matrix<double, 12, 12> state = Eigen::Matrix<double, 12, 12>::Zero();
  state.topRightCorner<6, 6>().setIdentity();
  state.bottomLeftCorner<6, 6>() = -Minv * K;
  state.bottomRightCorner<6, 6>() = -Minv * oc4.model.linear_damping;
  Eigen::EigenSolver<Eigen::Matrix<double, 12, 12>> eig(state);
  ASSERT_EQ(eig.info(), Eigen::Success);
  // The two modes with surge or pitch dominant in their displacement (positive w_d).
  for (const int dominant : {0, 4}) {
    Eigen::Index best = -1;
    double best_share = 0.0;
    for (Eigen::Index j = 0; j < 12; ++j) {
      const std::complex<double> lambda = eig.eigenvalues()(j);
      if (lambda.imag() <= 0.0) continue;
      const Eigen::Matrix<std::complex<double>, 6, 1> v = eig.eigenvectors().col(j).head<6>();
      // Share of the DOF in the mode, rotations weighted by 50 m (as above).
      const Vector6d w = (Vector6d() << 1, 1, 1, 50, 50, 50).finished();
      const double share = std::abs(v(dominant)) * w(dominant) / v.cwiseAbs().cwiseProduct(w).sum();
      if (share > best_share) {
        best_share = share;
        best = j;
      }
    }
    ASSERT_GE(best, 0);
    const std::complex<double> lambda = eig.eigenvalues()(best);
    Eigen::Matrix<std::complex<double>, 6, 1> v = eig.eigenvectors().col(best).head<6>();
    // Scale: 1 m surge or 0.02 rad pitch in the dominant DOF, real there.
    v *= (dominant < 3 ? 1.0 : 0.02) / v(dominant);
    const Vector6d q0 = v.real();
    const Vector6d v0 = (lambda * v).real();
    const double wd = lambda.imag();
    const double sigma = -lambda.real();
    const double period = 2.0 * kPi / wd;
    HullSimulationOptions options;
    const int n = static_cast<int>(std::ceil(6.0 * period / kOutputStep_s));
    for (int k = 0; k <= n; ++k) options.output_times_s.push_back(k * kOutputStep_s);
    const auto run = simulate_hull(oc4.model, HullLoads{oc4.lines, {}}, q0, v0, options);
    SCOPED_TRACE(testing::Message() << "dominant DOF " << dominant << ", T_d = " << period << " s, share "
                                    << best_share);
    const auto o = measure(run.position, dominant, 0.0);
    const double delta = 2.0 * kPi * sigma / wd;
    EXPECT_REL_NEAR(o.period_s, period, kPeriodTightRelTol);
    EXPECT_REL_NEAR(o.log_decrement, delta, kDecrementRelTol);
    // The other DOF of the pair decays alike (one complex mode).
    const int other = dominant == 0 ? 4 : 0;
    if (std::abs(v(other)) * (other < 3 ? 1.0 : 50.0) > 0.01) {
      EXPECT_REL_NEAR(measure(run.position, other, 0.0).log_decrement, delta, kDecrementRelTol);
    }
    // Coupling is not negligible: the mode's damping ratio differs from 5 %.
    const double zeta_mode = sigma / std::abs(lambda);
    RecordProperty(dominant == 0 ? "surge_mode_zeta" : "pitch_mode_zeta", sci(zeta_mode));
    RecordProperty(dominant == 0 ? "surge_decrement_rel_error" : "pitch_decrement_rel_error",
                   sci(o.log_decrement / delta - 1.0));
    EXPECT_REL_NEAR(o.log_decrement, delta, kDecrementTightRelTol);
    if (dominant == 4) {
      // Pitch: zeta 5.5 %, a decrement 11 % above the single-DOF 5 %: the
      // single-DOF oracle would fail the brief's 2 % band.
      const double single = 2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta);
      EXPECT_GT(std::abs(single / delta - 1.0), kDecrementRelTol);
    }
  }
}

TEST(HullFreeDecay, CoupledModesOfOc4OscillateAtTheirEigenperiods) {
  const auto oc4 = test::oc4_hull_dynamics();
  const Matrix6d M = oc4.model.mass + oc4.model.added_mass;
  const Matrix6d K = oc4.model.hydrostatic_stiffness + oc4.lines.stiffness;
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix6d> modes(K, M);
  ASSERT_EQ(modes.info(), Eigen::Success);
  // Surge–pitch modes of §1.8: ~113 s surge (surge–pitch coupled) and ~25 s pitch.
  for (int mode = 0; mode < 6; ++mode) {
    const double period = 2.0 * kPi / std::sqrt(modes.eigenvalues()(mode));
    Vector6d shape = modes.eigenvectors().col(mode);
    // Scale: 1 m (translation-dominated) or 0.02 rad (rotation-dominated) peak.
    Eigen::Index dominant = 0;
    const Vector6d scaled = shape.cwiseAbs().cwiseProduct((Vector6d() << 1, 1, 1, 50, 50, 50).finished());
    scaled.maxCoeff(&dominant);
    shape *= (dominant < 3 ? 1.0 : 0.02) / shape(dominant);
    HullSimulationOptions options;
    const int n = static_cast<int>(std::ceil(6.0 * period / kOutputStep_s));
    for (int k = 0; k <= n; ++k) options.output_times_s.push_back(k * kOutputStep_s);
    const auto run = simulate_hull(oc4.model, HullLoads{oc4.lines, {}}, shape, Vector6d::Zero(), options);
    SCOPED_TRACE(testing::Message() << "mode " << mode << ", T = " << period << " s, dominant DOF " << dominant);
    const auto o = measure(run.position, static_cast<int>(dominant), 0.0);
    EXPECT_REL_NEAR(o.period_s, period, kPeriodRelTol);
    EXPECT_REL_NEAR(o.period_s, period, kPeriodTightRelTol);
  }
  // The published single-DOF/coupled estimates (§1.8): heave 17.24 s, pitch 25.3 s (coupled),
  // surge 112.8 s, yaw 79.4 s; within the suggested bands (3 %, 8 %, 5 %, 5 %).
  std::vector<double> periods;
  for (int i = 0; i < 6; ++i) periods.push_back(2.0 * kPi / std::sqrt(modes.eigenvalues()(i)));
  EXPECT_REL_NEAR(periods[0], 112.8, 0.05);
  EXPECT_REL_NEAR(periods[1], 112.8, 0.05);
  EXPECT_REL_NEAR(periods[2], 79.4, 0.05);
  EXPECT_REL_NEAR(periods[3], 25.3, 0.08);
  EXPECT_REL_NEAR(periods[4], 25.3, 0.08);
  EXPECT_REL_NEAR(periods[5], 17.24, 0.03);
}

double mechanical_energy(const Matrix6d& M, const Matrix6d& K, const Vector6d& q, const Vector6d& v) {
  return 0.5 * v.dot(M * v) + 0.5 * q.dot(K * q);
}

TEST(HullFreeDecay, UndampedEnergyIsConservedOver20Periods) {
  const auto oc4 = test::oc4_hull_dynamics();
  const Matrix6d M = oc4.model.mass + oc4.model.added_mass;
  const Matrix6d K = oc4.model.hydrostatic_stiffness + oc4.lines.stiffness;
  Vector6d q0;
  q0 << 5.0, -3.0, 1.0, 0.02, 0.03, 0.05;  // all six DOFs, all modes excited
  HullSimulationOptions options;
  options.integrator.relative_tolerance = kEnergyTestRelativeTolerance;
  // atol scaled with rtol: velocities ~0.3 m/s would otherwise be governed by atol.
  options.integrator.absolute_tolerances =
      *options.integrator.absolute_tolerances * (kEnergyTestRelativeTolerance / 1e-10);
  const double duration = 20.0 * 112.8;  // 20 periods of the slowest mode
  for (double t = 0.0; t <= duration; t += 1.0) options.output_times_s.push_back(t);
  const auto run = simulate_hull(oc4.model, HullLoads{oc4.lines, {}}, q0, Vector6d::Zero(), options);
  const double E0 = mechanical_energy(M, K, q0, Vector6d::Zero());
  double worst = 0.0;
  for (Eigen::Index k = 0; k < run.times_s.size(); ++k) {
    const double E = mechanical_energy(M, K, run.position.col(k), run.velocity.col(k));
    worst = std::max(worst, std::abs(E / E0 - 1.0));
  }
  EXPECT_LT(worst, kEnergyDriftRelTol);
  RecordProperty("energy_drift_rel", sci(worst));
  RecordProperty("steps", std::to_string(run.statistics.steps));
}

TEST(HullFreeDecay, HarmonicForceAtResonance) {
  auto oc4 = test::oc4_hull_dynamics();
  const double w = 2.0 * kPi / kHeavePeriod_s;
  constexpr double F0_N = 1e5;
  const ExternalForce force = [w](double t, const Vector6d&, const Vector6d&) {
    Vector6d f = Vector6d::Zero();
    f(2) = F0_N * std::sin(w * t);
    return f;
  };
  HullSimulationOptions options;
  // 900 s: 52 periods; the damped transient has decayed by e^-16.
  for (int k = 0; k <= 18000; ++k) options.output_times_s.push_back(k * kOutputStep_s);

  // Undamped: x(t) = F0/(2 m w^2) (sin wt − wt cos wt), envelope F0 t/(2 m w).
  {
    const auto run = simulate_hull(oc4.model, HullLoads{oc4.lines, force}, Vector6d::Zero(), Vector6d::Zero(), options);
    const double t_end = run.times_s(run.times_s.size() - 1);
    const double scale = F0_N * t_end / (2.0 * kHeaveMass_kg * w);
    double worst = 0.0;
    for (Eigen::Index k = 0; k < run.times_s.size(); ++k) {
      const double t = run.times_s(k);
      const double exact = F0_N / (2.0 * kHeaveMass_kg * w * w) * (std::sin(w * t) - w * t * std::cos(w * t));
      worst = std::max(worst, std::abs(run.position(2, k) - exact));
    }
    EXPECT_LT(worst, kResonanceRelTol * scale);
    // Linear growth: the cycle maxima grow by F0 T/(2 m w) per period.
    std::vector<double> x(run.position.row(2).begin(), run.position.row(2).end());
    const auto peaks = cycle_maxima(x, 0.0);
    ASSERT_GE(peaks.size(), 10u);
    const double growth = (peaks.back() - peaks[peaks.size() - 6]) / 5.0;
    EXPECT_REL_NEAR(growth, F0_N * kHeavePeriod_s / (2.0 * kHeaveMass_kg * w), 1e-3);
  }
  // Damped (zeta = 5 %): steady amplitude F0/(B w) once the transient
  // (time constant 1/(zeta w) = 55 s) has decayed: e^-16 after 900 s.
  {
    const double B = 2.0 * 0.05 * std::sqrt(kHeaveStiffness_N_m * kHeaveMass_kg);
    oc4.model.linear_damping(2, 2) = B;
    const auto run = simulate_hull(oc4.model, HullLoads{oc4.lines, force}, Vector6d::Zero(), Vector6d::Zero(), options);
    const Eigen::Index tail = static_cast<Eigen::Index>(2.0 * kHeavePeriod_s / kOutputStep_s);
    const double amplitude = run.position.row(2).tail(tail).cwiseAbs().maxCoeff();
    // Sampled maximum: error <= (w dt/2)^2/2 = 4e-5 of the amplitude.
    EXPECT_REL_NEAR(amplitude, F0_N / (B * w), 1e-4);
  }
}

TEST(HullFreeDecay, SemiCoupledEquilibriumHoldsFor3Hours) {
  auto oc4 = test::oc4_hull_dynamics();
  oc4.model.quadratic_damping << 1e6, 1e6, 1e6, 1e10, 1e10, 1e10;
  oc4.model.hydrostatic_force_at_rest(2) = 1.8951e6;  // buoyancy excess = line pretension (§1.2)
  LinearizedLines lines = oc4.lines;
  lines.equilibrium_offset << 12.0, -4.0, -0.3, 0.004, 0.02, 0.03;
  // F0 balances the hull at q0: F_hs0 − C q0 + F0 = 0.
  lines.force_at_equilibrium =
      oc4.model.hydrostatic_stiffness * lines.equilibrium_offset - oc4.model.hydrostatic_force_at_rest;
  lines.damping = Matrix6d(Vector6d::Constant(1e5).asDiagonal());  // enhanced S-C
  lines.added_mass = Matrix6d(Vector6d::Constant(1e5).asDiagonal());
  HullSimulationOptions options;
  for (double t = 0.0; t <= 10800.0; t += 10.0) options.output_times_s.push_back(t);
  const auto run = simulate_hull(oc4.model, HullLoads{lines, {}}, lines.equilibrium_offset, Vector6d::Zero(), options);
  const double drift = (run.position.colwise() - lines.equilibrium_offset).cwiseAbs().maxCoeff();
  EXPECT_LT(drift, kEquilibriumDrift_m);
}

TEST(HullFreeDecay, NonlinearCallbackWithLinearForceMatchesLinearizedLines) {
  const auto oc4 = test::oc4_hull_dynamics();
  const Matrix6d K = oc4.lines.stiffness;
  const NonlinearLineForce curve = [K](const Vector6d& q) -> Vector6d { return -K * q; };
  const auto a = free_decay(oc4.model, oc4.lines, 0, 10.0, 300.0, 1.0);
  const auto b = free_decay(oc4.model, curve, 0, 10.0, 300.0, 1.0);
  EXPECT_EIGEN_REL_NEAR(b.position, a.position, 1e-6);
}

// Cummins memory: a band-limited constant radiation damping B(w) = b for
// w <= W has K(t) = (2b/pi) sin(W t)/t and, by Kramers–Kronig,
// A(w) = A(inf) − (b/(pi w)) ln((W + w)/(W − w)). The memory model must
// then decay like a linear damper b on the mass M + A(w_d).
TEST(HullFreeDecay, RadiationMemoryActsAsItsEquivalentLinearDamping) {
  constexpr double W = 4.0;  // rad/s, far above the 0.36 rad/s heave frequency
  const double b = 2.0 * 0.05 * std::sqrt(kHeaveStiffness_N_m * kHeaveMass_kg);
  std::vector<double> w;
  std::vector<Matrix6d> B;
  for (double wi = 0.0; wi <= 8.0 + 1e-9; wi += 0.002) {
    w.push_back(wi);
    Matrix6d Bi = Matrix6d::Zero();
    Bi(2, 2) = wi <= W + 1e-9 ? b : 0.0;
    B.push_back(Bi);
  }
  const auto kernel = make_retardation_kernel(w, B, 0.05, 60.0);
  // Kernel against the closed form (trapezoid on a 0.002 rad/s grid with a
  // step at W: error ~ b dw/pi relative to K(0) = 2bW/pi).
  for (double t : {0.0, 0.5, 3.3, 20.0}) {
    const double exact = t == 0.0 ? 2.0 * b * W / kPi : 2.0 * b / kPi * std::sin(W * t) / t;
    const auto j = static_cast<Eigen::Index>(std::lround(t / 0.05));
    EXPECT_NEAR(kernel.at_index(j)(2, 2), exact, 2e-3 * 2.0 * b * W / kPi) << "t = " << t;
  }

  auto oc4 = test::oc4_hull_dynamics();
  oc4.model.radiation_memory = kernel;
  const auto run = free_decay(oc4.model, oc4.lines, 2, 2.0, 10.0 * kHeavePeriod_s, kOutputStep_s);
  const auto o = measure(run.position, 2, 0.0);

  // Expected: iterate the damped frequency with A(w).
  double wd = 2.0 * kPi / kHeavePeriod_s, zeta = 0.0, mass = kHeaveMass_kg;
  for (int it = 0; it < 20; ++it) {
    mass = kHeaveMass_kg - b / (kPi * wd) * std::log((W + wd) / (W - wd));
    const double wn = std::sqrt(kHeaveStiffness_N_m / mass);
    zeta = b / (2.0 * std::sqrt(kHeaveStiffness_N_m * mass));
    wd = wn * std::sqrt(1.0 - zeta * zeta);
  }
  // Kernel truncation at 60 s leaves ~1/((W − w) t_max) = 0.4 % of b; the
  // frequency dependence of A(w) over the decay is second order.
  constexpr double kMemoryDecrementRelTol = 2e-2;
  EXPECT_REL_NEAR(o.period_s, 2.0 * kPi / wd, kPeriodRelTol);
  EXPECT_REL_NEAR(o.log_decrement, 2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta), kMemoryDecrementRelTol);
  RecordProperty("memory_period_rel_error", sci(o.period_s * wd / (2 * kPi) - 1.0));
  RecordProperty("memory_decrement_rel_error",
                 sci(o.log_decrement / (2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta)) - 1.0));
}

}  // namespace
}  // namespace spiral::engine
