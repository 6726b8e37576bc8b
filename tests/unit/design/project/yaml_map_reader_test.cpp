// The strict YAML map reader of the project loader on its own: typed keys
// with their positions, unknown and duplicate keys, missing required keys,
// degrees to radians and the two forms of a position. (The loader tests cover
// every section's mapping through parse_project.)

#include "design/project/yaml_map_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace spiral::design::loader_detail {
namespace {

constexpr double kTol = 1e-12;

TEST(YamlMapReader, ReadsTypedKeysAndRecordsTheirPositions) {
  const YAML::Node node = YAML::Load("depth: 1800\nname: deep\nheading_deg: 90\n");
  Context ctx{"test.yaml", {}, {}};
  {
    MapReader r(ctx, node, "site");
    EXPECT_EQ(r.number("depth", "m", kRequired), 1800.0);
    EXPECT_EQ(r.text("name", kRequired), "deep");
    EXPECT_NEAR(*r.angle("heading", kRequired), std::numbers::pi / 2, kTol);
    EXPECT_FALSE(r.number("gravity", "m/s^2", kOptional).has_value());
  }
  EXPECT_TRUE(ctx.issues.empty());
  ASSERT_TRUE(ctx.positions.count("site.name"));
  EXPECT_EQ(ctx.positions.at("site.name").line, 2);
  EXPECT_EQ(ctx.positions.at("site.name").column, 7);
}

TEST(YamlMapReader, ReportsUnknownKeysWithASuggestionWhenItGoesOutOfScope) {
  const YAML::Node node = YAML::Load("depht: 1800\n");
  Context ctx{"test.yaml", {}, {}};
  {
    MapReader r(ctx, node, "site");
    r.number("depth", "m", kOptional);
    EXPECT_TRUE(ctx.issues.empty());
  }
  ASSERT_EQ(ctx.issues.size(), 1u);
  EXPECT_EQ(ctx.issues[0].problem, "unknown_key");
  EXPECT_EQ(ctx.issues[0].path, "site.depht");
  EXPECT_EQ(ctx.issues[0].message, "unknown key \"depht\" (did you mean \"depth\"?)");
  EXPECT_EQ(ctx.issues[0].line, 1);
  EXPECT_EQ(ctx.issues[0].column, 1);
}

TEST(YamlMapReader, ReportsDuplicateAndMissingKeysAndWrongTypes) {
  const YAML::Node node = YAML::Load("a: 1\na: 2\nb: \"3\"\n");
  Context ctx{"test.yaml", {}, {}};
  {
    MapReader r(ctx, node, "");
    r.number("a", "m", kRequired);
    EXPECT_FALSE(r.number("b", "m", kRequired).has_value());  // a quoted number is text
    EXPECT_FALSE(r.number("c", "m", kRequired).has_value());
  }
  ASSERT_EQ(ctx.issues.size(), 3u);
  EXPECT_EQ(ctx.issues[0].problem, "duplicate_key");
  EXPECT_EQ(ctx.issues[0].path, "a");
  EXPECT_EQ(ctx.issues[1].problem, "wrong_type");
  EXPECT_EQ(ctx.issues[1].message, "expected a finite number in m, got \"3\"");
  EXPECT_EQ(ctx.issues[2].problem, "missing_key");
  EXPECT_EQ(ctx.issues[2].message, "required key is missing (m)");
}

TEST(YamlMapReader, ReadsAPositionInCartesianOrPolarForm) {
  const YAML::Node node = YAML::Load("xyz: [1, 2, -3]\npolar: {radius: 100, azimuth_deg: 90}\n");
  Context ctx{"test.yaml", {}, {}};
  {
    MapReader r(ctx, node, "");
    const auto xyz = r.position("xyz", kRequired);
    ASSERT_TRUE(xyz.has_value());
    EXPECT_EQ(*xyz, Eigen::Vector3d(1.0, 2.0, -3.0));
    const auto polar = r.position("polar", kRequired, -1800.0);  // z defaults to the seabed
    ASSERT_TRUE(polar.has_value());
    EXPECT_NEAR(polar->x(), 0.0, 1e-9);
    EXPECT_NEAR(polar->y(), 100.0, kTol);
    EXPECT_EQ(polar->z(), -1800.0);
  }
  EXPECT_TRUE(ctx.issues.empty());
}

}  // namespace
}  // namespace spiral::design::loader_detail
