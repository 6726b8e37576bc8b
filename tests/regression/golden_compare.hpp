#pragma once
// Compares a whole run's JSON document with its stored baseline, channel by
// channel, under named tolerances. The regression tier's contract: a number
// moves only within the tolerance its rule justifies, no key appears or
// disappears, no value turns into NaN/Inf (null in JSON) or changes type.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace spiral::golden {

/// One tolerance rule. A value's path is written JSON-pointer style
/// (`/lines/3/fairlead_tension_N`); `path` is an fnmatch(3) pattern on it
/// (`*` spans `/`), `run` one on the run's name. The first rule matching both
/// applies; a value that no rule matches must equal the baseline exactly.
struct ToleranceRule {
  std::string run = "*";
  std::string path = "*";
  bool ignore = false;    ///< value not compared (wall clock, host paths); the key must still exist
  double relative = 0.0;  ///< |a - b| <= absolute + relative * max(|a|, |b|)
  double absolute = 0.0;
  std::string why;  ///< the justification, printed with every failure under this rule
};

/// Reads `{"rules": [{"run", "path", "ignore", "rel", "abs", "why"}, ...]}`;
/// every rule must say why. Throws std::runtime_error on a malformed file.
std::vector<ToleranceRule> read_tolerance_rules(const std::string& file);

struct Difference {
  std::string path;
  std::string message;
  std::string why;  ///< the justification of the tolerance that was exceeded (empty: exact)
};

/// Every difference between `actual` and `baseline` for the run named `run`.
std::vector<Difference> compare_documents(const nlohmann::json& actual, const nlohmann::json& baseline,
                                          const std::string& run, const std::vector<ToleranceRule>& rules);

}  // namespace spiral::golden
