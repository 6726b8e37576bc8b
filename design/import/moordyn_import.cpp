#include "design/import/moordyn_import.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "design/project/input_error.hpp"

namespace spiral::design {
namespace {

// MoorDyn's own defaults where a deck leaves an option out (MoorDyn docs,
// "Options": g 9.80665 m/s², rhoW 1025 kg/m³, kBot 3.0e6 Pa/m; no friction).
constexpr double kMoorDynGravity_m_per_s2 = 9.80665;
constexpr double kMoorDynWaterDensity_kg_per_m3 = 1025.0;
constexpr double kMoorDynSeabedStiffness_Pa_per_m = 3.0e6;

/// Options spiral reads; every other one is a solver or output setting of
/// MoorDyn's own time integration, listed in one note.
const std::set<std::string> kReadOptions = {"wtrdpth", "depth", "waterdepth", "g",     "gravity", "rhow",
                                            "rho",     "kbot",  "kb",         "mu_kt", "mu_ka",   "frictioncoefficient",
                                            "cbot",    "cb"};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::optional<int> point_id(const std::string& end) {
  int id = 0;
  const auto r = std::from_chars(end.data(), end.data() + end.size(), id);
  if (r.ec != std::errc() || r.ptr != end.data() + end.size()) return std::nullopt;
  return id;
}

double option_value(const MoorDynDeck& deck, const MoorDynOption& option, std::vector<InputIssue>& issues) {
  double value = 0.0;
  const auto r = std::from_chars(option.value.data(), option.value.data() + option.value.size(), value);
  if (r.ec != std::errc() || r.ptr != option.value.data() + option.value.size() || !std::isfinite(value)) {
    issues.push_back({deck.source, option.line, 1, "", InputOrigin::file,
                      fmt::format("option {}: expected a number, got \"{}\"", option.name, option.value),
                      "moordyn_deck"});
  }
  return value;
}

/// What `spiral export moordyn` keeps in the front matter (docs/moordyn.md):
///   spiral: line type NAME breaking_load N
///   spiral: line NAME lines ID ID ... element_length M
///   spiral: riser NAME lines ID ID ...
struct FrontMatter {
  std::map<std::string, double> breaking_load_N;
  struct Named {
    std::string name;
    std::vector<int> lines;
    std::optional<double> element_length_m;
    bool riser = false;
  };
  std::vector<Named> named;
};

FrontMatter read_front_matter(const MoorDynDeck& deck) {
  FrontMatter out;
  for (const std::string& row : deck.front_matter) {
    std::istringstream in(row);
    std::string tag, what;
    in >> tag >> what;
    if (tag != "spiral:") continue;
    if (what == "line") {
      std::string name;
      in >> name;
      if (name == "type") {
        std::string type, key;
        double value = 0.0;
        if (in >> type >> key >> value && key == "breaking_load") out.breaking_load_N[type] = value;
        continue;
      }
      FrontMatter::Named named{name, {}, std::nullopt, false};
      std::string word;
      in >> word;  // "lines"
      while (in >> word && word != "element_length") named.lines.push_back(std::atoi(word.c_str()));
      double element = 0.0;
      if (word == "element_length" && in >> element) named.element_length_m = element;
      out.named.push_back(std::move(named));
    } else if (what == "riser") {
      FrontMatter::Named named{"", {}, std::nullopt, true};
      std::string word;
      in >> named.name >> word;
      while (in >> word) named.lines.push_back(std::atoi(word.c_str()));
      out.named.push_back(std::move(named));
    }
  }
  return out;
}

std::string join_ids(const std::vector<int>& ids) {
  std::string out;
  for (int id : ids) out += fmt::format("{}{}", out.empty() ? "" : " ", id);
  return out;
}

class Importer {
 public:
  Importer(const MoorDynDeck& deck, const MoorDynImportOptions& options)
      : deck_(deck), options_(options), front_(read_front_matter(deck)) {}

