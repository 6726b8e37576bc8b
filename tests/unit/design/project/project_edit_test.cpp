// Writing payouts back into the project text: only the top segment lengths
// change, everything the user wrote (comments, flow style, other numbers)
// stays, and the result loads again with the new lengths. The same for a
// project edited in memory (edited_project_text, the Python API's save):
// lengths read back as the same double, file references follow the file to
// its new folder, and an edit the text cannot take in place is refused.

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

TEST(ProjectEdit, EditedLengthReadsBackAsTheSameDouble) {
  const Project before = parse_project(kMinimal, "minimal.yaml");
  Project edited = before;
  edited.mooring.lines[0].segments[0].length_m += 0.1;  // 550.1000000000000227..., printed 550.1
  edited.mooring.lines[0].segments[0].type = "c";       // as it was: not written
  const std::string text = edited_project_text(kMinimal, before, edited, "minimal.yaml");
  EXPECT_EQ(text, replace(kMinimal, "length: 550.0}", "length: 550.1}"));
  EXPECT_EQ(parse_project(text, "minimal.yaml").mooring.lines[0].segments[0].length_m,
            edited.mooring.lines[0].segments[0].length_m);
}

TEST(ProjectEdit, RelativeFileReferenceFollowsTheFileToAnotherFolder) {
  const std::string text = replace(kMinimal, "  waterplane_inertia: [1.0e5, 1.0e5]\n",
                                   "  waterplane_inertia: [1.0e5, 1.0e5]\n  hydrostatics_file: hydro/hull.hst  # m\n");
  const Project before = parse_project(text, "/projects/a/minimal.yaml");
  const std::string moved = edited_project_text(text, before, before, "/projects/b/copy.yaml");
  EXPECT_NE(moved.find("  hydrostatics_file: ../a/hydro/hull.hst  # m\n"), std::string::npos) << moved;
  EXPECT_EQ(edited_project_text(text, before, before, "/projects/a/copy.yaml"), text);
}

TEST(ProjectEdit, ValueSharedThroughAnAnchorIsRefused) {
  const std::string second_line =
      "    - {name: L2, anchor: {radius: 500.0, azimuth_deg: 90.0}, fairlead: [0.0, 10.0, -10.0], segments: [*top]}\n";
  const std::string text = replace(kMinimal, "        - {type: c, length: 550.0}\n",
                                   "        - &top {type: c, length: 550.0}\n" + second_line);
  const Project before = parse_project(text, "minimal.yaml");
  ASSERT_EQ(before.mooring.lines.size(), 2u);
  Project edited = before;
  edited.mooring.lines[0].segments[0].length_m = 560.0;
  EXPECT_THROW(edited_project_text(text, before, edited, "minimal.yaml"), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::design
