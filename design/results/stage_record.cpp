#include "design/results/stage_record.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>

// Member lists of every struct a record holds. nlohmann's macros define
// to_json/from_json in each struct's namespace (found by ADL); they are
// defined here only, so the layout of a record is read in one place.

namespace nlohmann {

template <class T>
struct adl_serializer<std::optional<T>> {
  static void to_json(json& j, const std::optional<T>& value) {
    if (value)
      j = *value;
    else
      j = nullptr;
  }
  static void from_json(const json& j, std::optional<T>& value) {
    if (j.is_null())
      value.reset();
    else
      value = j.get<T>();
  }
};

/// Any Eigen matrix of doubles: its size and its coefficients in storage order.
template <int Rows, int Cols, int Options, int MaxRows, int MaxCols>
struct adl_serializer<Eigen::Matrix<double, Rows, Cols, Options, MaxRows, MaxCols>> {
  using Matrix = Eigen::Matrix<double, Rows, Cols, Options, MaxRows, MaxCols>;
  static void to_json(json& j, const Matrix& m) {
    j = json{{"rows", m.rows()}, {"cols", m.cols()}, {"data", std::vector<double>(m.data(), m.data() + m.size())}};
  }
  static void from_json(const json& j, Matrix& m) {
    const auto rows = j.at("rows").get<Eigen::Index>();
    const auto cols = j.at("cols").get<Eigen::Index>();
    const auto data = j.at("data").get<std::vector<double>>();
    if ((Rows != Eigen::Dynamic && rows != Rows) || (Cols != Eigen::Dynamic && cols != Cols) || rows < 0 || cols < 0 ||
        static_cast<std::size_t>(rows * cols) != data.size())
      throw std::runtime_error("matrix of the wrong size");
    m.resize(rows, cols);
    std::copy(data.begin(), data.end(), m.data());
  }
};

/// A profile's points as columns (struct of arrays), each a CBOR byte string
/// of native doubles. A static case holds hundreds of points per line and
/// riser: as one map per point (keys repeated, a JSON value per number) its
/// record was 2.7 MB and took 0.1 s to read, which made resuming the
/// 161-case matrix cost half a minute. Doubles stay bit for bit.
template <class Point>
struct ProfileColumn {
  const char* name;
  double (*get)(const Point&);
  void (*set)(Point&, double);
};

template <class Point, std::size_t N>
json profile_to_json(const std::vector<Point>& points, const std::array<ProfileColumn<Point>, N>& columns) {
  static_assert(std::endian::native == std::endian::little, "records store little-endian doubles");
  json j{{"points", points.size()}};
  for (const ProfileColumn<Point>& column : columns) {
    std::vector<std::uint8_t> bytes(points.size() * sizeof(double));
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double value = column.get(points[i]);
      std::memcpy(bytes.data() + i * sizeof(double), &value, sizeof(double));
    }
    j[column.name] = json::binary(std::move(bytes));
  }
  return j;
}

template <class Point, std::size_t N>
std::vector<Point> profile_from_json(const json& j, const std::array<ProfileColumn<Point>, N>& columns) {
  std::vector<Point> points(j.at("points").get<std::size_t>());
  for (const ProfileColumn<Point>& column : columns) {
    const std::vector<std::uint8_t>& bytes = j.at(column.name).get_binary();
    if (bytes.size() != points.size() * sizeof(double))
      throw std::runtime_error(fmt::format("profile column '{}' of the wrong length", column.name));
    for (std::size_t i = 0; i < points.size(); ++i) {
      double value = 0.0;
      std::memcpy(&value, bytes.data() + i * sizeof(double), sizeof(double));
      column.set(points[i], value);
    }
  }
  return points;
}

