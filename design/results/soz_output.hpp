#pragma once
// Output of `spiral soz`: the terminal table, the JSON document `spiral.soz`
// v1 and the CSV table (docs/output-format.md).

#include <nlohmann/json.hpp>
#include <string>

#include "design/soz/soz.hpp"

namespace spiral::design {

/// JSON document `spiral.soz` v1. Infinite values (a ratio against a zero
/// allowable offset) are written as null.
nlohmann::json soz_to_json(const SozResult& result);

/// Long-format CSV: one row per (direction, riser), then the platform rows
/// (riser = "platform").
std::string soz_to_csv(const SozResult& result);

/// Compact terminal table: riser summary (near/far/cross), allowable offset
/// per direction and riser with a one-letter governing criterion, the
/// platform zone, the offset check, solve statistics.
std::string soz_table(const SozResult& result);

}  // namespace spiral::design
