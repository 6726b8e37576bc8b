// `spiral lines` (design/analysis/motion_lines.hpp) against MoorDyn-C, an
// independent lumped-mass line model (Hall & Goupee 2015), on the same OC4-
// DeepCwind mooring under the same prescribed surge: 5 m at 100 s + 1 m at
// 10 s for 600 s (tests/data/motion/oc4-two-tone-surge.csv), built up over
// 20 s by the quintic smooth step in both, no waves or current.
//
// The reference is tests/data/validation/moordyn-oc4-surge/ (its README: the
// MoorDyn version and commit, the deck and its edits, the driver, the time
// step, the segment count and the convergence checked). The project is edited
// to the deck where the two models have the same knob: no seabed friction
// (the deck has none; the scenario's 1.0 is MAP's static CB) and the deck's
// seabed stiffness kBot 3e6 Pa/m (the scenario: 1e5). Everything else —
// 835.35 m of chain, d 0.0766 m, 113.35 kg/m, EA 7.536e8 N, Cd 2.0 / CdAx 0.4
// / Ca 0.8 / CaAx 0.25, fairleads at 40.868 m and z −14 m, anchors at
// 837.6 m, g 9.80665, ρ 1025 — is already the deck's. What stays different
// is listed in the README and docs/lines.md ("Against MoorDyn").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "design/analysis/motion_lines.hpp"
#include "design/import/motion_history.hpp"
#include "design/project/validated_project.hpp"
#include "engine/numerics/statistics.hpp"
#include "support/numeric_csv.hpp"