  MoorDynImport run() {
    out_.notes = deck_.notes;
    Project& p = out_.project;
    p.name = options_.project_name.empty() ? (deck_.title.empty() ? deck_.source : deck_.title) : options_.project_name;
    p.description = fmt::format("Imported from the MoorDyn v{} deck {} by spiral import moordyn", deck_.format_version,
                                std::filesystem::path(deck_.source).filename().string());
    p.source_file = deck_.source;
    read_site();
    chain_lines();
    read_line_types();
    placeholder_hull();
    p.criteria.mooring.code = MooringCode::api_rp_2sk;
    p.criteria.mooring.api_rp_2sk = ApiRp2skFactors{};
    note_the_rest();
    if (!issues_.empty()) throw InputError(std::move(issues_));
    return std::move(out_);
  }

 private:
  void fail(int line, std::string message) {
    issues_.push_back({deck_.source, line, 1, "", InputOrigin::file, std::move(message), "moordyn_import"});
  }

  void read_site() {
    Site& site = out_.project.site;
    const MoorDynOption* depth = find_option(deck_, {"WtrDpth", "depth", "WaterDepth"});
    double deepest = 0.0;
    for (const MoorDynPoint& p : deck_.points)
      if (p.kind == MoorDynPointKind::fixed) deepest = std::max(deepest, -p.position_m.z());
    if (options_.depth_m) {
      site.depth_m = *options_.depth_m;
      if (depth && std::abs(option_value(deck_, *depth, issues_) - site.depth_m) > 0.0)
        out_.notes.push_back(
            fmt::format("water depth {} m given on the command line; the deck's WtrDpth ({} m) "
                        "is not used",
                        site.depth_m, depth->value));
    } else if (depth && option_value(deck_, *depth, issues_) > 0.0) {
      site.depth_m = option_value(deck_, *depth, issues_);
    } else {
      site.depth_m = deepest;
      out_.notes.push_back(fmt::format(
          "water depth {} m: the deck gives no WtrDpth (MoorDyn-F takes it from HydroDyn), so the depth of the "
          "deepest Fixed point is taken (check it, or import with --depth)",
          deepest));
    }
    if (!(site.depth_m > 0.0)) fail(depth ? depth->line : 1, "no water depth: give WtrDpth in OPTIONS or --depth");
    for (const MoorDynPoint& p : deck_.points)
      if (p.kind == MoorDynPointKind::fixed && -p.position_m.z() > site.depth_m + 1e-6)
        fail(p.line,
             fmt::format("point {} lies at z = {} m, below the seabed at {} m", p.id, p.position_m.z(), -site.depth_m));
    const auto value_of = [&](std::initializer_list<std::string_view> names, double fallback) {
      const MoorDynOption* o = find_option(deck_, names);
      return o ? option_value(deck_, *o, issues_) : fallback;
    };
    site.gravity_m_per_s2 = value_of({"g", "gravity"}, kMoorDynGravity_m_per_s2);
    site.water_density_kg_per_m3 = value_of({"rhoW", "rho"}, kMoorDynWaterDensity_kg_per_m3);
    site.seabed.normal_stiffness_Pa_per_m = value_of({"kBot", "kb"}, kMoorDynSeabedStiffness_Pa_per_m);
    const double friction = value_of({"FrictionCoefficient"}, 0.0);
    site.seabed.friction_axial = value_of({"mu_kA"}, friction);
    site.seabed.friction_lateral = value_of({"mu_kT"}, friction);
    if (!find_option(deck_, {"mu_kA", "mu_kT", "FrictionCoefficient"}))
      out_.notes.push_back("seabed friction 0: the deck gives none (MoorDyn's default is a frictionless seabed)");
  }

