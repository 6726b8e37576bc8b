// Validation of the sections environments, load_cases, criteria and stages
// (project_validation_checks.hpp).

#include <algorithm>
#include <cmath>
#include <numbers>

#include "design/project/load_case_matrix.hpp"
#include "design/project/project_validation_checks.hpp"

namespace spiral::design::validation_detail {

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
               fmt::format("applies to the jonswap spectrum only, got spectrum {}", to_string(e.waves->spectrum)));
      }
      positive(r, at + ".waves.spreading_s", e.waves->spreading_s, "", "spreading_positive");
    }
    if (e.wind) {
      at_least(r, at + ".wind.speed", e.wind->speed_m_per_s, 0.0, "m/s", "wind_speed_non_negative");
      positive(r, at + ".wind.reference_height", e.wind->reference_height_m, "m", "reference_height_positive");
    }
    if (e.current) {
      const auto& profile = e.current->profile;
      if (profile.empty()) {
        r.fail(at + ".current.profile", "current_profile_valid", "needs at least one [z m, speed m/s] point");
      }
      for (std::size_t k = 0; k < profile.size(); ++k) {
        const std::string pat = fmt::format("{}.current.profile[{}]", at, k);
        const double z = profile[k].z_m;
        if (z > 0.0 || z < -p.site.depth_m - kSeabedTolerance_m) {
          r.fail(pat + "[0]", "current_profile_valid",
                 fmt::format("z must be in [{}, 0] m (seabed to surface), got {} m", -p.site.depth_m, z));
        }
        if (k > 0 && !(z < profile[k - 1].z_m)) {
          r.fail(pat + "[0]", "current_profile_valid",
                 fmt::format("z must decrease from the surface down, got {} m after {} m", z, profile[k - 1].z_m));
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
             fmt::format("undefined environment \"{}\"{}", c.environment, defined_list(p.environments)));
    }
    if (c.seed < 1) r.fail(at + ".seed", "seed_positive", fmt::format("must be >= 1, got {}", c.seed));
    if (c.damaged_line && !defined(p.mooring.lines, *c.damaged_line)) {
      r.fail(at + ".damaged_line", "line_defined",
             fmt::format("undefined mooring line \"{}\"{}", *c.damaged_line, defined_list(p.mooring.lines)));
    }
  }
}

