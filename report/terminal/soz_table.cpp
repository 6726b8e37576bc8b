#include "report/terminal/soz_table.hpp"

#include <numbers>

#include <fmt/format.h>

#include "design/results/soz_output.hpp"

namespace spiral::report {

using namespace design;

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

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

}  // namespace

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
        z.name, to_string(z.kind), z.azimuth_deg,
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
                         c.case_name, to_string(c.integrity), to_string(c.kind), c.offset_m, c.direction_deg,
                         c.allowable_m, c.margin_m, c.ratio, c.passes ? "PASS" : "FAIL", c.governing_riser, c.zone);
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

}  // namespace spiral::report
