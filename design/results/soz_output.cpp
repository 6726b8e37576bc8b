#include "design/results/soz_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

double pct(double offset_m, double depth_m) { return 100.0 * offset_m / depth_m; }

}  // namespace

double time_per_solve_s(const SozResult& r) { return r.solves > 0 ? r.zone_wall_s * r.threads / r.solves : 0.0; }

nlohmann::json soz_to_json(const SozResult& r) {
  const SozOptions& o = r.options;
  nlohmann::json risers = nlohmann::json::array();
  for (const RiserSoz& z : r.risers) {
    nlohmann::json allowable = nlohmann::json::array(), allowable_pct = nlohmann::json::array(),
                   governing = nlohmann::json::array(), utilization = nlohmann::json::array(),
                   limited = nlohmann::json::array(), bands = nlohmann::json::array(),
                   messages = nlohmann::json::array();
    for (const SozDirection& d : z.directions) {
      allowable.push_back(d.allowable_offset_m);
      allowable_pct.push_back(pct(d.allowable_offset_m, r.depth_m));
      governing.push_back(d.governing_criterion);
      utilization.push_back(number(d.governing_utilization));
      limited.push_back(d.limited_by_search);
      for (const SozBand& b : d.reopened_bands) {
        bands.push_back({{"direction_deg", d.direction_deg}, {"from_m", b.from_m}, {"to_m", b.to_m}});
      }
      if (!d.solver_message.empty())
        messages.push_back({{"direction_deg", d.direction_deg}, {"message", d.solver_message}});
    }
    risers.push_back({{"name", z.name},
                      {"kind", to_string(z.kind)},
                      {"azimuth_deg", z.azimuth_deg},
                      {"fails_at_zero_offset", z.fails_at_zero_offset},
                      {"zero_offset_governing_criterion", z.zero_offset_governing_criterion},
                      {"zero_offset_utilization", number(z.zero_offset_utilization)},
                      {"allowable_offset_m", allowable},
                      {"allowable_offset_pct_depth", allowable_pct},
                      {"governing_criterion", governing},
                      {"governing_utilization", utilization},
                      {"limited_by_search", limited},
                      {"star_shaped", z.star_shaped},
                      {"reopened_bands", bands},
                      {"solver_messages", messages},
                      {"near_m", z.near_m},
                      {"far_m", z.far_m},
                      {"cross_left_m", z.cross_left_m},
                      {"cross_right_m", z.cross_right_m},
                      {"near_governing", z.near_governing},
                      {"far_governing", z.far_governing},
                      {"solves", z.solves},
                      {"zone_rotated_from",
                       z.zone_rotated_from.empty() ? nlohmann::json(nullptr) : nlohmann::json(z.zone_rotated_from)},
                      {"zone_mirrored_from",
                       z.zone_mirrored_from.empty() ? nlohmann::json(nullptr) : nlohmann::json(z.zone_mirrored_from)},
                      {"zone_mirror_symmetric", z.zone_mirror_symmetric}});
  }
  nlohmann::json platform_pct = nlohmann::json::array();
  for (double a : r.platform.allowable_offset_m) platform_pct.push_back(pct(a, r.depth_m));
  nlohmann::json checks = nlohmann::json::array();
  for (const OffsetCheck& c : r.offset_checks) {
    nlohmann::json extreme(nullptr);
    if (c.extreme) {
      const OffsetExtreme& e = *c.extreme;
      extreme = {{"level", "sc-enhanced"},
                 {"duration_s", e.duration_s},
                 {"seed", e.seed},
                 {"estimator", "weibull"},
                 {"ratio_mpm_3h",
                  {{"gumbel", number(e.ratio_mpm_gumbel)},
                   {"weibull", number(e.ratio_mpm_weibull)},
                   {"rayleigh", number(e.ratio_mpm_rayleigh)}}},
                 {"record_max_ratio", number(e.record_max_ratio)},
                 {"record_max_ratio_time_s", e.record_max_ratio_time_s},
                 {"mean_offset_m", e.mean_offset_m},
                 {"offset_mpm_3h_m", e.offset_mpm_m}};
    }
    checks.push_back({{"case", c.case_name},
                      {"condition", to_string(c.integrity)},
                      {"damaged_line", c.damaged_line ? nlohmann::json(*c.damaged_line) : nlohmann::json(nullptr)},
                      {"kind", to_string(c.kind)},
                      {"zone", c.zone},
                      {"offset_m", number(c.offset_m)},
                      {"offset_pct_depth", number(pct(c.offset_m, r.depth_m))},
                      {"direction_deg", c.direction_deg},
                      {"allowable_m", number(c.allowable_m)},
                      {"margin_m", number(c.margin_m)},
                      {"ratio", number(c.ratio)},
                      {"passes", c.passes},
                      {"governing_riser", c.governing_riser},
                      {"extreme", extreme}});
  }
  nlohmann::json zones = nlohmann::json::array();
  for (const SozZone& zone : r.zones) {
    nlohmann::json zone_risers = nlohmann::json::array();
    for (const RiserSoz& z : zone.risers) {
      nlohmann::json allowable = nlohmann::json::array(), governing = nlohmann::json::array();
      for (const SozDirection& d : z.directions) {
        allowable.push_back(d.allowable_offset_m);
        governing.push_back(d.governing_criterion);
      }
      zone_risers.push_back({{"name", z.name},
                             {"fails_at_zero_offset", z.fails_at_zero_offset},
                             {"allowable_offset_m", allowable},
                             {"governing_criterion", governing},
                             {"star_shaped", z.star_shaped},
                             {"near_m", z.near_m},
                             {"far_m", z.far_m}});
    }
    zones.push_back({{"name", zone.name},
                     {"design_condition", to_string(zone.conditions.condition)},
                     {"current", zone.conditions.current.has_value()},
                     {"cases", zone.cases},
                     {"risers", zone_risers},
                     {"platform",
                      {{"allowable_offset_m", zone.platform.allowable_offset_m},
                       {"governing_riser", zone.platform.governing_riser},
                       {"governing_criterion", zone.platform.governing_criterion}}},
                     {"solves", zone.solves},
                     {"zone_wall_s", zone.zone_wall_s}});
  }
  const SozConditions& k = r.conditions;
  return {{"format", "spiral.soz"},
          {"format_version", 1},
          {"project", r.project},
          {"depth_m", r.depth_m},
          {"model", to_string(o.model)},
          {"conditions",
           {{"name", k.name},
            {"design_condition", to_string(k.condition)},
            {"current", k.current.has_value()},
            {"heave_m", k.heave_m},
            {"roll_deg", k.rotation_rad.x() * kRadToDeg},
            {"pitch_deg", k.rotation_rad.y() * kRadToDeg},
            {"yaw_deg", k.rotation_rad.z() * kRadToDeg}}},
          {"step_deg", o.step_deg},
          {"tolerance_m", o.tolerance_m},
          {"march_step_m", o.march_step_pct_depth * r.depth_m / 100.0},
          {"search_limit_m", o.search_limit_pct_depth * r.depth_m / 100.0},
          {"directions_deg", r.directions_deg},
          {"risers", risers},
          {"platform",
           {{"allowable_offset_m", r.platform.allowable_offset_m},
            {"allowable_offset_pct_depth", platform_pct},
            {"governing_riser", r.platform.governing_riser},
            {"governing_criterion", r.platform.governing_criterion}}},
          {"offset_checks", checks},
          {"zones", zones},
          {"notes", r.notes},
          {"solves", r.solves},
          {"threads", r.threads},
          {"zone_wall_s", r.zone_wall_s},
          {"time_per_solve_s", time_per_solve_s(r)},
          {"check_wall_s", r.check_wall_s}};
}