  void read_line_types() {
    for (const MoorDynLineType& t : deck_.line_types) {
      const auto& lines = out_.project.mooring.lines;
      const bool used = std::any_of(lines.begin(), lines.end(), [&](const MooringLine& l) {
        return std::any_of(l.segments.begin(), l.segments.end(),
                           [&](const LineSegment& s) { return s.type == t.name; });
      });
      if (!used) {
        out_.notes.push_back(
            fmt::format("line type {} (line {}) is used by no imported line: not imported", t.name, t.line));
        continue;
      }
      LineTypeInput in;
      in.name = t.name;
      in.kind = LineKind::user;
      in.diameter_m = t.diameter_m;
      in.mass_per_length_kg_per_m = t.mass_per_length_kg_per_m;
      in.axial_stiffness_N = t.EA_N;
      in.drag_normal = t.Cd;
      in.added_mass_normal = t.Ca;
      in.drag_axial = t.CdAx;
      in.added_mass_axial = t.CaAx;
      if (const auto mbl = front_.breaking_load_N.find(t.name); mbl != front_.breaking_load_N.end()) {
        in.breaking_load_N = mbl->second;
      } else {
        in.breaking_load_N = kPlaceholderMblPerEA * t.EA_N;
        out_.placeholder_breaking_loads.push_back(t.name);
        out_.notes.push_back(fmt::format(
            "line type {}: MoorDyn gives no breaking load; breaking_load is a PLACEHOLDER ({:.4g} N = {} % of EA) "
            "so the file validates: replace it with the data-sheet MBL before any code check",
            t.name, *in.breaking_load_N, 100.0 * kPlaceholderMblPerEA));
      }
      if (t.EA_text.find('|') != std::string::npos)
        out_.notes.push_back(
            fmt::format("line type {} (line {}): EA \"{}\": the static EA {} N is kept, the dynamic "
                        "stiffness is not",
                        t.name, t.line, t.EA_text, t.EA_N));
      out_.notes.push_back(fmt::format(
          "line type {} (line {}): internal damping BA/-zeta = {} not kept (spiral's FE lines use their own "
          "structural damping)",
          t.name, t.line, t.damping_text));
      if (t.EI_N_m2 != 0.0)
        out_.notes.push_back(
            fmt::format("line type {} (line {}): EI = {} N·m² not kept (a spiral line type has no "
                        "bending stiffness)",
                        t.name, t.line, t.EI_N_m2));
      out_.project.line_types.push_back(std::move(in));
    }
  }

  const MoorDynPoint* point(const std::string& end) const {
    const auto id = point_id(end);
    if (!id) return nullptr;
    for (const MoorDynPoint& p : deck_.points)
      if (p.id == *id) return &p;
    return nullptr;
  }

  /// The lines attached to each point.
  std::map<int, std::vector<const MoorDynLine*>> lines_at_points() const {
    std::map<int, std::vector<const MoorDynLine*>> at;
    for (const MoorDynLine& l : deck_.lines)
      for (const std::string* end : {&l.end_a, &l.end_b})
        if (const auto id = point_id(*end)) at[*id].push_back(&l);
    return at;
  }

  /// Whether a point is the vessel's: a coupled point, or one on the coupled body.
  bool on_vessel(const MoorDynPoint& p) const {
    if (p.kind == MoorDynPointKind::coupled) return true;
    return p.kind == MoorDynPointKind::body && coupled_body_ && p.body == coupled_body_->id;
  }

  void chain_lines() {
    for (const MoorDynBody& b : deck_.bodies) {
      const std::string a = lower(b.attachment);
      if ((a == "coupled" || a == "vessel") && !coupled_body_ && b.rotation_deg.isZero()) {
        coupled_body_ = &b;
        out_.project.hull.reference_point_g = b.position_m;
      } else {
        out_.notes.push_back(
            fmt::format("body {} (line {}, {}): spiral models one hull, the coupled body; this body "
                        "and what is attached to it are not imported",
                        b.id, b.line, b.attachment));
      }
    }
    const auto at = lines_at_points();
    std::set<int> used;
    for (const MoorDynLine& first : deck_.lines) {
      if (used.count(first.id)) continue;
      const MoorDynPoint* a = point(first.end_a);
      const MoorDynPoint* b = point(first.end_b);
      const MoorDynPoint* anchor = a && a->kind == MoorDynPointKind::fixed ? a : nullptr;
      if (!anchor && b && b->kind == MoorDynPointKind::fixed) anchor = b;
      if (!anchor) continue;  // not an anchor end: reached from its chain or noted below
      chain_from(*anchor, first, at, used);
    }
    for (const MoorDynLine& l : deck_.lines)
      if (!used.count(l.id))
        out_.notes.push_back(
            fmt::format("MoorDyn line {} (line {}, {} to {}) is not imported: it is not part of a "
                        "chain from a Fixed point to the vessel that spiral can represent",
                        l.id, l.line, l.end_a, l.end_b));
    if (out_.project.mooring.lines.empty())
      fail(deck_.lines.front().line,
           "no line runs from a Fixed point to the vessel (Vessel/Coupled point): nothing "
           "for a spiral mooring");
  }

