// End-to-end riser runs of `spiral equilibrium` and `spiral soz`: flexible
// risers in their documented form (bore, data-sheet EA/EI/mass, no steel wall).

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"
#include "support/soz_project.hpp"

namespace spiral::test {
namespace {

std::string format_sample() { return std::string("'") + SPIRAL_SOURCE_DIR + "/tests/data/format-sample.yaml'"; }

/// A free-hanging 8-inch-class flexible in the 400 m SOZ project: bore 0.2 m,
/// outer sheath 0.3 m, data-sheet EA, EI and mass, oil-filled.
const std::string kFlexible =
    "  - name: F\n    kind: flexible\n    hang_off: {radius: 20.0, azimuth_deg: 0.0, z: -20.0}\n"
    "    azimuth_deg: 0.0\n    top_angle_deg: 12.0\n    sections:\n"
    "      - {length: 700.0, outer_diameter: 0.3, inner_diameter: 0.2, contents_density: 800.0,\n"
    "         axial_stiffness: 5.0e8, bending_stiffness: 5.0e4, mass_per_length: 150.0}\n"
    "    fe: {element_length: 5.0, touchdown_refinement: {length: 60.0, element_length: 1.0}}\n"
    "    criteria: {min_bending_radius: 3.0}\n";

const nlohmann::json& riser_named(const nlohmann::json& risers, const std::string& name) {
  const auto it = std::find_if(risers.begin(), risers.end(), [&](const auto& r) { return r["name"] == name; });
  if (it == risers.end()) throw std::runtime_error("no riser " + name);
  return *it;
}

bool has_check(const nlohmann::json& riser, const std::string& criterion) {
  return std::any_of(riser["checks"].begin(), riser["checks"].end(),
                     [&](const auto& c) { return c["criterion"] == criterion; });
}

// The format sample's flexible F1 (no wall thickness) used to crash every
// riser command with "internal error: pipe.wall_thickness_m" (exit 1).
TEST(CliRiser, EquilibriumOfTheFormatSampleWithItsFlexibleRiser) {
  const auto r = run_spiral("equilibrium --json " + format_sample());
  ASSERT_EQ(r.exit_code, app::kExitOk) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const auto& flexible = riser_named(doc["risers"], "F1");
  EXPECT_EQ(flexible["kind"], "flexible");
  // No steel wall: no von Mises value, the bending radius and tensions are checked.
  EXPECT_TRUE(flexible["max_von_mises_utilization"].is_null());
  EXPECT_FALSE(has_check(flexible, "von_mises"));
  EXPECT_TRUE(has_check(flexible, "min_bending_radius"));
  EXPECT_TRUE(has_check(flexible, "min_effective_tension"));
  EXPECT_GT(flexible["top_tension_N"].get<double>(), 0.0);
  EXPECT_GT(flexible["touchdown_distance_m"].get<double>(), 0.0);
  // The steel SCR beside it keeps its von Mises check.
  const auto& steel = riser_named(doc["risers"], "P1");
  EXPECT_TRUE(has_check(steel, "von_mises"));
  EXPECT_GT(steel["max_von_mises_utilization"].get<double>(), 0.0);
}

// Wall tension at the hang-off from Sparks' identity, written out: the
// arithmetic of the JSON's own numbers, so only round-off remains.
constexpr double kIdentityRelTol = 1e-12;

TEST(CliRiser, EquilibriumJsonHasTheProfileAlongEachRiser) {
  const auto r = run_spiral("equilibrium --json " + format_sample());
  ASSERT_EQ(r.exit_code, app::kExitOk) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["risers"].size(), 2u);
  for (const auto& riser : doc["risers"]) {
    const std::string name = riser["name"];
    const auto& p = riser["profile"];
    const std::size_t n = p["arc_length_m"].size();
    ASSERT_GT(n, 10u) << name;
    for (const char* key : {"position_m", "section", "on_seabed", "effective_tension_N", "wall_tension_N",
                            "bending_moment_N_m", "curvature_per_m", "von_mises_Pa", "von_mises_utilization"}) {
      ASSERT_EQ(p[key].size(), n) << name << " " << key;
    }
    for (std::size_t i = 1; i < n; ++i) {
      EXPECT_GT(p["arc_length_m"][i].get<double>(), p["arc_length_m"][i - 1].get<double>()) << name;
    }
    EXPECT_NEAR(p["position_m"][n - 1][2].get<double>(), -14.0, 1.0) << name;  // the hang-off, hull near rest
    // The key values are the extremes of the profile.
    std::size_t i_min = 0;
    double max_curvature = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p["effective_tension_N"][i].get<double>() < p["effective_tension_N"][i_min].get<double>()) i_min = i;
      max_curvature = std::max(max_curvature, p["curvature_per_m"][i].get<double>());
    }
    EXPECT_EQ(p["effective_tension_N"][i_min].get<double>(), riser["min_effective_tension_N"].get<double>()) << name;
    EXPECT_EQ(p["arc_length_m"][i_min].get<double>(), riser["min_effective_tension_arc_m"].get<double>()) << name;
    EXPECT_EQ(max_curvature, riser["max_curvature_per_m"].get<double>()) << name;
    EXPECT_DOUBLE_EQ(riser["min_bending_radius_m"].get<double>(), 1.0 / max_curvature) << name;
    if (riser["max_von_mises_utilization"].is_null()) {
      for (const auto& u : p["von_mises_utilization"]) EXPECT_TRUE(u.is_null()) << name;
      continue;
    }
    std::size_t i_vm = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p["von_mises_utilization"][i].get<double>() > p["von_mises_utilization"][i_vm].get<double>()) i_vm = i;
    }
    EXPECT_EQ(p["von_mises_utilization"][i_vm].get<double>(), riser["max_von_mises_utilization"].get<double>());
    EXPECT_EQ(p["arc_length_m"][i_vm].get<double>(), riser["max_von_mises_arc_m"].get<double>());
  }
  // P1 (OD 273.1 mm, WT 25.4 mm, 10 MPa gauge at the hang-off, ≈ 14 m down):
  // T_w = T_e + p_i A_i − p_e A_o at its top node.
  const auto& p = riser_named(doc["risers"], "P1")["profile"];
  const std::size_t top = p["arc_length_m"].size() - 1;
  const double pi = std::numbers::pi;
  const double inner_m2 = pi / 4.0 * std::pow(0.2731 - 2.0 * 0.0254, 2);
  const double outer_m2 = pi / 4.0 * 0.2731 * 0.2731;
  const double p_e = 1025.0 * 9.80665 * -p["position_m"][top][2].get<double>();
  const double expected = p["effective_tension_N"][top].get<double>() + 1.0e7 * inner_m2 - p_e * outer_m2;
  EXPECT_NEAR(p["wall_tension_N"][top].get<double>(), expected, kIdentityRelTol * expected);
}

