// Writing payouts back into the project text: only the top segment lengths
// change, everything the user wrote (comments, flow style, other numbers)
// stays, and the result loads again with the new lengths.

#include "design/project/project_edit.hpp"

#include <gtest/gtest.h>

#include "design/project/project_loader.hpp"
#include "tests/support/project_fixture.hpp"

namespace spiral::design {
namespace {

TEST(ProjectEdit, PayoutChangesOnlyTheTopSegmentLength) {
  const std::string text = replace(kMinimal, "        - {type: c, length: 550.0}",
                                   "        - {type: c, length: 300.0}   # bottom\n"
                                   "        - {type: c, length: 250.0}   # top, at the fairlead");
  const Project before = parse_project(text, "minimal.yaml");
  const std::string edited = with_line_payouts(text, before, {{"L1", -2.5}}, "made by a test\n\nsecond line");
  EXPECT_EQ(edited.rfind("# made by a test\n#\n# second line\n", 0), 0u) << edited.substr(0, 80);
  EXPECT_NE(edited.find("{type: c, length: 247.5000}   # top, at the fairlead"), std::string::npos) << edited;
  EXPECT_NE(edited.find("{type: c, length: 300.0}   # bottom"), std::string::npos);
  const Project after = parse_project(edited, "minimal.yaml");
  ASSERT_EQ(after.mooring.lines[0].segments.size(), 2u);
  EXPECT_DOUBLE_EQ(after.mooring.lines[0].segments[1].length_m, 247.5);
  EXPECT_DOUBLE_EQ(after.mooring.lines[0].segments[0].length_m, 300.0);
}

TEST(ProjectEdit, BlockStyleLengthIsReplacedInPlace) {
  const std::string text =
      replace(kMinimal, "        - {type: c, length: 550.0}", "        - type: c\n          length: 550.0 # m\n");
  const Project before = parse_project(text, "minimal.yaml");
  const std::string edited = with_line_payouts(text, before, {{"L1", 1.25}}, "");
  EXPECT_NE(edited.find("          length: 551.2500 # m"), std::string::npos) << edited;
}

TEST(ProjectEdit, UnknownLineIsRefused) {
  const Project before = parse_project(kMinimal, "minimal.yaml");
  EXPECT_THROW(with_line_payouts(kMinimal, before, {{"L9", 1.0}}, ""), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::design
