// End-to-end runs of `spiral equilibrium` and `spiral stiffness`.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"

namespace spiral::test {
namespace {

// The OC4 definition report's stiffness (Robertson et al. 2014, Eq. 5-15), ±1 %:
// three significant figures and the report's own catenary model.
constexpr double kReportTolerance = 0.01;
// Analytic tangent vs central differences (see tests/validation/line_array_stiffness_test.cpp).
constexpr double kFiniteDifferenceCheck = 1e-6;

TEST(CliStaticCase, StiffnessJsonOfOc4StillWater) {
  const auto result = run_spiral("stiffness --json " + scenario("oc4-semisubmersible.yaml"));
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  const auto doc = nlohmann::json::parse(result.out);
  EXPECT_EQ(doc["format"], "spiral.static_case");
  EXPECT_EQ(doc["case"], "still-water");
  ASSERT_EQ(doc["stiffness_6x6"].size(), 6u);
  for (const auto& row : doc["stiffness_6x6"]) ASSERT_EQ(row.size(), 6u);
  const auto k = [&](int i, int j) { return doc["stiffness_6x6"][i][j].get<double>(); };
  EXPECT_NEAR(k(0, 0), 7.08e4, kReportTolerance * 7.08e4);
  EXPECT_NEAR(k(2, 2), 1.91e4, kReportTolerance * 1.91e4);
  EXPECT_NEAR(k(4, 4), 8.73e7, kReportTolerance * 8.73e7);
  EXPECT_LT(doc["stiffness_check_relative_difference"].get<double>(), kFiniteDifferenceCheck);
  ASSERT_EQ(doc["force_6dof"].size(), 6u);
  ASSERT_EQ(doc["offset_6dof"].size(), 6u);
  EXPECT_LT(doc["force_6dof"][2].get<double>(), 0.0);
  EXPECT_EQ(doc["lines"].size(), 3u);
  EXPECT_EQ(doc["lines"][0]["stiffness_6x6"].size(), 6u);
  EXPECT_EQ(doc["natural_modes"].size(), 6u);
}

TEST(CliStaticCase, EquilibriumTableOfALoadCase) {
  const auto result =
      run_spiral("equilibrium " + scenario("deepwater-fps.yaml") + " --case lc2-survival-collinear-45deg");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.out.find("Offset:"), std::string::npos);
  EXPECT_NE(result.out.find("L16"), std::string::npos);
}

TEST(CliStaticCase, DamagedCaseMovesFurther) {
  const auto intact = run_spiral("equilibrium --json " + scenario("deepwater-fps.yaml") +
                                 " --case lc2-survival-collinear-45deg");
  const auto damaged = run_spiral("equilibrium --json " + scenario("deepwater-fps.yaml") +
                                  " --case lc2-survival-collinear-45deg --damaged L10");
  ASSERT_EQ(intact.exit_code, app::kExitOk) << intact.err;
  ASSERT_EQ(damaged.exit_code, app::kExitOk) << damaged.err;
  const auto a = nlohmann::json::parse(intact.out);
  const auto b = nlohmann::json::parse(damaged.out);
  EXPECT_EQ(b["condition"], "damaged");
  EXPECT_EQ(b["lines"].size(), a["lines"].size() - 1);
  EXPECT_GT(b["offset"]["horizontal_m"].get<double>(), a["offset"]["horizontal_m"].get<double>());
}

TEST(CliStaticCase, UnknownDamagedLineIsBadInput) {
  const auto result = run_spiral("equilibrium " + scenario("oc4-semisubmersible.yaml") + " --damaged L9");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("--damaged"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("L9"), std::string::npos) << result.err;
}

TEST(CliStaticCase, UnknownCaseIsBadInput) {
  const auto result = run_spiral("stiffness " + scenario("oc4-semisubmersible.yaml") + " --case nope");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("--case"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace spiral::test
