#include "design/results/soz_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

double pct(double offset_m, double depth_m) { return 100.0 * offset_m / depth_m; }

/// One letter per criterion for the compact table (legend printed with it).
char criterion_letter(const std::string& c) {
  if (c == "von_mises") return 'v';
  if (c == "min_effective_tension") return 'c';
  if (c == "max_top_tension") return 't';
  if (c == "max_top_angle") return 'a';
  if (c == "flex_joint_rotation") return 'f';
  if (c == "min_bending_radius") return 'b';
  if (c == "max_touchdown_excursion") return 'x';
  if (c == "search_limit") return '>';
  if (c == "no_static_solution") return '!';
  return '?';
}

double time_per_solve_s(const SozResult& r) { return r.solves > 0 ? r.zone_wall_s * r.threads / r.solves : 0.0; }

}  // namespace

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
                      {"kind", z.kind},
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
                      {"kind", c.kind},
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

std::string soz_table(const SozResult& r) {
  const SozOptions& o = r.options;
  std::string out =
      fmt::format("Riser safe operational zones — {} — {} ({}; design condition {}; model {})\n", r.project,
                  r.conditions.name, r.conditions.current ? "with its current on the risers" : "no current",
                  to_string(r.conditions.condition), to_string(o.model));
  out += fmt::format(
      "Offsets of the hull reference point, m (% of depth {:.0f} m); directions every {}° CCW from "
      "+x; "
      "tolerance {} m; search to {:.0f} m in {:.0f} m steps.\n",
      r.depth_m, o.step_deg, o.tolerance_m, o.search_limit_pct_depth * r.depth_m / 100.0,
      o.march_step_pct_depth * r.depth_m / 100.0);
  if (r.conditions.heave_m != 0.0 || r.conditions.rotation_rad.norm() > 0.0) {
    out += fmt::format(
        "Mean hull position of the case: heave {:.3f} m, roll {:.3f}°, pitch {:.3f}°, yaw "
        "{:.3f}°\n",
        r.conditions.heave_m, r.conditions.rotation_rad.x() * kRadToDeg, r.conditions.rotation_rad.y() * kRadToDeg,
        r.conditions.rotation_rad.z() * kRadToDeg);
  }
  out += "\nPer riser (near: hull moves towards the riser's azimuth; far: away; cross: ±90°):\n";
  out += fmt::format("{:<6} {:<9} {:>6} {:>24} {:>15} {:<22} {:>15} {:<22} {:>8} {:>8} {:>5} {:>6}\n", "riser", "kind",
                     "az°", "at zero offset", "near m (%d)", "near governs", "far m (%d)", "far governs", "cross+ m",
                     "cross- m", "star", "solves");
  for (const RiserSoz& z : r.risers) {
    out += fmt::format(
        "{:<6} {:<9} {:>6.1f} {:>24} {:>7.1f} ({:>4.1f}) {:<22} {:>7.1f} ({:>4.1f}) {:<22} "
        "{:>8.1f} {:>8.1f} {:>5} "
        "{:>6}\n",
        z.name, z.kind, z.azimuth_deg,
        fmt::format("{:.3f} {}{}", z.zero_offset_utilization, z.zero_offset_governing_criterion,
                    z.fails_at_zero_offset ? " FAIL" : ""),
        z.near_m, pct(z.near_m, r.depth_m), z.near_governing, z.far_m, pct(z.far_m, r.depth_m), z.far_governing,
        z.cross_left_m, z.cross_right_m, z.star_shaped ? "yes" : "NO", z.solves);
  }

  out +=
      "\nAllowable offset per direction, m, with the governing criterion: v von Mises, c min "
      "effective tension "
      "(compression), t top tension, a top angle, f flex joint, b bending radius, x TDP excursion, "
      "> search "
      "limit, ! no static solution; * a band re-opens farther out (not star-shaped).\n";
  out += fmt::format("{:>5}", "dir°");
  for (const RiserSoz& z : r.risers) out += fmt::format(" {:>8}", z.name);
  out += fmt::format(" | {:>8} {:>6} {:<6}\n", "platform", "%depth", "riser");
  for (std::size_t k = 0; k < r.directions_deg.size(); ++k) {
    out += fmt::format("{:>5g}", r.directions_deg[k]);
    for (const RiserSoz& z : r.risers) {
      const SozDirection& d = z.directions[k];
      out += fmt::format(" {:>6.1f}{}{}", d.allowable_offset_m, criterion_letter(d.governing_criterion),
                         d.reopened_bands.empty() ? ' ' : '*');
    }
    const double a = r.platform.allowable_offset_m[k];
    out += fmt::format(" | {:>7.1f}{} {:>6.2f} {:<6}\n", a, criterion_letter(r.platform.governing_criterion[k]),
                       pct(a, r.depth_m), r.platform.governing_riser[k]);
  }

  if (!r.zones.empty()) {
    out += "\nPlatform allowable offset per direction, m, in the zones of the cases' currents (zone: cases):\n";
    for (std::size_t z = 0; z < r.zones.size(); ++z) {
      std::string cases;
      for (const std::string& c : r.zones[z].cases) cases += (cases.empty() ? "" : ", ") + c;
      out += fmt::format("  Z{} {}: {}\n", z + 1, r.zones[z].name, cases);
    }
    out += fmt::format("{:>5} {:>12}", "dir°", "still-water");
    for (std::size_t z = 0; z < r.zones.size(); ++z) out += fmt::format(" {:>12}", fmt::format("Z{}", z + 1));
    out += "\n";
    for (std::size_t k = 0; k < r.directions_deg.size(); ++k) {
      out += fmt::format("{:>5g} {:>11.1f}{}", r.directions_deg[k], r.platform.allowable_offset_m[k],
                         criterion_letter(r.platform.governing_criterion[k]));
      for (const SozZone& zone : r.zones) {
        out += fmt::format(" {:>11.1f}{}", zone.platform.allowable_offset_m[k],
                           criterion_letter(zone.platform.governing_criterion[k]));
      }
      out += "\n";
    }
  }

  if (!r.offset_checks.empty()) {
    out += "\nOffset check against the platform SOZ (ratio = offset / allowable, ≤ 1 passes):\n";
    out += fmt::format("{:<32} {:<8} {:<7} {:>9} {:>7} {:>11} {:>9} {:>7} {:<5} {:<6} {}\n", "case", "cond.", "kind",
                       "offset m", "dir°", "allowable m", "margin m", "ratio", "", "riser", "zone");
    for (const OffsetCheck& c : r.offset_checks) {
      out += fmt::format("{:<32} {:<8} {:<7} {:>9.2f} {:>7.1f} {:>11.2f} {:>9.2f} {:>7.3f} {:<5} {:<6} {}\n",
                         c.case_name, to_string(c.integrity), c.kind, c.offset_m, c.direction_deg, c.allowable_m,
                         c.margin_m, c.ratio, c.passes ? "PASS" : "FAIL", c.governing_riser, c.zone);
    }
  }
  for (const std::string& note : r.notes) out += "Note: " + note + "\n";
  for (const RiserSoz& z : r.risers) {
    for (const SozDirection& d : z.directions) {
      for (const SozBand& b : d.reopened_bands) {
        out += fmt::format(
            "Note: riser {} at {:g}°: fails beyond {:.1f} m but passes again from {:.1f} to {:.1f} "
            "m "
            "(not part of the zone)\n",
            z.name, d.direction_deg, d.allowable_offset_m, b.from_m, b.to_m);
      }
    }
  }
  out += fmt::format("\n{} riser static solves in {:.2f} s on {} threads ({:.2f} ms per solve per thread)", r.solves,
                     r.zone_wall_s, r.threads, 1e3 * time_per_solve_s(r));
  if (r.check_wall_s > 0.0) {
    out += fmt::format("; load-case equilibria{} {:.2f} s", r.options.extreme ? " and S-C storms" : "", r.check_wall_s);
  }
  out += "\n";
  return out;
}

}  // namespace spiral::design
