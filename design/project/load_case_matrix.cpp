#include "design/project/load_case_matrix.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace spiral::design {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

double turned(double heading_rad, double by_rad) {
  const double h = std::fmod(heading_rad + by_rad, 2.0 * std::numbers::pi);
  return h < 0.0 ? h + 2.0 * std::numbers::pi : h;
}

}  // namespace

std::string matrix_case_name(const std::string& base_environment, double heading_rad) {
  const double deg = heading_rad * kRadToDeg;
  const double whole = std::round(deg);
  return std::abs(deg - whole) < 1e-9 ? fmt::format("{}@h{:03.0f}", base_environment, whole)
                                      : fmt::format("{}@h{:g}", base_environment, deg);
}

std::vector<LoadCase> matrix_load_cases(const Project& project, const LoadCaseMatrixEntry& entry) {
  std::vector<LoadCase> out;
  // One seed keeps the plain names; several make a case per seed.
  const auto with_seed = [&](const std::string& name, int seed) {
    return entry.seeds.size() > 1 ? fmt::format("{}-seed{}", name, seed) : name;
  };
  for (const double heading : entry.headings_rad) {
    const std::string name = matrix_case_name(entry.environment, heading);
    for (const int seed : entry.seeds) {
      out.push_back({with_seed(name, seed), name, std::nullopt, entry.condition, seed});
      for (const MooringLine& line : project.mooring.lines) {
        const bool removed =
            entry.damaged == MatrixDamage::every_line ||
            (entry.damaged == MatrixDamage::listed &&
             std::find(entry.damaged_lines.begin(), entry.damaged_lines.end(), line.name) != entry.damaged_lines.end());
        if (removed)
          out.push_back(
              {with_seed(name + "-without-" + line.name, seed), name, line.name, entry.damaged_condition, seed});
      }
    }
  }
  return out;
}

void expand_load_case_matrix(Project& project) {
  std::vector<Environment> environments;
  std::vector<LoadCase> cases;
  for (const LoadCaseMatrixEntry& entry : project.load_case_matrix) {
    const Environment& base = *std::find_if(project.environments.begin(), project.environments.end(),
                                            [&](const Environment& e) { return e.name == entry.environment; });
    for (const double heading : entry.headings_rad) {
      Environment e = base;
      e.name = matrix_case_name(entry.environment, heading);
      if (e.waves) e.waves->heading_rad = turned(e.waves->heading_rad, heading);
      if (e.wind) e.wind->heading_rad = turned(e.wind->heading_rad, heading);
      if (e.current) e.current->heading_rad = turned(e.current->heading_rad, heading);
      environments.push_back(std::move(e));
    }
    for (LoadCase& c : matrix_load_cases(project, entry)) cases.push_back(std::move(c));
  }
  project.environments.insert(project.environments.end(), environments.begin(), environments.end());
  project.load_cases.insert(project.load_cases.end(), cases.begin(), cases.end());
}

}  // namespace spiral::design
