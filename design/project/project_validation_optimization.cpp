// Validation of the section optimization (project_validation_checks.hpp).

#include <algorithm>
#include <cmath>
#include <limits>

#include "design/project/payout_groups.hpp"
#include "design/project/project_validation_checks.hpp"

namespace spiral::design::validation_detail {

namespace {

/// A haul-in `min_m` that leaves a line of the group without a top segment,
/// or so short that even straight between anchor and fairlead at rest it
/// would need more than its weakest segment's MBL (the straight-line lower
/// bound of check_line_length: the stretch chord − L shared by the segments
/// in series). A taut line may well be shorter than its chord: its
/// stretch takes up the difference.
void check_haul_in(const Project& p, const LineCheckTable& table, const PayoutGroup& group, double min_m,
                   const std::string& path, Reporter& r) {
  for (const std::size_t i : group.lines) {
    const MooringLine& line = p.mooring.lines[i];
    if (line.segments.empty()) continue;
    const double top_m = line.segments.back().length_m;
    if (top_m + min_m <= 0.0) {
      r.fail(path, "payout_keeps_top_segment",
             fmt::format("hauling in {:.6g} m removes the whole top segment ({:.6g} m) of line {}", -min_m, top_m,
                         line.name));
      return;
    }
    const double chord_m = (p.hull.reference_point_g + line.fairlead_b - line.anchor_g).norm();
    const double hauled_m = total_length_m(line) + min_m;
    if (hauled_m >= chord_m) continue;
    double compliance_per_N = 0.0;
    std::optional<double> weakest_mbl_N;
    for (std::size_t k = 0; k < line.segments.size(); ++k) {
      const LineCheckProperties props = check_properties(p, table, line.segments[k].type);
      if (!props.axial_stiffness_N || !props.breaking_load_N || !(*props.axial_stiffness_N > 0.0)) return;
      const double length = line.segments[k].length_m + (k + 1 == line.segments.size() ? min_m : 0.0);
      compliance_per_N += length / *props.axial_stiffness_N;
      weakest_mbl_N = std::min(weakest_mbl_N.value_or(*props.breaking_load_N), *props.breaking_load_N);
    }
    const double tension_N = (chord_m - hauled_m) / compliance_per_N;
    if (tension_N > *weakest_mbl_N) {
      r.fail(path, "payout_line_too_short",
             fmt::format("hauling in {:.6g} m leaves line {} {:.6g} m long against its anchor-fairlead distance "
                         "{:.6g} m at rest: even straight it would need {:.4g} N, above its breaking load {:.4g} N",
                         -min_m, line.name, hauled_m, chord_m, tension_N, *weakest_mbl_N));
      return;
    }
  }
}

}  // namespace

void check_optimization(const Project& p, const LineCheckTable& table, Reporter& r) {
  if (!p.optimization) return;
  const Optimization& o = *p.optimization;
  const std::string at = "optimization";

  // Explicit groups: defined, and no line in two of them (one payout per line).
  std::vector<std::string> owner(p.mooring.lines.size());
  for (std::size_t k = 0; k < o.groups.size(); ++k) {
    const std::string path = fmt::format("{}.groups[{}]", at, k);
    const auto g = std::find_if(p.mooring.groups.begin(), p.mooring.groups.end(),
                                [&](const LineGroup& x) { return x.name == o.groups[k]; });
    if (g == p.mooring.groups.end()) {
      r.fail(path, "group_defined",
             fmt::format("undefined line group \"{}\"{}", o.groups[k], defined_list(p.mooring.groups)));
      continue;
    }
    for (const std::string& line : g->lines) {
      for (std::size_t i = 0; i < p.mooring.lines.size(); ++i) {
        if (p.mooring.lines[i].name != line) continue;
        if (!owner[i].empty() && owner[i] != g->name) {
          r.fail(path, "optimization_groups_disjoint",
                 fmt::format("line {} is in group {} and in group {}: each line takes one payout", line, owner[i],
                             g->name));
        }
        owner[i] = g->name;
      }
    }
  }

  const std::vector<PayoutGroup> groups = payout_groups(p);
  const auto find_group = [&](const std::string& name) -> const PayoutGroup* {
    const auto it = std::find_if(groups.begin(), groups.end(), [&](const PayoutGroup& g) { return g.name == name; });
    return it == groups.end() ? nullptr : &*it;
  };
  const auto group_names = [&] {
    std::vector<std::string> names;
    for (const PayoutGroup& g : groups) names.push_back(g.name);
    return fmt::format(" (the optimization's groups: {})", fmt::join(names, ", "));
  };

  for (std::size_t k = 0; k < o.bounds.size(); ++k) {
    const PayoutBound& b = o.bounds[k];
    const std::string path = fmt::format("{}.bounds[{}]", at, k);
    const PayoutGroup* group = find_group(b.group);
    if (!group) {
      r.fail(path + ".group", "group_defined", fmt::format("no optimization group \"{}\"{}", b.group, group_names()));
      continue;
    }
    if (!(b.min_m < b.max_m)) {
      r.fail(path + ".min", "payout_bounds_ordered",
             fmt::format("must be below max ({:.6g} m), got {:.6g} m", b.max_m, b.min_m));
      continue;
    }
    check_haul_in(p, table, *group, b.min_m, path + ".min", r);
  }
  positive(r, at + ".payout_limit_pct", o.payout_limit_pct, "%", "payout_limit_positive");
  if (o.payout_limit_pct > 0.0) {
    // The default bounds: ± the limit of each group's shortest line.
    for (const PayoutGroup& g : groups) {
      if (std::any_of(o.bounds.begin(), o.bounds.end(), [&](const PayoutBound& b) { return b.group == g.name; }))
        continue;
      double shortest = std::numeric_limits<double>::infinity();
      for (const std::size_t i : g.lines) shortest = std::min(shortest, total_length_m(p.mooring.lines[i]));
      check_haul_in(p, table, g, -0.01 * o.payout_limit_pct * shortest, at + ".payout_limit_pct", r);
    }
  }
  for (std::size_t k = 0; k < o.cases.size(); ++k) {
    if (!defined(p.load_cases, o.cases[k])) {
      r.fail(fmt::format("{}.cases[{}]", at, k), "load_case_defined",
             fmt::format("undefined load case \"{}\"{}", o.cases[k], defined_list(p.load_cases)));
    }
  }
  at_least(r, at + ".min_laid_length", o.min_laid_length_m, 0.0, "m", "min_laid_length_non_negative");
  positive(r, at + ".min_tension", o.min_tension_N, "N", "min_tension_positive");
  positive(r, at + ".payout_tolerance", o.payout_tolerance_m, "m", "payout_tolerance_positive");
  if (o.max_evaluations < 1) {
    r.fail(at + ".max_evaluations", "max_evaluations_positive", fmt::format("must be >= 1, got {}", o.max_evaluations));
  }
  for (std::size_t k = 0; k < o.target_pretension.size(); ++k) {
    const PretensionTarget& t = o.target_pretension[k];
    const std::string path = fmt::format("{}.target_pretension[{}]", at, k);
    if (!find_group(t.group)) {
      r.fail(path + ".group", "group_defined", fmt::format("no optimization group \"{}\"{}", t.group, group_names()));
    }
    positive(r, path + ".tension", t.tension_N, "N", "target_tension_positive");
  }
}

}  // namespace spiral::design::validation_detail
