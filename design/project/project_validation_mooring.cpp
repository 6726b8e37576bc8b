// Validation of the sections site, line_types and mooring, with the at-rest
// length of each mooring line against its anchor-fairlead geometry
// (project_validation_checks.hpp).

#include <Eigen/Core>

#include "design/project/project_validation_checks.hpp"

namespace spiral::design::validation_detail {

LineCheckProperties check_properties(const Project& p, const LineCheckTable& table, const std::string& type) {
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

namespace {

/// Length against the at-rest anchor-fairlead geometry (lines too short to
/// reach without breaking, or so long that they lie slack).
void check_line_length(const Project& p, const LineCheckTable& table, std::size_t index, Reporter& r) {
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
  const bool has_buoy = std::any_of(line.attachments.begin(), line.attachments.end(),
                                    [](const Attachment& a) { return a.kind == AttachmentKind::buoy; });
  const bool buoyant_segment = std::any_of(line.segments.begin(), line.segments.end(), [&](const LineSegment& s) {
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

}  // namespace

void check_site(const Project& p, Reporter& r) {
  positive(r, "site.depth", p.site.depth_m, "m", "depth_positive");
  positive(r, "site.water_density", p.site.water_density_kg_per_m3, "kg/m^3", "water_density_positive");
  positive(r, "site.gravity", p.site.gravity_m_per_s2, "m/s^2", "gravity_positive");
  positive(r, "site.air_density", p.site.air_density_kg_per_m3, "kg/m^3", "air_density_positive");
  at_least(r, "site.seabed.friction_axial", p.site.seabed.friction_axial, 0.0, "", "friction_non_negative");
  at_least(r, "site.seabed.friction_lateral", p.site.seabed.friction_lateral, 0.0, "", "friction_non_negative");
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
          std::pair{".added_mass_normal", t.added_mass_normal}, std::pair{".added_mass_axial", t.added_mass_axial}}) {
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
        r.fail(at + ".dynamic_stiffness_mbl", "key_not_applicable", "applies to polyester line types only");
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
               fmt::format("undefined line type \"{}\"{}", line.segments[s].type, defined_list(p.line_types)));
      }
    }
    for (std::size_t a = 0; a < line.attachments.size(); ++a) {
      const Attachment& att = line.attachments[a];
      const std::string aat = fmt::format("{}.attachments[{}]", at, a);
      const int joints = static_cast<int>(line.segments.size()) - 1;
      if (att.after_segment < 0 || att.after_segment >= joints) {
        r.fail(aat + ".after_segment", "attachment_joint_exists",
               joints > 0
                   ? fmt::format("must be a joint between segments, 0 to {}, got {}", joints - 1, att.after_segment)
                   : fmt::format("the line has no joint (one segment), got {}", att.after_segment));
      }
      at_least(r, aat + ".mass", att.mass_kg, 0.0, "kg", "attachment_value_non_negative");
      at_least(r, aat + ".volume", att.volume_m3, 0.0, "m^3", "attachment_value_non_negative");
    }
    if (p.site.depth_m > 0.0) {
      const double z = line.anchor_g.z();
      if (z < seabed_z - kSeabedTolerance_m) {
        r.fail(at + ".anchor", "anchor_below_seabed",
               fmt::format("anchor is {:.6g} m below the seabed: z = {} m, seabed at z = {} m", seabed_z - z, z,
                           seabed_z));
      } else if (z > 0.0) {
        r.fail(at + ".anchor", "anchor_above_water",
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
               fmt::format("undefined mooring line \"{}\"{}", names[k], defined_list(p.mooring.lines)));
      }
    }
  }
}

}  // namespace spiral::design::validation_detail
