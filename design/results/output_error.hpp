#pragma once
// A result that could not be written or read back: a report folder, a
// results store (exit code 4, app/exit_codes.hpp). The message names the
// folder or file.

#include <stdexcept>

namespace spiral::design {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace spiral::design
