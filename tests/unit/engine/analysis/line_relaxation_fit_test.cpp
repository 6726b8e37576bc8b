// The relaxation fit of a dynamic stiffness (engine/analysis/line_relaxation_fit)
// on data made from known dashpots, masses and relaxations.
#include "engine/analysis/line_relaxation_fit.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace spiral::engine {
namespace {

Matrix6cd model_at(double w, const Matrix6d& B, const Matrix6d& A, const std::vector<LineRelaxation>& relaxations) {
  Matrix6cd K =
      std::complex<double>(0.0, w) * B.cast<std::complex<double>>() - (w * w) * A.cast<std::complex<double>>();
  for (const LineRelaxation& r : relaxations) {
    const std::complex<double> iwt(0.0, w * r.time_constant_s);
    K += (iwt / (1.0 + iwt)) * r.stiffness.cast<std::complex<double>>();
  }
  return K;
}

struct Band {
  std::vector<double> omegas, weights;
  Band() {
    for (int k = 0; k < 10; ++k) {
      omegas.push_back(0.005 * std::pow(40.0, k / 9.0));
      weights.push_back(1.0);
    }
  }
};

/// A symmetric positive definite 6×6 of scale s with surge–sway–yaw coupling.
Matrix6d spd(double s, double coupling) {
  Matrix6d m = Matrix6d::Identity() * s;
  m(0, 1) = m(1, 0) = coupling * s;
  m(0, 5) = m(5, 0) = 0.5 * coupling * s;
  m(5, 5) = 40.0 * s;
  return m;
}

// Data from two relaxations whose time constants lie on the fit's grid
// (1 s · 3000^(i/39), i = 12 and 23: 11.7 s and 112 s), a dashpot and a
// mass: the fit gives them back (the grid holds the exact pair, so only
// round-off remains).
TEST(LineRelaxationFit, RecoversRelaxationsOnItsGrid) {
  const Band band;
  const double tau1 = std::pow(3000.0, 12.0 / 39.0), tau2 = std::pow(3000.0, 23.0 / 39.0);
  const Matrix6d B = spd(2e6, 0.1), A = spd(3e5, 0.05);
  const std::vector<LineRelaxation> truth{{spd(1.5e5, -0.2), tau1}, {spd(8e4, 0.3), tau2}};
  std::vector<Matrix6cd> data;
  for (double w : band.omegas) data.push_back(model_at(w, B, A, truth));
  const LineRelaxationFit fit = fit_line_relaxation(band.omegas, data, band.weights, 2);
  ASSERT_EQ(fit.relaxations.size(), 2u);
  EXPECT_NEAR(fit.relaxations[0].time_constant_s, tau1, 1e-9 * tau1);
  EXPECT_NEAR(fit.relaxations[1].time_constant_s, tau2, 1e-9 * tau2);
  EXPECT_LE((fit.relaxations[0].stiffness - truth[0].stiffness).norm(), 1e-6 * truth[0].stiffness.norm());
  EXPECT_LE((fit.relaxations[1].stiffness - truth[1].stiffness).norm(), 1e-6 * truth[1].stiffness.norm());
  EXPECT_LE((fit.damping - B).norm(), 1e-6 * B.norm());
  EXPECT_LE((fit.added_mass - A).norm(), 1e-6 * A.norm());
  EXPECT_LT(fit.relative_residual, 1e-8);
}

// A line whose impedance is a dashpot and a mass only (a chain in shallow
// water, OC4) gets no relaxation worth the name: every Δ_j below 1e-6 of the
// dashpot's ω-scale, and the dashpot and mass back.
TEST(LineRelaxationFit, ADashpotAndAMassGetNoRelaxation) {
  const Band band;
  const Matrix6d B = spd(7e4, 0.0), A = spd(2.5e5, 0.0);
  std::vector<Matrix6cd> data;
  for (double w : band.omegas) data.push_back(model_at(w, B, A, {}));
  const LineRelaxationFit fit = fit_line_relaxation(band.omegas, data, band.weights, 2);
  for (const LineRelaxation& r : fit.relaxations) EXPECT_LT(r.stiffness.norm(), 1e-6 * 0.2 * B.norm());
  EXPECT_LE((fit.damping - B).norm(), 1e-6 * B.norm());
  EXPECT_LE((fit.added_mass - A).norm(), 1e-6 * A.norm());
}

// Whatever the data, the model is passive: B, A and every Δ_j symmetric
// positive semi-definite (here data with a negative dashpot).
TEST(LineRelaxationFit, TheModelIsPassiveWhateverTheData) {
  const Band band;
  std::vector<Matrix6cd> data;
  for (double w : band.omegas) data.push_back(model_at(w, -spd(1e5, 0.1), spd(1e4, 0.0), {}));
  const LineRelaxationFit fit = fit_line_relaxation(band.omegas, data, band.weights, 1);
  for (const Matrix6d* m : {&fit.damping, &fit.added_mass, &fit.relaxations[0].stiffness}) {
    EXPECT_LE((*m - m->transpose()).norm(), 1e-12 * std::max(1.0, m->norm()));
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Matrix6d>(*m).eigenvalues().minCoeff(), -1e-9 * std::max(1.0, m->norm()));
  }
  EXPECT_GT(fit.relative_residual, 0.5) << "a negative dashpot cannot be fitted passively";
}

TEST(LineRelaxationFit, BadInputIsRefused) {
  const Band band;
  std::vector<Matrix6cd> data(band.omegas.size(), Matrix6cd::Zero());
  EXPECT_THROW(fit_line_relaxation(band.omegas, data, band.weights, 3), std::invalid_argument);
  std::vector<double> with_zero = band.omegas;
  with_zero[0] = 0.0;
  EXPECT_THROW(fit_line_relaxation(with_zero, data, band.weights, 1), std::invalid_argument);
  EXPECT_THROW(
      fit_line_relaxation(std::span<const double>(band.omegas).first(1), std::span<const Matrix6cd>(data).first(1),
                          std::span<const double>(band.weights).first(1), 1),
      std::invalid_argument);
}

}  // namespace
}  // namespace spiral::engine
