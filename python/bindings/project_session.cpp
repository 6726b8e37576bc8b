#include "python/bindings/project_session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "design/analysis/static_case.hpp"
#include "design/analysis/statics_study.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/project_edit.hpp"
#include "design/project/project_loader.hpp"
#include "design/results/motion_lines_output.hpp"
#include "design/results/optimization_output.hpp"
#include "design/results/soz_output.hpp"
#include "design/results/static_case_output.hpp"
#include "design/results/statics_output.hpp"

namespace spiral::python {

namespace {

/// The segment `index` of the line named `line` in `project` (const or not);
/// throws std::out_of_range naming what is missing.
template <class ProjectType>
auto& segment_of(ProjectType& project, const std::string& line, int index) {
  auto& lines = project.mooring.lines;
  const auto it =
      std::find_if(lines.begin(), lines.end(), [&](const design::MooringLine& l) { return l.name == line; });
  if (it == lines.end()) throw std::out_of_range(fmt::format("no mooring line named '{}'", line));
  if (index < 0 || static_cast<std::size_t>(index) >= it->segments.size())
    throw std::out_of_range(fmt::format("line '{}' has {} segments, no segment {}", line, it->segments.size(), index));
  return it->segments[static_cast<std::size_t>(index)];
}

std::string read_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

ProjectSession::ProjectSession(const std::string& file) : file_(file) {
  // Parsed once from the text kept for save(): the source map and the text agree.
  original_ = design::load_project(file);
  text_ = read_text(file);
  edited_ = original_;
  validated();
}

const design::LineSegment& ProjectSession::segment(const std::string& line, int index) const {
  return segment_of(edited_, line, index);
}

void ProjectSession::set_segment_length(const std::string& line, int index, double length_m) {
  segment_of(edited_, line, index).length_m = length_m;
  validated_.reset();
}

void ProjectSession::set_segment_type(const std::string& line, int index, const std::string& type) {
  segment_of(edited_, line, index).type = type;
  validated_.reset();
}

void ProjectSession::set_field(const std::string& path, const std::string& yaml_scalar) {
  std::string text = design::with_field_values(text_, original_, {{path, yaml_scalar}});
  // Read like the file (relative data files from its folder), then carry
  // the segment edits made in memory over to the new reading.
  design::Project reread = design::parse_project(text, file_, std::filesystem::path(file_).parent_path());
  design::Project edited = reread;
  const auto& before = original_.mooring.lines;
  for (std::size_t l = 0; l < before.size() && l < edited.mooring.lines.size(); ++l) {
    for (std::size_t s = 0; s < before[l].segments.size() && s < edited.mooring.lines[l].segments.size(); ++s) {
      const design::LineSegment& was = before[l].segments[s];
      const design::LineSegment& now = edited_.mooring.lines[l].segments[s];
      design::LineSegment& target = edited.mooring.lines[l].segments[s];
      if (now.length_m != was.length_m) target.length_m = now.length_m;
      if (now.type != was.type) target.type = now.type;
    }
  }
  text_ = std::move(text);
  original_ = std::move(reread);
  edited_ = std::move(edited);
  validated_.reset();
}

std::string ProjectSession::field(const std::string& path) const {
  return design::field_value_text(text_, original_, path);
}

const design::ValidatedProject& ProjectSession::validated() {
  if (!validated_) validated_ = design::validate_loaded_project(edited_);
  return *validated_;
}

std::string ProjectSession::statics_json(const std::array<double, 6>& offset_m_deg) {
  const design::ValidatedProject& loaded = validated();
  engine::Vector6d offset;
  // As `spiral statics --offset`: rotations in degrees, SI (rad) inside.
  for (int i = 0; i < 6; ++i)
    offset(i) = offset_m_deg[static_cast<std::size_t>(i)] * (i < 3 ? 1.0 : std::numbers::pi / 180.0);
  design::LineArrayModel model = design::build_mooring_model(loaded.project);
  return design::statics_to_json(design::run_statics(model, offset), loaded.project.name).dump();
}

std::string ProjectSession::static_case_json(const std::optional<std::string>& load_case,
                                             const std::optional<std::string>& damaged_line, bool stiffness_check) {
  const design::ValidatedProject& loaded = validated();
  design::StaticCaseRequest request;
  request.load_case = load_case;
  request.damaged_line = damaged_line;
  request.finite_difference_check = stiffness_check;
  return design::static_case_to_json(design::run_static_case(loaded, request), loaded.project.name).dump();
}

std::string ProjectSession::soz_json(const design::SozOptions& options) {
  return design::soz_to_json(design::run_soz(validated(), options)).dump();
}

AnalysisDocuments ProjectSession::analyze(const design::DynamicAnalysisRequest& request) {
  const design::ValidatedProject& loaded = validated();
  const design::DynamicAnalysisResult result = design::run_dynamic_analysis(loaded, request);
  return {design::dynamic_analysis_to_json(result, loaded.project.name).dump(),
          design::dynamic_time_series_columns(result)};
}

AnalysisDocuments ProjectSession::lines(const design::MotionLinesRequest& request, const std::string& motion_file) {
  const design::ValidatedProject& loaded = validated();
  const design::MotionLinesResult result = design::run_motion_lines(loaded, request);
  return {design::motion_lines_to_json(result, loaded, motion_file).dump(), design::motion_lines_columns(result)};
}

std::string ProjectSession::optimize_json(const design::OptimizationRequest& request) {
  return design::optimization_to_json(design::optimize_pretension(validated(), request)).dump();
}

void ProjectSession::save(const std::filesystem::path& target) {
  validated();  // a saved project is a valid one
  std::string text;
  try {
    text = design::edited_project_text(text_, original_, edited_, target);
  } catch (const std::invalid_argument& error) {
    throw OutputError(fmt::format("{}: not written: {}", target.string(), error.what()));
  }
  // Written beside the target and renamed: a failed write leaves no half file.
  std::filesystem::path partial = target;
  partial += ".partial";
  std::ofstream(partial, std::ios::binary) << text;
  std::error_code error;
  if (std::filesystem::file_size(partial, error) != text.size() || error) {
    std::filesystem::remove(partial, error);
    throw OutputError(fmt::format("cannot write {}", target.string()));
  }
  std::filesystem::rename(partial, target, error);
  if (error) throw OutputError(fmt::format("cannot write {}: {}", target.string(), error.message()));
}

}  // namespace spiral::python
