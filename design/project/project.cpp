#include "design/project/project.hpp"

#include <algorithm>
#include <stdexcept>
#include <numbers>
#include <utility>

namespace spiral::design {

DnvOsE301Factors dnv_os_e301_defaults(int consequence_class) {
  // DNV-OS-E301 (2010) Ch. 2 Sec. 2: ULS Table 1, ALS Table 2.
  DnvOsE301Factors factors;
  factors.consequence_class = consequence_class;
  if (consequence_class == 2) {
    factors.uls_mean = 1.40;
    factors.uls_dynamic = 2.10;
  }
  return factors;
}

const char* to_string(AttachmentKind kind) {
  switch (kind) {
    case AttachmentKind::clump:
      return "clump";
    case AttachmentKind::buoy:
      return "buoy";
  }
  return "?";
}

const char* to_string(RiserKind kind) {
  switch (kind) {
    case RiserKind::scr:
      return "scr";
    case RiserKind::lazy_wave:
      return "lazy_wave";
    case RiserKind::flexible:
      return "flexible";
  }
  return "?";
}

const char* to_string(FrequencyColumnKind column) {
  return column == FrequencyColumnKind::period ? "period" : "angular_frequency";
}

const char* to_string(RadiationModel model) { return model == RadiationModel::memory ? "memory" : "low_frequency"; }

const char* to_string(HullHydrodynamicsModel model) {
  return model == HullHydrodynamicsModel::morison ? "morison" : "bem";
}

const char* to_string(WaveSpectrum spectrum) {
  switch (spectrum) {
    case WaveSpectrum::jonswap:
      return "jonswap";
    case WaveSpectrum::pierson_moskowitz:
      return "pierson_moskowitz";
  }
  return "?";
}

const char* to_string(WindSpectrum spectrum) {
  switch (spectrum) {
    case WindSpectrum::api:
      return "api";
    case WindSpectrum::npd:
      return "npd";
    case WindSpectrum::none:
      return "none";
  }
  return "?";
}

const char* to_string(MooringCode code) {
  switch (code) {
    case MooringCode::api_rp_2sk:
      return "api_rp_2sk";
    case MooringCode::dnv_os_e301:
      return "dnv_os_e301";
  }
  return "?";
}

double total_length_m(const MooringLine& line) {
  double total = 0.0;
  for (const LineSegment& s : line.segments) total += s.length_m;
  return total;
}

double total_length_m(const Riser& riser) {
  double total = 0.0;
  for (const RiserSection& s : riser.sections) total += s.length_m;
  return total;
}

const char* to_string(LineModel model) {
  switch (model) {
    case LineModel::catenary:
      return "catenary";
    case LineModel::fe:
      return "fe";
  }
  return "?";
}

const char* to_string(LineIntegrity integrity) { return integrity == LineIntegrity::damaged ? "damaged" : "intact"; }

const char* to_string(OptimizationObjective objective) {
  switch (objective) {
    case OptimizationObjective::max_soz_margin:
      return "max_soz_margin";
    case OptimizationObjective::min_max_utilization:
      return "min_max_utilization";
    case OptimizationObjective::min_total_payout:
      return "min_total_payout";
    case OptimizationObjective::min_max_offset:
      return "min_max_offset";
  }
  return "?";
}

const char* to_string(OptimizationAlgorithm algorithm) {
  switch (algorithm) {
    case OptimizationAlgorithm::slsqp:
      return "slsqp";
    case OptimizationAlgorithm::ccsaq:
      return "ccsaq";
    case OptimizationAlgorithm::cobyla:
      return "cobyla";
  }
  return "?";
}

const char* to_string(DamagedConditions damaged) {
  return damaged == DamagedConditions::every_line ? "every_line" : "load_cases";
}

const char* to_string(DesignCondition condition) {
  switch (condition) {
    case DesignCondition::normal:
      return "normal";
    case DesignCondition::extreme:
      return "extreme";
    case DesignCondition::survival:
      return "survival";
  }
  return "?";
}

namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
// Typical design rotation of an SCR / lazy-wave flex joint (elastomeric or
// titanium stress joint): ±15° (recalled, U: manufacturers' catalogues; API
// RP 2RD and DNV-OS-F201 require the joint's own limit and give no number).
constexpr double kDefaultFlexJointRotation_deg = 15.0;
}  // namespace

