#pragma once
// The mooring code checks of a line's tension (DESIGN.md §6), one place for
// the factors every stage and report applies.
//
// Quasi-static (a static or mean tension alone). API RP 2SK: a line passes
// when T_max · SF ≤ MBL, SF = intact_quasi_static (intact) or
// damaged_quasi_static (one line removed), i.e. utilization T_max · SF / MBL.
// DNV-OS-E301 Ch. 2 Sec. 2: T_d = γ_mean · T_max against the characteristic
// strength S_C = 0.95 MBL, i.e. SF = γ_mean / 0.95 with γ_mean the ULS
// (intact) or ALS (damaged) mean factor.
//
// Dynamic (the MPM of a time-domain record). API RP 2SK: T_mpm · SF_dyn / MBL
// ≤ 1 (SF_dyn = intact_dynamic or damaged_dynamic). DNV-OS-E301 Ch. 2 Sec. 2
// [2.2]: (γ_mean T_mean + γ_dyn (T_mpm − T_mean)) / (0.95 MBL) ≤ 1, with the
// ULS (intact) or ALS (damaged) factors.

#include "design/project/project.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {

/// Characteristic strength of a mooring line in DNV-OS-E301 Ch. 2 Sec. 2 [4.1]: 0.95 MBL.
inline constexpr double kDnvCharacteristicStrengthFraction = 0.95;

/// Quasi-static safety factor of the project's mooring code for an intact or damaged case.
double mooring_safety_factor(const MooringCriteria& criteria, bool damaged);

/// Dynamic factor and utilization of the dynamic check above.
struct DynamicTensionCheck {
  double factor = 0.0;
  double utilization = 0.0;
};
DynamicTensionCheck dynamic_tension_check(const MooringCriteria& criteria, bool damaged, double mean_N, double mpm_N,
                                          double mbl_N);

/// MBL of the fairlead (top) segment of a mooring line: the segment the
/// fairlead tension is checked against; 0 for an unknown line.
double fairlead_segment_mbl(const ValidatedProject& project, const std::string& line_name);

}  // namespace spiral::design
