#include "report/terminal/statics_table.hpp"

#include <numbers>

#include <fmt/format.h>

namespace spiral::report {

using namespace design;

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

}  // namespace

std::string statics_table(const StaticsResult& result, const std::string& project_name) {
  std::string out;
  const engine::Vector6d& o = result.offset;
  out += fmt::format("Mooring statics — {}\n", project_name);
  out += fmt::format(
      "Hull offset: surge {:.3f} m, sway {:.3f} m, heave {:.3f} m, roll {:.3f}°, pitch {:.3f}°, "
      "yaw {:.3f}°\n\n",
      o(0), o(1), o(2), o(3) * kRadToDeg, o(4) * kRadToDeg, o(5) * kRadToDeg);
  out += fmt::format("{:<10} {:>11} {:>11} {:>11} {:>7} {:>11} {:>8} {:>9} {:>7} {:<9}\n", "line", "T_fair kN",
                     "H_fair kN", "V_fair kN", "ang °", "T_anch kN", "uplift°", "laid m", "util", "regime");
  for (const LineStaticsRow& row : result.lines) {
    out += fmt::format("{:<10} {:>11.1f} {:>11.1f} {:>11.1f} {:>7.2f} {:>11.1f} {:>8.2f} {:>9.1f} {:>7.3f} {:<9}\n",
                       row.name, row.fairlead_tension_N / 1e3, row.fairlead_horizontal_N / 1e3,
                       row.fairlead_vertical_N / 1e3, row.fairlead_angle_deg, row.anchor_tension_N / 1e3,
                       row.anchor_uplift_angle_deg, row.laid_length_m, row.utilization, engine::to_string(row.regime));
  }
  const engine::Vector6d& f = result.hull_force;
  out += fmt::format(
      "\nMooring force on the hull (global axes, about the displaced reference point):\n"
      "  Fx {:.1f} kN  Fy {:.1f} kN  Fz {:.1f} kN  Mx {:.1f} kN·m  My {:.1f} kN·m  Mz {:.1f} kN·m\n",
      f(0) / 1e3, f(1) / 1e3, f(2) / 1e3, f(3) / 1e3, f(4) / 1e3, f(5) / 1e3);
  out += "Utilization: largest tension in a segment / that segment's MBL (no safety factor).\n";
  return out;
}

}  // namespace spiral::report
