// Semantic validation of a project (format v1). Each check function covers
// one section and reports each violated condition under its name; the
// condition names and messages are listed in docs/project-format.md.
// (Layout after Drake's geometry/scene_graph_config.cc ValidateOrThrow.)
//
// Past the usual ~600 lines for the same reason as project_loader.cpp: one
// place per format section. If it grows further, the hull tables and the
// riser checks are the natural files to split off.

#include "design/project/project_validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <variant>

namespace spiral::design {

InputIssue make_issue(const Project& project, const std::string& path, std::string condition,
                      std::string message) {
  InputIssue issue;
  issue.file = project.source_file;
  // A value that was defaulted has no node: use its closest written parent.
  std::string at = path;
  while (true) {
    if (const auto it = project.source_map.find(at); it != project.source_map.end()) {
      issue.line = it->second.line;
      issue.column = it->second.column;
      break;
    }
    const auto cut = at.find_last_of(".[");
    if (cut == std::string::npos) break;
    at.resize(cut);
  }
  issue.path = path;
  issue.message = std::move(message);
  issue.condition = std::move(condition);
  return issue;
}

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

/// Collects issues, placing each at the nearest recorded node of its path.
class Reporter {
 public:
  Reporter(const Project& project, std::vector<InputIssue>& out) : project_(project), out_(out) {}

  void fail(const std::string& path, std::string condition, std::string message) {
    out_.push_back(make_issue(project_, path, std::move(condition), std::move(message)));
  }

 private:
  const Project& project_;
  std::vector<InputIssue>& out_;
};

std::string unit_suffix(std::string_view unit) {
  return unit.empty() ? std::string() : fmt::format(" {}", unit);
}

void positive(Reporter& r, const std::string& path, double value, std::string_view unit,
              const char* condition) {
  if (!(value > 0.0)) {
    r.fail(path, condition,
           fmt::format("must be > 0{}, got {}{}", unit_suffix(unit), value, unit_suffix(unit)));
  }
}

void positive(Reporter& r, const std::string& path, const std::optional<double>& value,
              std::string_view unit, const char* condition) {
  if (value) positive(r, path, *value, unit, condition);
}

void at_least(Reporter& r, const std::string& path, double value, double minimum,
              std::string_view unit, const char* condition) {
  if (!(value >= minimum)) {
    r.fail(path, condition,
           fmt::format("must be >= {}{}, got {}{}", minimum, unit_suffix(unit), value,
                       unit_suffix(unit)));
  }
}

void at_least(Reporter& r, const std::string& path, const std::optional<double>& value,
              double minimum, std::string_view unit, const char* condition) {
  if (value) at_least(r, path, *value, minimum, unit, condition);
}

/// Reports the second and later uses of a name in a list.
template <typename T>
void unique_names(Reporter& r, const std::vector<T>& items, const std::string& list_path,
                  const char* what, const char* condition) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (items[i].name == items[j].name) {
        r.fail(fmt::format("{}[{}].name", list_path, i), condition,
               fmt::format("duplicate {} name \"{}\", first used by {}[{}]", what, items[i].name,
                           list_path, j));
        break;
      }
    }
  }
}

template <typename T>
bool defined(const std::vector<T>& items, const std::string& name) {
  return std::any_of(items.begin(), items.end(), [&](const T& item) { return item.name == name; });
}

/// " (defined: a, b, c)" for reference errors.
template <typename T>
std::string defined_list(const std::vector<T>& items) {
  std::vector<std::string> names;
  for (const auto& item : items) names.push_back(item.name);
  return names.empty() ? std::string(" (none defined)")
                       : fmt::format(" (defined: {})", fmt::join(names, ", "));
}

// ---------------------------------------------------------------- checks ----

/// FE discretization of a line or riser at `at` (its `fe` map).
void check_fe_mesh(Reporter& r, const std::string& at, const FeMesh& mesh) {
  const char* c = "fe_mesh_positive";
  positive(r, at + ".element_length", mesh.element_length_m, "m", c);
  if (const auto& t = mesh.touchdown_refinement) {
    positive(r, at + ".touchdown_refinement.length", t->length_m, "m", c);
    positive(r, at + ".touchdown_refinement.element_length", t->element_length_m, "m", c);
    if (t->element_length_m > mesh.element_length_m) {
      r.fail(at + ".touchdown_refinement.element_length", "touchdown_refinement_finer",
             fmt::format("must be <= element_length {} m (a refinement), got {} m",
                         mesh.element_length_m, t->element_length_m));
    }
  }
}

/// Headings of a table: at least `minimum` of them, each in [0, 360) deg,
/// strictly increasing (periodic interpolation needs an ordered circle).
void check_headings(Reporter& r, const std::string& at, const std::vector<double>& headings_rad,
                    std::size_t minimum) {
  const char* c = "headings_valid";
  if (headings_rad.size() < minimum) {
    r.fail(at, c, fmt::format("needs at least {} headings, got {}", minimum, headings_rad.size()));
  }
  for (std::size_t k = 0; k < headings_rad.size(); ++k) {
    const double deg = headings_rad[k] * kRadToDeg;
    const std::string kat = fmt::format("{}[{}]", at, k);
    if (!(headings_rad[k] >= 0.0 && headings_rad[k] < 2.0 * std::numbers::pi)) {
      r.fail(kat, c, fmt::format("must be in [0, 360) deg, got {:.6g} deg", deg));
    } else if (k > 0 && !(headings_rad[k] > headings_rad[k - 1])) {
      r.fail(kat, c,
             fmt::format("headings must increase strictly, got {:.6g} deg after {:.6g} deg", deg,
                         headings_rad[k - 1] * kRadToDeg));
    }
  }
}

