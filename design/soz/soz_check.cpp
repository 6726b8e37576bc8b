// run_soz (soz.hpp): the zones the project's load cases are checked against,
// and the offset check — each case's static (mean) offset and, with
// SozOptions::extreme, its extreme offset from the enhanced S-C time-domain
// analysis (dynamic_analysis.hpp) — against the platform SOZ.
//
// Extreme offset. The zone is not a circle, so the largest offset is not
// necessarily the most critical one: a smaller excursion towards a tight
// direction can use more of the zone than a larger one towards a wide
// direction. The check therefore works on the utilization channel
//   r(t) = |d(t)| / A(θ(t)),
// d(t) the horizontal offset of the hull reference point (total motion, low +
// wave frequency), θ(t) its direction and A the platform zone in that
// direction; r ≤ 1 means the hull is inside the zone at that instant. Its 3-h
// most probable maximum is estimated with the same statistics the analysis
// summary reports (engine::most_probable_maximum: Gumbel, Weibull, Rayleigh).
// The check uses the Weibull estimate: it is fitted to the upper half of the
// record's global peaks — hundreds of low-frequency cycles in 3 h — where the
// Gumbel fit sees only its 10 segment maxima, and the Rayleigh estimate
// assumes a Gaussian process, which a slow-drift offset with its positive
// skew is not (statistics.hpp; DNV-OS-E301 Ch.2 Sec.2 as recalled there). The
// reported extreme offset is that ratio times the allowable offset in the
// direction of the record's largest r(t) (where the hull comes closest to the
// zone's edge), so ratio = offset / allowable holds as for the static check.
// The MPM of |d(t)| itself is reported beside it, for reference.
//
// Zones per current. Without --case the current on the risers moves the
// zone (soz_test: a current towards the foot shrinks the far limit), and the
// design factor of the case's condition scales the von Mises limit, so a case
// is checked against the zone of its own current and condition; the cases
// that share both share one zone, computed once. Each zone is at zero mean
// heave/rotations (--case gives the one case's exact zone).
//
// The zone stays a quasi-static one: the risers are checked at the mean hull
// heave and rotations of the case (or none), not at the instantaneous ones.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "design/project/request_error.hpp"
#include "design/model/environment_loads.hpp"
#include "design/analysis/dynamic_analysis.hpp"
#include "design/soz/soz.hpp"
#include "design/analysis/static_case.hpp"
#include "engine/numerics/statistics.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// A ratio channel whose standard deviation is below this fraction of its mean
// is constant (no waves, no gusts): it has no extreme-value distribution, its
// extreme is its value (the criterion of sc_analysis_output's summary).
constexpr double kConstantChannel = 1e-12;

/// The platform zone as a function of direction: each riser's polygon
/// interpolated in the direction, the smallest of them and its riser.
class PlatformPolygon {
 public:
  struct At {
    double allowable_m = std::numeric_limits<double>::infinity();
    const std::string* riser = nullptr;
  };

  PlatformPolygon(const std::vector<double>& directions_deg, const std::vector<RiserSoz>& risers)
      : directions_deg_(directions_deg) {
    for (const RiserSoz& z : risers) {
      names_.push_back(z.name);
      std::vector<double> a;
      for (const SozDirection& d : z.directions) a.push_back(d.allowable_offset_m);
      allowable_.push_back(std::move(a));
    }
  }

  At at(double direction_deg) const {
    At out;
    for (std::size_t r = 0; r < allowable_.size(); ++r) {
      const double a = polygon_allowable(directions_deg_, allowable_[r], direction_deg);
      if (a < out.allowable_m) out = {a, &names_[r]};
    }
    return out;
  }

 private:
  std::vector<double> directions_deg_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> allowable_;
};

OffsetCheck check_of(const StaticCaseResult& c, const std::string& zone) {
  OffsetCheck check;
  check.case_name = c.case_name;
  check.integrity = c.integrity;
  check.damaged_line = c.damaged_line;
  check.zone = zone;
  return check;
}

/// Margin, ratio and verdict from offset_m and allowable_m.
void finish(OffsetCheck& check) {
  check.margin_m = check.allowable_m - check.offset_m;
  if (check.kind == OffsetCheckKind::static_mean) {
    check.ratio =
        check.allowable_m > 0.0 ? check.offset_m / check.allowable_m : std::numeric_limits<double>::infinity();
  }
  check.passes = check.ratio <= 1.0;
}

