// Property test of solve_catenary over thousands of random feasible lines
// (fixed seed): it converges, returns finite values, closes the spans (checked
// through the independently integrated profile), keeps H >= 0, satisfies the
// equilibrium of every segment, and a warm start converges in a few steps.
//
// Two generators: geometry-first (heavy segments and clumps, any regime incl.
// slack-vertical) and forces-first (any segments incl. buoyant ones and buoys:
// spans from the forward span evaluation at chosen H, V_F, which the solver must
// then recover).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "engine/lines/catenary.hpp"
#include "engine/lines/catenary_spans.hpp"
#include "support/expect_near.hpp"

namespace spiral::engine {
namespace {

constexpr int kGeometryFirstCases = 2500;
constexpr int kForcesFirstCases = 1500;
constexpr std::uint64_t kSeed = 20240607;
// Profile closure: the profile re-integrates every piece from the anchor; each
// piece adds round-off ~1e-15 of the line length, so 1e-9 of the length is ample.
constexpr double kProfileClosureRelTol = 1e-9;
// Segment equilibrium from the profile's force components: round-off of sums of
// a few forces of the size of the tension.
constexpr double kEquilibriumRelTol = 1e-9;
// Forces recovered from spans closed to 1e-9 m: the compliance of taut elastic
// lines (EA up to 3e9 N over tens of m) amplifies the closure error to ~1e-7 of T.
constexpr double kRecoverRelTol = 1e-6;
// Warm start after a move that changes the force by ~1e-4: the linear model is
// then good to ~1e-8, so Newton closes to 1e-9 m in 2 steps; 3 allows one more.
constexpr int kMaxWarmIterations = 3;
constexpr double kSmallMoveFraction = 1e-4;

struct Case {
  CatenaryLine line;
  CatenaryGeometry geometry;
  bool has_expected = false;
  double H_N = 0.0, V_N = 0.0;
};

double total_length(const CatenaryLine& line) {
  double L = 0.0;
  for (const auto& s : line.segments) L += s.length_m;
  return L;
}

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

  CatenaryLine line(bool allow_buoyant) {
    CatenaryLine line;
    const int n = integer(1, 4);
    for (int i = 0; i < n; ++i) {
      CatenarySegment s;
      s.length_m = log_uniform(20.0, 1500.0);
      s.weight_N_per_m = allow_buoyant && chance(0.25) ? -log_uniform(5.0, 800.0) : log_uniform(2.0, 4000.0);
      s.EA_N = log_uniform(1e7, 3e9);
      line.segments.push_back(s);
    }
    if (n > 1 && chance(0.5)) {
      for (int i = 0; i + 1 < n; ++i) {
        double P = chance(0.5) ? log_uniform(1e2, 2e5) : 0.0;
        if (allow_buoyant && chance(0.3)) P = -log_uniform(1e2, 1e5);
        line.joint_load_N.push_back(P);
      }
    }
    line.seabed_friction = chance(0.3) ? 0.0 : uniform(0.0, 1.0);
    return line;
  }

