#include "engine/analysis/low_frequency_damping.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <variant>

namespace spiral::engine {
namespace {

// Central-difference steps: small against any motion the slow modes make
// (metres, degrees) and large against the line solvers' closure noise
// (≈ 1e-9 of forces of 1e6–1e8 N; engine/lines/catenary.hpp), which the
// position difference sees. The velocity difference meets |q̇| q̇ terms: at
// q̇ = 0 the step's own slope b h is left, negligible at these steps.
constexpr double kTranslationStep_m = 1e-2;
constexpr double kRotationStep_rad = 1e-4;
constexpr double kTranslationRateStep_m_per_s = 1e-4;
constexpr double kRotationRateStep_rad_per_s = 1e-6;

// ω = sqrt((K + Σ Δ (ωτ)²/(1 + (ωτ)²)) / M) by fixed-point iteration from the
// relaxed stiffness: the right side rises with ω and is bounded by K + ΣΔ, so
// the iterates rise monotonically to the root.
constexpr int kNaturalFrequencyIterations = 50;
constexpr double kNaturalFrequencyTolerance = 1e-10;

}  // namespace

std::vector<DofDamping> low_frequency_damping(const HullEquations& equations, const HullTimeSeries& record,
                                              std::span<const int> dofs, int samples) {
  const Eigen::Index n = record.times_s.size();
  if (n == 0 || record.position.cols() != n || record.velocity.cols() != n) {
    throw std::invalid_argument("low_frequency_damping: an empty record, or positions and velocities not at its times");
  }
  if (samples < 1) throw std::invalid_argument("low_frequency_damping: need at least one sample");
  const Eigen::Index count = std::min<Eigen::Index>(n, samples);

  std::vector<DofDamping> out;
  for (const int d : dofs) {
    if (d < 0 || d > 5) throw std::invalid_argument(fmt::format("low_frequency_damping: DOF {} is not 0..5", d));
    const double hq = d < 3 ? kTranslationStep_m : kRotationStep_rad;
    const double hv = d < 3 ? kTranslationRateStep_m_per_s : kRotationRateStep_rad_per_s;
    double stiffness = 0.0, damping = 0.0;
    for (Eigen::Index s = 0; s < count; ++s) {
      // Evenly over the record, its last sample included.
      const Eigen::Index k = count == 1 ? n - 1 : s * (n - 1) / (count - 1);
      const double t = record.times_s(k);
      const Vector6d q = record.position.col(k), v = record.velocity.col(k);
      Vector6d q_plus = q, q_minus = q, v_plus = v, v_minus = v;
      q_plus(d) += hq;
      q_minus(d) -= hq;
      v_plus(d) += hv;
      v_minus(d) -= hv;
      // The radiation memory (history) is left out: see the header.
      stiffness -= (hull_generalized_force(equations, t, q_plus, v, nullptr)(d) -
                    hull_generalized_force(equations, t, q_minus, v, nullptr)(d)) /
                   (2.0 * hq);
      damping -= (hull_generalized_force(equations, t, q, v_plus, nullptr)(d) -
                  hull_generalized_force(equations, t, q, v_minus, nullptr)(d)) /
                 (2.0 * hv);
    }
    DofDamping r;
    r.dof = d;
    r.mass = equations.total_mass(d, d);
    r.stiffness = stiffness / static_cast<double>(count);
    r.damping = damping / static_cast<double>(count);

    const auto* lines = std::get_if<LinearizedLines>(&equations.loads.lines);
    const auto relaxed_at = [&](double omega, double& k, double& b) {
      k = r.stiffness;
      b = r.damping;
      if (lines == nullptr) return;
      for (const LineRelaxation& x : lines->relaxations) {
        const double wt = omega * x.time_constant_s;
        k += x.stiffness(d, d) * wt * wt / (1.0 + wt * wt);
        b += x.stiffness(d, d) * x.time_constant_s / (1.0 + wt * wt);
      }
    };
    if (r.stiffness > 0.0 && r.mass > 0.0) {
      double omega = std::sqrt(r.stiffness / r.mass), k = r.stiffness, b = r.damping;
      for (int i = 0; i < kNaturalFrequencyIterations; ++i) {
        relaxed_at(omega, k, b);
        const double next = std::sqrt(k / r.mass);
        const bool converged = std::abs(next - omega) <= kNaturalFrequencyTolerance * next;
        omega = next;
        if (converged) break;
      }
      relaxed_at(omega, k, b);
      r.stiffness = k;
      r.damping = b;
      r.natural_period_s = 2.0 * std::numbers::pi / omega;
      r.damping_ratio = b / (2.0 * r.mass * omega);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace spiral::engine
