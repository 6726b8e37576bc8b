#pragma once
// The human summary printed by `spiral validate`: what the project contains,
// with the derived line-type properties an engineer wants to eyeball.

#include <string>
#include <vector>

#include "design/project/line_properties.hpp"
#include "design/project/project.hpp"

namespace spiral::design {

std::string project_summary(const Project& project, const std::vector<LineTypeProperties>& line_types);

}  // namespace spiral::design
