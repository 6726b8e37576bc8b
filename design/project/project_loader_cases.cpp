// Project loader, sections environments, load_cases, criteria and stages
// (project_loader_sections.hpp).

#include <fmt/format.h>

#include "design/project/project_loader_sections.hpp"

namespace spiral::design::loader_detail {
namespace {

const EnumTable<WaveSpectrum> kWaveSpectra = {{"jonswap", WaveSpectrum::jonswap},
                                              {"pierson_moskowitz", WaveSpectrum::pierson_moskowitz}};
const EnumTable<WindSpectrum> kWindSpectra = {
    {"api", WindSpectrum::api}, {"npd", WindSpectrum::npd}, {"none", WindSpectrum::none}};
const EnumTable<DesignCondition> kDesignConditions = {{"normal", DesignCondition::normal},
                                                      {"extreme", DesignCondition::extreme},
                                                      {"survival", DesignCondition::survival}};
const EnumTable<StageSozModel> kStageSozModels = {{"catenary", StageSozModel::catenary}, {"fe", StageSozModel::fe}};
const EnumTable<MooringCode> kMooringCodes = {{"api_rp_2sk", MooringCode::api_rp_2sk},
                                              {"dnv_os_e301", MooringCode::dnv_os_e301}};

}  // namespace

Environment read_environment(MapReader& r) {
  Environment env;
  assign(env.name, r.text("name", kRequired));
  r.map("waves", kOptional, [&](MapReader& w) {
    Waves waves;
    assign(waves.spectrum, w.enumeration("spectrum", kWaveSpectra, kRequired));
    assign(waves.hs_m, w.number("hs", "m", kRequired));
    assign(waves.tp_s, w.number("tp", "s", kRequired));
    waves.gamma = w.number("gamma", "", kOptional);
    assign(waves.heading_rad, w.angle("heading", kRequired));
    waves.spreading_s = w.number("spreading_s", "", kOptional);
    env.waves = waves;
  });
  r.map("wind", kOptional, [&](MapReader& w) {
    Wind wind;
    assign(wind.speed_m_per_s, w.number("speed", "m/s", kRequired));
    assign(wind.heading_rad, w.angle("heading", kRequired));
    assign(wind.spectrum, w.enumeration("spectrum", kWindSpectra, kRequired));
    assign(wind.reference_height_m, w.number("reference_height", "m", kOptional));
    env.wind = wind;
  });
  r.map("current", kOptional, [&](MapReader& c) {
    Current current;
    assign(current.heading_rad, c.angle("heading", kRequired));
    c.list("profile", kRequired, [&](const YAML::Node& item, const std::string& path) {
      if (const auto point = to_vector<2>(c.context(), item, path, "[z m, speed m/s]")) {
        current.profile.push_back(CurrentPoint{(*point)[0], (*point)[1]});
      }
    });
    env.current = current;
  });
  return env;
}

LoadCase read_load_case(MapReader& r) {
  LoadCase load_case;
  assign(load_case.name, r.text("name", kRequired));
  assign(load_case.environment, r.text("environment", kRequired));
  load_case.damaged_line = r.text("damaged_line", kOptional);
  assign(load_case.condition, r.enumeration("condition", kDesignConditions, kOptional));
  assign(load_case.seed, r.integer("seed", kOptional));
  return load_case;
}

LoadCaseMatrixEntry read_load_case_matrix_entry(MapReader& r) {
  LoadCaseMatrixEntry entry;
  assign(entry.environment, r.text("environment", kRequired));
  assign(entry.headings_rad, r.angles("headings", kRequired));
  assign(entry.condition, r.enumeration("condition", kDesignConditions, kOptional));
  assign(entry.damaged_condition, r.enumeration("damaged_condition", kDesignConditions, kOptional));
  if (const auto node = r.child("seeds", kOptional, "a list of integers")) {
    const std::string path = r.path_of("seeds");
    if (!node->IsSequence()) {
      r.context().add(node->Mark(), path, fmt::format("expected a list of integers, got {}", describe(*node)),
                      "wrong_type");
    } else {
      entry.seeds.clear();
      for (std::size_t i = 0; i < node->size(); ++i)
        if (const auto seed = to_integer(r.context(), (*node)[i], index_path(path, i))) entry.seeds.push_back(*seed);
    }
  }
  // `damaged`: none | every_line, or a list of line names.
  if (const auto node = r.child("damaged", kOptional, "none, every_line or a list of lines")) {
    const std::string path = r.path_of("damaged");
    if (node->IsSequence()) {
      entry.damaged = MatrixDamage::listed;
      for (std::size_t i = 0; i < node->size(); ++i)
        read_name(r.context(), (*node)[i], index_path(path, i), entry.damaged_lines);
    } else {
      static const EnumTable<MatrixDamage> kDamage = {{"none", MatrixDamage::none},
                                                      {"every_line", MatrixDamage::every_line}};
      assign(entry.damaged, to_enum(r.context(), *node, path, kDamage));
    }
  }
  return entry;
}

Criteria read_criteria(MapReader& r) {
  Criteria criteria;
  r.map("mooring", kRequired, [&](MapReader& m) {
    const auto code = m.enumeration("code", kMooringCodes, kRequired);
    assign(criteria.mooring.code, code);
    if (code == MooringCode::api_rp_2sk) {
      ApiRp2skFactors f;
      m.map("safety_factors", kOptional, [&](MapReader& s) {
        assign(f.intact_quasi_static, s.number("intact_quasi_static", "", kOptional));
        assign(f.intact_dynamic, s.number("intact_dynamic", "", kOptional));
        assign(f.damaged_quasi_static, s.number("damaged_quasi_static", "", kOptional));
        assign(f.damaged_dynamic, s.number("damaged_dynamic", "", kOptional));
      });
      criteria.mooring.api_rp_2sk = f;
    } else if (code == MooringCode::dnv_os_e301) {
      const auto cc_node = m.child("consequence_class", kRequired, "1 or 2");
      const auto cc = cc_node ? to_integer(m.context(), *cc_node, m.path_of("consequence_class")) : std::nullopt;
      if (cc && *cc != 1 && *cc != 2) {
        m.context().add(cc_node->Mark(), m.path_of("consequence_class"), fmt::format("must be 1 or 2, got {}", *cc),
                        "bad_enum");
      }
      DnvOsE301Factors f = dnv_os_e301_defaults(cc.value_or(1));
      m.map("partial_factors", kOptional, [&](MapReader& p) {
        assign(f.uls_mean, p.number("uls_mean", "", kOptional));
        assign(f.uls_dynamic, p.number("uls_dynamic", "", kOptional));
        assign(f.als_mean, p.number("als_mean", "", kOptional));
        assign(f.als_dynamic, p.number("als_dynamic", "", kOptional));
      });
      criteria.mooring.dnv_os_e301 = f;
    }
  });
  r.map("risers", kOptional, [&](MapReader& x) { criteria.risers = read_riser_criteria(x); });
  criteria.max_offset_pct_depth = r.number("max_offset_pct_depth", "%", kOptional);
  return criteria;
}

Stage read_stage(MapReader& r) {
  Stage stage;
  assign(stage.name, r.text("name", kRequired));
  r.map("soz", kOptional, [&](MapReader& z) {
    assign(stage.soz.model, z.enumeration("model", kStageSozModels, kOptional));
    assign(stage.soz.step_deg, z.number("step_deg", "deg", kOptional));
  });
  stage.duration_s = r.number("duration", "s", kOptional);
  assign(stage.optimize, r.boolean("optimize", kOptional));
  assign(stage.max_iterations, r.integer("max_iterations", kOptional));
  stage.critical_cases = r.integer("critical_cases", kOptional);
  return stage;
}

}  // namespace spiral::design::loader_detail
