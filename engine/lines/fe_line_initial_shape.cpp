#include "engine/lines/fe_line_initial_shape.hpp"

#include <cmath>

namespace spiral::engine {
namespace {

/// Root of f on [lo, hi] by bisection, f(lo), f(hi) of opposite signs.
template <typename F>
double bisect(F f, double lo, double hi) {
  const bool rising = f(hi) > f(lo);
  for (int i = 0; i < 200 && hi - lo > 1e-13 * std::max(1.0, std::abs(hi)); ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) < 0.0) == rising ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

InitialShape default_initial_shape(const FeLineModel& model,
                                                            const FeEnvironment& environment,
                                                            const Eigen::Vector3d& end_A_m,
                                                            const Eigen::Vector3d& end_B_m) {
  double L = 0.0, weight = 0.0;
  for (const auto& s : model.sections) {
    L += s.length_m;
    weight += s.length_m * s.weight_N_per_m;
  }
  const Eigen::Vector3d A = end_A_m, B = end_B_m;
  auto straight = [A, B, L](double s) -> Eigen::Vector3d { return A + (B - A) * (s / L); };

  Eigen::Vector3d ex(B.x() - A.x(), B.y() - A.y(), 0.0);
  const double X = ex.norm();
  const double chord = (B - A).norm();
  if (L <= chord * (1.0 + 1e-9) || weight == 0.0 || X < 1e-3 * L) return {straight, 0.0};
  const double w = std::abs(weight) / L;
  ex /= X;
  // A buoyant line hangs upwards: mirror the vertical axis.
  const double up = weight > 0.0 ? 1.0 : -1.0;
  const Eigen::Vector3d ez(0.0, 0.0, up);
  const double Z = up * (B.z() - A.z());
  auto to_global = [A, ex, ez](double x, double z) -> Eigen::Vector3d { return A + x * ex + z * ez; };

  const bool a_on_seabed = weight > 0.0 && environment.seabed_stiffness_N_per_m2 > 0.0 &&
                           A.z() <= environment.seabed_z_m + 1e-6 * L && Z > 0.0;
  if (a_on_seabed) {
    // Laid length Lb and suspended length Ls = L − Lb with the catenary
    // tangent to the seabed at the touchdown point: Ls² = Z² + 2aZ and
    // X − Lb = a·asinh(Ls/a).
    auto a_of = [Z](double Ls) { return (Ls * Ls - Z * Z) / (2.0 * Z); };
    // f rises from L − Z − X (vertical hang) to its fully suspended value.
  auto f = [&](double Ls) { return (L - Ls) + a_of(Ls) * std::asinh(Ls / a_of(Ls)) - X; };
    const double lo = Z * (1.0 + 1e-9);
    if (f(lo) < 0.0 && f(L) > 0.0) {
      const double Ls = bisect(f, lo, L);
      const double a = a_of(Ls), Lb = L - Ls;
      return {[=](double s) {
        if (s <= Lb) return to_global(s, 0.0);
        const double sigma = (s - Lb) / a;
        return to_global(Lb + a * std::asinh(sigma), a * (std::sqrt(1.0 + sigma * sigma) - 1.0));
      }, a * w};
    }
  }
  // Suspended catenary through both ends: √(L² − Z²) = 2a·sinh(X / 2a).
  const double ratio = std::sqrt(L * L - Z * Z) / X;  // sinh(β)/β with β = X / 2a
  if (!(ratio > 1.0)) return {straight, 0.0};
  auto g = [ratio](double beta) { return std::sinh(beta) / beta - ratio; };
  double hi = 1.0;
  while (g(hi) < 0.0 && hi < 300.0) hi *= 2.0;
  if (g(hi) < 0.0) return {straight, 0.0};
  const double beta = bisect(g, 1e-9, hi);
  const double a = X / (2.0 * beta);
  const double x0 = 0.5 * X - a * std::atanh(Z / L);  // vertex
  const double s0 = std::sinh(-x0 / a);                // arc from vertex to A, over a (signed)
  const double c0 = std::cosh(-x0 / a);
  return {[=](double s) {
    const double u = std::asinh(s / a + s0);  // (x − x0)/a
    return to_global(x0 + a * u, a * (std::cosh(u) - c0));
  }, a * w};
}

}  // namespace spiral::engine
