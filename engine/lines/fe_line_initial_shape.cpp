#include "engine/lines/fe_line_initial_shape.hpp"

#include <optional>

#include "engine/lines/catenary.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace spiral::engine {
namespace {

constexpr int kMinProfilePoints = 200;
constexpr int kMaxProfilePoints = 2000;

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

/// Inextensible catenary of length L and mean weight w (sign: up/down) through
/// A and B, as a function of the geometric arc length from A, and its H.
static InitialShape inextensible_shape(double L, double weight, const FeEnvironment& environment,
                                       const Eigen::Vector3d& end_A_m, const Eigen::Vector3d& end_B_m) {
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
              },
              a * w};
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
  const double s0 = std::sinh(-x0 / a);               // arc from vertex to A, over a (signed)
  const double c0 = std::cosh(-x0 / a);
  return {[=](double s) {
            const double u = std::asinh(s / a + s0);  // (x − x0)/a
            return to_global(x0 + a * u, a * (std::cosh(u) - c0));
          },
          a * w};
}

/// The multi-segment elastic catenary (solve_catenary: per-section weight
/// and EA, joint loads, seabed contact) as the start, when it has a solution:
/// much closer than the one-weight shape for chain–polyester–chain lines,
/// whose heavy ends hang differently. Empty if not applicable.
std::optional<InitialShape> catenary_solver_shape(const FeLineModel& model, const FeEnvironment& environment,
                                                  const Eigen::Vector3d& A, const Eigen::Vector3d& B) {
  Eigen::Vector3d ex(B.x() - A.x(), B.y() - A.y(), 0.0);
  const double X = ex.norm();
  double L = 0.0;
  CatenaryLine line;
  for (const auto& s : model.sections) {
    line.segments.push_back({s.length_m, s.weight_N_per_m, s.EA_N});
    L += s.length_m;
  }
  if (X < 1e-3 * L) return std::nullopt;
  ex /= X;
  line.joint_load_N = model.joint_load_N;
  CatenaryGeometry g;
  g.horizontal_span_m = X;
  g.vertical_span_m = B.z() - A.z();
  // Without a seabed (or an anchor off it) the catenary must not see one.
  const bool on_seabed = environment.seabed_stiffness_N_per_m2 > 0.0 && A.z() <= environment.seabed_z_m + 1e-6 * L;
  g.anchor_height_above_seabed_m = on_seabed ? 0.0 : std::max(1e6, 10.0 * L);
  CatenaryOptions o;
  // Profile points ≈ every 0.1 m (200..2000 per segment): the nodal slopes
  // are taken from the interpolated profile, and its chords must give the
  // stretch to ≈ (Δ/a)² ≪ T/EA.
  double longest = 0.0;
  for (const auto& s : model.sections) longest = std::max(longest, s.length_m);
  o.profile_points_per_segment = std::clamp(static_cast<int>(longest / 0.1), kMinProfilePoints, kMaxProfilePoints);
  CatenarySolution c;
  try {
    c = solve_catenary(line, g, o);
  } catch (const SolverError&) {
    return std::nullopt;  // e.g. slack or too short: the one-weight shape decides
  }
  if (c.profile.size() < 2 || c.regime == CatenaryRegime::slack_vertical) return std::nullopt;
  std::vector<CatenaryProfilePoint> pts = c.profile;
  std::stable_sort(pts.begin(), pts.end(),
                   [](const auto& a, const auto& b) { return a.arc_length_m < b.arc_length_m; });
  auto shape = [pts, A, ex](double s) -> Eigen::Vector3d {
    auto it = std::lower_bound(pts.begin(), pts.end(), s,
                               [](const CatenaryProfilePoint& p, double v) { return p.arc_length_m < v; });
    if (it == pts.begin()) return A + pts.front().x_m * ex + Eigen::Vector3d(0, 0, pts.front().z_m);
    if (it == pts.end()) it = pts.end() - 1;
    const auto& p1 = *it;
    const auto& p0 = *(it - 1);
    const double ds = p1.arc_length_m - p0.arc_length_m;
    const double f = ds > 0.0 ? (s - p0.arc_length_m) / ds : 1.0;
    const double x = p0.x_m + f * (p1.x_m - p0.x_m), z = p0.z_m + f * (p1.z_m - p0.z_m);
    return A + x * ex + Eigen::Vector3d(0.0, 0.0, z);
  };
  return InitialShape{shape, c.fairlead_horizontal_N};
}

InitialShape default_initial_shape(const FeLineModel& model, const FeEnvironment& environment,
                                   const Eigen::Vector3d& end_A_m, const Eigen::Vector3d& end_B_m) {
  if (auto c = catenary_solver_shape(model, environment, end_A_m, end_B_m)) return *c;
  double L = 0.0, weight = 0.0;
  for (const auto& s : model.sections) {
    L += s.length_m;
    weight += s.length_m * s.weight_N_per_m;
  }
  // First pass: inextensible, for the tension level H.
  const InitialShape first = inextensible_shape(L, weight, environment, end_A_m, end_B_m);
  if (first.horizontal_tension_N <= 0.0) return first;  // straight (taut) line: already consistent
  // Second pass on the stretched length, each section stretched by H/EA, and
  // node positions at the stretched arc length: positions and nodal slopes
  // (taken from them) then agree, every element starts in tension. Slopes
  // stretched on an unstretched shape instead would leave the element
  // interiors in compression (the cubic between longer end tangents bulges)
  // and Newton would crawl on an indefinite Jacobian.
  std::vector<double> s_end, stretch;
  double L_stretched = 0.0, s_acc = 0.0;
  for (const auto& sec : model.sections) {
    s_acc += sec.length_m;
    s_end.push_back(s_acc);
    stretch.push_back(1.0 + first.horizontal_tension_N / sec.EA_N);
    L_stretched += sec.length_m * stretch.back();
  }
  const InitialShape second = inextensible_shape(L_stretched, weight, environment, end_A_m, end_B_m);
  if (second.horizontal_tension_N <= 0.0) return first;
  auto geometric_arc = [s_end, stretch](double s) {
    double sigma = 0.0, s0 = 0.0;
    for (std::size_t i = 0; i < s_end.size(); ++i) {
      const double s1 = std::min(s, s_end[i]);
      if (s1 > s0) sigma += (s1 - s0) * stretch[i];
      s0 = s_end[i];
      if (s <= s_end[i]) break;
    }
    return sigma;
  };
  auto pos = second.position_m;
  return {[pos, geometric_arc](double s) { return pos(geometric_arc(s)); }, second.horizontal_tension_N};
}

}  // namespace spiral::engine
