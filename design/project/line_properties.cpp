// Line-type property formulas. Every coefficient below cites its source; the
// same table, with status tags (S sourced, Q quoted, D derived, U unconfirmed,
// C design choice), is in docs/line-types.md. Source short names follow
// shared/data/reference-platforms.md ("MoorPy", "ddjokic", "OrcaFlex Chain").

#include "design/project/line_properties.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

namespace spiral::design {
namespace {

constexpr double kPi = std::numbers::pi;

/// Hydrodynamic coefficients, all on the volume-equivalent diameter.
struct Hydro {
  double drag_normal, drag_axial, added_mass_normal, added_mass_axial;
};

// --- chain (reference-platforms.md §2.2) -----------------------------------

/// MBL coefficient c in MBL[kN] = c d^2 (44 - 0.08 d), d in mm; the same for
/// studless and studlink. ddjokic moorchain.py `BL(c)` (cites DNV-OS-E301),
/// spot-checked against a DNV-OS-E302 break-load table at d = 50 mm. [S]
double chain_mbl_coefficient(ChainGrade grade) {
  switch (grade) {
    case ChainGrade::R3:
      return 0.0223;
    case ChainGrade::R3S:
      return 0.0249;
    case ChainGrade::R4:
      return 0.0274;
    case ChainGrade::R4S:
      return 0.0304;
    case ChainGrade::R5:
      return 0.0320;
  }
  throw std::logic_error("chain_mbl_coefficient: unknown grade");
}

/// DNV-OS-E301 (2010-2015 editions) studless effective modulus
/// E = (a - b d[mm]) 1e10 N/m^2 [Q, ckunte.net and ddjokic]. R3S and R4S have
/// no separate line in the quoted table: they use R3 and R4 [U, assumption].
struct StudlessModulus {
  double a, b;
  const char* label;
};
StudlessModulus studless_modulus(ChainGrade grade) {
  switch (grade) {
    case ChainGrade::R3:
      return {5.40, 0.0040, "R3"};
    case ChainGrade::R3S:
      return {5.40, 0.0040, "R3 (R3S assumed as R3)"};
    case ChainGrade::R4:
      return {5.45, 0.0025, "R4"};
    case ChainGrade::R4S:
      return {5.45, 0.0025, "R4 (R4S assumed as R4)"};
    case ChainGrade::R5:
      return {6.00, 0.0033, "R5"};
  }
  throw std::logic_error("studless_modulus: unknown grade");
}

/// DNV-OS-E301 studlink effective modulus, all grades [Q, ddjokic].
constexpr double kStudlinkModulus_Pa = 5.6e10;

// MoorPy MoorProps_default.yaml, "DNV-OS-E301 adjusted for volumetric
// diameter" (Cd) and "Bureau Veritas 493-NR" (Ca) [S]. 1.333 x 1.8 = 2.4 and
// 0.639 x 1.8 = 1.15 reproduce the OrcaFlex "Chain" values on nominal d.
constexpr Hydro kStudlessChainHydro{1.333, 0.639, 1.0, 0.5};
constexpr Hydro kStudlinkChainHydro{1.376, 0.741, 1.0, 0.5};

// --- polyester (reference-platforms.md §2.3; MoorPy fits to 7 catalogues) ---

constexpr double kPolyesterMass_kg_per_m3 = 679.0;    // m = 679 d^2 kg/m [S]
constexpr double kPolyesterMaterialDensity = 1380.0;  // kg/m^3, MoorPy `density` [S]
constexpr double kPolyesterMbl_N_per_m2 = 308e6;      // MBL = 308e6 d^2 N [S]
constexpr double kPolyesterStaticMbl = 14.0;          // EA_s / MBL, MoorPy yaml default [S]
// EA_d / MBL = 11.6 + 0.40 L_m (L_m in % MBL); yaml gives 40.0 per unit fraction [S].
constexpr std::array<double, 2> kPolyesterDynamicMbl{11.6, 0.40};
constexpr Hydro kPolyesterHydro{2.021, 0.0, 1.1, 0.15};  // MoorPy yaml; Cd_ax not given [S]

// --- wire -------------------------------------------------------------------

// Six-strand wire rope with IWRC: the OrcaFlex fits as coded in MoorPy
// MoorProps.py "Orcaflex-original" (type "wire"/"IWRC") and ddjokic
// moorwire.py ("wire rope with wire core") [S]: mass 3.9897 d^2 t/m,
// EA 4.04e7 d^2 kN, MBL 633,358 d^2 kN, d_vol 0.80 d.
constexpr double kSixStrandMass_kg_per_m3 = 3.9897e3;
constexpr double kSixStrandEA_N_per_m2 = 4.04e10;
constexpr double kSixStrandMbl_N_per_m2 = 633358e3;
constexpr double kSixStrandVolumeDiameter = 0.80;

// Spiral strand: MoorPy MoorProps_default.yaml `wire` entry, a fit to two
// manufacturers' catalogues of sheathed wire rope (MoorPy library/readme.md)
// [S]; reading it as (sheathed) spiral strand, the mooring-grade wire, is our
// interpretation [D]. Mass 5293 d^2 kg/m, d_vol 1.18 d (sheath, 4875 kg/m^3),
// MBL 1022e6 d^2 N, EA 97.1e9 d^2 N, Cd 1.021 on d_vol, Cd_ax neglected.
constexpr double kSpiralStrandMass_kg_per_m3 = 5293.0;
constexpr double kSpiralStrandEA_N_per_m2 = 97.1e9;
constexpr double kSpiralStrandMbl_N_per_m2 = 1022e6;
constexpr double kSpiralStrandVolumeDiameter = 1.18;
// Ca 1.0 normal, 0 axial are the usual cylinder values; MoorPy gives no Ca for
// wire [U]. Six-strand Cd: the MoorPy wire drag per nominal diameter,
// 1.021 x 1.18 = 1.205 (the familiar ~1.2 on nominal d), moved onto its own
// d_vol = 0.80 d [D].
constexpr Hydro kSpiralStrandHydro{1.021, 0.0, 1.0, 0.0};
constexpr Hydro kSixStrandHydro{1.021 * kSpiralStrandVolumeDiameter / kSixStrandVolumeDiameter, 0.0, 1.0, 0.0};

// --- user -------------------------------------------------------------------

// Generic cylinder coefficients for a user type that gives none [C]: give
// drag/added mass explicitly for dynamic analyses of real lines.
constexpr Hydro kUserDefaultHydro{1.2, 0.0, 1.0, 0.0};

std::string prefix(const LineTypeInput& in) {
  return std::string("line_types: ") + to_string(in.kind) + " type '" + in.name + "'";
}

std::string fmt_double(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void require_positive(const LineTypeInput& in, const std::optional<double>& value, const char* key, const char* unit) {
  if (value && !(*value > 0.0 && std::isfinite(*value))) {
    throw std::invalid_argument(prefix(in) + ": " + key + " must be > 0 (" + unit + "), got " + fmt_double(*value));
  }
}

void require_non_negative(const LineTypeInput& in, const std::optional<double>& value, const char* key) {
  if (value && !(*value >= 0.0 && std::isfinite(*value))) {
    throw std::invalid_argument(prefix(in) + ": " + key + " must be >= 0 (-), got " + fmt_double(*value));
  }
}

/// Inputs that belong to one kind only are an error elsewhere: they would be
/// silently ignored otherwise.
void reject_foreign_inputs(const LineTypeInput& in) {
  auto reject = [&](bool present, const char* key, const char* kinds) {
    if (present) {
      throw std::invalid_argument(prefix(in) + ": " + key + " applies to " + kinds + " types only");
    }
  };
  reject(in.kind != LineKind::chain && in.grade.has_value(), "grade", "chain");
  reject(in.kind != LineKind::chain && in.chain_construction.has_value(), "construction (chain)", "chain");
  reject(in.kind != LineKind::wire && in.wire_construction.has_value(), "construction (wire)", "wire");
  reject(in.kind != LineKind::polyester && in.static_stiffness_mbl.has_value(), "static_stiffness_mbl", "polyester");
  reject(in.kind != LineKind::polyester && in.dynamic_stiffness_mbl.has_value(), "dynamic_stiffness_mbl", "polyester");
}

void validate(const LineTypeInput& in, double rho, double g) {
  if (!(rho > 0.0 && std::isfinite(rho))) {
    throw std::invalid_argument(prefix(in) + ": water density must be > 0 (kg/m^3), got " + fmt_double(rho));
  }
  if (!(g > 0.0 && std::isfinite(g))) {
    throw std::invalid_argument(prefix(in) + ": gravity must be > 0 (m/s^2), got " + fmt_double(g));
  }
  reject_foreign_inputs(in);
  require_positive(in, in.mass_per_length_kg_per_m, "mass_per_length", "kg/m");
  require_positive(in, in.hydrodynamic_diameter_m, "hydrodynamic_diameter", "m");
  require_positive(in, in.axial_stiffness_N, "axial_stiffness", "N");
  require_positive(in, in.breaking_load_N, "breaking_load", "N");
  require_positive(in, in.static_stiffness_mbl, "static_stiffness_mbl", "-");
  if (in.submerged_weight_N_per_m && !std::isfinite(*in.submerged_weight_N_per_m)) {
    throw std::invalid_argument(prefix(in) + ": submerged_weight must be finite (N/m)");
  }
  if (in.dynamic_stiffness_mbl) {
    const auto& ab = *in.dynamic_stiffness_mbl;
    if (!(ab[0] > 0.0 && std::isfinite(ab[0]) && ab[1] >= 0.0 && std::isfinite(ab[1]))) {
      throw std::invalid_argument(prefix(in) + ": dynamic_stiffness_mbl [a, b] needs a > 0 and " + "b >= 0 (-), got [" +
                                  fmt_double(ab[0]) + ", " + fmt_double(ab[1]) + "]");
    }
  }
  require_non_negative(in, in.drag_normal, "drag_normal");
  require_non_negative(in, in.drag_axial, "drag_axial");
  require_non_negative(in, in.added_mass_normal, "added_mass_normal");
  require_non_negative(in, in.added_mass_axial, "added_mass_axial");
  if (in.kind != LineKind::user && !(in.diameter_m > 0.0 && std::isfinite(in.diameter_m))) {
    throw std::invalid_argument(prefix(in) + ": diameter must be > 0 (m), got " + fmt_double(in.diameter_m));
  }
}

/// Formula values before explicit overrides.
struct Formula {
  double mass = 0.0, d_vol = 0.0, EA = 0.0, MBL = 0.0;
  Hydro hydro{};
  std::string mass_src, EA_src, MBL_src, hydro_src;
  bool has_mass = false, has_EA = false, has_MBL = false;
};

Formula chain_formula(const LineTypeInput& in) {
  const double d = in.diameter_m;
  const double d_mm = d * 1000.0;
  const bool studlink = in.chain_construction.value_or(ChainConstruction::studless) == ChainConstruction::studlink;
  Formula f;
  // Mass and volume-equivalent diameter: OrcaFlex "Chain"; MoorPy [S].
  f.mass = (studlink ? 21.9e3 : 19.9e3) * d * d;
  f.has_mass = true;
  f.mass_src =
      studlink ? "chain studlink 21.9 d^2 t/m (OrcaFlex Chain)" : "chain studless 19.9 d^2 t/m (OrcaFlex Chain)";
  f.d_vol = (studlink ? 1.89 : 1.80) * d;
  f.hydro = studlink ? kStudlinkChainHydro : kStudlessChainHydro;
  f.hydro_src = studlink ? "chain studlink: d_vol 1.89 d; Cd 1.376, Cd_ax 0.741, Ca 1.0, Ca_ax 0.5 "
                           "on d_vol (MoorPy)"
                         : "chain studless: d_vol 1.80 d; Cd 1.333, Cd_ax 0.639, Ca 1.0, Ca_ax 0.5 "
                           "on d_vol (MoorPy)";
  // Both legs of a link carry the load: A = 2 pi d^2 / 4 (DNV-OS-E301).
  const double area = 2.0 * kPi / 4.0 * d * d;
  if (studlink) {
    f.EA = kStudlinkModulus_Pa * area;
    f.has_EA = true;
    f.EA_src = "DNV-OS-E301 studlink: E = 5.6e10 Pa x 2 pi d^2/4";
  } else if (in.grade) {
    const StudlessModulus m = studless_modulus(*in.grade);
    f.EA = (m.a - m.b * d_mm) * 1e10 * area;
    f.has_EA = true;
    f.EA_src = std::string("DNV-OS-E301 studless ") + m.label + ": E = (" + fmt_double(m.a) + " - " + fmt_double(m.b) +
               " d[mm]) 1e10 Pa x 2 pi d^2/4";
  }
  if (in.grade) {
    const double c = chain_mbl_coefficient(*in.grade);
    f.MBL = c * d_mm * d_mm * (44.0 - 0.08 * d_mm) * 1e3;
    f.has_MBL = true;
    f.MBL_src = std::string("chain ") + to_string(*in.grade) + ": " + fmt_double(c) +
                " d^2 (44 - 0.08 d) kN, d in mm (DNV-OS-E301 via ddjokic)";
  }
  const bool need_grade = (!f.has_MBL && !in.breaking_load_N) || (!f.has_EA && !in.axial_stiffness_N);
  if (need_grade) {
    throw std::invalid_argument(prefix(in) + " needs grade (R3 | R3S | R4 | R4S | R5) " +
                                "unless breaking_load and axial_stiffness are given");
  }
  if ((f.has_EA && !in.axial_stiffness_N && !(f.EA > 0.0)) || (f.has_MBL && !in.breaking_load_N && !(f.MBL > 0.0))) {
    throw std::invalid_argument(prefix(in) + ": the chain formulas give no positive EA/MBL at " + "diameter " +
                                fmt_double(d) + " m; give them explicitly");
  }
  return f;
}

Formula polyester_formula(const LineTypeInput& in) {
  const double d = in.diameter_m;
  Formula f;
  f.mass = kPolyesterMass_kg_per_m3 * d * d;
  f.has_mass = true;
  f.mass_src = "polyester 679 d^2 kg/m (MoorPy catalogue fit)";
  // MoorPy derives d_vol from the material density: sqrt(4 * 679 / (pi * 1380)) = 0.7915.
  f.d_vol = std::sqrt(4.0 * kPolyesterMass_kg_per_m3 / (kPi * kPolyesterMaterialDensity)) * d;
  f.hydro = kPolyesterHydro;
  f.hydro_src =
      "polyester: d_vol 0.7915 d (1380 kg/m^3); Cd 2.021, Ca 1.1, Ca_ax 0.15 on d_vol "
      "(MoorPy)";
  f.MBL = kPolyesterMbl_N_per_m2 * d * d;
  f.has_MBL = true;
  f.MBL_src = "polyester 308e6 d^2 N (MoorPy catalogue fit)";
  // EA_static = K_rs MBL is set after the MBL override (it scales the resolved MBL).
  f.has_EA = true;
  return f;
}

Formula wire_formula(const LineTypeInput& in) {
  const double d = in.diameter_m;
  const bool spiral = in.wire_construction.value_or(WireConstruction::six_strand) == WireConstruction::spiral_strand;
  Formula f;
  f.has_mass = f.has_EA = f.has_MBL = true;
  if (spiral) {
    f.mass = kSpiralStrandMass_kg_per_m3 * d * d;
    f.EA = kSpiralStrandEA_N_per_m2 * d * d;
    f.MBL = kSpiralStrandMbl_N_per_m2 * d * d;
    f.d_vol = kSpiralStrandVolumeDiameter * d;
    f.hydro = kSpiralStrandHydro;
    f.mass_src = "spiral strand 5293 d^2 kg/m (MoorPy wire fit, sheathed)";
    f.EA_src = "spiral strand 97.1e9 d^2 N (MoorPy wire fit)";
    f.MBL_src = "spiral strand 1022e6 d^2 N (MoorPy wire fit)";
    f.hydro_src = "spiral strand: d_vol 1.18 d; Cd 1.021 on d_vol (MoorPy); Ca 1.0, Ca_ax 0 (U)";
  } else {
    f.mass = kSixStrandMass_kg_per_m3 * d * d;
    f.EA = kSixStrandEA_N_per_m2 * d * d;
    f.MBL = kSixStrandMbl_N_per_m2 * d * d;
    f.d_vol = kSixStrandVolumeDiameter * d;
    f.hydro = kSixStrandHydro;
    f.mass_src = "six-strand IWRC 3.9897 d^2 t/m (OrcaFlex fit via MoorPy)";
    f.EA_src = "six-strand IWRC 4.04e7 d^2 kN (OrcaFlex fit via MoorPy)";
    f.MBL_src = "six-strand IWRC 633358 d^2 kN (OrcaFlex fit via MoorPy)";
    f.hydro_src =
        "six-strand: d_vol 0.80 d; Cd 1.506 on d_vol (= 1.205 on d, from MoorPy wire); "
        "Ca 1.0, Ca_ax 0 (U)";
  }
  return f;
}

Formula user_formula(const LineTypeInput& in) {
  auto missing = [&](const char* key, const char* unit) {
    throw std::invalid_argument(prefix(in) + " needs " + key + " (" + unit + ")");
  };
  if (!in.mass_per_length_kg_per_m) missing("mass_per_length", "kg/m");
  if (!in.axial_stiffness_N) missing("axial_stiffness", "N");
  if (!in.breaking_load_N) missing("breaking_load", "N");
  const bool has_diameter = in.diameter_m > 0.0 && std::isfinite(in.diameter_m);
  if (!has_diameter && !in.hydrodynamic_diameter_m) missing("diameter", "m");
  if (in.diameter_m < 0.0 || !std::isfinite(in.diameter_m)) {
    throw std::invalid_argument(prefix(in) + ": diameter must be > 0 (m), got " + fmt_double(in.diameter_m));
  }
  Formula f;
  f.d_vol = has_diameter ? in.diameter_m : 0.0;  // for user types `diameter` is the hydrodynamic one
  f.hydro = kUserDefaultHydro;
  f.hydro_src = "user: diameter as given; default Cd 1.2, Cd_ax 0, Ca 1.0, Ca_ax 0 (C)";
  return f;
}

}  // namespace

LineTypeProperties resolve_line_type(const LineTypeInput& in, double water_density_kg_per_m3, double gravity_m_per_s2) {
  validate(in, water_density_kg_per_m3, gravity_m_per_s2);

  Formula f;
  switch (in.kind) {
    case LineKind::chain:
      f = chain_formula(in);
      break;
    case LineKind::polyester:
      f = polyester_formula(in);
      break;
    case LineKind::wire:
      f = wire_formula(in);
      break;
    case LineKind::user:
      f = user_formula(in);
      break;
  }

  LineTypeProperties p;
  p.name = in.name;
  p.kind = in.kind;
  p.nominal_diameter_m = in.diameter_m;

  // Explicit values always override the formulas.
  p.mass_per_length_kg_per_m = in.mass_per_length_kg_per_m.value_or(f.mass);
  p.mass_source = in.mass_per_length_kg_per_m ? "explicit" : f.mass_src;

  p.breaking_load_N = in.breaking_load_N.value_or(f.MBL);
  p.breaking_load_source = in.breaking_load_N ? "explicit" : f.MBL_src;

  if (in.kind == LineKind::polyester) {
    // EA_static = K_rs MBL on the resolved MBL (MoorPy; K_rs 13-15, default 14).
    const double k_rs = in.static_stiffness_mbl.value_or(kPolyesterStaticMbl);
    f.EA = k_rs * p.breaking_load_N;
    f.EA_src = "polyester EA_static = " + fmt_double(k_rs) + " MBL" +
               (in.static_stiffness_mbl ? " (explicit ratio)" : " (MoorPy default)");
    p.dynamic_stiffness_mbl = in.dynamic_stiffness_mbl.value_or(kPolyesterDynamicMbl);
  }
  p.axial_stiffness_N = in.axial_stiffness_N.value_or(f.EA);
  p.stiffness_source = in.axial_stiffness_N ? "explicit" : f.EA_src;

  p.hydrodynamic_diameter_m = in.hydrodynamic_diameter_m.value_or(f.d_vol);
  p.drag_normal = in.drag_normal.value_or(f.hydro.drag_normal);
  p.drag_axial = in.drag_axial.value_or(f.hydro.drag_axial);
  p.added_mass_normal = in.added_mass_normal.value_or(f.hydro.added_mass_normal);
  p.added_mass_axial = in.added_mass_axial.value_or(f.hydro.added_mass_axial);
  const bool any_hydro_explicit =
      in.hydrodynamic_diameter_m || in.drag_normal || in.drag_axial || in.added_mass_normal || in.added_mass_axial;
  p.hydrodynamics_source = any_hydro_explicit ? f.hydro_src + "; explicit values override" : f.hydro_src;

  // Archimedes on the volume-equivalent diameter.
  const double d_h = p.hydrodynamic_diameter_m;
  p.submerged_weight_N_per_m = in.submerged_weight_N_per_m.value_or(
      (p.mass_per_length_kg_per_m - water_density_kg_per_m3 * kPi / 4.0 * d_h * d_h) * gravity_m_per_s2);
  return p;
}

double dynamic_axial_stiffness_N(const LineTypeProperties& properties, double mean_tension_N) {
  if (!(mean_tension_N >= 0.0 && std::isfinite(mean_tension_N))) {
    throw std::invalid_argument("dynamic_axial_stiffness_N: line type '" + properties.name +
                                "': mean tension must be >= 0 (N), got " + fmt_double(mean_tension_N));
  }
  if (!has_dynamic_axial_stiffness(properties)) return properties.axial_stiffness_N;
  const auto& [a, b] = properties.dynamic_stiffness_mbl;
  const double mbl = properties.breaking_load_N;
  if (!(mbl > 0.0)) {
    throw std::invalid_argument("dynamic_axial_stiffness_N: line type '" + properties.name +
                                "' has no positive breaking load (N)");
  }
  const double mean_load_pct_mbl = 100.0 * mean_tension_N / mbl;
  return (a + b * mean_load_pct_mbl) * mbl;
}

bool has_dynamic_axial_stiffness(const LineTypeProperties& properties) {
  const auto& [a, b] = properties.dynamic_stiffness_mbl;
  return properties.kind == LineKind::polyester && (a != 0.0 || b != 0.0);
}

std::vector<double> incremental_axial_stiffness_N(const std::vector<LineTypeProperties>& segment_types,
                                                  const std::vector<int>& point_segment,
                                                  const std::vector<double>& point_tension_N) {
  if (point_segment.size() != point_tension_N.size())
    throw std::invalid_argument("incremental_axial_stiffness_N: one tension per point");
  std::vector<double> EA_N;
  for (std::size_t s = 0; s < segment_types.size(); ++s) {
    const LineTypeProperties& type = segment_types[s];
    if (type.kind != LineKind::polyester) {
      EA_N.push_back(type.axial_stiffness_N);
      continue;
    }
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < point_segment.size(); ++i) {
      if (point_segment[i] == static_cast<int>(s)) sum += point_tension_N[i], ++count;
    }
    // A slack stretch (compressive effective tension at a node) loads nothing.
    EA_N.push_back(dynamic_axial_stiffness_N(type, count > 0 ? std::max(0.0, sum / count) : 0.0));
  }
  return EA_N;
}

const char* to_string(LineKind kind) {
  switch (kind) {
    case LineKind::chain:
      return "chain";
    case LineKind::wire:
      return "wire";
    case LineKind::polyester:
      return "polyester";
    case LineKind::user:
      return "user";
  }
  return "unknown";
}

const char* to_string(ChainGrade grade) {
  switch (grade) {
    case ChainGrade::R3:
      return "R3";
    case ChainGrade::R3S:
      return "R3S";
    case ChainGrade::R4:
      return "R4";
    case ChainGrade::R4S:
      return "R4S";
    case ChainGrade::R5:
      return "R5";
  }
  return "unknown";
}

const char* to_string(ChainConstruction construction) {
  switch (construction) {
    case ChainConstruction::studless:
      return "studless";
    case ChainConstruction::studlink:
      return "studlink";
  }
  return "unknown";
}

const char* to_string(WireConstruction construction) {
  switch (construction) {
    case WireConstruction::six_strand:
      return "six_strand";
    case WireConstruction::spiral_strand:
      return "spiral_strand";
  }
  return "unknown";
}

}  // namespace spiral::design
