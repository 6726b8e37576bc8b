#pragma once
// A query outside the range of a tabulated input (a wave heading outside a
// hydrodynamic database, a relative heading outside a coefficient table):
// no extrapolation, the caller learns which input to extend. Typed, so that
// the design layer maps it to the project field at fault without reading the
// message. Derives from std::invalid_argument, which callers that only
// report the message already catch.

#include <stdexcept>

namespace spiral::engine {

class TableRangeError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace spiral::engine