/// The list at `at` must have `expected` values, one per entry of `axis`.
void check_length(Reporter& r, const std::string& at, std::size_t size, std::size_t expected,
                  const char* axis) {
  if (size != expected) {
    r.fail(at, "table_lengths_match",
           fmt::format("must have one value per entry of {} ({}), got {}", axis, expected, size));
  }
}

void check_load_coefficients(Reporter& r, const std::string& at, const HullLoadCoefficients& c) {
  check_headings(r, at + ".headings_deg", c.headings_rad, 2);
  const std::size_t n = c.headings_rad.size();
  check_length(r, at + ".surge", c.surge_m2.size(), n, "headings_deg");
  check_length(r, at + ".sway", c.sway_m2.size(), n, "headings_deg");
  check_length(r, at + ".yaw", c.yaw_m3.size(), n, "headings_deg");
}

void check_mean_drift_table(Reporter& r, const std::string& at, const MeanDriftTable& t) {
  check_headings(r, at + ".headings_deg", t.headings_rad, 2);
  const auto& f = t.frequencies_rad_per_s;
  if (f.empty()) r.fail(at + ".frequencies", "frequencies_valid", "needs at least one frequency");
  for (std::size_t k = 0; k < f.size(); ++k) {
    const std::string kat = fmt::format("{}.frequencies[{}]", at, k);
    if (!(f[k] > 0.0)) {
      r.fail(kat, "frequencies_valid", fmt::format("must be > 0 rad/s, got {} rad/s", f[k]));
    } else if (k > 0 && !(f[k] > f[k - 1])) {
      r.fail(kat, "frequencies_valid",
             fmt::format("frequencies must increase strictly, got {} rad/s after {} rad/s", f[k],
                         f[k - 1]));
    }
  }
  for (const auto& [key, rows] :
       {std::pair{".surge", &t.surge_N_per_m2}, std::pair{".sway", &t.sway_N_per_m2},
        std::pair{".yaw", &t.yaw_N_m_per_m2}}) {
    check_length(r, at + key, rows->size(), t.headings_rad.size(), "headings_deg (rows)");
    for (std::size_t i = 0; i < rows->size(); ++i) {
      check_length(r, fmt::format("{}{}[{}]", at, key, i), (*rows)[i].size(), f.size(),
                   "frequencies");
    }
  }
}

void check_member_coefficients(Reporter& r, const std::string& at, const MemberCoefficients& c) {
  at_least(r, at + ".drag", c.drag, 0.0, "", "coefficient_non_negative");
  at_least(r, at + ".added_mass", c.added_mass, 0.0, "", "coefficient_non_negative");
}

void check_file(Reporter& r, const std::string& at, const std::filesystem::path& file);

void check_hull_geometry(Reporter& r, const HullGeometry& g) {
  if (g.columns.empty() && g.pontoons.empty() && !g.panel_mesh) {
    r.fail("hull.geometry", "hull_geometry_members", "needs at least one column, pontoon or a panel_mesh");
  }
  if (g.panel_mesh) check_file(r, "hull.geometry.panel_mesh", *g.panel_mesh);
  for (std::size_t i = 0; i < g.columns.size(); ++i) {
    const HullColumn& c = g.columns[i];
    const std::string at = fmt::format("hull.geometry.columns[{}]", i);
    positive(r, at + ".diameter", c.diameter_m, "m", "hull_value_positive");
    if (!(c.z_top_m > c.z_bottom_m)) {
      r.fail(at + ".z_top", "column_top_above_bottom",
             fmt::format("must be above z_bottom {} m, got {} m", c.z_bottom_m, c.z_top_m));
    }
    check_member_coefficients(r, at, c.coefficients);
    at_least(r, at + ".end_added_mass", c.end_added_mass, 0.0, "", "coefficient_non_negative");
    at_least(r, at + ".end_drag", c.end_drag, 0.0, "", "coefficient_non_negative");
  }
  for (std::size_t i = 0; i < g.pontoons.size(); ++i) {
    const HullPontoon& p = g.pontoons[i];
    const std::string at = fmt::format("hull.geometry.pontoons[{}]", i);
    positive(r, at + ".diameter", p.diameter_m, "m", "hull_value_positive");
    check_member_coefficients(r, at, p.coefficients);
    if (!((p.to_b - p.from_b).norm() > 0.0)) {
      r.fail(at + ".to", "pontoon_length_positive",
             fmt::format("must differ from `from`, got both at [{}, {}, {}] m", p.to_b.x(),
                         p.to_b.y(), p.to_b.z()));
    }
  }
}