using LinePoint = spiral::engine::LineProfilePoint;
inline constexpr std::array<ProfileColumn<LinePoint>, 7> kLineProfileColumns{{
    {"x_m", [](const LinePoint& p) { return p.position_g.x(); }, [](LinePoint& p, double v) { p.position_g.x() = v; }},
    {"y_m", [](const LinePoint& p) { return p.position_g.y(); }, [](LinePoint& p, double v) { p.position_g.y() = v; }},
    {"z_m", [](const LinePoint& p) { return p.position_g.z(); }, [](LinePoint& p, double v) { p.position_g.z() = v; }},
    {"arc_length_m", [](const LinePoint& p) { return p.arc_length_m; },
     [](LinePoint& p, double v) { p.arc_length_m = v; }},
    {"tension_N", [](const LinePoint& p) { return p.tension_N; }, [](LinePoint& p, double v) { p.tension_N = v; }},
    {"segment", [](const LinePoint& p) { return double(p.segment); },
     [](LinePoint& p, double v) { p.segment = static_cast<int>(v); }},
    {"on_seabed", [](const LinePoint& p) { return p.on_seabed ? 1.0 : 0.0; },
     [](LinePoint& p, double v) { p.on_seabed = v != 0.0; }},
}};

using RiserPoint = spiral::design::RiserProfilePoint;
inline constexpr std::array<ProfileColumn<RiserPoint>, 14> kRiserProfileColumns{{
    {"x_m", [](const RiserPoint& p) { return p.position_g.x(); },
     [](RiserPoint& p, double v) { p.position_g.x() = v; }},
    {"y_m", [](const RiserPoint& p) { return p.position_g.y(); },
     [](RiserPoint& p, double v) { p.position_g.y() = v; }},
    {"z_m", [](const RiserPoint& p) { return p.position_g.z(); },
     [](RiserPoint& p, double v) { p.position_g.z() = v; }},
    {"arc_length_m", [](const RiserPoint& p) { return p.arc_length_m; },
     [](RiserPoint& p, double v) { p.arc_length_m = v; }},
    {"section", [](const RiserPoint& p) { return double(p.section); },
     [](RiserPoint& p, double v) { p.section = static_cast<int>(v); }},
    {"on_seabed", [](const RiserPoint& p) { return p.on_seabed ? 1.0 : 0.0; },
     [](RiserPoint& p, double v) { p.on_seabed = v != 0.0; }},
    {"effective_tension_N", [](const RiserPoint& p) { return p.effective_tension_N; },
     [](RiserPoint& p, double v) { p.effective_tension_N = v; }},
    {"wall_tension_N", [](const RiserPoint& p) { return p.wall_tension_N; },
     [](RiserPoint& p, double v) { p.wall_tension_N = v; }},
    {"bending_moment_N_m", [](const RiserPoint& p) { return p.bending_moment_N_m; },
     [](RiserPoint& p, double v) { p.bending_moment_N_m = v; }},
    {"curvature_per_m", [](const RiserPoint& p) { return p.curvature_per_m; },
     [](RiserPoint& p, double v) { p.curvature_per_m = v; }},
    // Presence and value of each optional in two columns: a NaN stress stays a NaN.
    {"has_von_mises_Pa", [](const RiserPoint& p) { return p.von_mises_Pa ? 1.0 : 0.0; },
     [](RiserPoint& p, double v) {
       if (v != 0.0) p.von_mises_Pa = 0.0;
     }},
    {"von_mises_Pa", [](const RiserPoint& p) { return p.von_mises_Pa.value_or(0.0); },
     [](RiserPoint& p, double v) {
       if (p.von_mises_Pa) p.von_mises_Pa = v;
     }},
    {"has_von_mises_utilization", [](const RiserPoint& p) { return p.von_mises_utilization ? 1.0 : 0.0; },
     [](RiserPoint& p, double v) {
       if (v != 0.0) p.von_mises_utilization = 0.0;
     }},
    {"von_mises_utilization", [](const RiserPoint& p) { return p.von_mises_utilization.value_or(0.0); },
     [](RiserPoint& p, double v) {
       if (p.von_mises_utilization) p.von_mises_utilization = v;
     }},
}};

