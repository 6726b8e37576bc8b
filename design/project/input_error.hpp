#pragma once
// The one exception type for invalid user input (project files and the files
// they reference). It carries every issue found in one pass over the input, so
// that the user fixes them all at once instead of one per run.
//
// Each issue reads like a compiler diagnostic:
//   file:line:col: field.path[3].sub: problem, got X unit
// Lines and columns are 1-based. Array indices in paths are 0-based.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace spiral::design {

/// What an issue's `path` names.
enum class InputOrigin {
  file,     ///< a field of the file, e.g. `mooring.lines[3].segments[1].length`
  request,  ///< an argument of a request made of the project, by its neutral name (`load_case`,
            ///< `duration_s`; design/project/request_error.hpp); the caller says it in its own words
};

/// One problem in the input.
struct InputIssue {
  std::string file;           ///< the file as the user named it
  std::optional<int> line;    ///< 1-based; absent when the issue has no position (missing file)
  std::optional<int> column;  ///< 1-based; absent together with `line`
  std::string path;           ///< field path or request argument (`origin`); may be empty
  InputOrigin origin = InputOrigin::file;
  std::string message;  ///< the problem, with the value and unit that were found
  /// Machine-readable name of the problem (`unknown_key`, `wrong_type`,
  /// `segment_length_positive`, ...); tests and tools key on it, users read `message`.
  std::string problem;
};

/// `file:line:col: path: message` (parts that are unknown are left out).
std::string format_issue(const InputIssue& issue);

/// Sorts `issues` into file order (line, then column; an issue without a
/// position first), keeping the order found among issues at one position.
void sort_in_file_order(std::vector<InputIssue>& issues);

/// Thrown by the project loader and the validation pass. `what()` lists every
/// issue, one per line, in the order found (file order for parse errors).
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<InputIssue> issues);
  const std::vector<InputIssue>& issues() const { return issues_; }

 private:
  std::vector<InputIssue> issues_;
};

}  // namespace spiral::design
