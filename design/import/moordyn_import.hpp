#pragma once
// A MoorDyn deck as a spiral project (docs/moordyn.md has the full mapping):
//
//  - each line type -> a `kind: user` line type: Diam -> diameter (MoorDyn's
//    is the volume-equivalent one, as spiral's `user` diameter), MassDen,
//    EA (static), Cd/Ca/CdAx/CaAx -> drag_normal/added_mass_normal/drag_axial/
//    added_mass_axial unchanged (both codes put Cd on d·l, CdAx on π·d·l, Ca
//    and CaAx on π/4·d²·l). MoorDyn has no MBL: the breaking load is a
//    placeholder, said so in the file (unless the deck's front matter, as
//    `spiral export moordyn` writes it, gives one);
//  - each chain Fixed point -> line -> [Free point -> line ...] -> coupled
//    point -> one mooring line, segments from the anchor to the fairlead, the
//    Free points' mass and volume as clump/buoy attachments, the fairlead the
//    coupled point's position (relative to the coupled body, whose origin is
//    the hull reference point), the FE element length from NumSegs;
//  - OPTIONS WtrDpth, g, rhoW, kBot and the friction coefficients -> site.
//
// What has no spiral meaning (rods, other bodies, outputs, solver settings,
// damping, bending stiffness of mooring lines, branching points, lines not
// between an anchor and the vessel) becomes a note; the notes head the
// written file. The deck has no hull: the project gets a placeholder hull
// (the format requires one), labelled as such.

#include <optional>
#include <string>
#include <vector>

#include "design/import/moordyn_deck.hpp"
#include "design/project/project.hpp"

namespace spiral::design {

struct MoorDynImportOptions {
  std::optional<double> depth_m;  ///< water depth, > 0; overrides the deck's WtrDpth
  std::string project_name;       ///< default: the deck's title
};

struct MoorDynImport {
  Project project;
  std::vector<std::string> notes;  ///< what the project does not hold of the deck, one sentence each
  /// Line-type names whose breaking load is a placeholder (MoorDyn gives none).
  std::vector<std::string> placeholder_breaking_loads;
};

/// Placeholder MBL of a line type the deck gives none for, as a fraction of
/// its EA: 0.5 %, below what the usual mooring materials have (R3 studless
/// chain 0.65 % at 76 mm — the OC4 scenario's 4.884 MN on 7.536e8 N — and
/// ~0.75 % at 185 mm with the docs/line-types.md formulas; wire rope ~1 %;
/// polyester 5-10 %), so a code check run on it by mistake errs on the safe
/// side. The file validates with it; the written project says it is a
/// placeholder at the value and in the header.
inline constexpr double kPlaceholderMblPerEA = 0.005;

/// Maps a deck to a project. The water depth is `options.depth_m`, else the
/// deck's WtrDpth, else (MoorDyn-F v1 decks take it from HydroDyn) the depth
/// of the deepest Fixed point, with a note. Throws InputError (`file:line:col:
/// problem`) when no line runs from an anchor to the vessel or a point lies
/// below the seabed.
MoorDynImport import_moordyn(const MoorDynDeck& deck, const MoorDynImportOptions& options = {});

/// The project as YAML text (format v1), the notes in its header.
std::string moordyn_import_yaml(const MoorDynImport& imported, const std::string& deck_name);

}  // namespace spiral::design