template <>
struct adl_serializer<std::vector<LinePoint>> {
  static void to_json(json& j, const std::vector<LinePoint>& points) {
    j = profile_to_json(points, kLineProfileColumns);
  }
  static void from_json(const json& j, std::vector<LinePoint>& points) {
    points = profile_from_json(j, kLineProfileColumns);
  }
};

template <>
struct adl_serializer<std::vector<RiserPoint>> {
  static void to_json(json& j, const std::vector<RiserPoint>& points) {
    j = profile_to_json(points, kRiserProfileColumns);
  }
  static void from_json(const json& j, std::vector<RiserPoint>& points) {
    points = profile_from_json(j, kRiserProfileColumns);
  }
};

}  // namespace nlohmann

namespace spiral::engine {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CurrentProfile, z_m, speed_m_per_s, heading_rad)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ChannelMoments, mean, std_dev, minimum, maximum, skewness, kurtosis, samples)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Spectrum, frequency_rad_s, density, frequency_step_rad_s, segments)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(GumbelFit, location, scale)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(WeibullFit, scale, shape)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ExtremeEstimate, record_duration_s, peaks, expected_peaks_in_target,
                                   expected_cycles_in_target, gumbel, weibull, mpm_gumbel, mpm_weibull, mpm_rayleigh)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ChannelStatistics, moments, spectrum, spectral_peak_period_s,
                                   zero_upcrossing_period_s, maximum, minimum)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(IdaStatistics, steps, residual_evaluations, newton_matrix_setups,
                                   newton_matrix_updates, linear_solves, error_test_failures, nonlinear_iterations,
                                   nonlinear_convergence_failures, newton_restarts, recoverable_residual_failures,
                                   last_step_s, current_time_s, last_order)
}  // namespace spiral::engine

namespace spiral::design {

// Statics and the static case.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LineStaticsRow, name, fairlead_tension_N, fairlead_horizontal_N, fairlead_vertical_N,
                                   fairlead_angle_deg, anchor_tension_N, anchor_horizontal_N, anchor_vertical_N,
                                   anchor_uplift_angle_deg, laid_length_m, touchdown_distance_m, max_tension_N,
                                   utilization, governing_segment_type, regime, iterations, profile)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StaticsResult, offset, lines, hull_force, wall_time_s)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(RiserCriterionCheck, criterion, value, limit, unit, utilization, passes)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(RiserStaticsRow, name, kind, top_tension_N, top_angle_deg, flex_joint_rotation_deg,
                                   touchdown_distance_m, min_effective_tension_N, min_effective_tension_arc_m,
                                   max_curvature_per_m, min_bending_radius_m, max_von_mises_utilization,
                                   max_von_mises_arc_m, checks, governing_criterion, utilization, passes, profile)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(OffsetSummary, horizontal_m, horizontal_pct_depth, direction_deg, heave_m, roll_deg,
                                   pitch_deg, yaw_deg)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(NaturalMode, period_s, dominant_dof)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StaticCaseResult, case_name, environment, integrity, damaged_line, offset,
                                   offset_summary, lines, risers, design_condition, lines_carry_current,
                                   current_on_every_line, line_force, stiffness, stiffness_finite_difference,
                                   stiffness_check_relative_difference, line_stiffness, line_force_6dof,
                                   hydrostatic_force, environment_force, residual, hydrostatic_stiffness, notes,
                                   natural_modes, dynamic_stiffness, dynamic_stiffness_lines, dynamic_natural_modes,
                                   added_mass_included, equilibrium_iterations, equilibrium_wall_s, stiffness_wall_s)

// The stage's mooring overview.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(RestoringCurve, direction_deg, offset_m, force_N, stopped)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LineStrength, name, segment_mbl_N, segment_types)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(MooringOverview, pretension, strengths, restoring)