OffsetCheck static_check(const StaticCaseResult& c, const PlatformPolygon& zone, const std::string& zone_name) {
  OffsetCheck check = check_of(c, zone_name);
  check.offset_m = c.offset_summary.horizontal_m;
  check.direction_deg = c.offset_summary.direction_deg;
  const PlatformPolygon::At at = zone.at(check.direction_deg);
  check.allowable_m = at.allowable_m;
  if (at.riser) check.governing_riser = *at.riser;
  finish(check);
  return check;
}

double direction_deg_of(double x, double y) {
  const double deg = std::atan2(y, x) * kRadToDeg;
  return deg < 0.0 ? deg + 360.0 : deg;
}

/// The extreme-offset rule (the file comment) on one motion record. A record
/// too short for the extreme-value fit keeps its largest sample, with
/// `fit_note` saying why (the caller decides whether that is acceptable).
OffsetCheck extreme_offset_of(const StaticCaseResult& c, const Eigen::Matrix<double, 6, Eigen::Dynamic>& motion,
                              const Eigen::VectorXd& times_s, const PlatformPolygon& zone, const std::string& zone_name,
                              std::string& fit_note) {
  OffsetCheck check = check_of(c, zone_name);
  check.kind = OffsetCheckKind::extreme;
  OffsetExtreme e;
  const Eigen::Index n = motion.cols();
  if (n < 2 || times_s.size() != n)
    throw std::invalid_argument(fmt::format("load case '{}': the record has {} samples", c.case_name, n));
  e.duration_s = times_s(n - 1) - times_s(0);
  const double dt_s = times_s(1) - times_s(0);
  std::vector<double> ratio(static_cast<std::size_t>(n)), offset(static_cast<std::size_t>(n));
  Eigen::Index worst = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double x = motion(0, k), y = motion(1, k);
    const double d = std::hypot(x, y);
    const double a = zone.at(direction_deg_of(x, y)).allowable_m;
    offset[static_cast<std::size_t>(k)] = d;
    ratio[static_cast<std::size_t>(k)] = a > 0.0 ? d / a : std::numeric_limits<double>::infinity();
    if (ratio[static_cast<std::size_t>(k)] > ratio[static_cast<std::size_t>(worst)]) worst = k;
  }
  e.record_max_ratio = ratio[static_cast<std::size_t>(worst)];
  e.record_max_ratio_time_s = times_s(worst);
  const engine::ChannelMoments m_offset = engine::channel_moments(offset);
  e.mean_offset_m = m_offset.mean;
  check.direction_deg = direction_deg_of(motion(0, worst), motion(1, worst));
  const PlatformPolygon::At at = zone.at(check.direction_deg);
  check.allowable_m = at.allowable_m;
  if (at.riser) check.governing_riser = *at.riser;

  const auto keep_record_maximum = [&] {
    e.ratio_mpm_gumbel = e.ratio_mpm_weibull = e.ratio_mpm_rayleigh = e.record_max_ratio;
    e.offset_mpm_m = m_offset.maximum;
  };
  if (!std::isfinite(e.record_max_ratio)) {
    // The zone is empty in a direction the hull visits: no extreme statistics needed.
    keep_record_maximum();
    check.ratio = e.record_max_ratio;
    check.offset_m = m_offset.maximum;
  } else {
    const engine::ChannelMoments m_ratio = engine::channel_moments(ratio);
    if (m_ratio.std_dev <= kConstantChannel * std::max(1.0, std::abs(m_ratio.mean))) {
      keep_record_maximum();
    } else {
      try {
        const engine::ExtremeEstimate r = engine::most_probable_maximum(ratio, dt_s);
        // |d(t)| by the offset limit's rule; a record it cannot fit is too short for this one too.
        const OffsetMpm d = horizontal_offset_mpm(offset, dt_s);
        if (!d.fitted) throw std::invalid_argument(d.note.empty() ? "constant horizontal offset" : d.note);
        e.ratio_mpm_gumbel = r.mpm_gumbel;
        e.ratio_mpm_weibull = r.mpm_weibull;
        e.ratio_mpm_rayleigh = r.mpm_rayleigh;
        e.offset_mpm_m = d.offset_m;
      } catch (const std::invalid_argument& error) {
        fit_note = error.what();
        keep_record_maximum();
      }
    }
    check.ratio = e.ratio_mpm_weibull;
    check.offset_m = check.ratio * check.allowable_m;
  }
  check.extreme = e;
  finish(check);
  return check;
}

