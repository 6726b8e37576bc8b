#pragma once
// A project's mooring (and risers) as a MoorDyn v2 deck, so the same system
// runs in MoorDyn-C or MoorDyn-F/OpenFAST (docs/moordyn.md):
//
//  - each line type a segment uses -> a LINE TYPES row with its resolved
//    properties: Diam = the hydrodynamic (volume-equivalent) diameter,
//    Mass/m, EA (static), EI 0, BA/-zeta −1 (critical axial damping of each
//    segment, as the NREL OC4 and IEA-15 decks), Cd/Ca/CdAx/CaAx unchanged;
//  - each riser section -> a LINE TYPES row of its own with the section's EI
//    and EA, Diam the outermost diameter, Mass/m the structural mass plus
//    the contents (MoorDyn has no bore), so the effective weight is spiral's;
//  - each segment -> a LINES row from a Fixed anchor through Free joints (an
//    attachment's mass and volume on its joint) to a Coupled fairlead (its
//    body-frame position: OpenFAST's platform reference point is spiral's hull
//    reference point); a riser from its foot (placed as spiral places it,
//    design/model/riser_model.hpp) to its hang-off; NumSegs from the FE mesh;
//  - OPTIONS: WtrDpth, g, the water density and the friction coefficients
//    under both programs' names (MoorDyn-C: rho, FrictionCoefficient;
//    MoorDyn-F: rhoW, mu_kA / mu_kT), kBot, and a dtM (MoorDyn-C's own
//    default step diverges on these decks; see moordyn_export.cpp).
//
// What MoorDyn has no place for (MBL, line names, element lengths) goes into
// the front matter as `spiral:` lines, which MoorDyn ignores and `spiral
// import moordyn` reads back; what is lost (touchdown refinement, polyester
// dynamic stiffness, internal pressure, groups, the hull) as `spiral note:` lines.

#include <string>
#include <vector>

#include "design/project/line_properties.hpp"
#include "design/project/project.hpp"

namespace spiral::design {

/// The deck text. `types` are the project's resolved line types (in
/// project order). Throws engine::SolverError when a riser's foot cannot be
/// placed (as every analysis would).
std::string export_moordyn(const Project& project, const std::vector<LineTypeProperties>& types);

/// MoorDyn's BA/-zeta written for every line type: −1, critical damping of
/// each segment's axial mode (MoorDyn docs, "Line Types"; the value of the
/// NREL OC4 and IEA-15 decks).
inline constexpr double kExportDampingRatio = -1.0;

/// dtM written: this fraction of the shortest axial wave transit time
/// l/√(EA/m) of any segment, rounded down to one digit. Checked on the
/// exported OC4 deck in MoorDyn-C v2.7.1: stable up to 0.5 (2 ms), diverged at
/// its default ≈ 3.1; NREL's own OC4 deck runs at 0.06 (docs/moordyn.md).
inline constexpr double kExportTimeStepFraction = 0.2;

}  // namespace spiral::design