  void chain_from(const MoorDynPoint& anchor, const MoorDynLine& first,
                  const std::map<int, std::vector<const MoorDynLine*>>& at, std::set<int>& used) {
    std::vector<const MoorDynLine*> chain{&first};
    std::vector<const MoorDynPoint*> joints;
    const MoorDynPoint* here = &anchor;
    for (;;) {
      const MoorDynLine& l = *chain.back();
      const MoorDynPoint* next = point(point(l.end_a) == here ? l.end_b : l.end_a);
      if (next == nullptr) return;  // a rod end: noted as not imported
      if (on_vessel(*next)) {
        here = next;
        break;
      }
      if (next->kind != MoorDynPointKind::free) return;
      const auto& lines = at.at(next->id);
      if (lines.size() != 2) {
        out_.notes.push_back(
            fmt::format("point {} (line {}) joins {} lines: a branching point (bridle, shared "
                        "anchor) has no spiral equivalent",
                        next->id, next->line, lines.size()));
        return;
      }
      const MoorDynLine* other = lines[0] == &l ? lines[1] : lines[0];
      if (std::find(chain.begin(), chain.end(), other) != chain.end()) return;
      joints.push_back(next);
      here = next;
      chain.push_back(other);
    }
    std::vector<int> ids;
    for (const MoorDynLine* l : chain) ids.push_back(l->id);
    for (int id : ids) used.insert(id);
    const FrontMatter::Named* named = nullptr;
    for (const FrontMatter::Named& n : front_.named)
      if (n.lines == ids) named = &n;
    if (named && named->riser) {
      out_.notes.push_back(
          fmt::format("MoorDyn lines {} are spiral riser {} (front matter): not imported as a "
                      "mooring line (a riser needs its wall, contents and top angle)",
                      join_ids(ids), named->name));
      return;
    }
    MooringLine line;
    line.name = named ? named->name : fmt::format("L{}", first.id);
    line.anchor_g = anchor.position_m;
    line.fairlead_b = here->position_m;
    if (here->kind == MoorDynPointKind::coupled && coupled_body_)
      line.fairlead_b -= coupled_body_->position_m;  // a coupled point is global; spiral's fairlead is on the body
    double element = 0.0;
    for (std::size_t k = 0; k < chain.size(); ++k) {
      line.segments.push_back({chain[k]->type, chain[k]->length_m});
      element = std::max(element, chain[k]->length_m / chain[k]->segments);
    }
    if (named && named->element_length_m) element = *named->element_length_m;
    line.fe.element_length_m = element;
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const MoorDynPoint& j = *joints[k];
      if (j.mass_kg == 0.0 && j.volume_m3 == 0.0) continue;
      const double rho = out_.project.site.water_density_kg_per_m3;
      line.attachments.push_back({static_cast<int>(k),
                                  j.volume_m3 * rho > j.mass_kg ? AttachmentKind::buoy : AttachmentKind::clump,
                                  j.mass_kg, j.volume_m3});
    }
    for (std::size_t k = 0; k < chain.size(); ++k) {
      // spiral divides a segment into whole elements no longer than the
      // element length (engine/lines/fe_line_problem.cpp, 1e-6 slack).
      const int n = std::max(1, static_cast<int>(std::ceil(chain[k]->length_m / element - 1e-6)));
      if (n != chain[k]->segments)
        out_.notes.push_back(
            fmt::format("line {} segment {}: MoorDyn NumSegs {}, spiral's mesh at element_length "
                        "{} m gives {} elements",
                        line.name, k + 1, chain[k]->segments, element, n));
    }
    for (const MoorDynPoint* end : {&anchor, here})
      if (end->mass_kg != 0.0 || end->volume_m3 != 0.0)
        out_.notes.push_back(
            fmt::format("point {} (line {}): mass {} kg, volume {} m³ at a line end are not kept "
                        "(spiral attachments sit at joints)",
                        end->id, end->line, end->mass_kg, end->volume_m3));
    out_.project.mooring.lines.push_back(std::move(line));
  }

