#pragma once
// A project as the Python API holds it: the file's text and the project read
// from it, the same project as edited in memory since, and its validated form
// for the analyses (validated again after every edit). Each analysis calls
// the design function the CLI command calls, with the CLI's defaults, and
// returns the command's JSON document (docs/output-format.md) as text, so
// that Python gets the numbers of `spiral ... --json` to the last bit. No
// Python here: python/bindings/module.cpp converts.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "design/analysis/dynamic_analysis.hpp"
#include "design/analysis/motion_lines.hpp"
#include "design/optimization/pretension_optimizer.hpp"
#include "design/project/validated_project.hpp"
#include "design/results/dynamic_analysis_output.hpp"
#include "design/soz/soz.hpp"

namespace spiral::python {

/// A file could not be written (the message names it).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `spiral analyze`'s two outputs: summary.json and the time series columns.
struct AnalysisDocuments {
  std::string summary_json;
  std::vector<design::TimeSeriesColumn> time_series;
};

class ProjectSession {
 public:
  /// Reads, parses and validates `file` (design::load_validated_project).
  /// Throws design::InputError with every problem (file:line:col).
  explicit ProjectSession(const std::string& file);

  const design::Project& project() const { return edited_; }
  const std::string& file() const { return file_; }

  /// The segment (0-based, from the anchor) of the line named `line`;
  /// throws std::out_of_range naming what is missing.
  const design::LineSegment& segment(const std::string& line, int index) const;
  /// Sets a segment's unstretched length (m) or line type; validated when
  /// the project is next used.
  void set_segment_length(const std::string& line, int index, double length_m);
  void set_segment_type(const std::string& line, int index, const std::string& type);

  /// Sets any value the file writes, by its field path as error messages
  /// name it (`environments[1].waves.hs`, `hull.mass`,
  /// `line_types[0].breaking_load`) to `yaml_scalar` (a YAML scalar: a
  /// number, a name, true/false). The edit is made in the file's text at the
  /// value's own position and the text parsed again, so any field the file
  /// gives can change, with the same reading and checks as a file; segment
  /// edits made since stay. Throws std::invalid_argument when the file gives
  /// no value of its own there (a default), design::InputError when the
  /// edited text does not parse.
  void set_field(const std::string& path, const std::string& yaml_scalar);
  /// The scalar the file writes at `path`, as written (after set_field edits);
  /// throws std::invalid_argument when there is none.
  std::string field(const std::string& path) const;

  /// The validated project as it is now; throws design::InputError.
  const design::ValidatedProject& validated();

  /// `spiral statics --json --offset ...`: offset x, y, z (m), rx, ry, rz (deg).
  std::string statics_json(const std::array<double, 6>& offset_m_deg);
  /// `spiral equilibrium --json` (stiffness_check false) or `spiral stiffness --json` (true).
  std::string static_case_json(const std::optional<std::string>& load_case,
                               const std::optional<std::string>& damaged_line, bool stiffness_check);
  /// `spiral soz --json`; the options as the command sets them.
  std::string soz_json(const design::SozOptions& options);
  /// `spiral analyze`: summary.json and time_series.csv's columns at full precision.
  AnalysisDocuments analyze(const design::DynamicAnalysisRequest& request);
  /// `spiral lines`: summary.json and time_series.csv's columns at full
  /// precision; `motion_file` names the history in the summary.
  AnalysisDocuments lines(const design::MotionLinesRequest& request, const std::string& motion_file);
  /// `spiral optimize --json` (optimization.json).
  std::string optimize_json(const design::OptimizationRequest& request);

  /// Writes the project as edited to `target` (design::edited_project_text):
  /// the file's own text with only the edited values changed. Validates
  /// first (design::InputError); throws OutputError when the edit cannot be
  /// written into the text or the file cannot be written.
  void save(const std::filesystem::path& target);

 private:
  std::string file_;          ///< as the user named it (messages name it so)
  std::string text_;          ///< the file as loaded
  design::Project original_;  ///< as parsed from text_, before the load-case matrix is expanded
  design::Project edited_;    ///< original_ with the edits made since
  std::optional<design::ValidatedProject> validated_;  ///< of edited_; reset by every edit
};

}  // namespace spiral::python