 private:
  std::mt19937_64 rng_;
};

Case geometry_first(Generator& g) {
  Case c;
  c.line = g.line(false);
  const double L = total_length(c.line);
  const bool on_seabed = g.chance(0.7);
  c.geometry.anchor_height_above_seabed_m = on_seabed ? 0.0 : g.uniform(1.0, 300.0);
  const double ZF = on_seabed ? g.uniform(0.02, 0.95) * L : g.uniform(-0.5, 0.95) * L;
  const double chord = g.uniform(0.2, 1.004) * L;  // up to 0.4 % mean strain
  const double XF = std::sqrt(std::max(chord * chord - ZF * ZF, std::pow(0.01 * L, 2)));
  c.geometry.horizontal_span_m = XF;
  c.geometry.vertical_span_m = ZF;
  return c;
}

bool forces_first(Generator& g, Case& c) {
  c = {};
  c.line = g.line(true);
  const bool on_seabed = g.chance(0.4);
  c.geometry.anchor_height_above_seabed_m = on_seabed ? 0.0 : g.uniform(1.0, 300.0);
  catenary_detail::LineView view;
  view.line = &c.line;
  view.anchor_on_seabed = on_seabed;
  for (const auto& s : c.line.segments) {
    view.total_weight_N += s.weight_N_per_m * s.length_m;
    view.total_length_m += s.length_m;
  }
  for (double P : c.line.joint_load_N) view.total_weight_N += P;
  const double W = std::max(std::abs(view.total_weight_N), 1e3);
  c.H_N = g.log_uniform(1e-2, 10.0) * W;
  c.V_N = g.uniform(-1.0, 1.5) * W;
  const auto e = catenary_detail::evaluate_spans(view, c.H_N, c.V_N);
  if (e.infeasible != catenary_detail::Infeasibility::none) return false;
  if (on_seabed && e.z_m <= 1e-3 * view.total_length_m) return false;
  if (e.x_m <= 1e-3 * view.total_length_m) return false;
  if (std::hypot(e.x_m, e.z_m) >= 1.2 * view.total_length_m) return false;
  c.geometry.horizontal_span_m = e.x_m;
  c.geometry.vertical_span_m = e.z_m;
  c.has_expected = true;
  return true;
}

std::string describe(const Case& c) {
  std::ostringstream o;
  o.precision(17);
  o << "segments (L, w, EA):";
  for (const auto& s : c.line.segments) o << " (" << s.length_m << ", " << s.weight_N_per_m << ", " << s.EA_N << ")";
  o << "; joints:";
  for (double P : c.line.joint_load_N) o << " " << P;
  o << "; mu " << c.line.seabed_friction << "; XF " << c.geometry.horizontal_span_m << ", ZF "
    << c.geometry.vertical_span_m << ", anchor height " << c.geometry.anchor_height_above_seabed_m;
  if (c.has_expected) o << "; expected H " << c.H_N << ", V " << c.V_N;
  return o.str();
}

void check_case(const Case& c, const std::string& label, int& max_warm_iterations) {
  SCOPED_TRACE(label + ": " + describe(c));
  CatenaryOptions options;
  options.profile_points_per_segment = 2;
  CatenarySolution s;
  try {
    s = solve_catenary(c.line, c.geometry, options);
  } catch (const SolverError& e) {
    ADD_FAILURE() << "threw: " << e.what();
    return;
  }
  const double L = total_length(c.line);
  const double T = std::max(s.fairlead_tension_N, 1.0);
  for (double v : {s.fairlead_horizontal_N, s.fairlead_vertical_N, s.fairlead_tension_N, s.anchor_horizontal_N,
                   s.anchor_vertical_N, s.anchor_tension_N, s.laid_length_m, s.touchdown_x_m, s.residual_m}) {
    ASSERT_TRUE(std::isfinite(v));
  }
  ASSERT_TRUE(s.tangent_stiffness.allFinite());
  EXPECT_GE(s.fairlead_horizontal_N, 0.0);
  EXPECT_GE(s.anchor_horizontal_N, 0.0);
  EXPECT_LE(s.anchor_horizontal_N, s.fairlead_horizontal_N * (1.0 + kEquilibriumRelTol));
  ASSERT_FALSE(s.profile.empty());
  EXPECT_REL_NEAR_SCALE(s.profile.back().x_m, c.geometry.horizontal_span_m, kProfileClosureRelTol, L);
  EXPECT_REL_NEAR_SCALE(s.profile.back().z_m, c.geometry.vertical_span_m, kProfileClosureRelTol, L);
  if (c.line.seabed_friction == 0.0 && s.regime == CatenaryRegime::touchdown) {
    EXPECT_REL_NEAR(s.anchor_horizontal_N, s.fairlead_horizontal_N, kEquilibriumRelTol);
  }
  // Equilibrium of every segment: the vertical force changes by the suspended
  // weight, the horizontal one by the friction of the laid part (while tension remains).
  for (std::size_t i = 0; i < c.line.segments.size(); ++i) {
    const CatenaryProfilePoint* bottom = nullptr;
    const CatenaryProfilePoint* top = nullptr;
    double laid_m = 0.0;
    for (const auto& p : s.profile) {
      if (p.segment != static_cast<int>(i)) continue;
      if (!bottom) bottom = &p;
      top = &p;
      if (p.on_seabed) laid_m = p.arc_length_m - bottom->arc_length_m;
    }
    ASSERT_TRUE(bottom && top);
    const auto& seg = c.line.segments[i];
    EXPECT_REL_NEAR_SCALE(top->vertical_N - bottom->vertical_N, seg.weight_N_per_m * (seg.length_m - laid_m),
                          kEquilibriumRelTol, T)
        << "segment " << i;
    if (bottom->horizontal_N > 0.0 && s.regime != CatenaryRegime::slack_vertical) {
      EXPECT_REL_NEAR_SCALE(top->horizontal_N - bottom->horizontal_N,
                            c.line.seabed_friction * seg.weight_N_per_m * laid_m, kEquilibriumRelTol, T)
          << "segment " << i;
    }
  }
  if (c.has_expected) {
    EXPECT_REL_NEAR_SCALE(s.fairlead_horizontal_N, c.H_N, kRecoverRelTol, std::hypot(c.H_N, c.V_N));
    EXPECT_REL_NEAR_SCALE(s.fairlead_vertical_N, c.V_N, kRecoverRelTol, std::hypot(c.H_N, c.V_N));
  }
  if (s.regime == CatenaryRegime::slack_vertical) return;
  const CatenaryGuess guess{s.fairlead_horizontal_N, s.fairlead_vertical_N};
  // Warm start after a small move: 1e-4 of the force's length scale T/|K|max
  // and of the horizontal span (a nearly vertical line's H is proportional to
  // XF), so that "small" means the same for a slack 2 km chain and a taut 30 m
  // tendon. Newton must need at most 3 steps.
  const double K_max = s.tangent_stiffness.cwiseAbs().maxCoeff();
  if (K_max > 0.0) {
    const double move_m = kSmallMoveFraction * std::min(s.fairlead_tension_N / K_max, c.geometry.horizontal_span_m);
    CatenaryGeometry moved = c.geometry;
    moved.horizontal_span_m += move_m;
    moved.vertical_span_m -= 0.5 * move_m;
    try {
      const CatenarySolution w = solve_catenary(c.line, moved, {}, guess);
      EXPECT_LE(w.iterations, kMaxWarmIterations) << "move " << move_m << " m";
    } catch (const SolverError& e) {
      // A nearly tight line may become too short; nothing else may throw.
      EXPECT_NE(std::string(e.what()).find("too short"), std::string::npos) << e.what();
    }
  }
  // A fixed 0.1 m fairlead move (large for stiff short lines): must converge.
  CatenaryGeometry moved = c.geometry;
  moved.horizontal_span_m += 0.1;
  moved.vertical_span_m -= 0.05;
  try {
    const CatenarySolution w = solve_catenary(c.line, moved, {}, guess);
    max_warm_iterations = std::max(max_warm_iterations, w.iterations);
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("too short"), std::string::npos) << e.what();
  }
}

TEST(CatenaryProperty, GeometryFirstRandomLines) {
  Generator g(kSeed);
  int max_warm = 0;
  for (int k = 0; k < kGeometryFirstCases; ++k) {
    const Case c = geometry_first(g);
    check_case(c, "geometry-first case " + std::to_string(k), max_warm);
    if (HasFatalFailure() || testing::Test::HasFailure()) break;  // keep the log readable
  }
  std::cout << "[ property ] geometry-first: max iterations after a warm-started 0.1 m move " << max_warm << "\n";
}

TEST(CatenaryProperty, ForcesFirstRandomLinesWithBuoyancy) {
  Generator g(kSeed + 1);
  int max_warm = 0, done = 0;
  for (int attempt = 0; done < kForcesFirstCases && attempt < 100 * kForcesFirstCases; ++attempt) {
    Case c;
    if (!forces_first(g, c)) continue;
    check_case(c, "forces-first case " + std::to_string(done), max_warm);
    ++done;
    if (testing::Test::HasFailure()) break;
  }
  EXPECT_EQ(done, kForcesFirstCases);
  std::cout << "[ property ] forces-first: max iterations after a warm-started 0.1 m move " << max_warm << "\n";
}

}  // namespace
}  // namespace spiral::engine