void check_load_case_matrix(const Project& p, Reporter& r) {
  std::vector<std::string> generated;  // names of the matrix's environments and cases so far
  for (std::size_t i = 0; i < p.load_case_matrix.size(); ++i) {
    const LoadCaseMatrixEntry& m = p.load_case_matrix[i];
    const std::string at = fmt::format("load_case_matrix[{}]", i);
    if (!defined(p.environments, m.environment)) {
      r.fail(at + ".environment", "environment_defined",
             fmt::format("undefined environment \"{}\"{}", m.environment, defined_list(p.environments)));
      continue;
    }
    if (m.headings_rad.empty()) r.fail(at + ".headings_deg", "matrix_headings_given", "needs at least one heading");
    bool headings_ok = true;
    for (std::size_t k = 0; k < m.headings_rad.size(); ++k) {
      const double deg = m.headings_rad[k] * 180.0 / std::numbers::pi;
      const std::string hat = fmt::format("{}.headings_deg[{}]", at, k);
      if (!(deg >= 0.0 && deg < 360.0)) {
        r.fail(hat, "matrix_heading_in_range", fmt::format("must be in [0, 360) deg, got {} deg", deg));
        headings_ok = false;
      }
      for (std::size_t j = 0; j < k; ++j) {
        if (std::abs(m.headings_rad[j] - m.headings_rad[k]) < 1e-12) {
          r.fail(hat, "matrix_headings_distinct", fmt::format("repeats heading {} deg (headings_deg[{}])", deg, j));
          headings_ok = false;
        }
      }
    }
    for (std::size_t k = 0; k < m.damaged_lines.size(); ++k) {
      if (!defined(p.mooring.lines, m.damaged_lines[k])) {
        r.fail(fmt::format("{}.damaged[{}]", at, k), "line_defined",
               fmt::format("undefined mooring line \"{}\"{}", m.damaged_lines[k], defined_list(p.mooring.lines)));
        headings_ok = false;
      }
    }
    if (m.seeds.empty()) r.fail(at + ".seeds", "matrix_seeds_given", "needs at least one seed");
    for (std::size_t k = 0; k < m.seeds.size(); ++k) {
      const std::string sat = fmt::format("{}.seeds[{}]", at, k);
      if (m.seeds[k] < 1) r.fail(sat, "seed_positive", fmt::format("must be >= 1, got {}", m.seeds[k]));
      for (std::size_t j = 0; j < k; ++j)
        if (m.seeds[j] == m.seeds[k])
          r.fail(sat, "matrix_seeds_distinct", fmt::format("repeats seed {} (seeds[{}])", m.seeds[k], j));
    }
    if (!headings_ok) continue;
    // Generated names must not meet the written ones or another entry's.
    for (const LoadCase& c : matrix_load_cases(p, m)) {
      const bool written =
          defined(p.load_cases, c.name) || (c.name == c.environment && defined(p.environments, c.name));
      const bool repeated = std::find(generated.begin(), generated.end(), c.name) != generated.end();
      if (written || repeated) {
        r.fail(at, "matrix_names_unique",
               fmt::format("generates \"{}\", a name {}", c.name,
                           written ? "the project already uses" : "an earlier entry generates"));
      }
      generated.push_back(c.name);
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
  positive(r, "criteria.max_offset_pct_depth", p.criteria.max_offset_pct_depth, "%", "offset_limit_positive");
}

void check_stages(const Project& p, Reporter& r) {
  unique_names(r, p.stages, "stages", "stage", "stage_name_unique");
  for (std::size_t i = 0; i < p.stages.size(); ++i) {
    // The zone is a polar polygon on a uniform grid closed at 360°.
    const double step = p.stages[i].soz.step_deg;
    const double count = 360.0 / step;
    if (!(step > 0.0) || std::abs(count - std::round(count)) > 1e-9 * count) {
      r.fail(fmt::format("stages[{}].soz.step_deg", i), "soz_step_divides_360",
             fmt::format("must be > 0 and divide 360, got {} deg", step));
    }
    if (const std::optional<int> n = p.stages[i].critical_cases) {
      const std::string path = fmt::format("stages[{}].critical_cases", i);
      if (p.stages[i].name != "intermediate") {
        r.fail(
            path, "stage_critical_cases_intermediate_only",
            fmt::format("only the intermediate stage selects critical cases, got it on stage '{}'", p.stages[i].name));
      } else if (*n < 1) {
        r.fail(path, "stage_critical_cases_positive", fmt::format("must be >= 1, got {}", *n));
      }
    }
    if (p.stages[i].max_iterations < 1) {
      r.fail(fmt::format("stages[{}].max_iterations", i), "stage_iterations_positive",
             fmt::format("must be >= 1 (the first iteration counts), got {}", p.stages[i].max_iterations));
    }
    if (const std::optional<double> duration = p.stages[i].duration_s) {
      const std::string path = fmt::format("stages[{}].duration", i);
      if (p.stages[i].name != "advanced") {
        // The preliminary and intermediate storms are 3 h by design (their
        // MPM extremes rank the cases); a duration there would be ignored.
        r.fail(path, "stage_duration_advanced_only",
               fmt::format("only the advanced stage takes a duration, got it on stage '{}'", p.stages[i].name));
      } else if (!(*duration > 0.0)) {
        r.fail(path, "stage_duration_positive", fmt::format("must be > 0, got {} s", *duration));
      }
    }
  }
}

}  // namespace spiral::design::validation_detail
