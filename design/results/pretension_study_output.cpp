#include "design/results/pretension_study_output.hpp"

#include <fmt/format.h>

namespace spiral::design {

namespace {

nlohmann::json optional_number(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }
std::string cell(const std::optional<double>& v) { return v ? fmt::format("{:.4f}", *v) : ""; }

}  // namespace

nlohmann::json pretension_study_to_json(const PretensionStudyResult& r) {
  nlohmann::json sweeps = nlohmann::json::array();
  for (const PretensionSweep& s : r.sweeps) {
    nlohmann::json points = nlohmann::json::array();
    for (const PretensionStudyPoint& p : s.points) {
      points.push_back({{"payout_m", p.payout_m},
                        {"pretension_N", p.pretension_N},
                        {"max_offset_m", p.max_offset_m},
                        {"max_soz_ratio_intact", optional_number(p.max_soz_ratio_intact)},
                        {"max_soz_ratio_damaged", optional_number(p.max_soz_ratio_damaged)},
                        {"max_utilization_intact", p.max_utilization_intact},
                        {"max_utilization_damaged", p.max_utilization_damaged},
                        {"worst_constraint", p.worst_constraint},
                        {"worst_constraint_name", p.worst_constraint_name},
                        {"feasible", p.feasible}});
    }
    nlohmann::json band;
    if (s.feasible_m) band = {{"from_m", s.feasible_m->first}, {"to_m", s.feasible_m->second}};
    sweeps.push_back({{"name", s.name}, {"lines", s.lines}, {"feasible_band", band}, {"points", points}});
  }
  nlohmann::json j = {{"format", "spiral.pretension_study"},
                      {"format_version", 1},
                      {"project", r.project},
                      {"scenarios", r.scenarios},
                      {"sweeps", sweeps},
                      {"notes", r.notes},
                      {"evaluations", r.evaluations},
                      {"wall_s", r.wall_s}};
  if (r.optimum_payouts_m) j["optimum"] = {{"payouts_m", *r.optimum_payouts_m}, {"status", r.optimum_status}};
  return j;
}

std::string pretension_study_csv(const PretensionStudyResult& r) {
  std::string out =
      "sweep,payout_m,pretension_kN,max_offset_m,max_soz_ratio_intact,max_soz_ratio_damaged,"
      "max_utilization_intact,max_utilization_damaged,feasible,worst_constraint\n";
  for (const PretensionSweep& s : r.sweeps) {
    for (const PretensionStudyPoint& p : s.points) {
      out +=
          fmt::format("{},{:.4f},{:.3f},{:.4f},{},{},{:.5f},{:.5f},{},\"{}\"\n", s.name, p.payout_m,
                      p.pretension_N / 1e3, p.max_offset_m, cell(p.max_soz_ratio_intact), cell(p.max_soz_ratio_damaged),
                      p.max_utilization_intact, p.max_utilization_damaged, p.feasible ? 1 : 0, p.worst_constraint_name);
    }
  }
  return out;
}

}  // namespace spiral::design