/// Riser criteria values given at `at` (criteria.risers or risers[i].criteria).
void check_riser_criteria(Reporter& r, const std::string& at, const RiserCriteriaOverrides& c) {
  for (const auto& [key, value] :
       {std::pair{".design_factor.normal", c.design_factor_normal},
        std::pair{".design_factor.extreme", c.design_factor_extreme},
        std::pair{".design_factor.survival", c.design_factor_survival}}) {
    if (value && !(*value > 0.0 && *value <= 1.0)) {
      r.fail(at + key, "design_factor_range",
             fmt::format("must be in (0, 1] (fraction of the yield stress), got {}", *value));
    }
  }
  at_least(r, at + ".min_effective_tension", c.min_effective_tension_N, 0.0, "N",
           "riser_criterion_non_negative");
  positive(r, at + ".max_top_tension", c.max_top_tension_N, "N", "riser_criterion_positive");
  positive(r, at + ".min_bending_radius", c.min_bending_radius_m, "m", "riser_criterion_positive");
  positive(r, at + ".max_touchdown_excursion", c.max_touchdown_excursion_m, "m",
           "riser_criterion_positive");
  for (const auto& [key, value] :
       {std::pair{".max_top_angle_deg", c.max_top_angle_rad},
        std::pair{".max_flex_joint_rotation_deg", c.max_flex_joint_rotation_rad}}) {
    if (value && !(*value > 0.0 && *value < std::numbers::pi / 2)) {
      r.fail(at + key, "riser_angle_limit_range",
             fmt::format("must be in (0, 90) deg, got {:.6g} deg", *value * kRadToDeg));
    }
  }
}


void check_site(const Project& p, Reporter& r) {
  positive(r, "site.depth", p.site.depth_m, "m", "depth_positive");
  positive(r, "site.water_density", p.site.water_density_kg_per_m3, "kg/m^3",
           "water_density_positive");
  positive(r, "site.gravity", p.site.gravity_m_per_s2, "m/s^2", "gravity_positive");
  positive(r, "site.air_density", p.site.air_density_kg_per_m3, "kg/m^3", "air_density_positive");
  at_least(r, "site.seabed.friction_axial", p.site.seabed.friction_axial, 0.0, "",
           "friction_non_negative");
  at_least(r, "site.seabed.friction_lateral", p.site.seabed.friction_lateral, 0.0, "",
           "friction_non_negative");
  positive(r, "site.seabed.normal_stiffness", p.site.seabed.normal_stiffness_Pa_per_m, "Pa/m",
           "seabed_stiffness_positive");
}

void check_line_types(const Project& p, Reporter& r) {
  unique_names(r, p.line_types, "line_types", "line type", "line_type_name_unique");
  for (std::size_t i = 0; i < p.line_types.size(); ++i) {
    const LineTypeInput& t = p.line_types[i];
    const std::string at = fmt::format("line_types[{}]", i);
    const char* c = "line_type_value_positive";
    positive(r, at + ".diameter", t.diameter_m, "m", c);
    positive(r, at + ".mass_per_length", t.mass_per_length_kg_per_m, "kg/m", c);
    positive(r, at + ".hydrodynamic_diameter", t.hydrodynamic_diameter_m, "m", c);
    positive(r, at + ".axial_stiffness", t.axial_stiffness_N, "N", c);
    positive(r, at + ".breaking_load", t.breaking_load_N, "N", c);
    positive(r, at + ".static_stiffness_mbl", t.static_stiffness_mbl, "", c);
    if (t.dynamic_stiffness_mbl) {
      positive(r, at + ".dynamic_stiffness_mbl[0]", (*t.dynamic_stiffness_mbl)[0], "", c);
      at_least(r, at + ".dynamic_stiffness_mbl[1]", (*t.dynamic_stiffness_mbl)[1], 0.0, "", c);
    }
    for (const auto& [key, value] :
         {std::pair{".drag_normal", t.drag_normal}, std::pair{".drag_axial", t.drag_axial},
          std::pair{".added_mass_normal", t.added_mass_normal},
          std::pair{".added_mass_axial", t.added_mass_axial}}) {
      at_least(r, at + key, value, 0.0, "", "coefficient_non_negative");
    }
    if (t.grade && t.kind != LineKind::chain) {
      r.fail(at + ".grade", "key_not_applicable", "applies to chain line types only");
    }
    if (t.kind != LineKind::polyester) {
      if (t.static_stiffness_mbl) {
        r.fail(at + ".static_stiffness_mbl", "key_not_applicable",
               "applies to polyester line types only (give axial_stiffness for other kinds)");
      }
      if (t.dynamic_stiffness_mbl) {
        r.fail(at + ".dynamic_stiffness_mbl", "key_not_applicable",
               "applies to polyester line types only");
      }
    }
    if (t.kind == LineKind::user) {
      // No formula can supply these for a user-defined line.
      if (!t.mass_per_length_kg_per_m && !t.submerged_weight_N_per_m) {
        r.fail(at, "user_line_type_complete",
               "a user line type needs mass_per_length (kg/m) or submerged_weight (N/m)");
      }
      if (!t.axial_stiffness_N) {
        r.fail(at, "user_line_type_complete", "a user line type needs axial_stiffness (N)");
      }
      if (!t.breaking_load_N) {
        r.fail(at, "user_line_type_complete", "a user line type needs breaking_load (N)");
      }
    }
  }
}

/// The EA/MBL/weight of a type: resolved table first, explicit input second.
LineCheckProperties check_properties(const Project& p, const LineCheckTable& table,
                                     const std::string& type) {
  if (const auto it = table.find(type); it != table.end()) return it->second;
  LineCheckProperties props;
  for (const auto& t : p.line_types) {
    if (t.name != type) continue;
    props.axial_stiffness_N = t.axial_stiffness_N;
    props.breaking_load_N = t.breaking_load_N;
    props.submerged_weight_N_per_m = t.submerged_weight_N_per_m;
  }
  return props;
}

