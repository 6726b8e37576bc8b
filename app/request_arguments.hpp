#pragma once
// The design layer names a request's arguments neutrally (`load_case`,
// `duration_s`; design/project/request_error.hpp); the user typed flags.
// This is the one table between the two.
#include <string>

#include "design/project/input_error.hpp"

namespace spiral::app {

/// The command-line flag of the request argument `argument` (`load_case` ->
/// `--case`); an argument without a flag is returned as it is.
std::string flag_of(const std::string& argument);

/// `error` as the user reads it: every issue as design::format_issue, a
/// request's argument named by its flag.
std::string describe(const design::InputError& error);

}  // namespace spiral::app
