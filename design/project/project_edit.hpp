#pragma once
// Writing a changed project back as YAML text without losing what the user
// wrote: the values that change are replaced in place in the original text
// (found through the source map of the loaded project), so comments, order,
// flow style and every other number stay as they were.

#include <map>
#include <string>

#include "design/project/project.hpp"

namespace spiral::design {

/// `text` (the file `project` was loaded from) with the top (fairlead-end)
/// segment of each line in `payouts_m` lengthened by its payout (m; negative
/// hauls in), the new lengths printed to 0.1 mm, and `header` (lines that
/// become `# ` comments) put first. Throws std::invalid_argument when a
/// line is unknown or the source map has no position for its length (a
/// project built in code).
std::string with_line_payouts(const std::string& text, const Project& project,
                              const std::map<std::string, double>& payouts_m, const std::string& header);

}  // namespace spiral::design
