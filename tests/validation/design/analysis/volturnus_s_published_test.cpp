// The shipped VolturnUS-S scenario (scenarios/iea15-volturnus-s.yaml: the
// public OpenFAST model of the IEA 15 MW turbine on the UMaine VolturnUS-S,
// ElastoDyn masses combined into one rigid body) against the published
// definition report, Allen et al. 2020, "Definition of the UMaine
// VolturnUS-S Reference Platform Developed for the IEA Wind 15-Megawatt
// Offshore Reference Wind Turbine", NREL/TP-5000-76773:
//
//  - the mooring system table: fairlead pretension and the line's angle at
//    the fairlead, at the undisplaced position;
//  - the rigid-body natural frequencies of the full moored system (surge,
//    sway, heave, roll, pitch, yaw), which `spiral stiffness` gives as the
//    undamped modes of M + A(omega_LF) against hydrostatics + lines at the
//    still-water equilibrium.
//
// STATUS OF THE PUBLISHED NUMBERS: U (recalled). The report's text was not
// available to the session that wrote this test (no copy in the repository,
// none found by search); the numbers below are recalled from its mooring
// table and its natural-frequency table. The recalled natural periods one
// usually quotes (142.9, 20.4, 27.8, 90.9 s) are exactly 1/f of the report's
// frequencies printed to 0.001 Hz, so the comparison is made in Hz, with the
// rounding of the printed value as part of the tolerance. Confirm against the
// report and change U to S with the table numbers.
//
// Also checked here, from the repository's own copies: the hydrostatics take
// the .hst as buoyancy-only (the WAMIT run put the CoG at the origin) and add
// the gravity terms of the scenario's mass; the mass is the sum of the
// ElastoDyn parts the scenario documents.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "design/analysis/static_case.hpp"
#include "design/analysis/statics_study.hpp"
#include "design/model/hull_model.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/validated_project.hpp"
#include "engine/hull/wamit_hst.hpp"

