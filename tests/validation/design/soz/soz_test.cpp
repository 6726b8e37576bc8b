// Riser safe operational zones (design/soz/soz.hpp) on a small SCR project
// (tests/support/soz_project.hpp): symmetry, the physics of near/far limits,
// the search against a brute-force sweep, the platform intersection, current,
// the catenary screening model against FE, and bad input.

#include "design/soz/soz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "design/model/environment_loads.hpp"
#include "design/project/input_error.hpp"
#include "design/project/project_loader.hpp"
#include "design/project/project_validation.hpp"
#include "design/criteria/riser_checks.hpp"
#include "support/soz_project.hpp"

namespace spiral::design {
namespace {

// The zone search closes each bracket to this width (SozOptions default).
constexpr double kTolerance_m = 0.1;
// Two symmetric directions run their own searches (different sample points,
// warm starts): each is within the tolerance of the true boundary, so they
// agree within twice of it.
constexpr double kSymmetry_m = 2.0 * kTolerance_m;
// Brute-force sweep: 1 m steps to the first failure, then this step inside it.
constexpr double kSweepCoarse_m = 1.0;
constexpr double kSweepFine_m = 0.02;
// Catenary screening vs FE: the catenary ignores bending stiffness (top
// tension within a fraction of a percent for an SCR) and takes the TDP
// curvature as w/H (FE within ≈ 1 %, fe_line_statics.hpp); allowable
// offsets through those curvatures and tensions agree to a few percent.
constexpr double kScreeningTopTension = 0.01;
constexpr double kScreeningOffset = 0.10;

Project project(const std::string& risers, const std::optional<std::string>& criteria = std::nullopt) {
  Project p = criteria ? parse_project(test::soz_project_yaml(risers, *criteria), "soz-test.yaml")
                       : parse_project(test::soz_project_yaml(risers), "soz-test.yaml");
  return p;
}

std::vector<RiserDesign> designs(const Project& p) {
  std::vector<RiserDesign> out;
  for (const Riser& r : p.risers) out.push_back(riser_design(p, r));
  return out;
}

SozOptions options(double step_deg) {
  SozOptions o;
  o.step_deg = step_deg;
  o.offset_check = false;
  return o;
}

double at(const SozResult& r, std::size_t riser, double direction_deg) {
  std::vector<double> a;
  for (const SozDirection& d : r.risers[riser].directions) a.push_back(d.allowable_offset_m);
  return polygon_allowable(r.directions_deg, a, direction_deg);
}

TEST(Soz, SymmetricAboutTheAzimuthPlaneAndNearFarGovernedByDifferentPhysics) {
  const Project p = project(test::soz_riser_yaml("R", 0.0));
  SozOptions o = options(30.0);
  o.exploit_symmetry = false;  // every direction searched: the symmetry is the physics', not a copy
  const SozResult r = compute_soz(p, designs(p), {}, o);
  ASSERT_FALSE(r.risers.front().zone_mirror_symmetric);
  ASSERT_EQ(r.risers.size(), 1u);
  const RiserSoz& z = r.risers[0];
  ASSERT_FALSE(z.fails_at_zero_offset) << z.zero_offset_governing_criterion;
  for (std::size_t k = 1; k < r.directions_deg.size() / 2; ++k) {
    const std::size_t mirror = r.directions_deg.size() - k;
    EXPECT_NEAR(z.directions[k].allowable_offset_m, z.directions[mirror].allowable_offset_m, kSymmetry_m)
        << r.directions_deg[k] << "° vs " << r.directions_deg[mirror] << "°";
    EXPECT_EQ(z.directions[k].governing_criterion, z.directions[mirror].governing_criterion);
  }
  // Near (hull towards the riser's azimuth, 0°): the riser slackens at the
  // TDP — curvature (stress) or compression there. Far (180°): the top
  // tension / angle grow.
  const std::string& near = z.directions.front().governing_criterion;
  const std::string& far = z.directions[r.directions_deg.size() / 2].governing_criterion;
  EXPECT_NE(near, far);
  EXPECT_TRUE(near == "von_mises" || near == "min_effective_tension" || near == "min_bending_radius") << near;
  EXPECT_TRUE(far == "max_top_tension" || far == "max_top_angle" || far == "von_mises") << far;
  EXPECT_TRUE(z.star_shaped);
  EXPECT_GT(z.near_m, 0.0);
  EXPECT_GT(z.far_m, 0.0);
}

TEST(Soz, SearchAgreesWithABruteForceSweep) {
  const Project p = project(test::soz_riser_yaml("R", 0.0));
  const std::vector<RiserDesign> d = designs(p);
  // 90° steps: every march point solved; 5° steps: points near the centre
  // covered by the neighbouring direction of the task (soz.cpp).
  const SozResult coarse = compute_soz(p, d, {}, options(90.0));
  const SozResult fine = compute_soz(p, d, {}, options(5.0));
  for (const auto& [r, direction_deg] : {std::pair{&coarse, 0.0}, std::pair{&coarse, 180.0}, std::pair{&fine, 0.0},
                                         std::pair{&fine, 180.0}, std::pair{&fine, 5.0}, std::pair{&fine, 145.0}}) {
    const double found = at(*r, 0, direction_deg);
    const RiserOffsetEvaluator evaluator(p, d[0], {}, SozModel::fe);
    const Eigen::Vector2d unit(std::cos(direction_deg * M_PI / 180.0), std::sin(direction_deg * M_PI / 180.0));
    std::shared_ptr<const engine::FeStaticsResult> warm = evaluator.zero_offset().solution;
    double last_pass = 0.0;
    for (double s = kSweepCoarse_m;; s += kSweepCoarse_m) {
      ASSERT_LT(s, 200.0) << "no failure found";
      const auto e = evaluator.evaluate(s * unit, warm.get());
      if (!e.passes()) break;
      last_pass = s;
      warm = e.solution;
    }
    double boundary = last_pass;
    for (double s = last_pass + kSweepFine_m; s < last_pass + kSweepCoarse_m; s += kSweepFine_m) {
      const auto e = evaluator.evaluate(s * unit, warm.get());
      if (!e.passes()) break;
      boundary = s;
      warm = e.solution;
    }
    EXPECT_NEAR(found, boundary, kTolerance_m + kSweepFine_m)
        << "direction " << direction_deg << ", step " << r->options.step_deg;
  }
  EXPECT_LT(fine.solves, 72 * coarse.solves / 4);  // the covered points are not solved
}

TEST(Soz, CoveredMarchPointsDoNotChangeTheZone) {
  // The 5° zone skips march points covered by a neighbouring direction. The
  // reference solves every point: with 90° steps no point is covered, and 18
  // copies of the riser turned by 0°, 5°, …, 85° put every 5° direction
  // relative to the riser on that 90° grid (none is a whole number of 90°
  // steps from another, so each is solved).
  std::string risers;
  for (int i = 0; i < 18; ++i) {
    std::string name = "R";  // not "R" + to_string: GCC 12's false -Wrestrict (bug 105329)
    name += std::to_string(i);
    risers += test::soz_riser_yaml(name, 5.0 * i);
  }
  const Project p = project(risers);
  const std::vector<RiserDesign> d = designs(p);
  const SozResult fine = compute_soz(p, {d[0]}, {}, options(5.0));
  SozOptions every = options(90.0);
  every.exploit_symmetry = false;  // mirror images among the 18 would be copied
  const SozResult reference = compute_soz(p, d, {}, every);
  for (int i = 0; i < 18; ++i) {
    ASSERT_TRUE(reference.risers[static_cast<std::size_t>(i)].zone_rotated_from.empty());
    for (int q = 0; q < 4; ++q) {
      // Riser i at azimuth 5i°, grid direction 90q°: relative direction 90q − 5i.
      const double relative_deg = std::fmod(90.0 * q - 5.0 * i + 360.0, 360.0);
      const SozDirection& ref = reference.risers[static_cast<std::size_t>(i)].directions[static_cast<std::size_t>(q)];
      const SozDirection& got = fine.risers[0].directions[static_cast<std::size_t>(std::lround(relative_deg / 5.0))];
      EXPECT_NEAR(got.allowable_offset_m, ref.allowable_offset_m, kSymmetry_m) << relative_deg << "°";
      EXPECT_EQ(got.governing_criterion, ref.governing_criterion) << relative_deg << "°";
    }
  }
}

TEST(Soz, IdenticalRiserTurnedAboutTheVerticalSharesTheZone) {
  // A and B differ only in azimuth (0° and 90°, three 30° steps): without
  // current or hull rotations B's zone is A's turned by 90°.
  const Project p = project(test::soz_riser_yaml("A", 0.0, 20.0) + test::soz_riser_yaml("B", 90.0, 20.0));
  const std::vector<RiserDesign> both = designs(p);
  const SozResult r = compute_soz(p, both, {}, options(30.0));
  ASSERT_EQ(r.risers.size(), 2u);
  EXPECT_TRUE(r.risers[0].zone_rotated_from.empty());
  EXPECT_EQ(r.risers[1].zone_rotated_from, "A");
  EXPECT_EQ(r.risers[1].solves, 0);
  // Against B solved on its own: the same zone within the search tolerance
  // (each search closes its own brackets from its own samples).
  const SozResult alone = compute_soz(p, {both[1]}, {}, options(30.0));
  ASSERT_TRUE(alone.risers[0].zone_rotated_from.empty());
  for (std::size_t k = 0; k < r.directions_deg.size(); ++k) {
    EXPECT_NEAR(r.risers[1].directions[k].allowable_offset_m, alone.risers[0].directions[k].allowable_offset_m,
                kSymmetry_m)
        << r.directions_deg[k];
    EXPECT_EQ(r.risers[1].directions[k].governing_criterion, alone.risers[0].directions[k].governing_criterion);
  }
  EXPECT_NEAR(r.risers[1].near_m, r.risers[0].near_m, 1e-9);
  // A current breaks the symmetry: both risers are solved.
  SozConditions current;
  current.current = current_profile_of(*p.environments[1].current);
  const SozResult with_current = compute_soz(p, both, current, options(30.0));
  EXPECT_TRUE(with_current.risers[1].zone_rotated_from.empty());
  EXPECT_GT(with_current.risers[1].solves, 0);
  // So does an azimuth that is not a whole number of steps away.
  const Project q = project(test::soz_riser_yaml("A", 0.0, 20.0) + test::soz_riser_yaml("B", 100.0, 20.0));
  EXPECT_TRUE(compute_soz(q, designs(q), {}, options(30.0)).risers[1].zone_rotated_from.empty());
}

TEST(Soz, MirrorImageRiserSharesTheMirroredZone) {
  // A at 10° and B at 170° are mirror images in the plane at 90° (on the 30°
  // grid: 2 × 90° is six steps), but 160° apart — not a whole number of
  // steps, so no rotation maps them, and neither is its own mirror image on
  // the grid (2 × 10° is not a whole number of steps).
  const Project p = project(test::soz_riser_yaml("A", 10.0, 20.0) + test::soz_riser_yaml("B", 170.0, 20.0));
  const std::vector<RiserDesign> both = designs(p);
  const SozResult r = compute_soz(p, both, {}, options(30.0));
  EXPECT_TRUE(r.risers[0].zone_mirrored_from.empty());
  EXPECT_FALSE(r.risers[0].zone_mirror_symmetric);
  EXPECT_EQ(r.risers[1].zone_mirrored_from, "A");
  EXPECT_TRUE(r.risers[1].zone_rotated_from.empty());
  EXPECT_EQ(r.risers[1].solves, 0);
  // Against B searched on its own: the same zone within the search tolerance.
  SozOptions every = options(30.0);
  every.exploit_symmetry = false;
  const SozResult alone = compute_soz(p, {both[1]}, {}, every);
  for (std::size_t k = 0; k < r.directions_deg.size(); ++k) {
    EXPECT_NEAR(r.risers[1].directions[k].allowable_offset_m, alone.risers[0].directions[k].allowable_offset_m,
                kSymmetry_m)
        << r.directions_deg[k];
    EXPECT_EQ(r.risers[1].directions[k].governing_criterion, alone.risers[0].directions[k].governing_criterion)
        << r.directions_deg[k];
  }
  EXPECT_NEAR(r.risers[1].far_m, r.risers[0].far_m, 1e-9);
}

TEST(Soz, RiserSymmetricAboutItsOwnPlaneIsSearchedOnOneHalf) {
  // R at 60° on the 30° grid: its plane falls on the grid, so the directions
  // from 60° to 240° are searched and the rest mirrored.
  const Project p = project(test::soz_riser_yaml("R", 60.0, 20.0));
  const std::vector<RiserDesign> d = designs(p);
  const SozResult half = compute_soz(p, d, {}, options(30.0));
  SozOptions every = options(30.0);
  every.exploit_symmetry = false;
  const SozResult full = compute_soz(p, d, {}, every);
  ASSERT_TRUE(half.risers[0].zone_mirror_symmetric);
  EXPECT_FALSE(full.risers[0].zone_mirror_symmetric);
  for (std::size_t k = 0; k < half.directions_deg.size(); ++k) {
    const double relative_deg = std::fmod(half.directions_deg[k] - 60.0 + 360.0, 360.0);
    EXPECT_EQ(half.risers[0].directions[k].solves == 0, relative_deg > 180.0) << half.directions_deg[k];
    EXPECT_NEAR(half.risers[0].directions[k].allowable_offset_m, full.risers[0].directions[k].allowable_offset_m,
                kSymmetry_m)
        << half.directions_deg[k];
    EXPECT_EQ(half.risers[0].directions[k].governing_criterion, full.risers[0].directions[k].governing_criterion);
  }
  EXPECT_LT(half.solves, 0.7 * full.solves);  // 7 of 12 directions searched
  // Off the grid (2 × 10° is not a whole number of 30° steps) and under a
  // current the whole zone is searched.
  const Project q = project(test::soz_riser_yaml("R", 10.0, 20.0));
  EXPECT_FALSE(compute_soz(q, designs(q), {}, options(30.0)).risers[0].zone_mirror_symmetric);
  SozConditions current;
  current.current = current_profile_of(*p.environments[1].current);
  EXPECT_FALSE(compute_soz(p, d, current, options(30.0)).risers[0].zone_mirror_symmetric);
}

TEST(Soz, PlatformZoneIsTheIntersectionAndShrinksWithEveryRiser) {
  const Project p = project(test::soz_riser_yaml("A", 0.0, 20.0) + test::soz_riser_yaml("B", 120.0, 20.0) +
                            test::soz_riser_yaml("C", 240.0, 20.0));
  const std::vector<RiserDesign> all = designs(p);
  const SozResult r = compute_soz(p, all, {}, options(30.0));
  for (std::size_t k = 0; k < r.directions_deg.size(); ++k) {
    for (const RiserSoz& z : r.risers) EXPECT_LE(r.platform.allowable_offset_m[k], z.directions[k].allowable_offset_m);
  }
  // Remove the riser that governs direction 0 and recompute.
  const std::string governing = r.platform.governing_riser[0];
  std::vector<RiserDesign> fewer;
  for (const RiserDesign& d : all) {
    if (d.name != governing) fewer.push_back(d);
  }
  const SozResult s = compute_soz(p, fewer, {}, options(30.0));
  // The three risers are one design turned by 120°: a riser's zone may be
  // solved in either run or turned from another's (compute_soz), each within
  // the search tolerance of the true boundary — equal zones agree to 2 tol.
  bool larger_somewhere = false;
  for (std::size_t k = 0; k < r.directions_deg.size(); ++k) {
    EXPECT_GE(s.platform.allowable_offset_m[k], r.platform.allowable_offset_m[k] - kSymmetry_m);
    larger_somewhere =
        larger_somewhere || s.platform.allowable_offset_m[k] > r.platform.allowable_offset_m[k] + kSymmetry_m;
  }
  EXPECT_GT(s.platform.allowable_offset_m[0], r.platform.allowable_offset_m[0] + kSymmetry_m);
  EXPECT_TRUE(larger_somewhere);
}

TEST(Soz, CurrentInTheRiserPlaneMovesTheFarLimitAsTheTopAngleSays) {
  // The far limit of this riser is its top angle. A current towards its foot
  // (+x; azimuth 0°) pushes the riser away from the hull and raises the top
  // angle — the far allowable offset (180°) shrinks; a current towards the
  // hull lowers it and the far offset grows. (The near limit, TDP curvature,
  // tightens with a current towards the foot as well: the sag bend is pushed
  // onto the touchdown zone.)
  const Project p = project(test::soz_riser_yaml("R", 0.0));
  const std::vector<RiserDesign> d = designs(p);
  const SozResult still = compute_soz(p, d, {}, options(180.0));
  ASSERT_EQ(still.risers[0].directions[1].governing_criterion, "max_top_angle");
  SozConditions downstream;
  downstream.current = current_profile_of(*p.environments[1].current);
  SozConditions upstream = downstream;
  upstream.current->heading_rad = M_PI;
  const SozResult towards_foot = compute_soz(p, d, downstream, options(180.0));
  const SozResult towards_hull = compute_soz(p, d, upstream, options(180.0));
  EXPECT_LT(at(towards_foot, 0, 180.0), at(still, 0, 180.0) - kTolerance_m);
  EXPECT_GT(at(towards_hull, 0, 180.0), at(still, 0, 180.0) + kTolerance_m);
  EXPECT_LT(at(towards_foot, 0, 0.0), at(still, 0, 0.0) - kTolerance_m);
}

TEST(Soz, CatenaryScreeningAgreesWithFeWhereTensionGovernsAndIsConservativeAtTheTdp) {
  const Project p = project(test::soz_riser_yaml("R", 0.0));
  const std::vector<RiserDesign> d = designs(p);
  SozOptions o = options(90.0);
  const SozResult fe = compute_soz(p, d, {}, o);
  o.model = SozModel::catenary;
  const SozResult catenary = compute_soz(p, d, {}, o);
  const RiserOffsetEvaluator fe_zero(p, d[0], {}, SozModel::fe), cat_zero(p, d[0], {}, SozModel::catenary);
  EXPECT_NEAR(cat_zero.zero_offset().row.top_tension_N / fe_zero.zero_offset().row.top_tension_N, 1.0,
              kScreeningTopTension);
  for (std::size_t k = 0; k < fe.directions_deg.size(); ++k) {
    const SozDirection& f = fe.risers[0].directions[k];
    const SozDirection& c = catenary.risers[0].directions[k];
    const std::string where = std::to_string(fe.directions_deg[k]) + "°: fe " + std::to_string(f.allowable_offset_m) +
                              " m (" + f.governing_criterion + "), catenary " + std::to_string(c.allowable_offset_m) +
                              " m (" + c.governing_criterion + ")";
    if (f.governing_criterion == "von_mises") {
      // Near: the TDP curvature. The catenary's w/H is the rigid-seabed
      // boundary-layer peak (Pesce et al. 1998); the FE riser rests on the
      // project's elastic seabed, which spreads the bend: lower peak.
      EXPECT_LE(c.allowable_offset_m, f.allowable_offset_m + kTolerance_m) << where;
    } else {
      EXPECT_EQ(c.governing_criterion, f.governing_criterion) << where;
      EXPECT_NEAR(c.allowable_offset_m / f.allowable_offset_m, 1.0, kScreeningOffset) << where;
    }
  }
}

TEST(Soz, TouchdownExcursionLimitsTheZoneWhereGiven) {
  // TDP travel is about as large as the hull offset along the riser plane:
  // a 5 m limit governs there, long before the top angle.
  const Project p = project(test::soz_riser_yaml("R", 0.0), std::string("    max_top_angle_deg: 16.0\n"
                                                                        "    max_touchdown_excursion: 5.0\n"));
  const std::vector<RiserDesign> d = designs(p);
  const SozResult r = compute_soz(p, d, {}, options(180.0));
  const SozDirection& far = r.risers[0].directions[1];
  EXPECT_EQ(far.governing_criterion, "max_touchdown_excursion");
  const RiserOffsetEvaluator evaluator(p, d[0], {}, SozModel::fe);
  const auto e = evaluator.evaluate({-far.allowable_offset_m, 0.0}, nullptr);
  ASSERT_TRUE(e.passes());
  const auto check = std::find_if(e.row.checks.begin(), e.row.checks.end(), [](const RiserCriterionCheck& c) {
    return c.criterion == "max_touchdown_excursion";
  });
  ASSERT_NE(check, e.row.checks.end());
  EXPECT_LE(check->value, 5.0);
  EXPECT_GT(check->value, 5.0 - 2.0 * kTolerance_m);  // TDP moves ≈ as far as the hang-off
}

/// The riser evaluated at `d_m` along `unit`, reached by warm-started steps
/// of `step_m` from zero offset (a cold solve 400 m out need not converge).
RiserOffsetEvaluator::Evaluation evaluate_along(const RiserOffsetEvaluator& evaluator, const Eigen::Vector2d& unit,
                                                double d_m, double step_m) {
  std::shared_ptr<const engine::FeStaticsResult> warm = evaluator.zero_offset().solution;
  for (double s = std::min(step_m, d_m);; s = std::min(s + step_m, d_m)) {
    auto e = evaluator.evaluate(s * unit, warm.get());
    if (s >= d_m || !e.solution) return e;
    warm = e.solution;
  }
}

TEST(Soz, ZoneThatIsNotStarShapedKeepsItsFirstBoundaryAndReportsTheBand) {
  // A physical band that re-opens: the hull moves along a ray 60° off the
  // riser's azimuth (riser at 300°, ray at 0°). The hang-off first closes on
  // the riser's foot — the span shrinks, the riser slackens and the TDP
  // curvature fails (von Mises) — passes its closest approach at
  // d* = L cos 60° (L: horizontal hang-off–foot distance, ≈ 460 m), and then
  // draws away again: the span grows back, the TDP curvature drops below its
  // limit and the riser passes again, until the growing span fails the top
  // angle or the flex joint. The search limit is raised to 130 % of depth (520 m) to see it.
  const Project p = project(test::soz_riser_yaml("R", 300.0));
  const std::vector<RiserDesign> d = designs(p);
  SozOptions o = options(180.0);
  o.search_limit_pct_depth = 130.0;
  o.march_step_pct_depth = 5.0;
  const SozResult r = compute_soz(p, d, {}, o);
  const RiserSoz& z = r.risers[0];
  const SozDirection& ray = z.directions[0];
  EXPECT_FALSE(z.star_shaped);
  ASSERT_EQ(ray.reopened_bands.size(), 1u);
  const SozBand& band = ray.reopened_bands.front();
  EXPECT_EQ(ray.governing_criterion, "von_mises");
  // The allowable offset is the first boundary, not the band's far edge.
  EXPECT_LT(ray.allowable_offset_m, band.from_m);
  EXPECT_LT(band.from_m, band.to_m);
  EXPECT_LT(band.to_m, o.search_limit_pct_depth * p.site.depth_m / 100.0);
  EXPECT_DOUBLE_EQ(r.platform.allowable_offset_m[0], ray.allowable_offset_m);
  // The closest approach to the foot lies in the failing gap.
  const Eigen::Vector2d unit(1.0, 0.0);
  const Eigen::Vector3d hang_off0 = p.hull.reference_point_g + d[0].hang_off_b;
  const Eigen::Vector2d to_foot = (d[0].foot_g - hang_off0).head<2>();
  const double closest_m = to_foot.dot(unit);
  EXPECT_GT(closest_m, ray.allowable_offset_m);
  EXPECT_LT(closest_m, band.from_m);
  // The riser itself confirms each stretch: pass / fail / pass / fail.
  const RiserOffsetEvaluator evaluator(p, d[0], {}, SozModel::fe);
  const double step_m = o.march_step_pct_depth * p.site.depth_m / 100.0;
  EXPECT_TRUE(evaluate_along(evaluator, unit, ray.allowable_offset_m, step_m).passes());
  EXPECT_FALSE(evaluate_along(evaluator, unit, closest_m, step_m).passes());
  EXPECT_TRUE(evaluate_along(evaluator, unit, 0.5 * (band.from_m + band.to_m), step_m).passes());
  const auto beyond = evaluate_along(evaluator, unit, band.to_m + 2.0 * kTolerance_m, step_m);
  EXPECT_FALSE(beyond.passes());
  // Closed by the growing span: the top angle, or the flex joint, which sees
  // the riser plane swung ≈ 60° about the foot besides the larger top angle.
  EXPECT_TRUE(beyond.row.governing_criterion == "max_top_angle" ||
              beyond.row.governing_criterion == "flex_joint_rotation")
      << beyond.row.governing_criterion;
}

TEST(Soz, ResultsDoNotDependOnTheThreadCount) {
  const Project p = project(test::soz_riser_yaml("A", 0.0, 20.0) + test::soz_riser_yaml("B", 180.0, 20.0));
  const std::vector<RiserDesign> d = designs(p);
  SozOptions o = options(45.0);
  o.exploit_symmetry = false;  // four tasks, not one half-riser
  o.threads = 1;
  const SozResult one = compute_soz(p, d, {}, o);
  o.threads = 3;
  const SozResult three = compute_soz(p, d, {}, o);
  EXPECT_EQ(one.platform.allowable_offset_m, three.platform.allowable_offset_m);  // bit for bit
  EXPECT_EQ(one.platform.governing_riser, three.platform.governing_riser);
  EXPECT_EQ(one.solves, three.solves);
}

TEST(Soz, RiserFailingAtZeroOffsetHasNoZoneAndNamesTheCriterion) {
  const Project p = project(test::soz_riser_yaml("R", 0.0), std::string("    max_top_tension: 3.0e5\n"));
  const SozResult r = compute_soz(p, designs(p), {}, options(90.0));
  const RiserSoz& z = r.risers[0];
  EXPECT_TRUE(z.fails_at_zero_offset);
  EXPECT_EQ(z.zero_offset_governing_criterion, "max_top_tension");
  EXPECT_GT(z.zero_offset_utilization, 1.0);
  for (const SozDirection& d : z.directions) {
    EXPECT_EQ(d.allowable_offset_m, 0.0);
    EXPECT_EQ(d.governing_criterion, "max_top_tension");
  }
  EXPECT_EQ(r.platform.allowable_offset_m[0], 0.0);
}

TEST(Soz, DirectionStepMustDivide360) {
  const Project p = project(test::soz_riser_yaml("R", 0.0));
  for (const double step : {7.0, 0.0, -5.0}) {
    try {
      compute_soz(p, designs(p), {}, options(step));
      ADD_FAILURE() << "step " << step << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.issues().front().problem, "soz_step_divides_360");
      EXPECT_EQ(e.issues().front().origin, InputOrigin::request);
      EXPECT_EQ(e.issues().front().path, "step_deg");  // the request's argument, not a command-line flag
    }
  }
  EXPECT_NO_THROW(validate_soz_options(p, options(2.5)));
}

TEST(Soz, PolygonInterpolatesBetweenGridDirections) {
  const std::vector<double> dirs{0.0, 90.0, 180.0, 270.0};
  const std::vector<double> a{10.0, 20.0, 30.0, 40.0};
  EXPECT_DOUBLE_EQ(polygon_allowable(dirs, a, 45.0), 15.0);
  EXPECT_DOUBLE_EQ(polygon_allowable(dirs, a, 315.0), 25.0);  // between 270 (40) and 360 (10)
  EXPECT_DOUBLE_EQ(polygon_allowable(dirs, a, -90.0), 40.0);
}

}  // namespace
}  // namespace spiral::design
