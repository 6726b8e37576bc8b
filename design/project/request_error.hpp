#pragma once
// Errors in a request made of a project (the load case to run, a line to
// damage, a duration, a SOZ step): reported like input errors, with the
// project file and, as the path, the request's argument by its neutral name
// (`load_case`, `damaged_line`, `duration_s`, ...). Whoever made the request
// says the argument in its own words: app/ prints its command-line flag.

#include <string>

#include "design/project/input_error.hpp"
#include "design/project/project.hpp"

namespace spiral::design {

/// An InputError on `argument` of a request run on `project`
/// (InputOrigin::request).
InputError request_error(const Project& project, const std::string& argument, const std::string& message,
                         const std::string& problem = "request_argument");

/// The load case named `name`; throws request_error on `load_case`, listing
/// the defined names, when there is none.
const LoadCase& find_load_case(const Project& project, const std::string& name);

}  // namespace spiral::design
