// The comparer must fail on what the regression tier exists to catch: a
// number outside its tolerance, NaN/Inf, a missing or extra key, a type or
// text change; and pass within the tolerance its rule gives.
#include "regression/golden_compare.hpp"

#include <gtest/gtest.h>

namespace spiral::golden {
namespace {

using nlohmann::json;

const std::vector<ToleranceRule> kRules = {
    {"*", "*/wall_s", true, 0.0, 0.0, "wall clock"},
    {"dyn-*", "*/tension_N", false, 1e-6, 0.0, "integrator tolerance"},
    {"*", "*/offset_m", false, 0.0, 1e-3, "closure tolerance"},
};

json baseline() {
  return json::parse(R"({"lines": [{"name": "L1", "tension_N": 1.0e6, "offset_m": 12.5}],
                         "timings": {"wall_s": 0.31}, "count": 4, "verdict": "PASS"})");
}

TEST(GoldenCompare, IdenticalDocumentsMatch) {
  EXPECT_TRUE(compare_documents(baseline(), baseline(), "dyn-a", kRules).empty());
}

TEST(GoldenCompare, IgnoredValuesMayDifferButMustExist) {
  json a = baseline();
  a["timings"]["wall_s"] = 99.0;
  EXPECT_TRUE(compare_documents(a, baseline(), "dyn-a", kRules).empty());
  a["timings"].erase("wall_s");
  const auto d = compare_documents(a, baseline(), "dyn-a", kRules);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].path, "/timings/wall_s");
}

TEST(GoldenCompare, NumbersWithinTheirRuleMatchAndOutsideFail) {
  json a = baseline();
  a["lines"][0]["tension_N"] = 1.0e6 * (1 + 0.9e-6);
  a["lines"][0]["offset_m"] = 12.5 + 0.9e-3;
  EXPECT_TRUE(compare_documents(a, baseline(), "dyn-a", kRules).empty());
  a["lines"][0]["tension_N"] = 1.0e6 * (1 + 1.1e-6);
  const auto d = compare_documents(a, baseline(), "dyn-a", kRules);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].path, "/lines/0/tension_N");
  EXPECT_EQ(d[0].why, "integrator tolerance");
}

TEST(GoldenCompare, RulesApplyToTheirRunsOnly) {
  json a = baseline();
  a["lines"][0]["tension_N"] = 1.0e6 * (1 + 1e-9);
  // "static-a" has no tension rule: exact.
  EXPECT_EQ(compare_documents(a, baseline(), "static-a", kRules).size(), 1u);
}

TEST(GoldenCompare, NanMissingExtraTypeAndTextChangesFail) {
  json a = baseline();
  a["lines"][0]["offset_m"] = nullptr;  // how nlohmann writes NaN and Inf
  a["lines"][0]["extra_N"] = 1.0;
  a.erase("count");
  a["verdict"] = "FAIL";
  a["timings"] = json::array();
  const auto d = compare_documents(a, baseline(), "dyn-a", kRules);
  EXPECT_EQ(d.size(), 5u);
  a = baseline();
  a["lines"].push_back(a["lines"][0]);
  EXPECT_EQ(compare_documents(a, baseline(), "dyn-a", kRules).size(), 1u);
}

TEST(GoldenCompare, NanInsideAnIgnoredValueStillFails) {
  json a = baseline();
  a["timings"]["wall_s"] = nullptr;
  EXPECT_EQ(compare_documents(a, baseline(), "dyn-a", kRules).size(), 1u);
}

}  // namespace
}  // namespace spiral::golden
