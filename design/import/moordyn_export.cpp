#include "design/import/moordyn_export.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "design/model/mooring_model.hpp"
#include "design/model/riser_model.hpp"

namespace spiral::design {
namespace {

/// A name as one MoorDyn token (MoorDyn splits rows at blanks).
std::string token(std::string name) {
  std::replace_if(
      name.begin(), name.end(), [](unsigned char c) { return std::isspace(c) != 0; }, '_');
  return name;
}

/// Numbers as the shortest text that reads back to the same double, so
/// import(export(p)) gives p's values back exactly.
std::string num(double value) { return fmt::format("{}", value); }

/// Elements of a segment as spiral meshes it: whole elements no longer than
/// the element length (engine/lines/fe_line_problem.cpp, with its 1e-6 slack).
int elements(double length_m, double element_length_m) {
  return std::max(1, static_cast<int>(std::ceil(length_m / element_length_m - 1e-6)));
}

struct TypeRow {
  std::string name;
  double diameter_m, mass_kg_per_m, EA_N, EI_N_m2, Cd, Ca, CdAx, CaAx;
};

struct PointRow {
  std::string attachment;
  Eigen::Vector3d position_m;
  double mass_kg = 0.0, volume_m3 = 0.0;
};

struct LineRow {
  std::string type;
  int a = 0, b = 0;
  double length_m = 0.0;
  int segments = 1;
};

class DeckWriter {
 public:
  DeckWriter(const Project& project, const std::vector<LineTypeProperties>& types) : project_(project), types_(types) {}

  std::string write() {
    for (const MooringLine& line : project_.mooring.lines) add_mooring_line(line);
    for (const Riser& riser : project_.risers) add_riser(riser);
    notes();
    return text();
  }

 private:
  int add_point(PointRow row) {
    points_.push_back(std::move(row));
    return static_cast<int>(points_.size());
  }

  void use_type(const std::string& name) {
    if (!used_types_.insert(name).second) return;
    const LineTypeProperties& t = find_type(types_, name);
    type_rows_.push_back({token(t.name), t.hydrodynamic_diameter_m, t.mass_per_length_kg_per_m, t.axial_stiffness_N,
                          0.0, t.drag_normal, t.added_mass_normal, t.drag_axial, t.added_mass_axial});
    front_.push_back(fmt::format("spiral: line type {} breaking_load {}", token(t.name), num(t.breaking_load_N)));
    const double w_moordyn =
        (t.mass_per_length_kg_per_m - project_.site.water_density_kg_per_m3 * 0.25 * std::numbers::pi *
                                          t.hydrodynamic_diameter_m * t.hydrodynamic_diameter_m) *
        project_.site.gravity_m_per_s2;
    if (std::abs(w_moordyn - t.submerged_weight_N_per_m) > 1e-9 * std::max(1.0, std::abs(t.submerged_weight_N_per_m)))
      front_.push_back(
          fmt::format("spiral note: line type {}: its explicit submerged weight {} N/m is not MoorDyn's "
                      "(m - rho pi/4 d^2) g = {} N/m",
                      token(t.name), num(t.submerged_weight_N_per_m), num(w_moordyn)));
    if (has_dynamic_axial_stiffness(t))
      front_.push_back(
          fmt::format("spiral note: line type {}: static EA only; spiral's dynamic stiffness "
                      "({} + {} x mean load % MBL) x MBL is not written",
                      token(t.name), num(t.dynamic_stiffness_mbl[0]), num(t.dynamic_stiffness_mbl[1])));
  }

  void add_mooring_line(const MooringLine& line) {
    int previous = add_point({"Fixed", line.anchor_g});
    std::vector<int> ids;
    for (std::size_t k = 0; k < line.segments.size(); ++k) {
      const LineSegment& s = line.segments[k];
      use_type(s.type);
      int next = 0;
      if (k + 1 == line.segments.size()) {
        next = add_point({"Coupled", line.fairlead_b});
      } else {
        PointRow joint{"Free", joint_position(line, k)};
        for (const Attachment& a : line.attachments)
          if (a.after_segment == static_cast<int>(k)) {
            joint.mass_kg += a.mass_kg;
            joint.volume_m3 += a.volume_m3;
          }
        next = add_point(joint);
      }
      line_rows_.push_back({token(s.type), previous, next, s.length_m, elements(s.length_m, line.fe.element_length_m)});
      ids.push_back(static_cast<int>(line_rows_.size()));
      previous = next;
    }
    std::string list;
    for (int id : ids) list += fmt::format(" {}", id);
    front_.push_back(fmt::format("spiral: line {} lines{} element_length {}", token(line.name), list,
                                 num(line.fe.element_length_m)));
    if (line.fe.touchdown_refinement)
      front_.push_back(
          fmt::format("spiral note: line {}: the touchdown refinement of its FE mesh is not written "
                      "(MoorDyn segments are uniform per line)",
                      token(line.name)));
  }

