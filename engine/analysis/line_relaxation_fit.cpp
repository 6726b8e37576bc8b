#include "engine/analysis/line_relaxation_fit.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace spiral::engine {
namespace {

constexpr int kTimeConstants = 40;
constexpr double kShortestTimeConstant_s = 1.0;
constexpr double kLongestTimeConstant_s = 3000.0;
/// Two time constants at least this many grid steps apart (a factor 2.3).
constexpr int kSmallestPairSpacing = 4;

/// Rows: Re and Im of each frequency (weighted); columns: B, then Δ_j.
Eigen::MatrixXd basis(std::span<const double> omegas, std::span<const double> weights,
                      const std::vector<double>& taus) {
  const auto n = static_cast<Eigen::Index>(omegas.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 + static_cast<Eigen::Index>(taus.size()));
  for (Eigen::Index k = 0; k < n; ++k) {
    const double w = omegas[static_cast<std::size_t>(k)], weight = weights[static_cast<std::size_t>(k)];
    A(n + k, 0) = weight * w;   // iω B
    A(k, 1) = -weight * w * w;  // −ω² A
    for (std::size_t j = 0; j < taus.size(); ++j) {
      const double wt = w * taus[j], denominator = 1.0 + wt * wt;
      A(k, 2 + static_cast<Eigen::Index>(j)) = weight * wt * wt / denominator;
      A(n + k, 2 + static_cast<Eigen::Index>(j)) = weight * wt / denominator;
    }
  }
  return A;
}

Eigen::VectorXd entry_data(std::span<const Matrix6cd> data, std::span<const double> weights, int r, int c) {
  const auto n = static_cast<Eigen::Index>(data.size());
  Eigen::VectorXd b(2 * n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double weight = weights[static_cast<std::size_t>(k)];
    b(k) = weight * data[static_cast<std::size_t>(k)](r, c).real();
    b(n + k) = weight * data[static_cast<std::size_t>(k)](r, c).imag();
  }
  return b;
}

Matrix6d positive_semidefinite(const Matrix6d& m) {
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(0.5 * (m + m.transpose()));
  return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace

LineRelaxationFit fit_line_relaxation(std::span<const double> omegas, std::span<const Matrix6cd> data,
                                      std::span<const double> weights, int poles) {
  if (omegas.size() < 2 || data.size() != omegas.size() || weights.size() != omegas.size()) {
    throw std::invalid_argument(
        fmt::format("fit_line_relaxation: need >= 2 frequencies with one matrix and one weight each, got {} / {} / {}",
                    omegas.size(), data.size(), weights.size()));
  }
  for (double w : omegas) {
    if (!(w > 0.0)) throw std::invalid_argument(fmt::format("fit_line_relaxation: frequencies must be > 0, got {}", w));
  }
  if (poles < 1 || poles > 2)
    throw std::invalid_argument(fmt::format("fit_line_relaxation: 1 or 2 poles, got {}", poles));

  std::vector<double> grid(kTimeConstants);
  for (int i = 0; i < kTimeConstants; ++i) {
    grid[static_cast<std::size_t>(i)] =
        kShortestTimeConstant_s *
        std::pow(kLongestTimeConstant_s / kShortestTimeConstant_s, static_cast<double>(i) / (kTimeConstants - 1));
  }
  std::vector<std::vector<double>> candidates;
  for (int i = 0; i < kTimeConstants; ++i) {
    if (poles == 1) {
      candidates.push_back({grid[static_cast<std::size_t>(i)]});
      continue;
    }
    for (int j = i + kSmallestPairSpacing; j < kTimeConstants; ++j)
      candidates.push_back({grid[static_cast<std::size_t>(i)], grid[static_cast<std::size_t>(j)]});
  }

  // Each entry's weighted data, the right-hand side of every candidate's fit.
  std::array<Eigen::VectorXd, 36> rhs;
  double data_norm2 = 0.0;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) {
      rhs[static_cast<std::size_t>(6 * r + c)] = entry_data(data, weights, r, c);
      data_norm2 += rhs[static_cast<std::size_t>(6 * r + c)].squaredNorm();
    }

  // For each choice of time constants: B, A and Δ_j by least squares, made
  // passive, and the residual of that passive model. The least-squares
  // optimum alone can pair nearly equal time constants with large opposite
  // Δ_j that the projection then breaks (measured: OC4's chains, whose
  // impedance is a dashpot and a mass, came out 27× off).
  LineRelaxationFit best;
  double best_residual = std::numeric_limits<double>::infinity();
  for (const std::vector<double>& taus : candidates) {
    const Eigen::MatrixXd A = basis(omegas, weights, taus);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    std::vector<Matrix6d> coefficients(2 + taus.size(), Matrix6d::Zero());
    for (int r = 0; r < 6; ++r) {
      for (int c = 0; c < 6; ++c) {
        const Eigen::VectorXd x = qr.solve(rhs[static_cast<std::size_t>(6 * r + c)]);
        for (std::size_t m = 0; m < coefficients.size(); ++m) coefficients[m](r, c) = x(static_cast<Eigen::Index>(m));
      }
    }
    LineRelaxationFit fit;
    fit.damping = positive_semidefinite(coefficients[0]);
    fit.added_mass = positive_semidefinite(coefficients[1]);
    for (std::size_t j = 0; j < taus.size(); ++j)
      fit.relaxations.push_back({positive_semidefinite(coefficients[2 + j]), taus[j]});
    double residual = 0.0;
    for (std::size_t k = 0; k < omegas.size() && residual < best_residual; ++k) {
      const double w = omegas[k];
      Matrix6cd model = std::complex<double>(0.0, w) * fit.damping.cast<std::complex<double>>() -
                        (w * w) * fit.added_mass.cast<std::complex<double>>();
      for (const LineRelaxation& r : fit.relaxations) {
        const std::complex<double> iwt(0.0, w * r.time_constant_s);
        model += (iwt / (1.0 + iwt)) * r.stiffness.cast<std::complex<double>>();
      }
      residual += weights[k] * weights[k] * (model - data[k]).squaredNorm();
    }
    if (residual < best_residual) {
      best_residual = residual;
      best = std::move(fit);
    }
  }
  best.relative_residual = data_norm2 > 0.0 ? std::sqrt(best_residual / data_norm2) : 0.0;
  return best;
}

}  // namespace spiral::engine