// Safe operational zones.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SozExtremeOptions, duration_s, seed)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SozOptions, step_deg, tolerance_m, march_step_pct_depth, search_limit_pct_depth,
                                   load_case, condition, zone_per_current, offset_check, extreme, exclude_risers, model,
                                   exploit_symmetry, threads)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SozConditions, name, heave_m, rotation_rad, current, condition)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SozBand, from_m, to_m)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SozDirection, direction_deg, allowable_offset_m, governing_criterion,
                                   governing_utilization, limited_by_search, reopened_bands, solver_message, solves)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(RiserSoz, name, kind, azimuth_deg, zero_offset_governing_criterion,
                                   zero_offset_utilization, fails_at_zero_offset, directions, near_m, far_m,
                                   cross_left_m, cross_right_m, near_governing, far_governing, star_shaped, solves,
                                   zone_rotated_from, zone_mirrored_from, zone_mirror_symmetric)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PlatformSoz, allowable_offset_m, governing_riser, governing_criterion)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(OffsetExtreme, duration_s, seed, ratio_mpm_gumbel, ratio_mpm_weibull,
                                   ratio_mpm_rayleigh, record_max_ratio, record_max_ratio_time_s, mean_offset_m,
                                   offset_mpm_m)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(OffsetCheck, case_name, integrity, damaged_line, kind, offset_m, direction_deg,
                                   allowable_m, margin_m, ratio, passes, governing_riser, zone, extreme)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SozZone, name, conditions, cases, risers, platform, solves, zone_wall_s)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SozResult, project, depth_m, options, conditions, directions_deg, risers, platform,
                                   offset_checks, zones, notes, solves, zone_wall_s, check_wall_s, threads)

// Storms.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StormChannel, name, unit, values, statistics, extremes_note)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(AnalysisTimings, equilibrium_s, reduction_s, forcing_s, dynamics_s, wave_frequency_s,
                                   tensions_s, line_dynamics_s)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StageDynamics, case_name, integrity, damaged_line, selection, level, duration_s,
                                   output_step_s, seed, times_s, channels, most_loaded_line, tension_source,
                                   fairlead_mbl_N, dynamic_safety_factor, tension_utilization, tension_pass,
                                   extreme_offset, notes, timing, wall_s, solver_steps)

// Verification of a critical case.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ChannelSummary, name, unit, moments, mpm, mpm_fitted)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LevelSummary, level, wall_s, line_dynamics_wall_s, channels, notes, coupled_solver,
                                   error)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LevelComparison, case_name, seed, duration_s, levels)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(FinalLineCheck, line, mean_N, max_N, mpm_N, mpm_fitted, mbl_N, dynamic_factor,
                                   utilization, pass)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(FinalRiserCheck, riser, mean_N, max_N, mpm_N, limit_N, utilization, pass)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CriticalCaseVerification, rank, case_name, integrity, intermediate_score,
                                   intermediate_governing, sc, coupled, comparison, error, lines, soz_offset,
                                   mpm_offset_m, offset_limit_m, offset_limit_pass, risers, static_risers_pass,
                                   static_riser_utilization, static_riser, static_riser_criterion, pass, wall_s,
                                   shared_with)

// The pretension optimization of a feedback iteration.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(GroupVariable, name, lines, min_m, max_m)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ConstraintValue, scenario, kind, subject, value)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ZoneOutline, name, directions_deg, allowable_m)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ScenarioSummary, scenario, zone, case_name, damaged_line, offset_m, direction_deg,
                                   soz_allowable_m, soz_ratio, offset_limit_m, worst_utilization, worst_line,
                                   min_laid_length_m, min_fairlead_tension_N, mpm_offset_m, mpm_soz_ratio,
                                   worst_dynamic_utilization, worst_dynamic_line)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LinePayout, name, group, payout_m, length_before_m, length_after_m,
                                   top_segment_before_m, top_segment_after_m, pretension_before_N, pretension_after_N,
                                   top_segment_mbl_N)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(OptimizationHistoryRow, evaluation, objective, worst_constraint,
                                   worst_constraint_name, feasible, wall_s, payouts_m)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ActiveConstraint, name, value, multiplier)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(OptimizationResult, project, objective, algorithm, dynamic, status, stop_reason,
                                   groups, scenarios, payouts_m, objective_start, objective_best, objective_unit,
                                   before, after, lines, history, active, objective_gradient, most_violated, findings,
                                   notes, zone_conservatism_m, zones, evaluations, wall_s, zone_wall_s)