TEST(CliRiser, EquilibriumWithCurrentOnAFlexibleRiser) {
  const std::string file = write_temp_project("riser-flex-eq.yaml", soz_project_yaml(kFlexible));
  const auto r = run_spiral("equilibrium --json " + file + " --case lc2");
  ASSERT_EQ(r.exit_code, app::kExitOk) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["risers"].size(), 1u);
  const auto& flexible = doc["risers"][0];
  EXPECT_TRUE(flexible["max_von_mises_utilization"].is_null());
  EXPECT_GT(flexible["min_effective_tension_N"].get<double>(), 0.0);
  // (The one-line mooring of this project lets the hull drift ≈ 90 m, so the
  // top angle fails; the bending radius is far above the 3 m MBR.)
  EXPECT_GT(flexible["min_bending_radius_m"].get<double>(), 3.0);
  const auto& checks = flexible["checks"];
  const auto mbr =
      std::find_if(checks.begin(), checks.end(), [](const auto& c) { return c["criterion"] == "min_bending_radius"; });
  ASSERT_NE(mbr, checks.end());
  EXPECT_TRUE((*mbr)["passes"].get<bool>());
}

TEST(CliRiser, SozOfAFlexibleRiserWithBothModels) {
  const std::string file = write_temp_project("riser-flex-soz.yaml", soz_project_yaml(kFlexible));
  for (const std::string model : {"catenary", "fe"}) {
    const auto r = run_spiral("soz --json " + file + " --step-deg 90 --no-check --model " + model);
    ASSERT_EQ(r.exit_code, app::kExitOk) << model << ": " << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    ASSERT_EQ(doc["risers"].size(), 1u);
    const auto& zone = doc["risers"][0];
    EXPECT_FALSE(zone["fails_at_zero_offset"].get<bool>()) << model;
    ASSERT_EQ(zone["allowable_offset_m"].size(), 4u) << model;
    for (const auto& criterion : zone["governing_criterion"]) EXPECT_NE(criterion, "von_mises") << model;
    for (const auto& offset : zone["allowable_offset_m"]) EXPECT_GT(offset.get<double>(), 0.0) << model;
  }
}

}  // namespace
}  // namespace spiral::test