/// Length against the at-rest anchor-fairlead geometry (lines too short to
/// reach without breaking, or so long that they lie slack).
void check_line_length(const Project& p, const LineCheckTable& table, std::size_t index,
                       Reporter& r) {
  const MooringLine& line = p.mooring.lines[index];
  const std::string at = fmt::format("mooring.lines[{}].segments", index);
  double total_m = 0.0;
  for (const auto& s : line.segments) {
    if (!(s.length_m > 0.0) || !defined(p.line_types, s.type)) return;  // reported elsewhere
    total_m += s.length_m;
  }
  if (line.segments.empty()) return;

  const Eigen::Vector3d fairlead_g = p.hull.reference_point_g + line.fairlead_b;
  const Eigen::Vector3d chord = fairlead_g - line.anchor_g;
  const double chord_m = chord.norm();
  const double span_m = chord.head<2>().norm();
  const double height_m = chord.z();

  if (total_m < chord_m) {
    // Straight-line lower bound of the tension (weight ignored): the stretch
    // chord - L shared by segments in series, T = (chord - L) / sum(L_i / EA_i).
    const double strain = chord_m / total_m - 1.0;
    double compliance_per_N = 0.0;
    std::optional<double> weakest_mbl_N;
    std::string weakest_type;
    bool all_known = true;
    for (const auto& s : line.segments) {
      const LineCheckProperties props = check_properties(p, table, s.type);
      if (!props.axial_stiffness_N || !props.breaking_load_N || !(*props.axial_stiffness_N > 0)) {
        all_known = false;
        break;
      }
      compliance_per_N += s.length_m / *props.axial_stiffness_N;
      if (!weakest_mbl_N || *props.breaking_load_N < *weakest_mbl_N) {
        weakest_mbl_N = *props.breaking_load_N;
        weakest_type = s.type;
      }
    }
    const std::string head = fmt::format(
        "line too short: total unstretched length {:.6g} m is less than the anchor-fairlead "
        "distance {:.6g} m at rest, a mean strain of {:.3g} %",
        total_m, chord_m, 100.0 * strain);
    if (all_known) {
      const double tension_N = (chord_m - total_m) / compliance_per_N;
      if (tension_N > *weakest_mbl_N) {
        r.fail(at, "line_too_short",
               fmt::format("{}; that takes a tension of at least {:.4g} N, above the breaking load "
                           "{:.4g} N of line type \"{}\"",
                           head, tension_N, *weakest_mbl_N, weakest_type));
      }
    } else if (strain > kMaxStrainWithoutProperties) {
      r.fail(at, "line_too_short",
             fmt::format("{}, more than {:g} % (EA and MBL of the line types not known)", head,
                         100.0 * kMaxStrainWithoutProperties));
    }
    return;
  }

  // Slack: hanging straight down from the fairlead and lying on the seabed,
  // the line still reaches past the anchor, so the horizontal tension is zero.
  // Only meaningful for a sinking line without buoys.
  const bool has_buoy =
      std::any_of(line.attachments.begin(), line.attachments.end(),
                  [](const Attachment& a) { return a.kind == AttachmentKind::buoy; });
  const bool buoyant_segment =
      std::any_of(line.segments.begin(), line.segments.end(), [&](const LineSegment& s) {
        const auto w = check_properties(p, table, s.type).submerged_weight_N_per_m;
        return w && *w <= 0.0;
      });
  if (has_buoy || buoyant_segment || height_m <= 0.0) return;
  if (total_m - height_m > span_m) {
    r.fail(at, "line_slack",
           fmt::format("line lies slack: total length {:.6g} m minus the fairlead height {:.6g} m "
                       "above the anchor exceeds the horizontal span {:.6g} m by {:.4g} m, so the "
                       "line has zero horizontal tension at rest",
                       total_m, height_m, span_m, total_m - height_m - span_m));
  }
}

