#include "design/criteria/mooring_checks.hpp"

#include <algorithm>

namespace spiral::design {

double mooring_safety_factor(const MooringCriteria& criteria, bool damaged) {
  if (criteria.code == MooringCode::dnv_os_e301) {
    const DnvOsE301Factors f = criteria.dnv_os_e301.value_or(dnv_os_e301_defaults(1));
    return (damaged ? f.als_mean : f.uls_mean) / kDnvCharacteristicStrengthFraction;
  }
  const ApiRp2skFactors f = criteria.api_rp_2sk.value_or(ApiRp2skFactors{});
  return damaged ? f.damaged_quasi_static : f.intact_quasi_static;
}

DynamicTensionCheck dynamic_tension_check(const MooringCriteria& criteria, bool damaged, double mean_N, double mpm_N,
                                          double mbl_N) {
  DynamicTensionCheck out;
  if (!(mbl_N > 0.0)) return out;
  if (criteria.code == MooringCode::dnv_os_e301) {
    const DnvOsE301Factors f = criteria.dnv_os_e301.value_or(dnv_os_e301_defaults(1));
    const double g_mean = damaged ? f.als_mean : f.uls_mean;
    out.factor = damaged ? f.als_dynamic : f.uls_dynamic;
    out.utilization =
        (g_mean * mean_N + out.factor * std::max(0.0, mpm_N - mean_N)) / (kDnvCharacteristicStrengthFraction * mbl_N);
    return out;
  }
  const ApiRp2skFactors f = criteria.api_rp_2sk.value_or(ApiRp2skFactors{});
  out.factor = damaged ? f.damaged_dynamic : f.intact_dynamic;
  out.utilization = mpm_N * out.factor / mbl_N;
  return out;
}

double fairlead_segment_mbl(const ValidatedProject& vp, const std::string& line_name) {
  for (const MooringLine& line : vp.project.mooring.lines) {
    if (line.name != line_name || line.segments.empty()) continue;
    for (const LineTypeProperties& t : vp.line_types)
      if (t.name == line.segments.back().type) return t.breaking_load_N;
  }
  return 0.0;
}

}  // namespace spiral::design