  /// The format requires a hull; a MoorDyn deck has none. Neutrally buoyant
  /// (volume = mass / rho) so the numbers at least balance; labelled in the file.
  void placeholder_hull() {
    Hull& h = out_.project.hull;
    h.mass_kg = 1.0e6;
    h.radii_of_gyration_m = Eigen::Vector3d(10.0, 10.0, 10.0);
    h.displaced_volume_m3 = h.mass_kg / out_.project.site.water_density_kg_per_m3;
    h.center_of_buoyancy_b = Eigen::Vector3d::Zero();
    h.waterplane_area_m2 = 100.0;
    h.waterplane_inertia_m4 = Eigen::Vector2d(1.0e4, 1.0e4);
    out_.notes.push_back(
        "hull: a PLACEHOLDER (mass 1e6 kg, neutrally buoyant, 100 m² waterplane): the project format requires a "
        "hull and a MoorDyn deck has none. `spiral validate` and `spiral statics` (lines at a given offset) are "
        "meaningful; equilibrium, analyze and report need the real hull");
  }

  void note_the_rest() {
    std::string settings;
    for (const MoorDynOption& o : deck_.options)
      if (!kReadOptions.count(lower(o.name)))
        settings += fmt::format("{}{} {}", settings.empty() ? "" : ", ", o.name, o.value);
    if (!settings.empty())
      out_.notes.push_back("MoorDyn solver, initial-condition and output settings not used by spiral: " + settings);
    if (const MoorDynOption* c = find_option(deck_, {"cBot", "cb"}))
      out_.notes.push_back(
          fmt::format("seabed damping cBot = {} Pa·s/m not kept (spiral's seabed is a stiffness and "
                      "friction only)",
                      c->value));
    if (!deck_.outputs.empty()) {
      std::string outputs;
      for (const std::string& o : deck_.outputs) outputs += fmt::format("{}{}", outputs.empty() ? "" : " ", o);
      out_.notes.push_back("OUTPUTS channels not kept (spiral writes its own results): " + outputs);
    }
    for (const MoorDynPoint& p : deck_.points)
      if (p.has_point_loads)
        out_.notes.push_back(
            fmt::format("point {} (line {}): its external force, CdA or Ca are not kept (spiral has "
                        "no point drag or point force)",
                        p.id, p.line));
    if (!deck_.bodies.empty() || coupled_body_ == nullptr) {
      for (const MoorDynPoint& p : deck_.points)
        if (p.kind == MoorDynPointKind::body && !on_vessel(p))
          out_.notes.push_back(
              fmt::format("point {} (line {}) is on body {}, which is not the coupled body", p.id, p.line, p.body));
    }
    out_.notes.push_back(
        "fairleads are the Vessel/Coupled points' positions relative to the coupled body's origin, "
        "which is spiral's hull reference point");
  }

