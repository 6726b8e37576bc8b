// Project loader, sections site, line_types and mooring
// (project_loader_sections.hpp).

#include <fmt/format.h>

#include <array>
#include <string>
#include <vector>

#include "design/project/project_loader_sections.hpp"

namespace spiral::design::loader_detail {
namespace {

const EnumTable<LineKind> kLineKinds = {
    {"chain", LineKind::chain}, {"wire", LineKind::wire}, {"polyester", LineKind::polyester}, {"user", LineKind::user}};
const EnumTable<ChainGrade> kChainGrades = {{"R3", ChainGrade::R3},
                                            {"R3S", ChainGrade::R3S},
                                            {"R4", ChainGrade::R4},
                                            {"R4S", ChainGrade::R4S},
                                            {"R5", ChainGrade::R5}};
const EnumTable<ChainConstruction> kChainConstructions = {{"studless", ChainConstruction::studless},
                                                          {"studlink", ChainConstruction::studlink}};
const EnumTable<WireConstruction> kWireConstructions = {{"six_strand", WireConstruction::six_strand},
                                                        {"spiral_strand", WireConstruction::spiral_strand}};
const EnumTable<AttachmentKind> kAttachmentKinds = {{"clump", AttachmentKind::clump}, {"buoy", AttachmentKind::buoy}};
const EnumTable<LineModel> kLineModels = {{"catenary", LineModel::catenary}, {"fe", LineModel::fe}};

MooringLine read_mooring_line(MapReader& r, std::optional<double> seabed_z) {
  MooringLine line;
  assign(line.name, r.text("name", kRequired));
  assign(line.anchor_g, r.position("anchor", kRequired, seabed_z));
  assign(line.fairlead_b, r.position("fairlead", kRequired));
  r.list_of_maps("segments", kRequired, [&](MapReader& s) {
    LineSegment segment;
    assign(segment.type, s.text("type", kRequired));
    assign(segment.length_m, s.number("length", "m", kRequired));
    line.segments.push_back(segment);
  });
  r.list_of_maps("attachments", kOptional, [&](MapReader& a) {
    Attachment attachment;
    assign(attachment.after_segment, a.integer("after_segment", kRequired));
    assign(attachment.kind, a.enumeration("kind", kAttachmentKinds, kRequired));
    assign(attachment.mass_kg, a.number("mass", "kg", kRequired));
    assign(attachment.volume_m3, a.number("volume", "m^3", kRequired));
    line.attachments.push_back(attachment);
  });
  assign(line.model, r.enumeration("model", kLineModels, kOptional));
  read_fe_mesh(r, line.fe);
  return line;
}

}  // namespace

void read_name(Context& ctx, const YAML::Node& node, const std::string& path, std::vector<std::string>& out) {
  if (auto name = to_string_value(ctx, node, path)) out.push_back(*name);
}

Site read_site(MapReader& r) {
  Site site;
  assign(site.depth_m, r.number("depth", "m", kRequired));
  assign(site.water_density_kg_per_m3, r.number("water_density", "kg/m^3", kRequired));
  assign(site.gravity_m_per_s2, r.number("gravity", "m/s^2", kRequired));
  assign(site.air_density_kg_per_m3, r.number("air_density", "kg/m^3", kOptional));
  r.map("seabed", kRequired, [&](MapReader& s) {
    assign(site.seabed.friction_axial, s.number("friction_axial", "", kRequired));
    assign(site.seabed.friction_lateral, s.number("friction_lateral", "", kRequired));
    assign(site.seabed.normal_stiffness_Pa_per_m, s.number("normal_stiffness", "Pa/m", kRequired));
  });
  return site;
}

LineTypeInput read_line_type(MapReader& r) {
  LineTypeInput t;
  assign(t.name, r.text("name", kRequired));
  const auto kind = r.enumeration("kind", kLineKinds, kRequired);
  assign(t.kind, kind);
  assign(t.diameter_m, r.number("diameter", "m", kRequired));
  t.grade = r.enumeration("grade", kChainGrades, kOptional);
  // `construction` is a chain or a wire construction depending on `kind`.
  if (const auto node = r.child("construction", kOptional); node && kind) {
    const std::string path = r.path_of("construction");
    if (*kind == LineKind::chain) {
      t.chain_construction = to_enum(r.context(), *node, path, kChainConstructions);
    } else if (*kind == LineKind::wire) {
      t.wire_construction = to_enum(r.context(), *node, path, kWireConstructions);
    } else {
      r.context().add(node->Mark(), path,
                      fmt::format("applies to chain and wire line types only, got kind {}",
                                  *kind == LineKind::polyester ? "polyester" : "user"),
                      "key_not_applicable");
    }
  }
  t.mass_per_length_kg_per_m = r.number("mass_per_length", "kg/m", kOptional);
  t.submerged_weight_N_per_m = r.number("submerged_weight", "N/m", kOptional);
  t.hydrodynamic_diameter_m = r.number("hydrodynamic_diameter", "m", kOptional);
  t.axial_stiffness_N = r.number("axial_stiffness", "N", kOptional);
  t.breaking_load_N = r.number("breaking_load", "N", kOptional);
  t.static_stiffness_mbl = r.number("static_stiffness_mbl", "", kOptional);
  if (const auto ab = r.vector<2>("dynamic_stiffness_mbl", "", kOptional)) {
    t.dynamic_stiffness_mbl = std::array<double, 2>{(*ab)[0], (*ab)[1]};
  }
  t.drag_normal = r.number("drag_normal", "", kOptional);
  t.drag_axial = r.number("drag_axial", "", kOptional);
  t.added_mass_normal = r.number("added_mass_normal", "", kOptional);
  t.added_mass_axial = r.number("added_mass_axial", "", kOptional);
  return t;
}

void read_fe_mesh(MapReader& r, FeMesh& mesh) {
  r.map("fe", kOptional, [&](MapReader& f) {
    assign(mesh.element_length_m, f.number("element_length", "m", kOptional));
    f.map("touchdown_refinement", kOptional, [&](MapReader& t) {
      TouchdownRefinement refinement;
      assign(refinement.length_m, t.number("length", "m", kRequired));
      assign(refinement.element_length_m, t.number("element_length", "m", kRequired));
      mesh.touchdown_refinement = refinement;
    });
  });
}

Mooring read_mooring(MapReader& r, std::optional<double> seabed_z) {
  Mooring mooring;
  r.list_of_maps("lines", kRequired, [&](MapReader& l) { mooring.lines.push_back(read_mooring_line(l, seabed_z)); });
  r.list_of_maps("groups", kOptional, [&](MapReader& g) {
    LineGroup group;
    assign(group.name, g.text("name", kRequired));
    g.list("lines", kRequired,
           [&](const YAML::Node& item, const std::string& path) { read_name(g.context(), item, path, group.lines); });
    mooring.groups.push_back(group);
  });
  return mooring;
}

}  // namespace spiral::design::loader_detail
