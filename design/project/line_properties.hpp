#pragma once
// Line types of a project: what the YAML says (nominal diameter, grade,
// construction, optional explicit values) and the resolved physical
// properties the engine uses (mass, submerged weight, EA, MBL, hydrodynamic
// coefficients), derived with published formulas where not given explicitly.
// The formulas and their sources are listed in docs/line-types.md
// ("Line-type property formulas"); docs/project-format.md links to it.

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace spiral::design {

enum class LineKind { chain, wire, polyester, user };
enum class ChainGrade { R3, R3S, R4, R4S, R5 };
enum class ChainConstruction { studless, studlink };
enum class WireConstruction { six_strand, spiral_strand };

/// A line type as written in the project. Every optional value, when present,
/// overrides the formula for that property.
struct LineTypeInput {
  std::string name;
  LineKind kind = LineKind::user;
  double diameter_m = 0.0;          ///< nominal diameter (chain bar, rope/wire); for `user`, the hydrodynamic one
  std::optional<ChainGrade> grade;  ///< chain only
  std::optional<ChainConstruction> chain_construction;         ///< chain only (default studless)
  std::optional<WireConstruction> wire_construction;           ///< wire only (default six_strand)
  std::optional<double> mass_per_length_kg_per_m;              ///< in air
  std::optional<double> submerged_weight_N_per_m;              ///< wet weight per length
  std::optional<double> hydrodynamic_diameter_m;               ///< volume-equivalent diameter
  std::optional<double> axial_stiffness_N;                     ///< EA (polyester: static EA)
  std::optional<double> breaking_load_N;                       ///< MBL
  std::optional<double> static_stiffness_mbl;                  ///< polyester: EA_static / MBL
  std::optional<std::array<double, 2>> dynamic_stiffness_mbl;  ///< polyester: EA_dyn/MBL = a + b * (mean load, % MBL)
  std::optional<double> drag_normal;                           ///< Cd on the hydrodynamic diameter
  std::optional<double> drag_axial;
  std::optional<double> added_mass_normal;
  std::optional<double> added_mass_axial;
};

/// Resolved properties (SI). `*_source` strings name the formula or say "explicit".
struct LineTypeProperties {
  std::string name;
  LineKind kind = LineKind::user;
  double nominal_diameter_m = 0.0;
  double hydrodynamic_diameter_m = 0.0;  ///< volume-equivalent: buoyancy and Morison forces use it
  double mass_per_length_kg_per_m = 0.0;
  double submerged_weight_N_per_m = 0.0;  ///< (m - rho * pi/4 * d_hyd^2) g unless explicit
  double axial_stiffness_N = 0.0;         ///< EA used by statics (polyester: static EA)
  /// Polyester dynamic EA = (a + b * L_m) * MBL, L_m mean load in % MBL; zero for other kinds.
  std::array<double, 2> dynamic_stiffness_mbl = {0.0, 0.0};
  double breaking_load_N = 0.0;
  double drag_normal = 0.0;
  double drag_axial = 0.0;
  double added_mass_normal = 0.0;
  double added_mass_axial = 0.0;
  std::string mass_source, stiffness_source, breaking_load_source;
  /// Where the hydrodynamic diameter and the Cd/Ca set come from ("explicit" or the formula).
  std::string hydrodynamics_source;
};

/// Derives the properties of a line type. Throws std::invalid_argument naming
/// the missing input when a `user` type lacks a value no formula can supply,
/// when a chain without explicit MBL/EA has no grade, when an input is not
/// positive (diameter, explicit mass/EA/MBL/diameter, water density, gravity)
/// or when an input does not apply to the kind (e.g. `grade` on a polyester
/// type). Messages start with "line_types: <kind> type '<name>' ...".
LineTypeProperties resolve_line_type(const LineTypeInput& input, double water_density_kg_per_m3,
                                     double gravity_m_per_s2);

/// Dynamic axial stiffness at a mean load (polyester; other kinds return the static EA).
/// Polyester: EA_dyn = (a + b * L_m) * MBL with L_m = 100 * mean_tension_N / MBL (% MBL).
/// Throws std::invalid_argument if mean_tension_N < 0 or is not finite.
double dynamic_axial_stiffness_N(const LineTypeProperties& properties, double mean_tension_N);

/// Whether the type has a dynamic EA of its own (polyester with a non-zero
/// `dynamic_stiffness_mbl`); otherwise dynamic_axial_stiffness_N is the static EA.
bool has_dynamic_axial_stiffness(const LineTypeProperties& properties);

/// The EA that carries the strain changes about a line's static state, per
/// segment (anchor first): a polyester segment's dynamic EA at its mean
/// tension (the mean over the state's points in that segment), every other
/// segment's own EA — the static–dynamic convention (DNV-OS-E301 ch. 2
/// sec. 2 [2.4]: mean state on the static EA, motions about it on the
/// dynamic one). point_segment[i] is the segment of the point whose
/// effective tension is point_tension_N[i] (a catenary profile, FE nodes).
std::vector<double> incremental_axial_stiffness_N(const std::vector<LineTypeProperties>& segment_types,
                                                  const std::vector<int>& point_segment,
                                                  const std::vector<double>& point_tension_N);

const char* to_string(LineKind kind);
const char* to_string(ChainGrade grade);
const char* to_string(ChainConstruction construction);
const char* to_string(WireConstruction construction);

}  // namespace spiral::design