void check_mooring(const Project& p, const LineCheckTable& table, Reporter& r) {
  unique_names(r, p.mooring.lines, "mooring.lines", "mooring line", "line_name_unique");
  const double seabed_z = -p.site.depth_m;
  for (std::size_t i = 0; i < p.mooring.lines.size(); ++i) {
    const MooringLine& line = p.mooring.lines[i];
    const std::string at = fmt::format("mooring.lines[{}]", i);
    if (line.segments.empty()) {
      r.fail(at + ".segments", "line_has_segments", "a line needs at least one segment");
    }
    for (std::size_t s = 0; s < line.segments.size(); ++s) {
      const std::string sat = fmt::format("{}.segments[{}]", at, s);
      positive(r, sat + ".length", line.segments[s].length_m, "m", "segment_length_positive");
      if (!defined(p.line_types, line.segments[s].type)) {
        r.fail(sat + ".type", "line_type_defined",
               fmt::format("undefined line type \"{}\"{}", line.segments[s].type,
                           defined_list(p.line_types)));
      }
    }
    for (std::size_t a = 0; a < line.attachments.size(); ++a) {
      const Attachment& att = line.attachments[a];
      const std::string aat = fmt::format("{}.attachments[{}]", at, a);
      const int joints = static_cast<int>(line.segments.size()) - 1;
      if (att.after_segment < 0 || att.after_segment >= joints) {
        r.fail(aat + ".after_segment", "attachment_joint_exists",
               joints > 0
                   ? fmt::format("must be a joint between segments, 0 to {}, got {}", joints - 1,
                                 att.after_segment)
                   : fmt::format("the line has no joint (one segment), got {}", att.after_segment));
      }
      at_least(r, aat + ".mass", att.mass_kg, 0.0, "kg", "attachment_value_non_negative");
      at_least(r, aat + ".volume", att.volume_m3, 0.0, "m^3", "attachment_value_non_negative");
    }
    if (p.site.depth_m > 0.0) {
      const double z = line.anchor_g.z();
      if (z < seabed_z - kSeabedTolerance_m) {
        r.fail(at + ".anchor", "anchor_below_seabed",
               fmt::format("anchor is {:.6g} m below the seabed: z = {} m, seabed at z = {} m",
                           seabed_z - z, z, seabed_z));
      } else if (z > 0.0) {
        r.fail(
            at + ".anchor", "anchor_above_water",
            fmt::format("anchor is above the water: z = {} m, must be in [{}, 0] m", z, seabed_z));
      }
    }
    const double fairlead_z_g = p.hull.reference_point_g.z() + line.fairlead_b.z();
    if (fairlead_z_g > 0.0) {
      r.fail(at + ".fairlead", "fairlead_above_water",
             fmt::format("fairlead is above the water at rest: z = {:.6g} m global (hull reference "
                         "point z {} m + fairlead z {} m), must be <= 0 m",
                         fairlead_z_g, p.hull.reference_point_g.z(), line.fairlead_b.z()));
    }
    check_fe_mesh(r, at + ".fe", line.fe);
    check_line_length(p, table, i, r);
  }
  unique_names(r, p.mooring.groups, "mooring.groups", "line group", "group_name_unique");
  for (std::size_t g = 0; g < p.mooring.groups.size(); ++g) {
    const auto& names = p.mooring.groups[g].lines;
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!defined(p.mooring.lines, names[k])) {
        r.fail(fmt::format("mooring.groups[{}].lines[{}]", g, k), "line_defined",
               fmt::format("undefined mooring line \"{}\"{}", names[k],
                           defined_list(p.mooring.lines)));
      }
    }
  }
}

void check_file(Reporter& r, const std::string& at, const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) {
    r.fail(at, "file_exists", fmt::format("file not found: {}", file.string()));
  }
}

void check_hull_hydrodynamics(Reporter& r, const Hull& hull) {
  const HullHydrodynamics& h = *hull.hydrodynamics;
  const std::string at = "hull.hydrodynamics";
  if (h.model == HullHydrodynamicsModel::morison) {
    positive(r, at + ".strip_length", h.strip_length_m, "m", "hull_value_positive");
    if (!hull.geometry || (hull.geometry->columns.empty() && hull.geometry->pontoons.empty())) {
      r.fail(at + ".model", "morison_needs_geometry",
             "model: morison builds the members from hull.geometry, which has none");
    }
  } else {
    check_file(r, at + ".radiation_file", h.radiation_file);
  }
  if (h.excitation_file) check_file(r, at + ".excitation_file", *h.excitation_file);
  if (h.rao_file) check_file(r, at + ".rao_file", *h.rao_file);
  positive(r, at + ".ulen", h.ulen_m, "m", "hull_value_positive");
  positive(r, at + ".period_scale", h.period_scale, "", "hull_value_positive");
  positive(r, at + ".added_mass_frequency", h.added_mass_frequency_rad_per_s, "rad/s",
           "hull_value_positive");
  positive(r, at + ".memory_time_step", h.memory_time_step_s, "s", "hull_value_positive");
  if (!(h.memory_duration_s > h.memory_time_step_s)) {
    r.fail(at + ".memory_duration", "memory_duration_above_step",
           fmt::format("must be above memory_time_step {} s, got {} s", h.memory_time_step_s,
                       h.memory_duration_s));
  }
  for (int k = 0; k < 6; ++k) {
    at_least(r, fmt::format("{}.linear_damping[{}]", at, k), h.linear_damping[k], 0.0,
             k < 3 ? "N s/m" : "N m s/rad", "hull_damping_non_negative");
    at_least(r, fmt::format("{}.quadratic_damping[{}]", at, k), h.quadratic_damping[k], 0.0,
             k < 3 ? "N s^2/m^2" : "N m s^2/rad^2", "hull_damping_non_negative");
  }
}