/// `spiral soz --extreme`: the rule on the case's enhanced S-C run; a record
/// too short for the fit is an error of the requested duration.
OffsetCheck extreme_check(const Project& project, const StaticCaseResult& c, const DynamicAnalysisResult& run,
                          const PlatformPolygon& zone, const std::string& zone_name, const SozExtremeOptions& options) {
  if (run.total.cols() < 2) {
    throw request_error(project, "duration_s",
                        fmt::format("load case '{}': the record has {} samples; a longer "
                                    "duration is needed for the extreme offset",
                                    c.case_name, run.total.cols()),
                        "soz_extreme_record");
  }
  std::string fit_note;
  OffsetCheck check = extreme_offset_of(c, run.total, run.times_s, zone, zone_name, fit_note);
  if (!fit_note.empty()) {
    throw request_error(project, "duration_s",
                        fmt::format("load case '{}': no extreme-value fit on a {:g} s record ({}); "
                                    "simulate longer (3 h = 10800 s is the design sea state)",
                                    c.case_name, options.duration_s, fit_note),
                        "soz_extreme_record");
  }
  check.extreme->duration_s = options.duration_s;
  check.extreme->seed = options.seed;
  return check;
}

bool same_current(const std::optional<Current>& a, const std::optional<Current>& b) {
  if (!a || !b) return !a && !b;
  if (a->heading_rad != b->heading_rad || a->profile.size() != b->profile.size()) return false;
  for (std::size_t i = 0; i < a->profile.size(); ++i) {
    if (a->profile[i].z_m != b->profile[i].z_m || a->profile[i].speed_m_per_s != b->profile[i].speed_m_per_s)
      return false;
  }
  return true;
}

/// The zones of the cases' currents: per checked case the index of its zone
/// in `zones`, or −1 for the still-water zone (no current and the still-water
/// design condition). Cases with the same current (the same values, whatever
/// the environment's name) and design condition share a zone.
std::vector<int> zones_of_cases(const Project& project, const std::vector<std::string>& case_names,
                                DesignCondition still_water_condition, bool ignore_current,
                                std::vector<SozZone>& zones) {
  std::vector<int> index;
  std::vector<std::optional<Current>> currents;  // of `zones`
  for (const std::string& name : case_names) {
    const LoadCase& lc = find_load_case(project, name);
    const Environment& env = environment_of(project, lc);
    const std::optional<Current> current = ignore_current ? std::nullopt : env.current;
    if (!current && lc.condition == still_water_condition) {
      index.push_back(-1);
      continue;
    }
    int k = 0;
    while (k < static_cast<int>(zones.size()) &&
           !(same_current(currents[static_cast<std::size_t>(k)], current) &&
             zones[static_cast<std::size_t>(k)].conditions.condition == lc.condition)) {
      ++k;
    }
    if (k == static_cast<int>(zones.size())) {
      SozZone zone;
      zone.name = fmt::format("{}/{}", current ? env.name : "no-current", to_string(lc.condition));
      zone.conditions.name = zone.name;
      if (current) zone.conditions.current = current_profile_of(env);
      zone.conditions.condition = lc.condition;
      zones.push_back(std::move(zone));
      currents.push_back(current);
    }
    zones[static_cast<std::size_t>(k)].cases.push_back(name);
    index.push_back(k);
  }
  return index;
}

/// The project's load cases checked by `options` (one with --case).
std::vector<std::string> checked_case_names(const Project& project, const SozOptions& options) {
  std::vector<std::string> names;
  if (options.load_case) {
    names.push_back(*options.load_case);
  } else if (options.offset_check) {
    for (const LoadCase& c : project.load_cases) names.push_back(c.name);
  }
  return names;
}

}  // namespace

