#pragma once
// Output of `spiral soz`: the JSON document `spiral.soz` v1 and the CSV
// table (docs/output-format.md); the terminal table is in report/terminal.

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

/// Riser static solve time per solve and thread, s (0 without solves).
double time_per_solve_s(const SozResult& result);

}  // namespace spiral::design