void check_hull(const Project& p, Reporter& r) {
  const Hull& h = p.hull;
  positive(r, "hull.mass", h.mass_kg, "kg", "hull_value_positive");
  if (h.radii_of_gyration_m) {
    for (int k = 0; k < 3; ++k) {
      positive(r, fmt::format("hull.radii_of_gyration[{}]", k), (*h.radii_of_gyration_m)[k], "m",
               "hull_value_positive");
    }
  }
  if (h.inertia_kg_m2) {
    for (int k = 0; k < 3; ++k) {
      positive(r, fmt::format("hull.inertia[{}]", k), (*h.inertia_kg_m2)(k, k), "kg m^2",
               "hull_value_positive");
    }
  }
  const bool all_values = h.displaced_volume_m3 && h.center_of_buoyancy_b && h.waterplane_area_m2 &&
                          h.waterplane_inertia_m4;
  if (!all_values && !h.hydrostatics_file) {
    r.fail("hull", "hull_hydrostatics_complete",
           "give displaced_volume, center_of_buoyancy, waterplane_area and waterplane_inertia, or "
           "a hydrostatics_file (.hst)");
  }
  positive(r, "hull.displaced_volume", h.displaced_volume_m3, "m^3", "hull_value_positive");
  positive(r, "hull.waterplane_area", h.waterplane_area_m2, "m^2", "hull_value_positive");
  if (h.waterplane_inertia_m4) {
    for (int k = 0; k < 2; ++k) {
      positive(r, fmt::format("hull.waterplane_inertia[{}]", k), (*h.waterplane_inertia_m4)[k],
               "m^4", "hull_value_positive");
    }
  }
  if (h.hydrostatics_file && !std::filesystem::is_regular_file(*h.hydrostatics_file)) {
    r.fail("hull.hydrostatics_file", "file_exists",
           fmt::format("file not found: {}", h.hydrostatics_file->string()));
  }
  if (h.wind_coefficients) {
    check_load_coefficients(r, "hull.wind_coefficients", *h.wind_coefficients);
    positive(r, "hull.wind_coefficients.reference_height", h.wind_coefficients->reference_height_m,
             "m", "hull_value_positive");
  }
  if (h.current_coefficients) {
    check_load_coefficients(r, "hull.current_coefficients", *h.current_coefficients);
  }
  if (h.mean_drift) {
    if (const auto* f = std::get_if<MeanDriftFile>(&*h.mean_drift)) {
      if (!std::filesystem::is_regular_file(f->file)) {
        r.fail("hull.mean_drift.file", "file_exists",
               fmt::format("file not found: {}", f->file.string()));
      }
      positive(r, "hull.mean_drift.ulen", f->ulen_m, "m", "hull_value_positive");
      positive(r, "hull.mean_drift.period_scale", f->period_scale, "", "hull_value_positive");
    } else {
      check_mean_drift_table(r, "hull.mean_drift", std::get<MeanDriftTable>(*h.mean_drift));
    }
  }
  if (h.hydrodynamics) check_hull_hydrodynamics(r, h);
  if (h.geometry) check_hull_geometry(r, *h.geometry);
}

void check_riser_section(const Riser& riser, const RiserSection& s, const std::string& at,
                         Reporter& r) {
  const char* c = "riser_value_positive";
  positive(r, at + ".length", s.length_m, "m", c);
  positive(r, at + ".outer_diameter", s.outer_diameter_m, "m", c);
  at_least(r, at + ".contents_density", s.contents_density_kg_per_m3, 0.0, "kg/m^3",
           "riser_value_non_negative");
  positive(r, at + ".wall_thickness", s.wall_thickness_m, "m", c);
  positive(r, at + ".inner_diameter", s.inner_diameter_m, "m", c);
  positive(r, at + ".youngs_modulus", s.youngs_modulus_Pa, "Pa", c);
  positive(r, at + ".yield_stress", s.yield_stress_Pa, "Pa", c);
  positive(r, at + ".steel_density", s.steel_density_kg_per_m3, "kg/m^3", c);
  positive(r, at + ".coating_thickness", s.coating_thickness_m, "m", c);
  positive(r, at + ".coating_density", s.coating_density_kg_per_m3, "kg/m^3", c);
  positive(r, at + ".buoyancy_density", s.buoyancy_density_kg_per_m3, "kg/m^3", c);
  positive(r, at + ".axial_stiffness", s.axial_stiffness_N, "N", c);
  positive(r, at + ".bending_stiffness", s.bending_stiffness_N_m2, "N m^2", c);
  positive(r, at + ".mass_per_length", s.mass_per_length_kg_per_m, "kg/m", c);
  for (const auto& [key, value] :
       {std::pair{".drag_normal", s.drag_normal}, std::pair{".drag_axial", s.drag_axial},
        std::pair{".added_mass_normal", s.added_mass_normal},
        std::pair{".added_mass_axial", s.added_mass_axial}}) {
    at_least(r, at + key, value, 0.0, "", "coefficient_non_negative");
  }
  if (s.wall_thickness_m && s.outer_diameter_m > 0.0 &&
      !(*s.wall_thickness_m < 0.5 * s.outer_diameter_m)) {
    r.fail(at + ".wall_thickness", "wall_thinner_than_radius",
           fmt::format("must be < outer_diameter / 2 = {} m, got {} m", 0.5 * s.outer_diameter_m,
                       *s.wall_thickness_m));
  }
  if (s.inner_diameter_m && s.wall_thickness_m) {
    r.fail(at + ".inner_diameter", "bore_defined_once",
           "give wall_thickness (steel wall) or inner_diameter (flexible bore), not both");
  } else if (s.inner_diameter_m && s.outer_diameter_m > 0.0 &&
             !(*s.inner_diameter_m < s.outer_diameter_m)) {
    r.fail(at + ".inner_diameter", "bore_inside_pipe",
           fmt::format("must be < outer_diameter {} m, got {} m", s.outer_diameter_m,
                       *s.inner_diameter_m));
  }
  if (s.coating_thickness_m.has_value() != s.coating_density_kg_per_m3.has_value()) {
    r.fail(at, "coating_complete",
           "give coating_thickness (m) and coating_density (kg/m^3) together");
  }
  if (s.buoyancy_outer_diameter_m.has_value() != s.buoyancy_density_kg_per_m3.has_value()) {
    r.fail(at, "buoyancy_complete",
           "give buoyancy_outer_diameter (m) and buoyancy_density (kg/m^3) together");
  }
  if (s.buoyancy_outer_diameter_m && !(*s.buoyancy_outer_diameter_m > s.outer_diameter_m)) {
    r.fail(at + ".buoyancy_outer_diameter", "buoyancy_outside_pipe",
           fmt::format("must be > outer_diameter {} m, got {} m", s.outer_diameter_m,
                       *s.buoyancy_outer_diameter_m));
  }
  if (s.buoyancy_outer_diameter_m && riser.kind != RiserKind::lazy_wave) {
    r.fail(at + ".buoyancy_outer_diameter", "key_not_applicable",
           fmt::format("buoyancy sections apply to lazy_wave risers only, got kind {}",
                       to_string(riser.kind)));
  }
  const bool steel = s.wall_thickness_m && s.youngs_modulus_Pa && s.steel_density_kg_per_m3;
  if (riser.kind != RiserKind::flexible) {
    for (const auto& [key, present] :
         {std::pair{"wall_thickness (m)", s.wall_thickness_m.has_value()},
          std::pair{"youngs_modulus (Pa)", s.youngs_modulus_Pa.has_value()},
          std::pair{"yield_stress (Pa)", s.yield_stress_Pa.has_value()},
          std::pair{"steel_density (kg/m^3)", s.steel_density_kg_per_m3.has_value()}}) {
      if (!present) {
        r.fail(at, "steel_riser_complete",
               fmt::format("a {} riser section needs {}", to_string(riser.kind), key));
      }
    }
  } else if (!steel && !(s.axial_stiffness_N && s.bending_stiffness_N_m2 &&
                         s.mass_per_length_kg_per_m && s.inner_diameter_m)) {
    r.fail(at, "flexible_riser_complete",
           "a flexible riser section needs inner_diameter (m, the bore), axial_stiffness (N), "
           "bending_stiffness (N m^2) and mass_per_length (kg/m), or the steel wall_thickness, "
           "youngs_modulus and steel_density");
  }
}