// The pretension study of the optimization report.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PretensionStudyPoint, payout_m, pretension_N, max_offset_m, max_soz_ratio_intact,
                                   max_soz_ratio_damaged, max_utilization_intact, max_utilization_damaged,
                                   worst_constraint, worst_constraint_name, feasible)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PretensionSweep, name, lines, points, feasible_m)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PretensionStudyResult, project, scenarios, sweeps, notes, optimum_payouts_m,
                                   optimum_status, evaluations, wall_s)

namespace {

template <class T>
constexpr const char* record_type() {
  if constexpr (std::is_same_v<T, MooringOverview>) return "mooring-overview";
  if constexpr (std::is_same_v<T, StaticCaseResult>) return "static-case";
  if constexpr (std::is_same_v<T, SozResult>) return "soz";
  if constexpr (std::is_same_v<T, StageDynamics>) return "storm";
  if constexpr (std::is_same_v<T, CriticalCaseVerification>) return "verification";
  if constexpr (std::is_same_v<T, OptimizationResult>) return "optimization";
  if constexpr (std::is_same_v<T, PretensionStudyResult>) return "pretension-study";
}

template <class T>
RecordBytes encode(const T& value) {
  const nlohmann::json record{{"type", record_type<T>()}, {"version", kStageRecordVersion}, {"value", value}};
  return nlohmann::json::to_cbor(record);
}

}  // namespace

RecordBytes encode_record(const MooringOverview& value) { return encode(value); }
RecordBytes encode_record(const StaticCaseResult& value) { return encode(value); }
RecordBytes encode_record(const SozResult& value) { return encode(value); }
RecordBytes encode_record(const StageDynamics& value) { return encode(value); }
RecordBytes encode_record(const CriticalCaseVerification& value) { return encode(value); }
RecordBytes encode_record(const OptimizationResult& value) { return encode(value); }
RecordBytes encode_record(const PretensionStudyResult& value) { return encode(value); }

template <class T>
T decode_record(std::span<const std::uint8_t> bytes) {
  try {
    const nlohmann::json record = nlohmann::json::from_cbor(bytes.begin(), bytes.end());
    if (record.at("type") != record_type<T>() || record.at("version") != kStageRecordVersion)
      throw std::runtime_error(fmt::format("a '{}' record of version {} where a '{}' record of version {} was expected",
                                           record.at("type").dump(), record.at("version").dump(), record_type<T>(),
                                           kStageRecordVersion));
    return record.at("value").get<T>();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(fmt::format("a '{}' record cannot be read: {}", record_type<T>(), e.what()));
  }
}

template MooringOverview decode_record<MooringOverview>(std::span<const std::uint8_t>);
template StaticCaseResult decode_record<StaticCaseResult>(std::span<const std::uint8_t>);
template SozResult decode_record<SozResult>(std::span<const std::uint8_t>);
template StageDynamics decode_record<StageDynamics>(std::span<const std::uint8_t>);
template CriticalCaseVerification decode_record<CriticalCaseVerification>(std::span<const std::uint8_t>);
template OptimizationResult decode_record<OptimizationResult>(std::span<const std::uint8_t>);
template PretensionStudyResult decode_record<PretensionStudyResult>(std::span<const std::uint8_t>);

}  // namespace spiral::design