  /// A first guess of a joint's position (MoorDyn solves Free points): on the
  /// chord, at the joint's share of the unstretched length.
  Eigen::Vector3d joint_position(const MooringLine& line, std::size_t after_segment) const {
    double total = 0.0, below = 0.0;
    for (std::size_t k = 0; k < line.segments.size(); ++k) {
      total += line.segments[k].length_m;
      if (k <= after_segment) below += line.segments[k].length_m;
    }
    const Eigen::Vector3d fairlead_g = project_.hull.reference_point_g + line.fairlead_b;
    return line.anchor_g + (fairlead_g - line.anchor_g) * (below / total);
  }

  void add_riser(const Riser& riser) {
    const RiserDesign design = riser_design(project_, riser);
    int previous = add_point({"Fixed", design.foot_g});
    std::vector<int> ids;
    for (std::size_t k = 0; k < design.sections.size(); ++k) {
      const RiserSectionDesign& s = design.sections[k];
      // design.sections run foot -> hang-off; the project lists them hang-off down.
      const RiserSection& in = riser.sections[riser.sections.size() - 1 - k];
      const std::string name = token(fmt::format("{}_s{}", riser.name, riser.sections.size() - k));
      const auto& q = s.properties;
      type_rows_.push_back({name, q.hydrodynamic_diameter_m, q.mass_per_length_kg_per_m + q.contents_mass_kg_per_m,
                            q.EA_N, q.EI_N_m2, in.drag_normal, in.added_mass_normal, in.drag_axial,
                            in.added_mass_axial});
      int next = 0;
      if (k + 1 == design.sections.size()) {
        next = add_point({"Coupled", riser.hang_off_b});
      } else {
        const Eigen::Vector3d top_g = project_.hull.reference_point_g + riser.hang_off_b;
        next = add_point({"Free", design.foot_g + (top_g - design.foot_g) * (double(k + 1) / design.sections.size())});
      }
      line_rows_.push_back({name, previous, next, s.length_m, elements(s.length_m, riser.fe.element_length_m)});
      ids.push_back(static_cast<int>(line_rows_.size()));
      previous = next;
    }
    std::string list;
    for (int id : ids) list += fmt::format(" {}", id);
    front_.push_back(fmt::format("spiral: riser {} lines{}", token(riser.name), list));
    if (riser.internal_pressure_Pa != 0.0)
      front_.push_back(
          fmt::format("spiral note: riser {}: internal pressure {} Pa not written (MoorDyn lines have "
                      "no bore; the contents' mass is in Mass/m)",
                      token(riser.name), num(riser.internal_pressure_Pa)));
  }

  void notes() {
    if (project_.site.seabed.friction_lateral != project_.site.seabed.friction_axial)
      front_.push_back(
          fmt::format("spiral note: MoorDyn-C has one isotropic FrictionCoefficient: the axial {} is written, "
                      "not the lateral {} (MoorDyn-F reads both, mu_kA and mu_kT)",
                      num(project_.site.seabed.friction_axial), num(project_.site.seabed.friction_lateral)));
    front_.push_back(
        "spiral note: not written: the hull, the environments, load cases, criteria and line groups; "
        "MBL, names and element lengths are in the spiral: lines above");
    front_.push_back(
        fmt::format("spiral note: BA/-zeta {} (critical axial damping) on every line type; anchors on "
                    "the seabed at WtrDpth; Coupled points relative to the hull reference point "
                    "[{}, {}, {}]",
                    num(kExportDampingRatio), num(project_.hull.reference_point_g.x()),
                    num(project_.hull.reference_point_g.y()), num(project_.hull.reference_point_g.z())));
  }

