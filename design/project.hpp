#pragma once
// The project model, format v1: what one YAML project file describes, as plain
// structs in SI units (m, kg, s, N, Pa, rad). The YAML mapping is in
// project_loader.cpp, the semantic checks in project_validation.cpp, and the
// key-by-key reference (units, defaults, ranges, frames) in
// docs/project-format.md.
//
// Frames (docs/project-format.md, "Frames"):
//  - global (`_g`): origin at mean water level, z up, seabed at z = -depth;
//  - hull body (`_b`): origin at the hull reference point, axes aligned with
//    the global ones at rest.
// Directions (`heading_rad`, `azimuth_rad`): counter-clockwise from global +x;
// environmental headings are the direction of propagation.
//
// Optional inputs are std::optional (never sentinel values); defaults that the
// format documents are written as member initialisers.

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "design/line_properties.hpp"

namespace spiral::design {

/// The format version this build reads (the `version` key).
inline constexpr int kProjectFormatVersion = 1;

struct Seabed {
  double friction_axial = 0.0;             ///< -, Coulomb coefficient along the line, >= 0
  double friction_lateral = 0.0;           ///< -, Coulomb coefficient across the line, >= 0
  double normal_stiffness_Pa_per_m = 0.0;  ///< contact pressure per metre of penetration, > 0
};

struct Site {
  double depth_m = 0.0;                  ///< water depth, > 0; seabed at z_g = -depth_m
  double water_density_kg_per_m3 = 0.0;  ///< > 0
  double gravity_m_per_s2 = 0.0;         ///< > 0
  Seabed seabed;
};

enum class AttachmentKind { clump, buoy };

/// A point mass / buoyancy at the joint after segment `after_segment`.
struct Attachment {
  int after_segment = 0;  ///< 0-based index of the segment the joint follows; < segments - 1
  AttachmentKind kind = AttachmentKind::clump;
  double mass_kg = 0.0;    ///< in air, >= 0
  double volume_m3 = 0.0;  ///< displaced volume, >= 0
};

struct LineSegment {
  std::string type;       ///< name of a `line_types` entry
  double length_m = 0.0;  ///< unstretched, > 0
};

struct MooringLine {
  std::string name;
  Eigen::Vector3d anchor_g = Eigen::Vector3d::Zero();    ///< global frame, m
  Eigen::Vector3d fairlead_b = Eigen::Vector3d::Zero();  ///< hull body frame, m
  std::vector<LineSegment> segments;                     ///< from the anchor to the fairlead
  std::vector<Attachment> attachments;
};

struct LineGroup {
  std::string name;
  std::vector<std::string> lines;  ///< names of `mooring.lines` entries
};

struct Mooring {
  std::vector<MooringLine> lines;
  std::vector<LineGroup> groups;
};

struct Hull {
  Eigen::Vector3d reference_point_g = Eigen::Vector3d::Zero();    ///< body origin at rest, m
  double mass_kg = 0.0;                                           ///< > 0
  Eigen::Vector3d center_of_gravity_b = Eigen::Vector3d::Zero();  ///< m
  /// Exactly one of the two is given: radii of gyration about the CoG (m,
  /// about body x, y, z) or the inertia tensor about the CoG (kg m^2).
  std::optional<Eigen::Vector3d> radii_of_gyration_m;
  std::optional<Eigen::Matrix3d> inertia_kg_m2;
  /// Hydrostatics: either all four values below or a WAMIT .hst file (or both;
  /// the file's restoring matrix then takes precedence in the engine).
  std::optional<double> displaced_volume_m3;
  std::optional<Eigen::Vector3d> center_of_buoyancy_b;  ///< m
  std::optional<double> waterplane_area_m2;
  std::optional<Eigen::Vector2d> waterplane_inertia_m4;  ///< second moments about body x, y
  /// WAMIT .hst file, resolved relative to the project file's folder.
  std::optional<std::filesystem::path> hydrostatics_file;
};

enum class RiserKind { scr, lazy_wave, flexible };

/// A riser section of uniform properties, ordered from the hang-off down.
struct RiserSection {
  double length_m = 0.0;
  double outer_diameter_m = 0.0;  ///< steel (or flexible) outer diameter
  double contents_density_kg_per_m3 = 0.0;
  /// Steel pipe properties: required for scr and lazy_wave, optional for flexible.
  std::optional<double> wall_thickness_m;
  std::optional<double> youngs_modulus_Pa;
  std::optional<double> yield_stress_Pa;
  std::optional<double> steel_density_kg_per_m3;
  /// External coating (both or neither).
  std::optional<double> coating_thickness_m;
  std::optional<double> coating_density_kg_per_m3;
  /// Lazy-wave buoyancy modules smeared to an equivalent cylinder (both or neither).
  std::optional<double> buoyancy_outer_diameter_m;
  std::optional<double> buoyancy_density_kg_per_m3;
  /// Explicit overrides (flexible pipes: from the manufacturer's data sheet).
  std::optional<double> axial_stiffness_N;         ///< EA
  std::optional<double> bending_stiffness_N_m2;    ///< EI
  std::optional<double> mass_per_length_kg_per_m;  ///< in air, empty pipe incl. coating
  /// Morison coefficients on the outermost diameter.
  double drag_normal = 1.0;
  double drag_axial = 0.0;
  double added_mass_normal = 1.0;
  double added_mass_axial = 0.0;
};

struct Riser {
  std::string name;
  RiserKind kind = RiserKind::scr;
  Eigen::Vector3d hang_off_b = Eigen::Vector3d::Zero();  ///< hull body frame, m
  double azimuth_rad = 0.0;    ///< global direction the riser runs away from the hull
  double top_angle_rad = 0.0;  ///< from vertical, [0, pi/2)
  std::vector<RiserSection> sections;
};

enum class WaveSpectrum { jonswap, pierson_moskowitz };
enum class WindSpectrum { api, npd, none };

struct Waves {
  WaveSpectrum spectrum = WaveSpectrum::jonswap;
  double hs_m = 0.0;            ///< significant wave height, > 0
  double tp_s = 0.0;            ///< peak period, > 0
  std::optional<double> gamma;  ///< JONSWAP peak enhancement, >= 1 (absent: DNV-RP-C205 3.5.5.5)
  double heading_rad = 0.0;     ///< direction of propagation
  std::optional<double>
      spreading_s;  ///< cos-2s directional spreading exponent, > 0 (absent: long-crested)
};

struct Wind {
  double speed_m_per_s = 0.0;  ///< 1-hour mean at the reference height, >= 0
  double heading_rad = 0.0;    ///< direction the wind blows towards
  WindSpectrum spectrum = WindSpectrum::none;
  double reference_height_m = 10.0;  ///< above mean water level, > 0
};

struct CurrentPoint {
  double z_m = 0.0;            ///< global z, in [-depth, 0]
  double speed_m_per_s = 0.0;  ///< >= 0
};

struct Current {
  double heading_rad = 0.0;
  std::vector<CurrentPoint> profile;  ///< from the surface down (z strictly decreasing)
};

struct Environment {
  std::string name;
  std::optional<Waves> waves;
  std::optional<Wind> wind;
  std::optional<Current> current;
};

struct LoadCase {
  std::string name;
  std::string environment;                  ///< name of an `environments` entry
  std::optional<std::string> damaged_line;  ///< name of a mooring line removed in this case
};

enum class MooringCode { api_rp_2sk, dnv_os_e301 };

/// API RP 2SK (3rd ed., Table 2) safety factors on MBL.
struct ApiRp2skFactors {
  double intact_quasi_static = 2.00;
  double intact_dynamic = 1.67;
  double damaged_quasi_static = 1.43;
  double damaged_dynamic = 1.25;
};

/// DNV-OS-E301 (Ch. 2 Sec. 2, Tables 1-2) partial safety factors on the mean
/// and dynamic tension for the ULS (intact) and ALS (one line damaged).
struct DnvOsE301Factors {
  int consequence_class = 1;  ///< 1 or 2
  double uls_mean = 1.10;     ///< class 2: 1.40
  double uls_dynamic = 1.50;  ///< class 2: 2.10
  double als_mean = 1.00;
  double als_dynamic = 1.10;
};

/// Default DNV-OS-E301 factors of a consequence class (1 or 2).
DnvOsE301Factors dnv_os_e301_defaults(int consequence_class);

struct MooringCriteria {
  MooringCode code = MooringCode::api_rp_2sk;
  /// Set (with defaults filled in) for the chosen code only.
  std::optional<ApiRp2skFactors> api_rp_2sk;
  std::optional<DnvOsE301Factors> dnv_os_e301;
};

struct Criteria {
  MooringCriteria mooring;
  std::optional<double> max_offset_pct_depth;  ///< %, of water depth, > 0
};

struct Stage {
  std::string name;  ///< preliminary, intermediate, advanced (DESIGN.md §2) or a user name
};

/// Position of a YAML node in its file (1-based).
struct SourcePosition {
  int line = 1;
  int column = 1;
};

/// Field path (`mooring.lines[0].anchor`) -> where it was written.
using SourceMap = std::map<std::string, SourcePosition, std::less<>>;

struct Project {
  int version = kProjectFormatVersion;
  std::string name;
  std::optional<std::string> description;
  std::string source_file;  ///< file name as given by the user (or the source name of parsed text)
  Site site;
  std::vector<LineTypeInput> line_types;
  Mooring mooring;
  Hull hull;
  std::vector<Riser> risers;
  std::vector<Environment> environments;
  std::vector<LoadCase> load_cases;
  Criteria criteria;
  std::vector<Stage> stages;  ///< absent in YAML: preliminary, intermediate, advanced
  /// Where each field came from, so later passes report file:line:col.
  /// Empty for projects built in code.
  SourceMap source_map;
};

const char* to_string(AttachmentKind kind);
const char* to_string(RiserKind kind);
const char* to_string(WaveSpectrum spectrum);
const char* to_string(WindSpectrum spectrum);
const char* to_string(MooringCode code);

}  // namespace spiral::design