void check_risers(const Project& p, Reporter& r) {
  unique_names(r, p.risers, "risers", "riser", "riser_name_unique");
  for (std::size_t i = 0; i < p.risers.size(); ++i) {
    const Riser& riser = p.risers[i];
    const std::string at = fmt::format("risers[{}]", i);
    if (!(riser.top_angle_rad >= 0.0 && riser.top_angle_rad < std::numbers::pi / 2)) {
      r.fail(at + ".top_angle_deg", "top_angle_range",
             fmt::format("must be in [0, 90) deg from vertical, got {:.6g} deg",
                         riser.top_angle_rad * kRadToDeg));
    }
    if (riser.sections.empty()) {
      r.fail(at + ".sections", "riser_has_sections", "a riser needs at least one section");
    }
    for (std::size_t s = 0; s < riser.sections.size(); ++s) {
      check_riser_section(riser, riser.sections[s], fmt::format("{}.sections[{}]", at, s), r);
    }
    at_least(r, at + ".internal_pressure", riser.internal_pressure_Pa, 0.0, "Pa",
             "riser_value_non_negative");
    check_fe_mesh(r, at + ".fe", riser.fe);
    check_riser_criteria(r, at + ".criteria", riser.criteria);
    if (riser.kind == RiserKind::flexible &&
        !riser_criteria(p.criteria, riser).min_bending_radius_m) {
      r.fail(at + ".criteria.min_bending_radius", "flexible_min_bending_radius",
             "a flexible riser needs min_bending_radius (m), in criteria.risers or in the riser's "
             "criteria");
    }
    const bool has_buoyancy =
        std::any_of(riser.sections.begin(), riser.sections.end(),
                    [](const RiserSection& s) { return s.buoyancy_outer_diameter_m.has_value(); });
    if (riser.kind == RiserKind::lazy_wave && !has_buoyancy) {
      r.fail(at + ".sections", "lazy_wave_buoyancy_section",
             "a lazy_wave riser needs a buoyancy section (buoyancy_outer_diameter, "
             "buoyancy_density)");
    }
  }
}

void check_environments(const Project& p, Reporter& r) {
  unique_names(r, p.environments, "environments", "environment", "environment_name_unique");
  for (std::size_t i = 0; i < p.environments.size(); ++i) {
    const Environment& e = p.environments[i];
    const std::string at = fmt::format("environments[{}]", i);
    if (e.waves) {
      positive(r, at + ".waves.hs", e.waves->hs_m, "m", "hs_positive");
      positive(r, at + ".waves.tp", e.waves->tp_s, "s", "tp_positive");
      at_least(r, at + ".waves.gamma", e.waves->gamma, 1.0, "", "gamma_at_least_one");
      if (e.waves->gamma && e.waves->spectrum != WaveSpectrum::jonswap) {
        r.fail(at + ".waves.gamma", "key_not_applicable",
               fmt::format("applies to the jonswap spectrum only, got spectrum {}",
                           to_string(e.waves->spectrum)));
      }
      positive(r, at + ".waves.spreading_s", e.waves->spreading_s, "", "spreading_positive");
    }
    if (e.wind) {
      at_least(r, at + ".wind.speed", e.wind->speed_m_per_s, 0.0, "m/s", "wind_speed_non_negative");
      positive(r, at + ".wind.reference_height", e.wind->reference_height_m, "m",
               "reference_height_positive");
    }
    if (e.current) {
      const auto& profile = e.current->profile;
      if (profile.empty()) {
        r.fail(at + ".current.profile", "current_profile_valid",
               "needs at least one [z m, speed m/s] point");
      }
      for (std::size_t k = 0; k < profile.size(); ++k) {
        const std::string pat = fmt::format("{}.current.profile[{}]", at, k);
        const double z = profile[k].z_m;
        if (z > 0.0 || z < -p.site.depth_m - kSeabedTolerance_m) {
          r.fail(pat + "[0]", "current_profile_valid",
                 fmt::format("z must be in [{}, 0] m (seabed to surface), got {} m",
                             -p.site.depth_m, z));
        }
        if (k > 0 && !(z < profile[k - 1].z_m)) {
          r.fail(pat + "[0]", "current_profile_valid",
                 fmt::format("z must decrease from the surface down, got {} m after {} m", z,
                             profile[k - 1].z_m));
        }
        at_least(r, pat + "[1]", profile[k].speed_m_per_s, 0.0, "m/s", "current_profile_valid");
      }
    }
  }
}