std::string soz_to_csv(const SozResult& r) {
  std::string out =
      "direction_deg,riser,allowable_offset_m,allowable_offset_pct_depth,governing_criterion,"
      "governing_utilization,"
      "limited_by_search,reopened_bands\n";
  for (const RiserSoz& z : r.risers) {
    for (const SozDirection& d : z.directions) {
      out += fmt::format("{},{},{:.3f},{:.4f},{},{:.4f},{},{}\n", d.direction_deg, z.name, d.allowable_offset_m,
                         pct(d.allowable_offset_m, r.depth_m), d.governing_criterion, d.governing_utilization,
                         d.limited_by_search ? 1 : 0, d.reopened_bands.size());
    }
  }
  for (std::size_t k = 0; k < r.directions_deg.size(); ++k) {
    const double a = r.platform.allowable_offset_m[k];
    out += fmt::format("{},platform,{:.3f},{:.4f},{},,,\n", r.directions_deg[k], a, pct(a, r.depth_m),
                       r.platform.governing_riser[k] + ":" + r.platform.governing_criterion[k]);
  }
  for (const SozZone& zone : r.zones) {
    for (std::size_t k = 0; k < r.directions_deg.size(); ++k) {
      const double a = zone.platform.allowable_offset_m[k];
      out += fmt::format("{},platform@{},{:.3f},{:.4f},{},,,\n", r.directions_deg[k], zone.name, a, pct(a, r.depth_m),
                         zone.platform.governing_riser[k] + ":" + zone.platform.governing_criterion[k]);
    }
  }
  return out;
}

}  // namespace spiral::design
