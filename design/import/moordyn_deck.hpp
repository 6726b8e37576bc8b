#pragma once
// A MoorDyn input file ("deck") as written: its line types, points, lines,
// options and outputs, each with the line of the file it came from. Reads
// both formats (MoorDyn docs, "Input Files": v1 of MoorDyn-C 1.x and
// MoorDyn-F/OpenFAST, v2 of MoorDyn-C 2.x and MoorDyn-F 2.x):
//
//   v1 headers  LINE DICTIONARY | LINE TYPES, NODE PROPERTIES | CONNECTION
//               PROPERTIES | POINT PROPERTIES, LINE PROPERTIES, SOLVER OPTIONS
//   v2 headers  LINE TYPES, ROD TYPES, BODIES, RODS, POINTS, LINES, OPTIONS
//
// Tables have a column-name row and a unit row. MoorDyn v2 reads columns by
// position; v1 decks differ in order (MoorDyn-C 1.x: Can Cat Cdn Cdt and
// Line LineType UnstrLen NumSegs NodeAnch NodeFair; MoorDyn-F: EI Cd Ca CdAx
// CaAx), so a column is found by its header name and, when the header names
// none we know, at its v2 position. What spiral does not read (rods, bodies,
// failure, control, external loads) is kept as a note with its line numbers.
//
// Errors: design::InputError, one issue per problem, `file:line:col: problem`
// (a number that is not a number, a row with too few columns, a line type or
// point a line names that the deck does not define, ...), all at once.

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace spiral::design {

/// A LINE TYPES row. Coefficients as MoorDyn defines them: Cd on d·l, CdAx on
/// π·d·l, Ca and CaAx on the displaced volume π/4·d²·l.
struct MoorDynLineType {
  std::string name;
  double diameter_m = 0.0;                ///< volume-equivalent diameter
  double mass_per_length_kg_per_m = 0.0;  ///< in air
  double EA_N = 0.0;                      ///< the first value of `EA` (v2 `EA_s|EA_d`: the static one)
  std::string EA_text;                    ///< as written (a `|` list or a table file is noted)
  std::string damping_text;               ///< BA (N·s) or, negative, −ζ (fraction of critical), as written
  double EI_N_m2 = 0.0;                   ///< bending stiffness; 0 where the deck has no EI column
  double Cd = 0.0, Ca = 0.0, CdAx = 0.0, CaAx = 0.0;
  int line = 0;  ///< 1-based line of the file
};

/// What a point is attached to (MoorDyn's "Type"/"Attachment" column).
enum class MoorDynPointKind {
  fixed,    ///< Fixed / Anchor: global position
  coupled,  ///< Vessel / Coupled / Fairlead / TurbineN: moves with the coupled body
  free,     ///< Connect / Free / Point: a joint whose position MoorDyn solves for
  body,     ///< BodyN: fixed to a MoorDyn body (position in the body frame)
};

struct MoorDynPoint {
  int id = 0;
  std::string attachment;  ///< as written
  MoorDynPointKind kind = MoorDynPointKind::fixed;
  int body = 0;  ///< kind == body: the body's ID
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double mass_kg = 0.0;
  double volume_m3 = 0.0;
  bool has_point_loads = false;  ///< nonzero FX/FY/FZ, CdA or Ca (noted: spiral has no point drag)
  int line = 0;
};

/// A LINES row. Ends are point IDs as written (`R1A` is a rod end).
struct MoorDynLine {
  int id = 0;
  std::string type;
  std::string end_a, end_b;  ///< AttachA / NodeAnch, AttachB / NodeFair
  double length_m = 0.0;     ///< unstretched
  int segments = 0;          ///< NumSegs, >= 1
  int line = 0;
};

/// An OPTIONS row: `value name [description]`.
struct MoorDynOption {
  std::string name;
  std::string value;
  int line = 0;
};

/// A BODIES row, as far as spiral uses it (the coupled body's frame).
struct MoorDynBody {
  int id = 0;
  std::string attachment;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();  ///< roll, pitch, yaw
  int line = 0;
};

struct MoorDynDeck {
  std::string source;      ///< the file as the user named it
  int format_version = 2;  ///< 1 when a v1-only header (LINE DICTIONARY, ... PROPERTIES, SOLVER OPTIONS) is met
  std::string title;       ///< the front matter's first free line
  std::vector<std::string> front_matter;  ///< the lines before the first section (title included)
  std::vector<MoorDynLineType> line_types;
  std::vector<MoorDynPoint> points;
  std::vector<MoorDynLine> lines;
  std::vector<MoorDynBody> bodies;
  std::vector<MoorDynOption> options;
  std::vector<std::string> outputs;
  /// What the deck holds that spiral does not read, one sentence each.
  std::vector<std::string> notes;
};

/// Parses deck text; `source_name` names it in messages. Throws InputError.
MoorDynDeck parse_moordyn_deck(std::string_view text, const std::string& source_name);

/// Reads and parses a deck file. Throws InputError (missing_file when it
/// cannot be read).
MoorDynDeck read_moordyn_deck(const std::filesystem::path& file);

/// The option named `name` (case-insensitive; any of `names`), if the deck has it.
const MoorDynOption* find_option(const MoorDynDeck& deck, std::initializer_list<std::string_view> names);

}  // namespace spiral::design
