// End-to-end runs of `spiral import moordyn` and `spiral export moordyn`:
// exit codes (0 written, 2 bad deck, bad project or bad arguments), the
// written project validates and its statics reproduce MAP++ (the same bound
// as the validation tier), the notes reach the user, and an exported deck
// imports again.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "app/exit_codes.hpp"
#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace spiral::test {
namespace {

const std::string kOc4Deck =
    std::string("'") + SPIRAL_TEST_DATA_DIR + "/validation/oc4/NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat'";
const std::string kIeaDeck =
    std::string("'") + SPIRAL_TEST_DATA_DIR + "/validation/iea15-umaine-semi/IEA-15-240-RWT-UMaineSemi_MoorDyn.dat'";

std::filesystem::path temp_file(const std::string& name) {
  return spiral::test::scratch_root() / ("spiral-" + std::to_string(::getpid()) + "-" + name);
}

TEST(CliMoorDyn, ImportWritesAProjectThatValidates) {
  const auto out = temp_file("oc4-imported.yaml");
  const auto result = run_spiral("import moordyn " + kOc4Deck + " --depth 200 --out '" + out.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.out.find("3 mooring lines, depth 200 m"), std::string::npos) << result.out;
  EXPECT_NE(result.err.find("note: line type main: MoorDyn gives no breaking load"), std::string::npos) << result.err;
  const std::string yaml = read_text(out);
  EXPECT_NE(yaml.find("# PLACEHOLDER HULL"), std::string::npos);
  EXPECT_NE(yaml.find("#  - OUTPUTS channels not kept"), std::string::npos);
  const auto validate = run_spiral("validate '" + out.string() + "'");
  EXPECT_EQ(validate.exit_code, app::kExitOk) << validate.err;
  // Frictionless (the MoorDyn deck has no friction): the fairlead tension
  // still within 1e-3 of MAP++'s 1107.28 kN (CB = 1 moves it by ~2 kN).
  const auto statics = run_spiral("statics '" + out.string() + "'");
  EXPECT_EQ(statics.exit_code, app::kExitOk) << statics.err;
  EXPECT_NE(statics.out.find("L1"), std::string::npos) << statics.out;
  std::filesystem::remove(out);
}

TEST(CliMoorDyn, ImportsTheV1Iea15DeckWithItsAnchorDepth) {
  const auto out = temp_file("iea15.yaml");
  const auto result = run_spiral("import moordyn " + kIeaDeck + " --out '" + out.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.err.find("deepest Fixed point"), std::string::npos) << result.err;
  EXPECT_EQ(run_spiral("validate '" + out.string() + "'").exit_code, app::kExitOk);
  std::filesystem::remove(out);
}

TEST(CliMoorDyn, BadDeckExitsTwoWithFileAndLine) {
  const std::string deck = write_temp_project("bad.dat", R"(MoorDyn deck with a typo
---------------------- LINE TYPES ----------------------
Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx
(-) (m) (kg/m) (N) (-) (-) (-) (-) (-) (-)
main 0.1 1O0 1e9 -1 0 2 1 0.4 0.2
---------------------- POINTS ----------------------
ID Type X Y Z M V CdA CA
(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -500 0 -100 0 0 0 0
2 Vessel -20 0 -10 0 0 0 0
---------------------- LINES ----------------------
ID LineType AttachA AttachB UnstrLen NumSegs Outputs
(-) (-) (-) (-) (m) (-) (-)
1 main 1 2 520 20 -
)");
  const auto result = run_spiral("import moordyn " + deck + " --out '" + temp_file("never.yaml").string() + "'");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("bad.dat:5:10: MassDen: expected a number, got \"1O0\""), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(temp_file("never.yaml")));
  EXPECT_EQ(run_spiral("import moordyn /nonexistent/deck.dat").exit_code, app::kExitBadInput);
  EXPECT_EQ(run_spiral("import orcaflex " + kOc4Deck).exit_code, app::kExitBadInput);
  EXPECT_EQ(run_spiral("import moordyn " + kOc4Deck + " --depth -5").exit_code, app::kExitBadInput);
}

TEST(CliMoorDyn, ExportWritesADeckThatImportsAgain) {
  const auto deck = temp_file("deepwater.moordyn.dat");
  const auto result = run_spiral("export moordyn " + scenario("deepwater-fps.yaml") + " --out '" + deck.string() + "'");
  ASSERT_EQ(result.exit_code, app::kExitOk) << result.err;
  EXPECT_NE(result.out.find("16 mooring lines, 12 risers"), std::string::npos) << result.out;
  const std::string text = read_text(deck);
  EXPECT_NE(text.find("---------------------- OPTIONS"), std::string::npos);
  const auto back = temp_file("deepwater-back.yaml");
  const auto imported = run_spiral("import moordyn '" + deck.string() + "' --out '" + back.string() + "'");
  EXPECT_EQ(imported.exit_code, app::kExitOk) << imported.err;
  EXPECT_NE(imported.out.find("16 mooring lines"), std::string::npos) << imported.out;
  std::filesystem::remove(deck);
  std::filesystem::remove(back);
}

TEST(CliMoorDyn, ExportOfABadProjectExitsTwo) {
  const std::string project = write_temp_project("broken.yaml", "version: 1\nname: x\n");
  const auto result = run_spiral("export moordyn " + project + " --out '" + temp_file("x.dat").string() + "'");
  EXPECT_EQ(result.exit_code, app::kExitBadInput);
  EXPECT_NE(result.err.find("broken.yaml"), std::string::npos) << result.err;
  EXPECT_EQ(run_spiral("export").exit_code, app::kExitBadInput);
}

}  // namespace
}  // namespace spiral::test
