// The value checks of the validation pass and the checks shared by several
// sections (project_validation_checks.hpp).

#include "design/project/project_validation_checks.hpp"

namespace spiral::design::validation_detail {
namespace {

std::string unit_suffix(std::string_view unit) { return unit.empty() ? std::string() : fmt::format(" {}", unit); }

}  // namespace

void positive(Reporter& r, const std::string& path, double value, std::string_view unit, const char* problem) {
  if (!(value > 0.0)) {
    r.fail(path, problem, fmt::format("must be > 0{}, got {}{}", unit_suffix(unit), value, unit_suffix(unit)));
  }
}

void positive(Reporter& r, const std::string& path, const std::optional<double>& value, std::string_view unit,
              const char* problem) {
  if (value) positive(r, path, *value, unit, problem);
}

void at_least(Reporter& r, const std::string& path, double value, double minimum, std::string_view unit,
              const char* problem) {
  if (!(value >= minimum)) {
    r.fail(path, problem,
           fmt::format("must be >= {}{}, got {}{}", minimum, unit_suffix(unit), value, unit_suffix(unit)));
  }
}

void at_least(Reporter& r, const std::string& path, const std::optional<double>& value, double minimum,
              std::string_view unit, const char* problem) {
  if (value) at_least(r, path, *value, minimum, unit, problem);
}

void check_fe_mesh(Reporter& r, const std::string& at, const FeMesh& mesh) {
  const char* c = "fe_mesh_positive";
  positive(r, at + ".element_length", mesh.element_length_m, "m", c);
  if (const auto& t = mesh.touchdown_refinement) {
    positive(r, at + ".touchdown_refinement.length", t->length_m, "m", c);
    positive(r, at + ".touchdown_refinement.element_length", t->element_length_m, "m", c);
    if (t->element_length_m > mesh.element_length_m) {
      r.fail(at + ".touchdown_refinement.element_length", "touchdown_refinement_finer",
             fmt::format("must be <= element_length {} m (a refinement), got {} m", mesh.element_length_m,
                         t->element_length_m));
    }
  }
}

void check_global_analysis(const Project& p, Reporter& r) {
  const std::optional<double>& length = p.global_analysis.element_length_m;
  if (!length) return;
  const std::string at = "global_analysis.element_length";
  positive(r, at, *length, "m", "fe_mesh_positive");
  if (!(*length > 0.0)) return;
  // The shortest line or riser: the one the element length must fit.
  std::string shortest;
  double shortest_m = 0.0;
  const auto consider = [&](const std::string& name, double length_m) {
    if (shortest.empty() || length_m < shortest_m) {
      shortest = name;
      shortest_m = length_m;
    }
  };
  for (const MooringLine& line : p.mooring.lines)
    consider(fmt::format("mooring line {}", line.name), total_length_m(line));
  for (const Riser& riser : p.risers) consider(fmt::format("riser {}", riser.name), total_length_m(riser));
  if (!shortest.empty() && shortest_m / *length < kMinGlobalElementsPerLine) {
    r.fail(at, "global_analysis_elements",
           fmt::format("{} m leaves {} ({:.0f} m) {:.1f} elements; at most {:.3g} m ({:.0f} elements per line)",
                       *length, shortest, shortest_m, shortest_m / *length, shortest_m / kMinGlobalElementsPerLine,
                       kMinGlobalElementsPerLine));
  }
}

void check_file(Reporter& r, const std::string& at, const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) {
    r.fail(at, "file_exists", fmt::format("file not found: {}", file.string()));
  }
}

}  // namespace spiral::design::validation_detail
