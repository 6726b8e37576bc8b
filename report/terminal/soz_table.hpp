#pragma once
// `spiral soz` in a terminal: the compact table of the safe operational zones.

#include <string>

#include "design/soz/soz.hpp"

namespace spiral::report {

/// Compact terminal table: riser summary (near/far/cross), allowable offset
/// per direction and riser with a one-letter governing criterion, the
/// platform zone, the offset check, solve statistics.
std::string soz_table(const design::SozResult& result);

}  // namespace spiral::report