namespace spiral::design {
namespace {

const std::string kScenario = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/iea15-volturnus-s.yaml";

// Mooring table of the report (U, recalled): fairlead pretension 2,437 kN,
// fairlead angle from the still-water line 56.4 deg. spiral solves the same
// deck (3 x 850 m, 685 kg/m, d 0.333 m, EA 3.27e9 N) as a frictionless
// elastic catenary; the report's value is MoorDyn's (lumped mass, 50
// segments, a 3e6 Pa/m elastic seabed the chain sinks into by ~2 mm).
// 0.5 %: the report's four printed digits (+-0.02 %) and the lumped-mass
// discretisation and seabed penetration (of order 0.1 % on a catenary with
// 500 m on the bottom); the angle to its printed 0.1 deg plus the same.
constexpr double kPublishedPretensionN = 2.437e6;
constexpr double kPretensionRelTol = 0.005;
constexpr double kPublishedFairleadAngleDeg = 56.4;
constexpr double kFairleadAngleTolDeg = 0.15;

// Natural-frequency table of the report (U, recalled), Hz, printed to 0.001.
struct PublishedMode {
  const char* dof;
  double frequency_hz;
};
constexpr PublishedMode kPublishedModes[] = {
    {"surge", 0.007}, {"sway", 0.007}, {"heave", 0.049}, {"roll", 0.036}, {"pitch", 0.036}, {"yaw", 0.011},
};
// Tolerance = half a unit of the printed digit (0.0005 Hz: for surge and
// sway that alone is +-7 %, 133...154 s) + 3 % of the frequency for what
// differs physically between the report's OpenFAST free decays and spiral's
// linear modes: the decays are nonlinear in amplitude (catenary stiffness,
// quadratic drag: a damped period) with flexible tower and blades and
// frequency-dependent radiation, where spiral takes A at the file's lowest
// frequency (0.05 rad/s) for every mode; and the report's model had a
// different mass (20,093 t) from the one published in OpenFAST now
// (20,252 t: a 0.4 % frequency effect). Not tuned to spiral's results, which
// the test prints (surge +5.6 %, pitch -1.5 %, yaw +2.5 %, heave +0.2 %).
constexpr double kFrequencyRoundingHz = 0.0005;
constexpr double kFrequencyPhysicalRelTol = 0.03;

TEST(VolturnUsSPublished, FairleadPretensionAndAngleAtRest) {
  const ValidatedProject p = load_validated_project(kScenario);
  LineArrayModel model = build_mooring_model(p.project);
  const StaticsResult rest = run_statics(model, engine::Vector6d::Zero());
  ASSERT_EQ(rest.lines.size(), 3u);
  for (const LineStaticsRow& line : rest.lines) {
    SCOPED_TRACE(line.name);
    EXPECT_NEAR(line.fairlead_tension_N, kPublishedPretensionN, kPretensionRelTol * kPublishedPretensionN);
    EXPECT_NEAR(line.fairlead_angle_deg, kPublishedFairleadAngleDeg, kFairleadAngleTolDeg);
  }
  const LineStaticsRow& l1 = rest.lines.front();
  std::cout << "[ VolturnUS-S ] fairlead T " << l1.fairlead_tension_N / 1e3 << " kN (report 2437 kN, "
            << 100.0 * (l1.fairlead_tension_N / kPublishedPretensionN - 1.0) << " %), angle " << l1.fairlead_angle_deg
            << " deg (report 56.4), H " << l1.fairlead_horizontal_N / 1e3 << " kN, laid " << l1.laid_length_m << " m\n";
}

TEST(VolturnUsSPublished, NaturalFrequenciesOfTheMooredSystem) {
  const ValidatedProject p = load_validated_project(kScenario);
  const StaticCaseResult still = run_static_case(p, {"intact-still-water", std::nullopt, false});
  ASSERT_TRUE(still.added_mass_included);
  ASSERT_EQ(still.natural_modes.size(), 6u);
  for (const PublishedMode& published : kPublishedModes) {
    SCOPED_TRACE(published.dof);
    int found = 0;
    double period_s = 0.0;
    for (const NaturalMode& m : still.natural_modes) {
      if (m.dominant_dof == published.dof) {
        ++found;
        period_s = m.period_s;
      }
    }
    ASSERT_EQ(found, 1) << "one mode dominated by " << published.dof;
    const double f_hz = 1.0 / period_s;
    EXPECT_NEAR(f_hz, published.frequency_hz, kFrequencyRoundingHz + kFrequencyPhysicalRelTol * published.frequency_hz);
    std::cout << "[ VolturnUS-S ] " << published.dof << ": " << period_s << " s = " << f_hz << " Hz; report "
              << published.frequency_hz << " Hz (" << 100.0 * (f_hz / published.frequency_hz - 1.0) << " %)\n";
  }
}

TEST(VolturnUsSPublished, HydrostaticsAddTheGravityTermsTheHstLeavesOut) {
  const ValidatedProject p = load_validated_project(kScenario);
  const Project& project = p.project;
  const HullModel hull = build_hull_model(project);
  const engine::Seawater water{project.site.water_density_kg_per_m3, project.site.gravity_m_per_s2};
  const auto hst = engine::read_wamit_hst(*project.hull.hydrostatics_file, {1.0, water});
  const double rho_g = 1025.0 * 9.80665;
  // The file as written (WAMIT .hst, non-dimensional): C33 443.0486, C44 218,240.5, C55 218,216.6.
  EXPECT_NEAR(hst.restoring_6x6(2, 2), 443.0486 * rho_g, 1e-6 * 443.0486 * rho_g);
  EXPECT_NEAR(hst.restoring_6x6(4, 4), 2.182166e5 * rho_g, 1e-6 * 2.182166e5 * rho_g);
  // spiral's total = the file + the gravity part of the scenario's mass and
  // CoG: -m g z_g on roll and pitch, m g x_g on roll-yaw C46 (WAMIT §3.1).
  const double m = project.hull.mass_kg, g = project.site.gravity_m_per_s2;
  const Eigen::Vector3d& cg = project.hull.center_of_gravity_b;
  const engine::Matrix6d& total = hull.restoring.total_6x6;
  EXPECT_NEAR(total(3, 3), hst.restoring_6x6(3, 3) - m * g * cg.z(), 1e-9 * total(3, 3));
  EXPECT_NEAR(total(4, 4), hst.restoring_6x6(4, 4) - m * g * cg.z(), 1e-9 * total(4, 4));
  EXPECT_NEAR(total(3, 5), hst.restoring_6x6(3, 5) + m * g * cg.x(), 1e-6 * std::abs(m * g * cg.x()));
  EXPECT_NEAR(total(2, 2), hst.restoring_6x6(2, 2), 1e-12 * total(2, 2));  // no gravity term in heave
  // The CoG is above the keel but 1.5 m below the water: the gravity part
  // adds ~14 % to the buoyancy-only pitch restoring (2.19e9 -> 2.49e9 N m/rad).
  EXPECT_GT(total(4, 4), 1.1 * hst.restoring_6x6(4, 4));
}

TEST(VolturnUsSPublished, MassIsTheSumOfTheElastoDynParts) {
  const ValidatedProject p = load_validated_project(kScenario);
  // ElastoDyn (the scenario's comments): PtfmMass 1.7838e7 kg; the tower's
  // TMassDen integrated, 1,466,657 kg; the RNA, 69,131 + 644,857 + 28,249 +
  // 3 x 68,516 kg (blades integrated) = 947,785 kg.
  const double platform = 1.7838e7, tower = 1.466657e6, rna = 69131.0 + 644857.0 + 28249.0 + 3.0 * 68516.0;
  EXPECT_NEAR(p.project.hull.mass_kg, platform + tower + rna, 50.0);  // the scenario's 6 digits
  // The CoG: mass-weighted, platform at z -14.4, tower at 58.19, RNA at
  // (-6.974, 148.949).
  const double zg = (platform * -14.4 + tower * 58.187 + rna * 148.949) / (platform + tower + rna);
  const double xg = rna * -6.974 / (platform + tower + rna);
  EXPECT_NEAR(p.project.hull.center_of_gravity_b.z(), zg, 1e-3);
  EXPECT_NEAR(p.project.hull.center_of_gravity_b.x(), xg, 1e-3);
}

}  // namespace
}  // namespace spiral::design