void check_load_cases(const Project& p, Reporter& r) {
  unique_names(r, p.load_cases, "load_cases", "load case", "load_case_name_unique");
  for (std::size_t i = 0; i < p.load_cases.size(); ++i) {
    const LoadCase& c = p.load_cases[i];
    const std::string at = fmt::format("load_cases[{}]", i);
    if (!defined(p.environments, c.environment)) {
      r.fail(at + ".environment", "environment_defined",
             fmt::format("undefined environment \"{}\"{}", c.environment,
                         defined_list(p.environments)));
    }
    if (c.damaged_line && !defined(p.mooring.lines, *c.damaged_line)) {
      r.fail(at + ".damaged_line", "line_defined",
             fmt::format("undefined mooring line \"{}\"{}", *c.damaged_line,
                         defined_list(p.mooring.lines)));
    }
  }
}

void check_criteria(const Project& p, Reporter& r) {
  const MooringCriteria& m = p.criteria.mooring;
  const char* c = "safety_factor_at_least_one";
  if (m.api_rp_2sk) {
    const std::string at = "criteria.mooring.safety_factors";
    at_least(r, at + ".intact_quasi_static", m.api_rp_2sk->intact_quasi_static, 1.0, "", c);
    at_least(r, at + ".intact_dynamic", m.api_rp_2sk->intact_dynamic, 1.0, "", c);
    at_least(r, at + ".damaged_quasi_static", m.api_rp_2sk->damaged_quasi_static, 1.0, "", c);
    at_least(r, at + ".damaged_dynamic", m.api_rp_2sk->damaged_dynamic, 1.0, "", c);
  }
  if (m.dnv_os_e301) {
    const std::string at = "criteria.mooring.partial_factors";
    at_least(r, at + ".uls_mean", m.dnv_os_e301->uls_mean, 1.0, "", c);
    at_least(r, at + ".uls_dynamic", m.dnv_os_e301->uls_dynamic, 1.0, "", c);
    at_least(r, at + ".als_mean", m.dnv_os_e301->als_mean, 1.0, "", c);
    at_least(r, at + ".als_dynamic", m.dnv_os_e301->als_dynamic, 1.0, "", c);
  }
  check_riser_criteria(r, "criteria.risers", p.criteria.risers);
  positive(r, "criteria.max_offset_pct_depth", p.criteria.max_offset_pct_depth, "%",
           "offset_limit_positive");
}

}  // namespace

std::vector<InputIssue> check_project(const Project& project, const LineCheckTable& line_types) {
  std::vector<InputIssue> issues;
  Reporter r(project, issues);
  check_site(project, r);
  check_line_types(project, r);
  check_mooring(project, line_types, r);
  check_hull(project, r);
  check_risers(project, r);
  check_environments(project, r);
  check_load_cases(project, r);
  check_criteria(project, r);
  unique_names(r, project.stages, "stages", "stage", "stage_name_unique");
  for (std::size_t i = 0; i < project.stages.size(); ++i) {
    // The zone is a polar polygon on a uniform grid closed at 360°.
    const double step = project.stages[i].soz.step_deg;
    const double count = 360.0 / step;
    if (!(step > 0.0) || std::abs(count - std::round(count)) > 1e-9 * count) {
      r.fail(fmt::format("stages[{}].soz.step_deg", i), "soz_step_divides_360",
             fmt::format("must be > 0 and divide 360, got {} deg", step));
    }
    if (const std::optional<double> duration = project.stages[i].duration_s) {
      const std::string path = fmt::format("stages[{}].duration", i);
      if (project.stages[i].name != "advanced") {
        // The preliminary and intermediate storms are 3 h by design (their
        // MPM extremes rank the cases); a duration there would be ignored.
        r.fail(path, "stage_duration_advanced_only",
               fmt::format("only the advanced stage takes a duration, got it on stage '{}'",
                           project.stages[i].name));
      } else if (!(*duration > 0.0)) {
        r.fail(path, "stage_duration_positive", fmt::format("must be > 0, got {} s", *duration));
      }
    }
  }
  std::stable_sort(issues.begin(), issues.end(), [](const InputIssue& a, const InputIssue& b) {
    return std::pair(a.line.value_or(0), a.column.value_or(0)) <
           std::pair(b.line.value_or(0), b.column.value_or(0));
  });
  return issues;
}

void validate_project(const Project& project, const LineCheckTable& line_types) {
  auto issues = check_project(project, line_types);
  if (!issues.empty()) throw InputError(std::move(issues));
}

}  // namespace spiral::design