RiserCriteriaOverrides riser_criteria_defaults(RiserKind kind) {
  RiserCriteriaOverrides d;
  // API RP 2RD allowable stress: sigma_vM <= C_f C_a sigma_y, C_a = 2/3,
  // C_f = 1.0 (normal), 1.2 (extreme), 1.5 (survival) (recalled, U). Unused
  // by a flexible (no steel wall is checked) but harmless there.
  d.design_factor_normal = 0.67;
  d.design_factor_extreme = 0.80;
  d.design_factor_survival = 1.00;
  // No compression anywhere: API RP 2RD / DNV-OS-F201 (steel, TDP buckling),
  // API RP 17B (flexible: birdcaging of the tensile armour).
  d.min_effective_tension_N = 0.0;
  switch (kind) {
    case RiserKind::scr:
    case RiserKind::lazy_wave:
      d.max_flex_joint_rotation_rad = kDefaultFlexJointRotation_deg * kDegToRad;
      break;
    case RiserKind::flexible:
      // Hung off through a bend stiffener, not a flex joint; its MBR comes
      // from the pipe (API 17J) and has no default.
      break;
  }
  return d;
}

RiserCriteria riser_criteria(const Criteria& criteria, const Riser& riser) {
  return with_overrides(
      with_overrides(with_overrides(RiserCriteria{}, riser_criteria_defaults(riser.kind)), criteria.risers),
      riser.criteria);
}

RiserCriteria with_overrides(RiserCriteria base, const RiserCriteriaOverrides& o) {
  RiserCriteria out = std::move(base);
  out.design_factor.normal = o.design_factor_normal.value_or(out.design_factor.normal);
  out.design_factor.extreme = o.design_factor_extreme.value_or(out.design_factor.extreme);
  out.design_factor.survival = o.design_factor_survival.value_or(out.design_factor.survival);
  out.min_effective_tension_N = o.min_effective_tension_N.value_or(out.min_effective_tension_N);
  if (o.max_top_tension_N) out.max_top_tension_N = o.max_top_tension_N;
  if (o.max_top_angle_rad) out.max_top_angle_rad = o.max_top_angle_rad;
  if (o.max_flex_joint_rotation_rad) out.max_flex_joint_rotation_rad = o.max_flex_joint_rotation_rad;
  if (o.min_bending_radius_m) out.min_bending_radius_m = o.min_bending_radius_m;
  if (o.max_touchdown_excursion_m) out.max_touchdown_excursion_m = o.max_touchdown_excursion_m;
  return out;
}

double design_factor(const RiserDesignFactors& factors, DesignCondition condition) {
  switch (condition) {
    case DesignCondition::normal:
      return factors.normal;
    case DesignCondition::extreme:
      return factors.extreme;
    case DesignCondition::survival:
      return factors.survival;
  }
  return factors.extreme;
}

const MooringLine& mooring_line(const Project& project, const std::string& name) {
  const auto it = std::find_if(project.mooring.lines.begin(), project.mooring.lines.end(),
                               [&](const MooringLine& l) { return l.name == name; });
  if (it == project.mooring.lines.end()) throw std::logic_error("no mooring line named " + name + " in the project");
  return *it;
}

const Environment& environment_of(const Project& project, const LoadCase& load_case) {
  const auto it = std::find_if(project.environments.begin(), project.environments.end(),
                               [&](const Environment& e) { return e.name == load_case.environment; });
  if (it == project.environments.end())
    throw std::logic_error("load case " + load_case.name + " names no environment of the project");
  return *it;
}

bool same_analysis_inputs(const Project& project, const LoadCase& a, const LoadCase& b) {
  if (a.damaged_line != b.damaged_line || a.condition != b.condition || a.seed != b.seed) return false;
  const Environment& ea = environment_of(project, a);
  const Environment& eb = environment_of(project, b);
  return ea.waves == eb.waves && ea.wind == eb.wind && ea.current == eb.current;
}

}  // namespace spiral::design
