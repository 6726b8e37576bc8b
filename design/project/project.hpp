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
#include <variant>
#include <vector>

#include "design/project/line_properties.hpp"

namespace spiral::design {

/// The format version this build reads (the `version` key).
inline constexpr int kProjectFormatVersion = 1;

/// Air density used with the hull wind coefficients when the site gives none:
/// ISO 2533 standard atmosphere at sea level.
inline constexpr double kStandardAirDensity_kg_per_m3 = 1.225;

struct Seabed {
  double friction_axial = 0.0;             ///< -, Coulomb coefficient along the line, >= 0
  double friction_lateral = 0.0;           ///< -, Coulomb coefficient across the line, >= 0
  double normal_stiffness_Pa_per_m = 0.0;  ///< contact pressure per metre of penetration, > 0
};

struct Site {
  double depth_m = 0.0;                                          ///< water depth, > 0; seabed at z_g = -depth_m
  double water_density_kg_per_m3 = 0.0;                          ///< > 0
  double gravity_m_per_s2 = 0.0;                                 ///< > 0
  double air_density_kg_per_m3 = kStandardAirDensity_kg_per_m3;  ///< > 0, for hull wind loads
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

/// The static model of a mooring line in the statics and equilibrium
/// analyses: the multi-segment elastic catenary, or the FE line (Newton
/// statics with current drag and bending). Dynamic analyses always build an
/// FE model from `MooringLine::fe`.
enum class LineModel { catenary, fe };

/// Default FE element lengths (docs/project-format.md): mooring lines, risers.
inline constexpr double kDefaultLineElementLength_m = 10.0;
inline constexpr double kDefaultRiserElementLength_m = 5.0;

/// A finer mesh around the touchdown point of the at-rest static shape.
struct TouchdownRefinement {
  double length_m = 0.0;          ///< arc length of the refined zone, centred on the TDP, > 0
  double element_length_m = 0.0;  ///< element length inside it, > 0, <= FeMesh::element_length_m
  bool operator==(const TouchdownRefinement&) const = default;
};

/// Discretization of a line or riser into finite elements (unstretched lengths).
struct FeMesh {
  double element_length_m = kDefaultLineElementLength_m;  ///< target element length, > 0
  std::optional<TouchdownRefinement> touchdown_refinement;
  bool operator==(const FeMesh&) const = default;
};

/// The lines' mesh in the global (time-domain) analyses (`global_analysis`):
/// the coupled level's FE lines and the prescribed-motion FE lines of
/// `--line-dynamics`. Their outputs are the hull's motions and the lines' top
/// tensions, which a mesh far coarser than the statics' converges for
/// (docs/decisions/global-analysis-mesh.md); the statics, the stiffness, the
/// SOZ, the riser checks and the S-C line reduction keep each line's `fe`.
struct GlobalAnalysis {
  /// Every section of every mooring line and riser in equal elements of at
  /// most this length, no touchdown refinement (m, > 0; absent: each line's
  /// own `fe` mesh).
  std::optional<double> element_length_m;
  bool operator==(const GlobalAnalysis&) const = default;
};

struct MooringLine {
  std::string name;
  Eigen::Vector3d anchor_g = Eigen::Vector3d::Zero();    ///< global frame, m
  Eigen::Vector3d fairlead_b = Eigen::Vector3d::Zero();  ///< hull body frame, m
  std::vector<LineSegment> segments;                     ///< from the anchor to the fairlead
  std::vector<Attachment> attachments;
  LineModel model = LineModel::catenary;
  FeMesh fe{kDefaultLineElementLength_m, std::nullopt};
};

struct LineGroup {
  std::string name;
  std::vector<std::string> lines;  ///< names of `mooring.lines` entries
};

struct Mooring {
  std::vector<MooringLine> lines;
  std::vector<LineGroup> groups;
};

/// Mean wind or current load coefficients of the hull against the relative
/// heading (the direction of propagation of the wind or current in the body
/// frame: its global heading minus the hull yaw). Loads in body axes, about the
/// hull reference point: F_x = 1/2 rho V^2 surge(beta), F_y = 1/2 rho V^2
/// sway(beta), M_z = 1/2 rho V^2 yaw(beta); rho the air (wind) or water
/// (current) density, V the wind speed at `reference_height_m` or the surface
/// current speed. Linear interpolation in heading, periodic over 360 deg.
struct HullLoadCoefficients {
  std::vector<double> headings_rad;  ///< >= 2 values, strictly increasing, in [0, 2 pi)
  std::vector<double> surge_m2;      ///< C A per heading, m^2 (signed, body x)
  std::vector<double> sway_m2;       ///< C A per heading, m^2 (signed, body y)
  std::vector<double> yaw_m3;        ///< C A L per heading, m^3 (signed, about body z)
};

struct WindCoefficients : HullLoadCoefficients {
  double reference_height_m = 10.0;  ///< height of the speed V above mean water level, > 0
};

/// Mean drift coefficients from a WAMIT .12d file (difference-frequency QTF;
/// its diagonal gives the mean drift). Dimensional values follow the WAMIT
/// manual (ch. 4) with the file's length scale `ulen_m`.
struct MeanDriftFile {
  std::filesystem::path file;  ///< resolved relative to the project file's folder
  double ulen_m = 1.0;         ///< WAMIT ULEN of the file, > 0
  double period_scale = 1.0;   ///< file periods multiplied by this (Froude-scaled hull: sqrt(lambda)), > 0
};
/// What column 1 of a WAMIT-format file holds.
enum class FrequencyColumnKind { period, angular_frequency };
/// How the low-frequency hull equations take the radiation forces of the .1
/// data: A(w_LF) (no memory), or A(inf) with Cummins' retardation kernel.
enum class RadiationModel { low_frequency, memory };
/// Where the hull's hydrodynamic loads come from: WAMIT-format files of a BEM
/// code, or a Morison member model built from hull.geometry.
enum class HullHydrodynamicsModel { bem, morison };

/// Where a BEM hull's first-order wave excitation comes from: the
/// excitation_file / rao_file (none given: no wave-frequency motion), or the
/// Morison members of hull.geometry with the MacCamy–Fuchs correction.
enum class ExcitationSource { files, morison_maccamy_fuchs };
/// Frequency-dependent hull hydrodynamics from WAMIT-format files, and the
/// hull's viscous damping (docs/project-format.md, "Hull hydrodynamics").
struct HullHydrodynamics {
  HullHydrodynamicsModel model = HullHydrodynamicsModel::bem;
  std::filesystem::path radiation_file;  ///< WAMIT .1 (added mass, radiation damping); bem only
  FrequencyColumnKind frequency_column = FrequencyColumnKind::period;
  double ulen_m = 1.0;                                   ///< WAMIT ULEN, > 0
  double period_scale = 1.0;                             ///< periods multiplied by this (frequencies divided), > 0
  std::optional<std::filesystem::path> excitation_file;  ///< WAMIT .3 (first-order excitation)
  /// bem without a .3 or .4: the first-order excitation from the Morison
  /// members of hull.geometry with the MacCamy–Fuchs correction of the
  /// columns (engine/hull/morison_hull.hpp), through the BEM radiation.
  ExcitationSource excitation = ExcitationSource::files;
  std::optional<std::filesystem::path> rao_file;  ///< WAMIT .4 (motion RAOs)
  /// Diagonal viscous damping, surge..yaw: N s/m (translations), N m s/rad (rotations), >= 0.
  Eigen::Matrix<double, 6, 1> linear_damping = Eigen::Matrix<double, 6, 1>::Zero();
  /// Quadratic damping per DOF, N s^2/m^2, N m s^2/rad^2, >= 0.
  Eigen::Matrix<double, 6, 1> quadratic_damping = Eigen::Matrix<double, 6, 1>::Zero();
  /// Frequency of A(w) used for the low-frequency equations, rad/s, > 0;
  /// absent: the lowest frequency in the file.
  std::optional<double> added_mass_frequency_rad_per_s;
  /// Radiation forces in the time-domain analyses (docs/project-format.md).
  RadiationModel radiation = RadiationModel::low_frequency;
  double memory_duration_s = 60.0;  ///< retardation kernel length t_max, > memory_time_step_s
  double memory_time_step_s = 0.1;  ///< kernel and velocity-history step, > 0
  /// morison: target strip length along the members, m, > 0.
  double strip_length_m = 1.0;
};

/// Mean drift coefficients as a table: force per wave amplitude squared
/// (mean force in regular waves of amplitude a is coefficient x a^2), body
/// axes about the reference point; headings as for the wave heading relative
/// to the hull (direction of propagation in the body frame).
struct MeanDriftTable {
  std::vector<double> headings_rad;           ///< >= 2, strictly increasing, in [0, 2 pi)
  std::vector<double> frequencies_rad_per_s;  ///< >= 1, > 0, strictly increasing
  /// [heading][frequency]; N/m^2 (surge, sway) and N m/m^2 (yaw).
  std::vector<std::vector<double>> surge_N_per_m2;
  std::vector<std::vector<double>> sway_N_per_m2;
  std::vector<std::vector<double>> yaw_N_m_per_m2;
};

using MeanDrift = std::variant<MeanDriftFile, MeanDriftTable>;

/// How the mean drift data serve wave headings they do not hold
/// (`hull.mean_drift.symmetry`, `hull.mean_drift.wave_frame_fill`;
/// engine/hull/mean_drift_headings.hpp). Both are the project's explicit
/// choice: without them a heading outside the data is an input error.
struct MeanDriftHeadings {
  /// The hull maps onto itself turned by 360°/n (`symmetry.rotations`, ≥ 1).
  int symmetry_rotations = 1;
  /// The hull maps onto itself under y → −y (`symmetry.mirror_xz`).
  bool symmetry_mirror_xz = false;
  /// Wave-frame interpolation across gaps between headings no wider than
  /// this (`wave_frame_fill.max_span_deg`, in (0, 360]); absent: none.
  std::optional<double> wave_frame_fill_max_span_rad;
};

/// Morison coefficients of a member (hydrodynamics.model: morison), on its
/// diameter, normal to its axis (DNV-RP-C205 §6.2; defaults: engine/hull/morison_hull.hpp).
struct MemberCoefficients {
  double drag = 1.05;       ///< Cd, >= 0 (DNV-RP-C205 §6.7.2: rough, post-critical)
  double added_mass = 1.0;  ///< Ca, >= 0 (DNV-RP-C205 App. D: circle)
};

/// A vertical circular column (body frame).
struct HullColumn {
  Eigen::Vector2d center_b = Eigen::Vector2d::Zero();  ///< axis position [x, y], m
  double z_bottom_m = 0.0;                             ///< body z of the bottom, < z_top_m
  double z_top_m = 0.0;                                ///< body z of the top
  double diameter_m = 0.0;                             ///< > 0
  MemberCoefficients coefficients;
  /// Ca_end of each flat end face below water, on (2/3) pi R^3 (2/pi: one
  /// wetted side of a disc, DNV-RP-C205 App. D), >= 0.
  double end_added_mass = 2.0 / 3.141592653589793;
  double end_drag = 0.0;  ///< Cd_end of each end face on pi R^2 (axial drag), >= 0
};

/// A circular pontoon or brace between two points (body frame).
struct HullPontoon {
  Eigen::Vector3d from_b = Eigen::Vector3d::Zero();  ///< m
  Eigen::Vector3d to_b = Eigen::Vector3d::Zero();    ///< m, distinct from from_b
  double diameter_m = 0.0;                           ///< > 0
  MemberCoefficients coefficients;
};

/// Simple member geometry of the hull, for rendering and Morison members.
struct HullGeometry {
  std::vector<HullColumn> columns;
  std::vector<HullPontoon> pontoons;
  /// A WAMIT low-order panel mesh (.gdf) of the hull, body frame, resolved
  /// relative to the project file's folder: the 3D views draw it instead of
  /// the members (engine/hull/wamit_gdf.hpp). The members still feed the
  /// Morison model.
  std::optional<std::filesystem::path> panel_mesh;
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
  /// Mean environmental loads (absent: no wind / current load on the hull, no
  /// mean drift).
  std::optional<WindCoefficients> wind_coefficients;
  std::optional<HullLoadCoefficients> current_coefficients;
  std::optional<MeanDrift> mean_drift;
  MeanDriftHeadings mean_drift_headings;           ///< read inside hull.mean_drift
  std::optional<HullHydrodynamics> hydrodynamics;  ///< absent: no added mass, no WF motions
  std::optional<HullGeometry> geometry;
};

enum class RiserKind { scr, lazy_wave, flexible };

/// A riser section of uniform properties, ordered from the hang-off down.
struct RiserSection {
  double length_m = 0.0;
  double outer_diameter_m = 0.0;  ///< steel (or flexible outer-sheath) outer diameter
  double contents_density_kg_per_m3 = 0.0;
  /// Steel pipe properties: required for scr and lazy_wave, optional for flexible.
  std::optional<double> wall_thickness_m;
  /// Bore of a flexible pipe without a steel wall (layered wall, API 17J):
  /// required there with axial_stiffness, bending_stiffness, mass_per_length.
  std::optional<double> inner_diameter_m;
  std::optional<double> youngs_modulus_Pa;
  std::optional<double> yield_stress_Pa;
  std::optional<double> steel_density_kg_per_m3;
  /// External coating (both or neither).
  std::optional<double> coating_thickness_m;
  std::optional<double> coating_density_kg_per_m3;
  /// Lazy-wave buoyancy modules smeared to an equivalent cylinder (both or neither).
  std::optional<double> buoyancy_outer_diameter_m;
  std::optional<double> buoyancy_density_kg_per_m3;
  /// Explicit values (flexible pipes: from the manufacturer's data sheet), or
  /// overrides of the steel formulas (each one given replaces its formula).
  std::optional<double> axial_stiffness_N;         ///< EA
  std::optional<double> bending_stiffness_N_m2;    ///< EI
  std::optional<double> mass_per_length_kg_per_m;  ///< in air, empty pipe incl. coating
  /// Morison coefficients on the outermost diameter.
  double drag_normal = 1.0;
  double drag_axial = 0.0;
  double added_mass_normal = 1.0;
  double added_mass_axial = 0.0;
  bool operator==(const RiserSection&) const = default;
};

/// The design condition of a load case (API RP 2RD): it selects the riser
/// design factor. 1-yr operating: normal; 100-yr: extreme; beyond 100-yr or
/// damaged: survival.
enum class DesignCondition { normal, extreme, survival };

/// Whether a case has every mooring line (intact) or one removed (damaged):
/// it selects the mooring code's factors (API RP 2SK, DNV-OS-E301). Not a
/// design condition, which is the riser code's (above).
enum class LineIntegrity { intact, damaged };

/// API RP 2RD allowable-stress design factors: von Mises stress <= factor x
/// yield stress, the factor being C_f C_a with C_a = 2/3 and C_f = 1.0, 1.2,
/// 1.5. Each in (0, 1].
struct RiserDesignFactors {
  double normal = 0.67;
  double extreme = 0.80;
  double survival = 1.00;
  bool operator==(const RiserDesignFactors&) const = default;
};

/// Riser acceptance criteria (DESIGN.md §6) of one riser: its kind's
/// defaults (riser_criteria_defaults), then `criteria.risers`, then the
/// riser's own `criteria` (riser_criteria). Absent optionals are not checked.
struct RiserCriteria {
  RiserDesignFactors design_factor;
  double min_effective_tension_N = 0.0;     ///< >= 0, everywhere along the riser
  std::optional<double> max_top_tension_N;  ///< > 0
  std::optional<double> max_top_angle_rad;  ///< from vertical, (0, pi/2)
  /// Angle between the riser's top tangent and the hull-fixed flex-joint axis
  /// (the at-rest top tangent, turning with the hull), (0, pi/2).
  std::optional<double> max_flex_joint_rotation_rad;
  std::optional<double> min_bending_radius_m;       ///< > 0; required for flexible risers
  std::optional<double> max_touchdown_excursion_m;  ///< TDP horizontal travel from rest, > 0
  bool operator==(const RiserCriteria&) const = default;
};

/// Riser criteria as written (`criteria.risers`, `risers[i].criteria`):
/// only the keys given replace the values below them (riser_criteria()).
struct RiserCriteriaOverrides {
  std::optional<double> design_factor_normal;
  std::optional<double> design_factor_extreme;
  std::optional<double> design_factor_survival;
  std::optional<double> min_effective_tension_N;
  std::optional<double> max_top_tension_N;
  std::optional<double> max_top_angle_rad;
  std::optional<double> max_flex_joint_rotation_rad;
  std::optional<double> min_bending_radius_m;
  std::optional<double> max_touchdown_excursion_m;
};

struct Riser {
  std::string name;
  RiserKind kind = RiserKind::scr;
  Eigen::Vector3d hang_off_b = Eigen::Vector3d::Zero();  ///< hull body frame, m
  double azimuth_rad = 0.0;                              ///< global direction the riser runs away from the hull
  double top_angle_rad = 0.0;                            ///< from vertical, [0, pi/2)
  std::vector<RiserSection> sections;
  /// Internal pressure at the hang-off above ambient (gauge), >= 0; below the
  /// hang-off the contents head is added.
  double internal_pressure_Pa = 0.0;
  FeMesh fe{kDefaultRiserElementLength_m, std::nullopt};
  RiserCriteriaOverrides criteria;
};

enum class WaveSpectrum { jonswap, pierson_moskowitz };
enum class WindSpectrum { api, npd, none };

struct Waves {
  WaveSpectrum spectrum = WaveSpectrum::jonswap;
  double hs_m = 0.0;                  ///< significant wave height, > 0
  double tp_s = 0.0;                  ///< peak period, > 0
  std::optional<double> gamma;        ///< JONSWAP peak enhancement, >= 1 (absent: DNV-RP-C205 3.5.5.5)
  double heading_rad = 0.0;           ///< direction of propagation
  std::optional<double> spreading_s;  ///< cos-2s directional spreading exponent, > 0 (absent: long-crested)
  bool operator==(const Waves&) const = default;
};

struct Wind {
  double speed_m_per_s = 0.0;  ///< 1-hour mean at the reference height, >= 0
  double heading_rad = 0.0;    ///< direction the wind blows towards
  WindSpectrum spectrum = WindSpectrum::none;
  double reference_height_m = 10.0;  ///< above mean water level, > 0
  bool operator==(const Wind&) const = default;
};

struct CurrentPoint {
  double z_m = 0.0;            ///< global z, in [-depth, 0]
  double speed_m_per_s = 0.0;  ///< >= 0
  bool operator==(const CurrentPoint&) const = default;
};

struct Current {
  double heading_rad = 0.0;
  std::vector<CurrentPoint> profile;  ///< from the surface down (z strictly decreasing)
  bool operator==(const Current&) const = default;
};

struct Environment {
  std::string name;
  std::optional<Waves> waves;
  std::optional<Wind> wind;
  std::optional<Current> current;
};

struct LoadCase {
  std::string name;
  std::string environment;                               ///< name of an `environments` entry
  std::optional<std::string> damaged_line;               ///< name of a mooring line removed in this case
  DesignCondition condition = DesignCondition::extreme;  ///< selects the riser design factor
  /// The seed of the case's wave and wind realizations in the stages' storms
  /// and verification runs (`seed`, an integer >= 1): the same seed, the same sea.
  int seed = 1;
};

/// The line integrity a load-case matrix entry covers (`load_case_matrix[i].damaged`).
enum class MatrixDamage { none, every_line, listed };

/// `load_case_matrix[i]`: load cases generated from one environment turned
/// to several headings, intact and with single lines removed
/// (load_case_matrix.hpp expands them; docs/project-format.md).
struct LoadCaseMatrixEntry {
  std::string environment;           ///< the base environment: its headings are those of matrix heading 0
  std::vector<double> headings_rad;  ///< >= 1, distinct, in [0, 2 pi): added to every heading of the base
  DesignCondition condition = DesignCondition::extreme;  ///< of the intact cases
  MatrixDamage damaged = MatrixDamage::none;
  std::vector<std::string> damaged_lines;                         ///< MatrixDamage::listed
  DesignCondition damaged_condition = DesignCondition::survival;  ///< of the damaged cases
  /// Seeds of the realizations (`seeds`, integers >= 1, distinct): with more
  /// than one, every case is made once per seed, named `<case>-seed<k>`.
  std::vector<int> seeds{1};
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
  RiserCriteriaOverrides risers;               ///< project-wide, as given; riser_criteria() merges the layers
  std::optional<double> max_offset_pct_depth;  ///< %, of water depth, > 0
};

/// Riser model of a stage's safe operational zones (`stages[i].soz.model`):
/// the catenary screening model or the FE reference (design/soz/soz.hpp, SozModel).
enum class StageSozModel { catenary, fe };

/// How a stage computes the riser safe operational zones (`stages[i].soz`).
/// The screening default keeps the stage report cheap (12 SCRs at 15°:
/// 0.4 s; the FE model at 5° costs tens of seconds).
struct StageSoz {
  StageSozModel model = StageSozModel::catenary;
  double step_deg = 15.0;  ///< direction step, > 0, divides 360
};

struct Stage {
  std::string name;  ///< preliminary, intermediate, advanced (DESIGN.md §2) or a user name
  StageSoz soz;
  /// Simulated time of the advanced stage's coupled and S-C verification runs
  /// (s, > 0; absent: 3 h, the duration the MPM extremes refer to). Only the
  /// advanced stage takes it (`stage_duration_advanced_only`).
  std::optional<double> duration_s;
  /// Run the pretension optimizer after this stage even when its checks
  /// pass (`optimize`); it runs anyway when the preliminary stage's offset or
  /// tension checks fail (spiral run's feedback, DESIGN.md §2).
  bool optimize = false;
  /// Iterations of the stage with the optimizer's payouts, the first
  /// included (`max_iterations`, ≥ 1).
  int max_iterations = 3;
  /// Intermediate stage: the N most severe cases by each ranking measure
  /// (tension, offset, riser), with every failing case, go to the advanced
  /// stage (`critical_cases`, ≥ 1; absent: 3).
  std::optional<int> critical_cases;
};

/// What the pretension optimizer seeks (`optimization.objective`,
/// design/optimization/pretension_optimizer.hpp).
enum class OptimizationObjective {
  max_soz_margin,       ///< the smallest offset margin to the platform SOZ over all cases, as large as possible
  min_max_utilization,  ///< the largest line utilization over all cases, as small as possible
  min_total_payout,     ///< the least winching, sum of |payout| over the groups, that meets every constraint
  min_max_offset,       ///< the largest static offset over all cases, as small as possible
};

/// NLopt algorithm of the optimizer (`optimization.algorithm`): SLSQP and
/// CCSAQ use the analytic gradients, COBYLA none.
enum class OptimizationAlgorithm { slsqp, ccsaq, cobyla };

/// The damaged conditions the constraints cover (`optimization.damaged`):
/// the load cases as written (each with its own damaged line, if any), or
/// also every intact case with each single mooring line removed in turn.
enum class DamagedConditions { load_cases, every_line };

/// The payout range of one group (`optimization.bounds[i]`), m: negative
/// hauls in (shorter line, higher pretension), positive pays out.
struct PayoutBound {
  std::string group;
  double min_m = 0.0;
  double max_m = 0.0;
};

/// Target-pretension mode (`optimization.target_pretension[i]`): every line
/// of the group gets the payout that gives it this fairlead tension with the
/// hull at its rest position.
struct PretensionTarget {
  std::string group;
  double tension_N = 0.0;  ///< > 0
};

/// The pretension optimization study (`optimization`, docs/project-format.md).
struct Optimization {
  /// The design variables: one payout per group. Empty: the project's groups
  /// in order, skipping a group that shares a line with an earlier one; a
  /// line in no group is its own group.
  std::vector<std::string> groups;
  std::vector<PayoutBound> bounds;  ///< groups without one: ± payout_limit_pct of their shortest line
  double payout_limit_pct = 2.0;    ///< %, of the line's total unstretched length, > 0
  OptimizationObjective objective = OptimizationObjective::max_soz_margin;
  OptimizationAlgorithm algorithm = OptimizationAlgorithm::slsqp;
  std::vector<std::string> cases;  ///< load cases constrained; empty: every load case
  DamagedConditions damaged = DamagedConditions::load_cases;
  std::optional<double> min_laid_length_m;  ///< every line keeps at least this on the seabed, >= 0
  std::optional<double> min_tension_N;      ///< every fairlead tension at least this (no slack), > 0
  double payout_tolerance_m = 0.05;         ///< stop when no payout moves more than this, > 0
  int max_evaluations = 200;                ///< NLopt evaluation cap, >= 1
  std::vector<PretensionTarget> target_pretension;
};

/// Position of a YAML node in its file (1-based).
struct SourcePosition {
  int line = 1;
  int column = 1;
  /// The file it was written in when that is not Project::source_file: a
  /// section the project takes from its base file (`extends`).
  std::string file;
};

/// Field path (`mooring.lines[0].anchor`) -> where it was written.
using SourceMap = std::map<std::string, SourcePosition, std::less<>>;

struct Project {
  int version = kProjectFormatVersion;
  std::string name;
  std::optional<std::string> description;
  std::string source_file;  ///< file name as given by the user (or the source name of parsed text)
  /// The base files of a variation (`extends`), nearest first, as resolved
  /// from the file that names each; the sections this file does not write come from them.
  std::vector<std::string> base_files;
  Site site;
  std::vector<LineTypeInput> line_types;
  Mooring mooring;
  Hull hull;
  std::vector<Riser> risers;
  std::vector<Environment> environments;
  std::vector<LoadCase> load_cases;  ///< as written, then the expanded load_case_matrix (load_validated_project)
  std::vector<LoadCaseMatrixEntry> load_case_matrix;
  Criteria criteria;
  std::vector<Stage> stages;  ///< absent in YAML: preliminary, intermediate, advanced
  std::optional<Optimization> optimization;
  GlobalAnalysis global_analysis;
  /// Where each field came from, so later passes report file:line:col.
  /// Empty for projects built in code.
  SourceMap source_map;
};

const char* to_string(AttachmentKind kind);
const char* to_string(RiserKind kind);
const char* to_string(WaveSpectrum spectrum);
const char* to_string(FrequencyColumnKind column);
const char* to_string(RadiationModel model);
const char* to_string(HullHydrodynamicsModel model);
const char* to_string(WindSpectrum spectrum);
const char* to_string(MooringCode code);
const char* to_string(LineModel model);
const char* to_string(DesignCondition condition);
const char* to_string(LineIntegrity integrity);  ///< "intact" | "damaged"
const char* to_string(OptimizationObjective objective);
const char* to_string(OptimizationAlgorithm algorithm);
const char* to_string(DamagedConditions damaged);

/// `base` with the values given in `overrides` replacing its own.
RiserCriteria with_overrides(RiserCriteria base, const RiserCriteriaOverrides& overrides);

/// Unstretched length of a mooring line (its segments) or a riser (its sections), m.
double total_length_m(const MooringLine& line);
double total_length_m(const Riser& riser);

/// The criteria a riser of `kind` gets where neither `criteria.risers` nor
/// the riser gives a value (docs/project-format.md, "Riser criteria", for the
/// sources):
///   scr, lazy_wave: design factors 0.67 / 0.80 / 1.00 of yield (API RP 2RD
///     allowable-stress factors C_f C_a, C_a = 2/3, C_f = 1.0 / 1.2 / 1.5);
///     min effective tension 0 (API RP 2RD, DNV-OS-F201: no compression in
///     the touchdown zone); flex-joint rotation 15° (a typical flex-joint
///     design rotation; the codes leave it to the joint's data sheet).
///   flexible: min effective tension 0 (API RP 17B: no axial compression,
///     which birdcages the armour wires); no flex joint (a bend stiffener
///     takes the top angle: not checked); no steel wall (the design factors
///     are not used); min bending radius: no default — it is a property of
///     the pipe's structure (API 17J), required (validation
///     `flexible_min_bending_radius`).
RiserCriteriaOverrides riser_criteria_defaults(RiserKind kind);

/// The criteria of `riser`: its kind's defaults, then `criteria.risers`, then
/// the riser's own `criteria`.
RiserCriteria riser_criteria(const Criteria& criteria, const Riser& riser);

/// The environment a load case names (validation guarantees it exists).
const Environment& environment_of(const Project& project, const LoadCase& load_case);

/// Whether two load cases of `project` are the same analysis under two
/// names: equal sea, wind and current (value for value; the environments'
/// names aside), the same damaged line, design condition and seed. Every
/// result of one is then the other's (a load-case matrix may list a case
/// the project also names, e.g. an environment turned by 45 deg and the
/// 45 deg environment itself).
bool same_analysis_inputs(const Project& project, const LoadCase& a, const LoadCase& b);

/// The mooring line named `name`, for names the validation or a request
/// check has already found (std::logic_error otherwise: a bug).
const MooringLine& mooring_line(const Project& project, const std::string& name);

/// The design factor of `condition`.
double design_factor(const RiserDesignFactors& factors, DesignCondition condition);

}  // namespace spiral::design