OffsetCheck check_offset(const SozResult& zone, const StaticCaseResult& static_case, const std::string& zone_name) {
  return static_check(static_case, PlatformPolygon(zone.directions_deg, zone.risers), zone_name);
}

OffsetCheck extreme_offset_check(const SozResult& zone, const StaticCaseResult& static_case,
                                 const Eigen::Matrix<double, 6, Eigen::Dynamic>& motion, const Eigen::VectorXd& times_s,
                                 const std::string& zone_name, std::string& fit_note) {
  return extreme_offset_of(static_case, motion, times_s, PlatformPolygon(zone.directions_deg, zone.risers), zone_name,
                           fit_note);
}

OffsetMpm horizontal_offset_mpm(const std::vector<double>& offset_m, double dt_s) {
  OffsetMpm out;
  const engine::ChannelMoments m = engine::channel_moments(offset_m);
  out.offset_m = m.maximum;
  if (m.std_dev <= kConstantChannel * std::max(1.0, std::abs(m.mean))) return out;
  try {
    out.offset_m = engine::most_probable_maximum(offset_m, dt_s).mpm_weibull;
    out.fitted = true;
  } catch (const std::invalid_argument& error) {
    out.note = error.what();
  }
  return out;
}

SozResult run_soz(const ValidatedProject& validated, const SozOptions& options) {
  const Project& project = validated.project;
  validate_soz_options(project, options);
  SozConditions conditions;
  conditions.condition = options.condition;
  engine::Stopwatch check_start;
  const std::vector<std::string> case_names = checked_case_names(project, options);
  // Static equilibria of the load cases: the offsets to check, and (with
  // --case) the mean heave/rotations the zone is computed at.
  std::vector<StaticCaseResult> cases;
  RestSolutionCache rest_solutions;  // cases sharing an environment solve its lines once
  const bool zones_only = options.zones_only && !options.load_case;
  if (!zones_only) {
    for (const std::string& name : case_names)
      cases.push_back(run_static_case(validated, {name, std::nullopt, false}, &rest_solutions));
  }
  // Extreme offsets: one enhanced S-C storm per case, the cases in parallel
  // (each analysis is a function of its inputs; results go to their slots).
  std::vector<DynamicAnalysisResult> runs(options.extreme ? case_names.size() : 0);
  if (options.extreme) {
    const int count = static_cast<int>(runs.size());
    const int threads = options.threads > 0 ? std::min(options.threads, count) : engine::worker_count(count);
    engine::parallel_for(count, threads, [&](int i) {
      DynamicAnalysisRequest request;
      request.load_case = case_names[static_cast<std::size_t>(i)];
      request.level = AnalysisLevel::semi_coupled_enhanced;
      request.duration_s = options.extreme->duration_s;
      request.output_step_s = std::min(request.output_step_s, request.duration_s);
      request.seed = options.extreme->seed;
      request.compute_tensions = false;  // the check needs the hull motion only
      runs[static_cast<std::size_t>(i)] = run_dynamic_analysis(validated, request);
    });
  }
  const double check_wall_s = check_start.seconds();
  if (options.load_case) {
    const StaticCaseResult& c = cases.front();
    const LoadCase& lc = find_load_case(project, *options.load_case);
    const Environment& env = environment_of(project, lc);
    conditions.name = c.case_name;
    conditions.heave_m = c.offset(2);
    conditions.rotation_rad = c.offset.tail<3>();
    conditions.condition = lc.condition;
    conditions.current = current_profile_of(env);
  }

  std::vector<RiserDesign> designs;
  for (const Riser& riser : project.risers) {
    if (std::find(options.exclude_risers.begin(), options.exclude_risers.end(), riser.name) !=
        options.exclude_risers.end()) {
      continue;
    }
    designs.push_back(riser_design(project, riser));
  }
  // Without --case: a zone per current (and design condition) of the cases,
  // each computed once and shared by the cases that have it. Known before
  // any zone is computed, so that the progress hook runs once from 0 to 1.
  // The catenary screening model carries no current: its zones differ by
  // the design condition only.
  const bool zone_per_current = !designs.empty() && !options.load_case && options.zone_per_current;
  const bool ignore_current = options.model == SozModel::catenary;
  std::vector<SozZone> zones;
  std::vector<int> zone_of_case(case_names.size(), -1);
  if (zone_per_current) zone_of_case = zones_of_cases(project, case_names, options.condition, ignore_current, zones);
  const auto zone_count = static_cast<double>(zones.size() + 1);  // the result's own zone is zone 0
  const auto zone_options = [&](std::size_t zone) {
    SozOptions o = options;
    if (o.progress) {
      o.progress = [progress = options.progress, zone, zone_count](double fraction) {
        progress((static_cast<double>(zone) + fraction) / zone_count);
      };
    }
    return o;
  };
  SozResult result = compute_soz(project, designs, conditions, zone_options(0));
  result.zones = std::move(zones);
  if (options.model == SozModel::catenary && conditions.current) {
    result.notes.push_back(
        "the catenary screening model carries no current: this zone ignores the case's current on "
        "the risers (the FE riser model carries it)");
  }
  result.check_wall_s = check_wall_s;
  if (!options.exclude_risers.empty()) {
    std::string names;
    for (const std::string& n : options.exclude_risers) names += (names.empty() ? "" : ", ") + n;
    result.notes.push_back("risers left out of the platform zone: " + names);
  }
  if (designs.empty()) return result;

  if (zone_per_current) {
    if (ignore_current && std::any_of(case_names.begin(), case_names.end(), [&](const std::string& name) {
          const LoadCase& lc = find_load_case(project, name);
          return std::any_of(project.environments.begin(), project.environments.end(),
                             [&](const Environment& e) { return e.name == lc.environment && e.current; });
        })) {
      result.notes.push_back(
          "the catenary screening model carries no current: the zones per case differ by design condition "
          "only (the FE riser model carries it)");
    }
    for (std::size_t k = 0; k < result.zones.size(); ++k) {
      SozZone& zone = result.zones[k];
      SozResult z = compute_soz(project, designs, zone.conditions, zone_options(k + 1));
      zone.risers = std::move(z.risers);
      zone.platform = std::move(z.platform);
      zone.solves = z.solves;
      zone.zone_wall_s = z.zone_wall_s;
      result.solves += z.solves;
      result.zone_wall_s += z.zone_wall_s;
      for (const RiserSoz& r : zone.risers) {
        if (r.fails_at_zero_offset) {
          result.notes.push_back(fmt::format("zone {}: riser {} fails {} already at zero offset: no zone", zone.name,
                                             r.name, r.zero_offset_governing_criterion));
        }
      }
    }
  }
  std::vector<PlatformPolygon> polygons{PlatformPolygon(result.directions_deg, result.risers)};
  for (const SozZone& zone : result.zones) polygons.emplace_back(result.directions_deg, zone.risers);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const int k = zone_of_case[i];
    const PlatformPolygon& zone = polygons[static_cast<std::size_t>(k + 1)];
    const std::string zone_name = k >= 0              ? result.zones[static_cast<std::size_t>(k)].name
                                  : options.load_case ? "case"
                                                      : "still-water";
    result.offset_checks.push_back(static_check(cases[i], zone, zone_name));
    if (options.extreme) {
      result.offset_checks.push_back(extreme_check(project, cases[i], runs[i], zone, zone_name, *options.extreme));
    }
  }
  if (!options.load_case && !cases.empty()) {
    result.notes.push_back(
        options.zone_per_current
            ? "each case is checked against the zone of its own current and design condition (`zone`), at zero "
              "mean heave/rotations; the zone of one load case asked for alone is that case's exact zone"
            : "offset check against the still-water zone (no current on the risers, no mean heave/rotations); "
              "the zone of one load case asked for alone is that case's own zone");
  }
  if (!cases.empty() && !options.extreme) {
    result.notes.push_back(
        "offsets are static (mean); the extreme-offset check, when asked for, adds the 3-h extreme "
        "offsets of the enhanced S-C analysis");
  }
  if (options.extreme) {
    result.notes.push_back(
        fmt::format("extreme offsets: enhanced S-C analysis of each case ({:g} s, seed {}); ratio = 3-h MPM "
                    "(Weibull) of |offset(t)| / allowable(direction(t)); the zone is the quasi-static one at "
                    "the mean hull heave/rotations",
                    options.extreme->duration_s, options.extreme->seed));
  }
  return result;
}

}  // namespace spiral::design