namespace spiral::design {
namespace {

const std::string kOc4 = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml";
const std::string kMotion = std::string(SPIRAL_TEST_DATA_DIR) + "/motion/oc4-two-tone-surge.csv";
const std::string kMoorDyn =
    std::string(SPIRAL_TEST_DATA_DIR) + "/validation/moordyn-oc4-surge/moordyn_oc4_two_tone_surge.csv";

struct MoorDynRecord {
  std::vector<double> time_s;
  std::vector<std::vector<double>> fairlead_tension_N;  ///< L1..L3: the line's force on its coupled point
  std::vector<std::vector<double>> anchor_tension_N;    ///< L1..L3: the bottom segment's tension
};

MoorDynRecord read_moordyn() {
  const test::NumericCsv table = test::read_numeric_csv(kMoorDyn);
  // Columns: time, surge, fairlead L1..L3, top segment L1..L3, anchor L1..L3.
  EXPECT_EQ(table.header,
            "time_s,surge_m,fairlead_tension_L1_N,fairlead_tension_L2_N,fairlead_tension_L3_N,"
            "top_segment_tension_L1_N,top_segment_tension_L2_N,top_segment_tension_L3_N,"
            "anchor_tension_L1_N,anchor_tension_L2_N,anchor_tension_L3_N")
      << "CSV layout changed";
  MoorDynRecord r;
  r.fairlead_tension_N.resize(3);
  r.anchor_tension_N.resize(3);
  for (const std::vector<double>& v : table.rows) {
    EXPECT_EQ(v.size(), 11u);
    if (v.size() != 11u) continue;
    r.time_s.push_back(v[0]);
    for (std::size_t l = 0; l < 3; ++l) {
      r.fairlead_tension_N[l].push_back(v[2 + l]);
      r.anchor_tension_N[l].push_back(v[8 + l]);
    }
  }
  return r;
}

std::vector<double> from(const std::vector<double>& t, const std::vector<double>& x, double t0_s) {
  std::vector<double> out;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (t[k] >= t0_s - 1e-9) out.push_back(x[k]);
  return out;
}

TEST(MotionLinesMoorDyn, Oc4ChainsUnderTwoToneSurgeMatchMoorDyn) {
  Project project = load_validated_project(kOc4).project;
  project.site.seabed.friction_axial = 0.0;  // the deck: no friction (MoorDyn-C's default)
  project.site.seabed.friction_lateral = 0.0;
  project.site.seabed.normal_stiffness_Pa_per_m = 3.0e6;  // the deck's kbot
  const ValidatedProject aligned = validate_loaded_project(project);

  const MotionHistory history = read_motion_history(kMotion);
  MotionLinesRequest request;
  request.load_case = "intact-still-water";
  request.motion_times_s = history.time_s;
  request.motion = history.offset;
  request.output_step_s = 0.5;
  request.ramp_s = 20.0;
  request.waves_on_lines = false;
  const MotionLinesResult spiral = run_motion_lines(aligned, request);

  const MoorDynRecord moordyn = read_moordyn();
  ASSERT_EQ(spiral.lines.size(), 3u);
  ASSERT_EQ(moordyn.time_s.size(), spiral.times_s.size());
  for (std::size_t k = 0; k < spiral.times_s.size(); ++k) ASSERT_NEAR(moordyn.time_s[k], spiral.times_s[k], 1e-6);

  for (std::size_t l = 0; l < 3; ++l) {
    const auto& sp = spiral.lines[l].fairlead_tension_N;
    const auto& md = moordyn.fairlead_tension_N[l];
    const double t0_s = spiral.statistics_from_s;  // the end of the 20 s build-up
    const auto a = engine::channel_moments(from(spiral.times_s, sp, t0_s));
    const auto b = engine::channel_moments(from(moordyn.time_s, md, t0_s));
    // Largest difference at one time over the window, relative to the mean:
    // the two histories in phase, not only their statistics.
    double worst = 0.0;
    for (std::size_t k = 0; k < sp.size(); ++k)
      if (spiral.times_s[k] >= t0_s) worst = std::max(worst, std::abs(sp[k] - md[k]) / b.mean);
    const auto anchor_a = engine::channel_moments(from(spiral.times_s, spiral.lines[l].anchor_tension_N, t0_s));
    const auto anchor_b = engine::channel_moments(from(moordyn.time_s, moordyn.anchor_tension_N[l], t0_s));
    std::printf(
        "%s: spiral/MoorDyn - 1: mean %+.3e std %+.3e max %+.3e min %+.3e; worst at one time %.3e; "
        "anchor mean %+.3e max %+.3e\n",
        spiral.lines[l].name.c_str(), a.mean / b.mean - 1.0, a.std_dev / b.std_dev - 1.0, a.maximum / b.maximum - 1.0,
        a.minimum / b.minimum - 1.0, worst, anchor_a.mean / anchor_b.mean - 1.0,
        anchor_a.maximum / anchor_b.maximum - 1.0);
    // Measured on 2026-12-02 (docs/lines.md, "Against MoorDyn"; L1 = L3, L2):
    // mean +0.008 %, +0.004 %; std +0.13 %, +0.15 %; max +0.03 %, +0.05 %;
    // min −0.13 %, −0.09 %; worst single time 0.31 %, 0.36 % of the mean;
    // anchor mean +0.004 %, +0.002 %, max −0.04 %, +0.02 %.
    // The bounds are the two models' own uncertainties plus what is not
    // aligned, not the measured values widened:
    //  - mean 3e-4: MoorDyn's N = 40 → 80 segments change of the mean
    //    (+0.015…+0.017 %, first order in 1/N, so about as much is left at 80)
    //    plus spiral's mesh/tolerance error on the mean (0.003 %,
    //    motion_lines_validation_test), with the margin of that test's own bound;
    //  - std 4e-3: spiral's 0.19 % (shipped mesh and tolerances against a fine
    //    tight reference) and what is not aligned in the dynamic part — MoorDyn's
    //    critical axial damping per segment (BA = −1) and explicit RK2 against
    //    spiral's undamped line under BDF2, lumped against consistent mass;
    //  - max and min 3e-3: the 0.3 % spiral's tolerances are chosen for on the
    //    extremes (fe_line_dynamics.hpp); MoorDyn's N = 40 → 80 change of the
    //    extremes is 0.03…0.18 %;
    //  - a single time 1e-2: the extremes' 0.3 % and a small phase difference
    //    between the two lines' responses (a 1° lag of a harmonic of amplitude
    //    A differs from it by up to 1.7 % of A).
    EXPECT_NEAR(a.mean / b.mean, 1.0, 3e-4) << spiral.lines[l].name;
    EXPECT_NEAR(a.std_dev / b.std_dev, 1.0, 4e-3) << spiral.lines[l].name;
    EXPECT_NEAR(a.maximum / b.maximum, 1.0, 3e-3) << spiral.lines[l].name;
    EXPECT_NEAR(a.minimum / b.minimum, 1.0, 3e-3) << spiral.lines[l].name;
    EXPECT_LT(worst, 1e-2) << spiral.lines[l].name;
    EXPECT_NEAR(anchor_a.mean / anchor_b.mean, 1.0, 3e-4) << spiral.lines[l].name;
    EXPECT_NEAR(anchor_a.maximum / anchor_b.maximum, 1.0, 3e-3) << spiral.lines[l].name;
  }
}

}  // namespace
}  // namespace spiral::design