  const MoorDynDeck& deck_;
  const MoorDynImportOptions& options_;
  FrontMatter front_;
  MoorDynImport out_;
  std::vector<InputIssue> issues_;
  const MoorDynBody* coupled_body_ = nullptr;
};

/// A number as it round-trips: the shortest text that reads back to the same double.
std::string num(double value) { return fmt::format("{}", value); }

std::string vec(const Eigen::Vector3d& v) { return fmt::format("[{}, {}, {}]", num(v.x()), num(v.y()), num(v.z())); }

/// A YAML double-quoted string.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

MoorDynImport import_moordyn(const MoorDynDeck& deck, const MoorDynImportOptions& options) {
  return Importer(deck, options).run();
}

std::string moordyn_import_yaml(const MoorDynImport& imported, const std::string& deck_name) {
  const Project& p = imported.project;
  std::string y;
  y += fmt::format("# Imported from the MoorDyn deck {} by `spiral import moordyn` (docs/moordyn.md).\n", deck_name);
  y += "# Units SI (m, kg, N, Pa), as MoorDyn's. What the deck holds that this project does not:\n";
  for (const std::string& note : imported.notes) y += fmt::format("#  - {}\n", note);
  y += "version: 1\n";
  y += fmt::format("name: {}\n", quoted(p.name));
  if (p.description) y += fmt::format("description: {}\n", quoted(*p.description));
  y += "\nsite:\n";
  y += fmt::format("  depth: {}\n", num(p.site.depth_m));
  y += fmt::format("  water_density: {}\n", num(p.site.water_density_kg_per_m3));
  y += fmt::format("  gravity: {}\n", num(p.site.gravity_m_per_s2));
  y += "  seabed:\n";
  y += fmt::format("    friction_axial: {}\n", num(p.site.seabed.friction_axial));
  y += fmt::format("    friction_lateral: {}\n", num(p.site.seabed.friction_lateral));
  y += fmt::format("    normal_stiffness: {}  # Pa/m: MoorDyn kBot\n", num(p.site.seabed.normal_stiffness_Pa_per_m));
  y += "\nline_types:\n";
  for (const LineTypeInput& t : p.line_types) {
    const bool placeholder =
        std::find(imported.placeholder_breaking_loads.begin(), imported.placeholder_breaking_loads.end(), t.name) !=
        imported.placeholder_breaking_loads.end();
    y += fmt::format("  - name: {}\n    kind: user\n", quoted(t.name));
    y += fmt::format("    diameter: {}  # m, volume-equivalent (MoorDyn Diam)\n", num(t.diameter_m));
    y += fmt::format("    mass_per_length: {}\n", num(*t.mass_per_length_kg_per_m));
    y += fmt::format("    axial_stiffness: {}\n", num(*t.axial_stiffness_N));
    y += fmt::format("    breaking_load: {}{}\n", num(*t.breaking_load_N),
                     placeholder ? fmt::format("  # PLACEHOLDER: MoorDyn gives no MBL ({} % of EA); replace it",
                                               100.0 * kPlaceholderMblPerEA)
                                 : std::string());
    y += fmt::format("    drag_normal: {}  # MoorDyn Cd, on d\n", num(*t.drag_normal));
    y += fmt::format("    drag_axial: {}  # MoorDyn CdAx, on pi d\n", num(*t.drag_axial));
    y += fmt::format("    added_mass_normal: {}  # MoorDyn Ca\n", num(*t.added_mass_normal));
    y += fmt::format("    added_mass_axial: {}  # MoorDyn CaAx\n", num(*t.added_mass_axial));
  }
  y += "\nmooring:\n  lines:\n";
  for (const MooringLine& l : p.mooring.lines) {
    y += fmt::format("    - name: {}\n", quoted(l.name));
    y += fmt::format("      anchor: {}\n", vec(l.anchor_g));
    y += fmt::format("      fairlead: {}\n", vec(l.fairlead_b));
    y += "      segments:\n";
    for (const LineSegment& s : l.segments)
      y += fmt::format("        - {{type: {}, length: {}}}\n", quoted(s.type), num(s.length_m));
    if (!l.attachments.empty()) {
      y += "      attachments:\n";
      for (const Attachment& a : l.attachments)
        y += fmt::format("        - {{after_segment: {}, kind: {}, mass: {}, volume: {}}}\n", a.after_segment,
                         to_string(a.kind), num(a.mass_kg), num(a.volume_m3));
    }
    y += fmt::format("      fe: {{element_length: {}}}  # m, from MoorDyn NumSegs\n", num(l.fe.element_length_m));
  }
  const Hull& h = p.hull;
  y += "\n# PLACEHOLDER HULL: the format requires a hull and a MoorDyn deck has none. Replace\n";
  y += "# it with the platform's data before equilibrium, analyze or report.\n";
  y += "hull:\n";
  y += fmt::format("  reference_point: {}  # the coupled body's origin\n", vec(h.reference_point_g));
  y += fmt::format("  mass: {}\n", num(h.mass_kg));
  y += "  center_of_gravity: [0.0, 0.0, 0.0]\n";
  y += fmt::format("  radii_of_gyration: {}\n", vec(*h.radii_of_gyration_m));
  y += fmt::format("  displaced_volume: {}\n", num(*h.displaced_volume_m3));
  y += "  center_of_buoyancy: [0.0, 0.0, 0.0]\n";
  y += fmt::format("  waterplane_area: {}\n", num(*h.waterplane_area_m2));
  y += fmt::format("  waterplane_inertia: [{}, {}]\n", num(h.waterplane_inertia_m4->x()),
                   num(h.waterplane_inertia_m4->y()));
  y += "\n# A MoorDyn deck holds no sea states: add environments and load cases.\n";
  y += "environments: []\nload_cases: []\n";
  y += "\ncriteria:\n  mooring: {code: api_rp_2sk}  # the format requires a code; choose the project's\n";
  return y;
}

}  // namespace spiral::design
