#include "design/model/case_model.hpp"

#include "design/model/environment_loads.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/request_error.hpp"

namespace spiral::design {

CaseModel build_case_model(const Project& project, const std::optional<std::string>& load_case) {
  CaseModel model;
  if (load_case) {
    model.load_case = &find_load_case(project, *load_case);
    model.environment = &environment_of(project, *model.load_case);
    model.current = current_profile_of(*model.environment);
  }
  model.hull = std::make_shared<const HullModel>(build_hull_model(project));
  model.line_types = std::make_shared<const std::vector<LineTypeProperties>>(resolve_line_types(project));
  if (model.environment && model.environment->waves && project.hull.mean_drift)
    model.drift = std::make_shared<const engine::MeanDriftTable>(drift_table_of(project, *project.hull.mean_drift));
  return model;
}

}  // namespace spiral::design
