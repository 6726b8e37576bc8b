// The MoorDyn deck reader and the import mapping (design/import): every
// section of a v1 (MoorDyn-C 1.x column names, MoorDyn-F) and a v2 deck, the
// real IEA-15 (v1) and OC4 (v2 headers) decks of tests/data/validation, and
// deck errors as `file:line:col: problem`. Values are read exactly (the
// decks' text is the reference), so comparisons are exact.
#include <gtest/gtest.h>

#include <string>

#include "design/import/moordyn_deck.hpp"
#include "design/import/moordyn_import.hpp"
#include "design/project/input_error.hpp"

namespace spiral::design {
namespace {

// A MoorDyn v2 deck (MoorDyn docs, "The V2 Input File"): a bridle-free
// two-segment line with a clump between, a single-segment line, a rod and a
// body that spiral does not read, options with depth and friction.
const std::string kV2 = R"(--------------------- MoorDyn Input File ------------------------------------
Two-line test deck
---------------------- LINE TYPES ----------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI     Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2) (-)   (-)    (-)     (-)
chain      0.1     150.0      1.0e9      -1.0        0      2.4    1.0    1.15    0.5
rope       0.2     30.0       2.0e8|4e8  -0.8        5.0    1.2    0.9    0.008   0.1   ! polyester
---------------------- ROD TYPES ------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
Can           10       1.0e3     0.6    1.0     1.2      1.0
---------------------- RODS ----------------------------------------
ID   RodType  Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs  RodOutputs
(#)  (name)   (word/ID)   (m)   (m)   (m)   (m)   (m)   (m)  (-)       (-)
1    Can      Fixed       0     0     -100  0     0     -90  4         -
---------------------- POINTS --------------------------------------------------
ID  Attachment  X      Y    Z      Mass   Volume  CdA  Ca
(#)  (-)        (m)    (m)  (m)    (kg)   (m^3)   (m^2) (-)
1   Fixed       -800   0    -150   0      0       0    0
2   Free        -400   0    -120   5000   1.0     0    0
3   Coupled     -40    0    -10    0      0       0    0
4   Anchor      800    0    -150   0      0       0    0
5   Vessel      40     0    -10    0      0       0    0
---------------------- LINES ---------------------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)   (#)      (#)      (m)       (-)      (-)
1   chain     1        2        400       40       -
2   rope      2        3        420.5     21       pt
3   chain     5        4        830       83       -
4   chain     R1A      4        10        2        -
---------------------- OPTIONS -------------------------------------------------
0.001    dtM       - time step
150      WtrDpth   - water depth (m)
9.81     g
1025.5   rhoW
3.0e6    kBot
3.0e5    cBot
0.7      mu_kA
0.9      mu_kT
---------------------- OUTPUTS -------------------------------------------------
FairTen1
AnchTen3
END
------------------------- need this line ---------------------------------------
)";

// MoorDyn-C 1.x column names and order (MoorDyn docs, "The V1 Input File").
const std::string kV1 = R"(MoorDyn input file...
MoorDyn v1 sample input file
True          Echo          echo the input file data (flag)
------------------------- LINE DICTIONARY ---------------------------------------------------
LineType  Diam    MassDen    EA       BA/-zeta   Can   Cat   Cdn   Cdt
(-)       (m)     (kg/m)     (N)      (Pa-s/-)   (-)   (-)   (-)   (-)
nylon    0.124    13.76    2515288.0    -0.8     1.0   0.0   1.6   0.05
----------------------- NODE PROPERTIES ----------------------------------------------
Node      Type      X        Y         Z        M        V        FX       FY      FZ     CdA   CA
(-)       (-)      (m)      (m)       (m)      (kg)     (m^3)    (kN)     (kN)    (kN)   (m^2)  (-)
1         Vessel     5.0     0      -10.00       0        0        0        0       0       0     0
2         Fixed    267.0     0      -70.00       0        0        0        0       0       0     0
-------------------------- LINE PROPERTIES -------------------------------------------------
Line     LineType  UnstrLen  NumSegs    NodeAnch  NodeFair  Flags/Outputs
(-)      (-)       (m)         (-)       (-)       (-)      (-)
1        nylon     300.0        50        2         1        p
-------------------------- SOLVER OPTIONS---------------------------------------------------
0.001    dtM          - time step to use in mooring integration
3.0e6    kb           - bottom stiffness
70       WtrDpth      - water depth
--------------------------- OUTPUTS --------------------------------------------------------
FairTen1
END
--------------------- need this line ------------------
)";

/// The message of the InputError `parse` throws, or "" when it throws none.
template <typename F>
std::string error_of(F parse) {
  try {
    parse();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(MoorDynDeck, ReadsEverySectionOfAV2Deck) {
  const MoorDynDeck deck = parse_moordyn_deck(kV2, "v2.dat");
  EXPECT_EQ(deck.format_version, 2);
  EXPECT_EQ(deck.title, "Two-line test deck");
  ASSERT_EQ(deck.line_types.size(), 2u);
  const MoorDynLineType& rope = deck.line_types[1];
  EXPECT_EQ(rope.name, "rope");
  EXPECT_EQ(rope.diameter_m, 0.2);
  EXPECT_EQ(rope.mass_per_length_kg_per_m, 30.0);
  EXPECT_EQ(rope.EA_N, 2.0e8);  // the static value of EA_s|EA_d
  EXPECT_EQ(rope.EA_text, "2.0e8|4e8");
  EXPECT_EQ(rope.damping_text, "-0.8");  // -zeta: a fraction of critical damping
  EXPECT_EQ(rope.EI_N_m2, 5.0);
  EXPECT_EQ(rope.Cd, 1.2);
  EXPECT_EQ(rope.Ca, 0.9);
  EXPECT_EQ(rope.CdAx, 0.008);
  EXPECT_EQ(rope.CaAx, 0.1);
  EXPECT_EQ(rope.line, 7);
  ASSERT_EQ(deck.points.size(), 5u);
  EXPECT_EQ(deck.points[1].kind, MoorDynPointKind::free);
  EXPECT_EQ(deck.points[1].mass_kg, 5000.0);
  EXPECT_EQ(deck.points[1].volume_m3, 1.0);
  EXPECT_EQ(deck.points[2].kind, MoorDynPointKind::coupled);
  EXPECT_EQ(deck.points[3].kind, MoorDynPointKind::fixed);
  EXPECT_EQ(deck.points[4].kind, MoorDynPointKind::coupled);
  EXPECT_EQ(deck.points[0].position_m, Eigen::Vector3d(-800, 0, -150));
  ASSERT_EQ(deck.lines.size(), 4u);
  EXPECT_EQ(deck.lines[1].type, "rope");
  EXPECT_EQ(deck.lines[1].end_a, "2");
  EXPECT_EQ(deck.lines[1].end_b, "3");
  EXPECT_EQ(deck.lines[1].length_m, 420.5);
  EXPECT_EQ(deck.lines[1].segments, 21);
  EXPECT_EQ(deck.lines[3].end_a, "R1A");
  ASSERT_NE(find_option(deck, {"wtrdpth"}), nullptr);
  EXPECT_EQ(find_option(deck, {"WtrDpth"})->value, "150");
  EXPECT_EQ(find_option(deck, {"kBot"})->line, 36);
  EXPECT_EQ(deck.outputs, (std::vector<std::string>{"FairTen1", "AnchTen3"}));
  // The rods are kept as notes, never dropped silently.
  ASSERT_EQ(deck.notes.size(), 2u);
  EXPECT_NE(deck.notes[0].find("ROD TYPES"), std::string::npos) << deck.notes[0];
  EXPECT_NE(deck.notes[1].find("RODS (lines 12-15, 1 rows)"), std::string::npos) << deck.notes[1];
}

TEST(MoorDynDeck, ReadsAV1DeckByItsColumnNames) {
  const MoorDynDeck deck = parse_moordyn_deck(kV1, "v1.dat");
  EXPECT_EQ(deck.format_version, 1);
  ASSERT_EQ(deck.line_types.size(), 1u);
  const MoorDynLineType& t = deck.line_types[0];
  // Can Cat Cdn Cdt: MoorDyn-C 1.x order, read by name.
  EXPECT_EQ(t.Ca, 1.0);
  EXPECT_EQ(t.CaAx, 0.0);
  EXPECT_EQ(t.Cd, 1.6);
  EXPECT_EQ(t.CdAx, 0.05);
  EXPECT_EQ(t.EI_N_m2, 0.0);
  ASSERT_EQ(deck.lines.size(), 1u);
  // Line LineType UnstrLen NumSegs NodeAnch NodeFair.
  EXPECT_EQ(deck.lines[0].length_m, 300.0);
  EXPECT_EQ(deck.lines[0].segments, 50);
  EXPECT_EQ(deck.lines[0].end_a, "2");
  EXPECT_EQ(deck.lines[0].end_b, "1");
  EXPECT_EQ(deck.points[0].kind, MoorDynPointKind::coupled);
  EXPECT_EQ(find_option(deck, {"WtrDpth"})->value, "70");
}

TEST(MoorDynDeck, ReadsTheRealIea15AndOc4Decks) {
  const std::string data = std::string(SPIRAL_TEST_DATA_DIR) + "/validation/";
  const MoorDynDeck iea = read_moordyn_deck(data + "iea15-umaine-semi/IEA-15-240-RWT-UMaineSemi_MoorDyn.dat");
  ASSERT_EQ(iea.line_types.size(), 1u);
  EXPECT_EQ(iea.line_types[0].diameter_m, 0.333);
  EXPECT_EQ(iea.line_types[0].EA_N, 3.27e9);
  EXPECT_EQ(iea.line_types[0].CaAx, 0.27);
  EXPECT_EQ(iea.points.size(), 6u);
  ASSERT_EQ(iea.lines.size(), 3u);
  EXPECT_EQ(iea.lines[2].end_a, "6");
  EXPECT_EQ(iea.lines[2].segments, 50);
  EXPECT_EQ(iea.outputs.size(), 27u);
  const MoorDynDeck oc4 = read_moordyn_deck(data + "oc4/NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat");
  EXPECT_EQ(oc4.line_types[0].EA_N, 7.536e8);
  EXPECT_EQ(oc4.lines[0].length_m, 835.35);
  EXPECT_EQ(oc4.points[3].position_m, Eigen::Vector3d(20.434, 35.393, -14.0));
}

TEST(MoorDynDeck, ErrorsNameFileLineAndColumn) {
  std::string bad = kV2;
  bad.replace(bad.find("420.5"), 5, "4x0.5");
  EXPECT_NE(error_of([&] {
              parse_moordyn_deck(bad, "bad.dat");
            }).find("bad.dat:28:33: UnstrLen: expected a number, got \"4x0.5\""),
            std::string::npos)
      << error_of([&] { parse_moordyn_deck(bad, "bad.dat"); });
  std::string untyped = kV2;
  untyped.replace(untyped.find("3   chain     5"), 15, "3   chian     5");
  const std::string message = error_of([&] { parse_moordyn_deck(untyped, "t.dat"); });
  EXPECT_NE(message.find("t.dat:29:5: line 3: undefined line type \"chian\" (defined: chain, rope)"), std::string::npos)
      << message;
  std::string short_row = kV2;
  const auto row5 = short_row.find("5   Vessel");
  short_row.replace(row5, short_row.find('\n', row5) - row5, "5   Vessel  40");
  EXPECT_NE(error_of([&] { parse_moordyn_deck(short_row, "s.dat"); }).find("s.dat:23:"), std::string::npos);
  std::string unknown_point = kV2;
  unknown_point.replace(unknown_point.find("5   Vessel"), 10, "5   Floaty");
  EXPECT_NE(error_of([&] {
              parse_moordyn_deck(unknown_point, "p.dat");
            }).find("p.dat:23:5: point attachment \"Floaty\" is not one of"),
            std::string::npos);
  EXPECT_NE(error_of([&] { parse_moordyn_deck("just text\n", "e.dat"); }).find("e.dat:1:1: the deck defines no line"),
            std::string::npos);
  // Found by tests/fuzz/moordyn_fuzz.cpp: an empty deck said "e.dat:0:1".
  EXPECT_NE(error_of([&] { parse_moordyn_deck("", "e.dat"); }).find("e.dat:1:1: the deck defines no line"),
            std::string::npos);
  EXPECT_NE(error_of([] { read_moordyn_deck("/nonexistent/deck.dat"); }).find("/nonexistent/deck.dat: cannot read"),
            std::string::npos);
}

TEST(MoorDynImport, MapsLinesPointsAndOptionsToAProject) {
  const MoorDynImport imported = import_moordyn(parse_moordyn_deck(kV2, "v2.dat"));
  const Project& p = imported.project;
  EXPECT_EQ(p.site.depth_m, 150.0);
  EXPECT_EQ(p.site.gravity_m_per_s2, 9.81);
  EXPECT_EQ(p.site.water_density_kg_per_m3, 1025.5);
  EXPECT_EQ(p.site.seabed.normal_stiffness_Pa_per_m, 3.0e6);
  EXPECT_EQ(p.site.seabed.friction_axial, 0.7);
  EXPECT_EQ(p.site.seabed.friction_lateral, 0.9);
  ASSERT_EQ(p.line_types.size(), 2u);
  const LineTypeInput& chain = p.line_types[0];
  EXPECT_EQ(chain.kind, LineKind::user);
  EXPECT_EQ(chain.diameter_m, 0.1);
  EXPECT_EQ(*chain.mass_per_length_kg_per_m, 150.0);
  EXPECT_EQ(*chain.axial_stiffness_N, 1.0e9);
  EXPECT_EQ(*chain.drag_normal, 2.4);
  EXPECT_EQ(*chain.added_mass_normal, 1.0);
  EXPECT_EQ(*chain.drag_axial, 1.15);
  EXPECT_EQ(*chain.added_mass_axial, 0.5);
  EXPECT_EQ(*chain.breaking_load_N, kPlaceholderMblPerEA * 1.0e9);
  EXPECT_EQ(imported.placeholder_breaking_loads, (std::vector<std::string>{"chain", "rope"}));
  ASSERT_EQ(p.mooring.lines.size(), 2u);
  const MooringLine& l1 = p.mooring.lines[0];
  EXPECT_EQ(l1.name, "L1");
  EXPECT_EQ(l1.anchor_g, Eigen::Vector3d(-800, 0, -150));
  EXPECT_EQ(l1.fairlead_b, Eigen::Vector3d(-40, 0, -10));
  ASSERT_EQ(l1.segments.size(), 2u);
  EXPECT_EQ(l1.segments[0].type, "chain");
  EXPECT_EQ(l1.segments[1].length_m, 420.5);
  ASSERT_EQ(l1.attachments.size(), 1u);
  EXPECT_EQ(l1.attachments[0].after_segment, 0);
  EXPECT_EQ(l1.attachments[0].kind, AttachmentKind::clump);  // 5000 kg > 1025.5 kg of water
  EXPECT_EQ(l1.fe.element_length_m, 420.5 / 21);             // the coarser of 400/40 and 420.5/21
  // Line 3 runs fairlead -> anchor in the deck; spiral's segments run from the anchor.
  const MooringLine& l3 = p.mooring.lines[1];
  EXPECT_EQ(l3.name, "L3");
  EXPECT_EQ(l3.anchor_g, Eigen::Vector3d(800, 0, -150));
  EXPECT_EQ(l3.fairlead_b, Eigen::Vector3d(40, 0, -10));
  EXPECT_EQ(l3.fe.element_length_m, 10.0);
  // Nothing dropped silently: rods, the rod-attached line, damping, EI, the
  // dynamic EA, cBot, solver settings, outputs, the hull.
  std::string notes;
  for (const std::string& n : imported.notes) notes += n + "\n";
  for (const char* expected :
       {"RODS", "MoorDyn line 4", "BA/-zeta = -0.8", "EI = 5", "EA \"2.0e8|4e8\"", "cBot = 3.0e5", "dtM 0.001",
        "OUTPUTS channels not kept (spiral writes its own results): FairTen1 AnchTen3", "hull: a PLACEHOLDER",
        "breaking_load is a PLACEHOLDER"})
    EXPECT_NE(notes.find(expected), std::string::npos) << expected << " not in\n" << notes;
  // The YAML carries the notes in its header.
  const std::string yaml = moordyn_import_yaml(imported, "v2.dat");
  EXPECT_NE(yaml.find("#  - RODS"), std::string::npos);
  EXPECT_NE(yaml.find("# PLACEHOLDER HULL"), std::string::npos);
}

TEST(MoorDynImport, DepthFromTheCommandLineOrTheDeepestAnchor) {
  const MoorDynDeck deck = parse_moordyn_deck(kV1, "v1.dat");
  EXPECT_EQ(import_moordyn(deck).project.site.depth_m, 70.0);
  EXPECT_EQ(import_moordyn(deck, {.depth_m = 80.0, .project_name = ""}).project.site.depth_m, 80.0);
  const std::string data = std::string(SPIRAL_TEST_DATA_DIR) + "/validation/";
  const MoorDynImport iea =
      import_moordyn(read_moordyn_deck(data + "iea15-umaine-semi/IEA-15-240-RWT-UMaineSemi_MoorDyn.dat"));
  EXPECT_EQ(iea.project.site.depth_m, 200.0);  // no WtrDpth in the deck: its anchors' depth, with a note
  EXPECT_NE(iea.notes.front().find("deepest Fixed point"), std::string::npos) << iea.notes.front();
  ASSERT_EQ(iea.project.mooring.lines.size(), 3u);
  EXPECT_EQ(iea.project.mooring.lines[0].anchor_g, Eigen::Vector3d(-837.6, 0.0, -200.0));
  EXPECT_EQ(iea.project.mooring.lines[0].fairlead_b, Eigen::Vector3d(-58.0, 0.0, -14.0));
  EXPECT_EQ(iea.project.mooring.lines[0].fe.element_length_m, 850.0 / 50);
}

TEST(MoorDynImport, AnchorBelowTheSeabedIsAnError) {
  const MoorDynDeck deck = parse_moordyn_deck(kV1, "v1.dat");
  const std::string message = error_of([&] { import_moordyn(deck, {.depth_m = 60.0, .project_name = ""}); });
  EXPECT_NE(message.find("v1.dat:12:1: point 2 lies at z = -70 m, below the seabed at -60 m"), std::string::npos)
      << message;
}

// A v2 deck with a coupled body: fairleads on Body1 (body frame), a bridle
// (a Free point joining three lines) that spiral cannot represent, a buoy at
// a joint, Fortran `D` exponents and trailing comments.
const std::string kBodies = R"(--------------------- MoorDyn Input File ------------------------------------
Body deck
---------------------- LINE TYPES ----------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
wire 0.08 40.0 6.0D8 -1 0 1.2 1.0 0.01 0.0   # a steel wire
---------------------- BODIES ---------------------------------------
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*
(#) (word) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1 coupled 10 0 0 0 0 0 0 0 0 0 0 0
2 free -300 0 -50 0 0 0 0 0 0 0 0 0
---------------------- POINTS --------------------------------------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -600 0 -100 0 0 0 0
2 Free -300 0 -60 100 2.0 0 0
3 Body1 -20 0 -5 0 0 0 0
4 Fixed 600 0 -100 0 0 0 0
5 Free 300 0 -60 0 0 0 0
6 Body1 20 0 -5 0 0 0 0
7 Body1 20 5 -5 0 0 0 0
---------------------- LINES ---------------------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 wire 1 2 320 32 -
2 wire 2 3 300 30 -
3 wire 4 5 320 32 -
4 wire 5 6 300 30 -
5 wire 5 7 300 30 -
---------------------- OPTIONS -------------------------------------------------
100 WtrDpth ! depth
---------------------- OUTPUTS -------------------------------------------------
END
------------------------- need this line ---------------------------------------
)";

TEST(MoorDynImport, CoupledBodyBridlesAndBuoys) {
  const MoorDynDeck deck = parse_moordyn_deck(kBodies, "bodies.dat");
  EXPECT_EQ(deck.line_types[0].EA_N, 6.0e8);  // Fortran exponent
  EXPECT_EQ(deck.line_types[0].CaAx, 0.0);    // the comment is not a column
  ASSERT_EQ(deck.bodies.size(), 2u);
  EXPECT_EQ(deck.points[2].kind, MoorDynPointKind::body);
  EXPECT_EQ(deck.points[2].body, 1);
  const MoorDynImport imported = import_moordyn(deck);
  const Project& p = imported.project;
  EXPECT_EQ(p.hull.reference_point_g, Eigen::Vector3d(10, 0, 0));  // the coupled body's origin
  ASSERT_EQ(p.mooring.lines.size(), 1u);                           // the bridled line is not representable
  const MooringLine& l = p.mooring.lines[0];
  EXPECT_EQ(l.fairlead_b, Eigen::Vector3d(-20, 0, -5));  // Body1 points are in the body frame
  ASSERT_EQ(l.attachments.size(), 1u);
  EXPECT_EQ(l.attachments[0].kind, AttachmentKind::buoy);  // 2 m³ of water > 100 kg
  std::string notes;
  for (const std::string& n : imported.notes) notes += n + "\n";
  for (const char* expected : {"point 5 (line 19) joins 3 lines", "MoorDyn line 3 ", "MoorDyn line 4 ",
                               "MoorDyn line 5 ", "body 2 (line 11, free)"})
    EXPECT_NE(notes.find(expected), std::string::npos) << expected << " not in\n" << notes;
}

}  // namespace
}  // namespace spiral::design