  std::string text() const {
    std::string d;
    d += "--------------------- MoorDyn Input File ------------------------------------\n";
    d += fmt::format("{} - written by spiral export moordyn (MoorDyn v2 format)\n", project_.name);
    for (const std::string& row : front_) d += row + "\n";
    d += "---------------------- LINE TYPES ----------------------------------------------\n";
    d += "TypeName  Diam  Mass/m  EA  BA/-zeta  EI  Cd  Ca  CdAx  CaAx\n";
    d += "(name)  (m)  (kg/m)  (N)  (N-s/-)  (N-m^2)  (-)  (-)  (-)  (-)\n";
    for (const TypeRow& t : type_rows_)
      d += fmt::format("{}  {}  {}  {}  {}  {}  {}  {}  {}  {}\n", t.name, num(t.diameter_m), num(t.mass_kg_per_m),
                       num(t.EA_N), num(kExportDampingRatio), num(t.EI_N_m2), num(t.Cd), num(t.Ca), num(t.CdAx),
                       num(t.CaAx));
    d += "---------------------- POINTS --------------------------------------------------\n";
    d += "ID  Attachment  X  Y  Z  Mass  Volume  CdA  Ca\n";
    d += "(#)  (-)  (m)  (m)  (m)  (kg)  (m^3)  (m^2)  (-)\n";
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const PointRow& p = points_[i];
      d += fmt::format("{}  {}  {}  {}  {}  {}  {}  0  0\n", i + 1, p.attachment, num(p.position_m.x()),
                       num(p.position_m.y()), num(p.position_m.z()), num(p.mass_kg), num(p.volume_m3));
    }
    d += "---------------------- LINES ---------------------------------------------------\n";
    d += "ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  LineOutputs\n";
    d += "(#)  (name)  (#)  (#)  (m)  (-)  (-)\n";
    for (std::size_t i = 0; i < line_rows_.size(); ++i) {
      const LineRow& l = line_rows_[i];
      d += fmt::format("{}  {}  {}  {}  {}  {}  -\n", i + 1, l.type, l.a, l.b, num(l.length_m), l.segments);
    }
    const Site& site = project_.site;
    d += "---------------------- OPTIONS -------------------------------------------------\n";
    d += fmt::format("{}  WtrDpth  - water depth (m)\n", num(site.depth_m));
    d += fmt::format("{}  g  - gravity (m/s^2)\n", num(site.gravity_m_per_s2));
    // MoorDyn-C and MoorDyn-F name the water density and the friction
    // differently (MoorDyn docs, "Options"): MoorDyn-C v2.7.1 reads `rho` and
    // one isotropic `FrictionCoefficient` and skips `rhoW`, `mu_kA`, `mu_kT`
    // with a warning (their values then silently become its defaults, 1025
    // and no friction); MoorDyn-F reads those. Both sets are written, so
    // either program gets every value (each warns about the other's names).
    d += fmt::format("{}  rho  - water density (kg/m^3), MoorDyn-C\n", num(site.water_density_kg_per_m3));
    d += fmt::format("{}  rhoW  - water density (kg/m^3), MoorDyn-F\n", num(site.water_density_kg_per_m3));
    d += fmt::format("{}  kBot  - seabed stiffness (Pa/m)\n", num(site.seabed.normal_stiffness_Pa_per_m));
    d += fmt::format("{}  FrictionCoefficient  - seabed friction, MoorDyn-C (isotropic: the axial one)\n",
                     num(site.seabed.friction_axial));
    d += fmt::format("{}  mu_kA  - seabed friction along the line (-), MoorDyn-F\n", num(site.seabed.friction_axial));
    d +=
        fmt::format("{}  mu_kT  - seabed friction across the line (-), MoorDyn-F\n", num(site.seabed.friction_lateral));
    d += fmt::format("{}  dtM  - time step (s): {} of the shortest segment's axial wave transit time\n",
                     num(time_step_s()), num(kExportTimeStepFraction));
    d += "---------------------- OUTPUTS -------------------------------------------------\n";
    for (std::size_t i = 0; i < line_rows_.size(); ++i) d += fmt::format("FairTen{}\nAnchTen{}\n", i + 1, i + 1);
    d += "END\n";
    d += "------------------------- need this line ---------------------------------------\n";
    return d;
  }

  /// dtM: MoorDyn-C without one steps at CFL 0.5 of each segment's axial
  /// period (source/Util/CFL.hpp: 0.5 · 2π l / c, c = √(EA/m)), about 3 l/c,
  /// beyond its explicit RK2's stability: the exported OC4 deck (10 m
  /// segments, l/c = 3.9 ms) diverged at 0.14 s with its 12 ms (MoorDyn-C
  /// v2.7.1, 2026-12-02), and ran stable at 2 ms. Written: that fraction of
  /// the shortest l/c of any segment (structural mass: the added mass only
  /// slows the wave), rounded down to one significant digit.
  double time_step_s() const {
    double transit_s = std::numeric_limits<double>::infinity();
    for (const LineRow& l : line_rows_)
      for (const TypeRow& t : type_rows_)
        if (t.name == l.type)
          transit_s = std::min(transit_s, l.length_m / l.segments / std::sqrt(t.EA_N / t.mass_kg_per_m));
    if (!std::isfinite(transit_s)) return 0.001;
    const double dt_s = kExportTimeStepFraction * transit_s;
    const double per_decade = std::pow(10.0, -std::floor(std::log10(dt_s)));  // exact for 10^k, k <= 22
    return std::floor(dt_s * per_decade) / per_decade;  // digit / 10^k: the double nearest the decimal
  }

  const Project& project_;
  const std::vector<LineTypeProperties>& types_;
  std::set<std::string> used_types_;
  std::vector<std::string> front_;
  std::vector<TypeRow> type_rows_;
  std::vector<PointRow> points_;
  std::vector<LineRow> line_rows_;
};

}  // namespace

std::string export_moordyn(const Project& project, const std::vector<LineTypeProperties>& types) {
  return DeckWriter(project, types).write();
}

}  // namespace spiral::design
