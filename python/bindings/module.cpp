// The C++ half of the Python package `spiral` (python/spiral/__init__.py is
// the other): the project session, its analyses with the GIL released, and
// the mapping of spiral's exceptions to Python's. Results cross as the JSON
// text of docs/output-format.md's documents (the Python half turns them into
// dicts and numpy arrays) and, for a time series, as numpy arrays.
#include <numbers>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>  // save(path)

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "design/import/motion_history.hpp"
#include "design/project/input_error.hpp"
#include "design/project/request_error.hpp"
#include "engine/common/file_format_error.hpp"
#include "engine/common/solver_error.hpp"
#include "python/bindings/interruptible.hpp"
#include "python/bindings/project_session.hpp"

namespace py = pybind11;

namespace spiral::python {
namespace {

/// The keyword argument of the Python API that sets the request argument
/// `argument` of design/ (design/project/request_error.hpp); app/'s
/// request_arguments is the same table for the CLI's flags.
std::string keyword_of(const std::string& argument) {
  static constexpr std::pair<std::string_view, std::string_view> kKeywords[] = {
      {"load_case", "case"},
      {"damaged_line", "damaged"},
      {"duration_s", "duration"},
      {"tolerance_m", "tolerance"},
      {"search_limit_pct_depth", "search_limit"},
      {"exclude_risers", "exclude"},
  };
  for (const auto& [name, keyword] : kKeywords)
    if (name == argument) return std::string(keyword);
  return argument;
}

/// The exception types of the module, created in PYBIND11_MODULE.
struct ExceptionTypes {
  py::object input_error, solver_error, output_error;
};
ExceptionTypes& exception_types() {
  static ExceptionTypes types;
  return types;
}

py::object make_exception_type(py::module_& m, const char* name, py::object base, PyObject* builtin, const char* doc) {
  py::tuple bases = builtin ? py::make_tuple(base, py::handle(builtin)) : py::make_tuple(base);
  const std::string qualified = std::string("spiral.") + name;
  py::object type =
      py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr));
  if (!type) throw py::error_already_set();
  m.attr(name) = type;
  return type;
}

/// Raises `type(message)` with `attributes` set on the exception object.
void raise(const py::object& type, const std::string& message, const py::dict& attributes = py::dict()) {
  py::object error = type(message);
  for (const auto& [key, value] : attributes) error.attr(key) = value;
  PyErr_SetObject(type.ptr(), error.ptr());
}

void translate(std::exception_ptr failure) {
  const ExceptionTypes& types = exception_types();
  try {
    std::rethrow_exception(failure);
  } catch (const design::InputError& error) {
    // As the CLI prints it (app/request_arguments describe), a request's
    // argument named by its keyword here instead of its flag.
    std::string message;
    py::list issues;
    for (design::InputIssue issue : error.issues()) {
      if (issue.origin == design::InputOrigin::request) issue.path = keyword_of(issue.path);
      message += (message.empty() ? "" : "\n") + design::format_issue(issue);
      py::dict d;
      d["file"] = issue.file;
      d["line"] = issue.line ? py::object(py::int_(*issue.line)) : py::object(py::none());
      d["column"] = issue.column ? py::object(py::int_(*issue.column)) : py::object(py::none());
      d["path"] = issue.path;
      d["message"] = issue.message;
      d["problem"] = issue.problem;
      issues.append(d);
    }
    py::dict attributes;
    attributes["issues"] = issues;
    raise(types.input_error, message, attributes);
  } catch (const engine::FileFormatError& error) {
    raise(types.input_error, error.what());
  } catch (const engine::SolverError& error) {
    // The CLI's message, without its "solver failure: " (the exception's type says it).
    const engine::SolverDiagnostics& d = error.diagnostics();
    std::string message = error.what();
    if (d.iterations > 0)
      message += fmt::format("\n  after {} iterations, residual {:.3g} {}", d.iterations, d.residual, d.residual_unit);
    message += "\n  check the line lengths against the anchor-fairlead span and the hull offset.";
    py::dict attributes;
    attributes["iterations"] = d.iterations;
    attributes["residual"] = d.residual;
    attributes["residual_unit"] = d.residual_unit;
    raise(types.solver_error, message, attributes);
  } catch (const OutputError& error) {
    raise(types.output_error, error.what());
  }
}

/// `value` if it is one of `allowed`; else an InputError on the keyword `keyword`.
std::string one_of(const ProjectSession& session, const std::string& keyword, const std::string& value,
                   std::initializer_list<std::string_view> allowed) {
  std::string names;
  for (const std::string_view a : allowed) {
    if (a == value) return value;
    names += fmt::format("{}'{}'", names.empty() ? "" : ", ", a);
  }
  throw design::request_error(session.project(), keyword, fmt::format("expected one of {}, got '{}'", names, value));
}

design::DesignCondition condition_of(const std::string& name) {
  if (name == "extreme") return design::DesignCondition::extreme;
  if (name == "survival") return design::DesignCondition::survival;
  return design::DesignCondition::normal;
}

design::OptimizationObjective objective_of(const std::string& name) {
  if (name == "min_max_utilization") return design::OptimizationObjective::min_max_utilization;
  if (name == "min_total_payout") return design::OptimizationObjective::min_total_payout;
  if (name == "min_max_offset") return design::OptimizationObjective::min_max_offset;
  return design::OptimizationObjective::max_soz_margin;
}

design::OptimizationAlgorithm algorithm_of(const std::string& name) {
  if (name == "ccsaq") return design::OptimizationAlgorithm::ccsaq;
  if (name == "cobyla") return design::OptimizationAlgorithm::cobyla;
  return design::OptimizationAlgorithm::slsqp;
}

py::dict columns_to_numpy(const std::vector<design::TimeSeriesColumn>& columns) {
  py::dict out;
  for (const design::TimeSeriesColumn& c : columns)
    out[py::str(c.name)] = py::array_t<double>(static_cast<py::ssize_t>(c.values.size()), c.values.data());
  return out;
}

}  // namespace
}  // namespace spiral::python

PYBIND11_MODULE(_spiral, m) {
  using namespace spiral;
  using namespace spiral::python;
  using py::arg;
  m.doc() = "spiral's C++ core (the API is the package `spiral`, docs/python.md)";

  py::object error = make_exception_type(m, "Error", py::reinterpret_borrow<py::object>(PyExc_Exception), nullptr,
                                         "Base of spiral's exceptions.");
  ExceptionTypes& types = exception_types();
  types.input_error = make_exception_type(
      m, "InputError", error, PyExc_ValueError,
      "Bad input: the project file (file:line:col: field: problem, every problem at once) or an argument of a "
      "call; `issues` lists them as dicts (file, line, column, path, message, problem).");
  types.solver_error = make_exception_type(m, "SolverError", error, PyExc_RuntimeError,
                                           "A solver failed (the message names the line, the iterations and the "
                                           "residual; also as `iterations`, `residual`, `residual_unit`).");
  types.output_error = make_exception_type(m, "OutputError", error, nullptr, "A file could not be written.");
  py::register_exception_translator(translate);

  py::class_<ProjectSession>(m, "ProjectSession")
      .def(py::init<const std::string&>(), arg("file"))
      .def_property_readonly("file", &ProjectSession::file)
      .def_property_readonly("name", [](const ProjectSession& s) { return s.project().name; })
      .def_property_readonly("depth_m", [](const ProjectSession& s) { return s.project().site.depth_m; })
      .def("line_names",
           [](const ProjectSession& s) {
             std::vector<std::string> names;
             for (const design::MooringLine& l : s.project().mooring.lines) names.push_back(l.name);
             return names;
           })
      .def("segment_count",
           [](const ProjectSession& s, const std::string& line) {
             for (const design::MooringLine& l : s.project().mooring.lines)
               if (l.name == line) return l.segments.size();
             throw py::key_error(line);
           })
      .def("segment_length",
           [](const ProjectSession& s, const std::string& line, int index) { return s.segment(line, index).length_m; })
      .def("segment_type",
           [](const ProjectSession& s, const std::string& line, int index) { return s.segment(line, index).type; })
      .def("set_segment_length", &ProjectSession::set_segment_length)
      .def("set_segment_type", &ProjectSession::set_segment_type)
      .def("set_field", &ProjectSession::set_field, arg("path"), arg("yaml_scalar"))
      .def("field", &ProjectSession::field, arg("path"))
      .def("load_case_names",
           [](ProjectSession& s) {
             // With the load-case matrix expanded: the names a call may be given.
             std::vector<std::string> names;
             for (const design::LoadCase& c : s.validated().project.load_cases) names.push_back(c.name);
             return names;
           })
      .def("riser_names",
           [](const ProjectSession& s) {
             std::vector<std::string> names;
             for (const design::Riser& r : s.project().risers) names.push_back(r.name);
             return names;
           })
      .def("line_type_names",
           [](const ProjectSession& s) {
             std::vector<std::string> names;
             for (const design::LineTypeInput& t : s.project().line_types) names.push_back(t.name);
             return names;
           })
      .def("validate", [](ProjectSession& s) { s.validated(); })
      .def(
          "statics",
          [](ProjectSession& s, const std::array<double, 6>& offset) {
            return run_interruptible([&](RunMonitor&) { return s.statics_json(offset); }, py::none());
          },
          arg("offset"))
      .def(
          "static_case",
          [](ProjectSession& s, std::optional<std::string> load_case, std::optional<std::string> damaged,
             bool stiffness_check) {
            return run_interruptible(
                [&](RunMonitor&) { return s.static_case_json(load_case, damaged, stiffness_check); }, py::none());
          },
          arg("case"), arg("damaged"), arg("stiffness_check"))
      .def(
          "soz",
          [](ProjectSession& s, std::optional<std::string> load_case, double step_deg, double tolerance_m,
             double search_limit_pct_depth, double march_step_pct_depth, const std::string& condition,
             const std::string& model, std::vector<std::string> exclude, int threads, bool check, bool still_water_only,
             bool extreme, double duration_s, std::uint64_t seed, const py::object& progress) {
            design::SozOptions options;  // as `spiral soz` sets them
            options.load_case = std::move(load_case);
            options.step_deg = step_deg;
            options.tolerance_m = tolerance_m;
            options.search_limit_pct_depth = search_limit_pct_depth;
            options.march_step_pct_depth = march_step_pct_depth;
            options.condition = condition_of(one_of(s, "condition", condition, {"normal", "extreme", "survival"}));
            options.model = one_of(s, "model", model, {"fe", "catenary"}) == "catenary" ? design::SozModel::catenary
                                                                                        : design::SozModel::fe;
            options.exclude_risers = std::move(exclude);
            options.threads = threads;
            options.offset_check = check;
            options.zone_per_current = !still_water_only;
            if (extreme) options.extreme = design::SozExtremeOptions{duration_s, seed};
            return run_interruptible(
                [&](RunMonitor& monitor) {
                  options.progress = monitor.hook();
                  return s.soz_json(options);
                },
                progress);
          },
          arg("case"), arg("step_deg"), arg("tolerance"), arg("search_limit"), arg("march_step"), arg("condition"),
          arg("model"), arg("exclude"), arg("threads"), arg("check"), arg("still_water_only"), arg("extreme"),
          arg("duration"), arg("seed"), arg("progress"))
      .def(
          "analyze",
          [](ProjectSession& s, const std::string& load_case, const std::string& level, double duration_s,
             double step_s, std::uint64_t seed, bool line_dynamics, const py::object& progress) {
            design::DynamicAnalysisRequest request;  // as `spiral analyze` sets it
            request.load_case = load_case;
            request.level = design::parse_analysis_level(level, s.project());
            request.duration_s = duration_s;
            request.output_step_s = step_s;
            request.seed = seed;
            request.line_dynamics = line_dynamics;
            AnalysisDocuments documents = run_interruptible(
                [&](RunMonitor& monitor) {
                  request.progress = monitor.hook();
                  return s.analyze(request);
                },
                progress);
            return py::make_tuple(documents.summary_json, columns_to_numpy(documents.time_series));
          },
          arg("case"), arg("level"), arg("duration"), arg("step"), arg("seed"), arg("line_dynamics"), arg("progress"))
      .def(
          "lines",
          [](ProjectSession& s, const std::string& load_case, const std::optional<std::string>& motion_file,
             const std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>>& times_s,
             const std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>>& offsets_m_deg,
             std::vector<std::string> lines, double step_s, double ramp_s, std::optional<std::uint64_t> seed,
             bool waves, const py::object& progress) {
            design::MotionLinesRequest request;  // as `spiral lines` sets it
            std::string source = "<arrays>";
            if (motion_file) {
              const design::MotionHistory history = design::read_motion_history(*motion_file);
              request.motion_times_s = history.time_s;
              request.motion = history.offset;
              for (const std::string& note : history.notes) request.motion_notes.push_back(*motion_file + ": " + note);
              source = *motion_file;
            } else {
              // (N,) times in s, (N, 6) offsets in m and deg: the CSV's units.
              const auto t = times_s->unchecked<1>();
              const auto q = offsets_m_deg->unchecked<2>();
              if (q.shape(0) != t.shape(0) || q.shape(1) != 6)
                throw design::request_error(s.project(), "motion",
                                            fmt::format("needs times (N,) and offsets (N, 6), got ({},) and ({}, {})",
                                                        t.shape(0), q.shape(0), q.shape(1)));
              request.motion.resize(6, t.shape(0));
              for (py::ssize_t k = 0; k < t.shape(0); ++k) {
                request.motion_times_s.push_back(t(k));
                for (py::ssize_t d = 0; d < 6; ++d)
                  request.motion(d, k) = q(k, d) * (d < 3 ? 1.0 : std::numbers::pi / 180.0);
              }
            }
            request.load_case = load_case;
            request.lines = std::move(lines);
            request.output_step_s = step_s;
            request.ramp_s = ramp_s;
            request.seed = seed;
            request.waves_on_lines = waves;
            AnalysisDocuments documents = run_interruptible(
                [&](RunMonitor& monitor) {
                  request.progress = monitor.hook();
                  return s.lines(request, source);
                },
                progress);
            return py::make_tuple(documents.summary_json, columns_to_numpy(documents.time_series));
          },
          arg("case"), arg("motion_file"), arg("times"), arg("offsets"), arg("lines"), arg("step"), arg("ramp"),
          arg("seed"), arg("waves"), arg("progress"))
      .def(
          "optimize",
          [](ProjectSession& s, std::optional<std::string> objective, std::optional<std::string> algorithm,
             std::optional<std::string> damaged, std::vector<std::string> cases, std::optional<int> max_evaluations,
             int threads, const std::string& level, double duration_s, std::uint64_t seed, const py::object& progress) {
            design::OptimizationRequest request;  // as `spiral optimize` sets it
            if (objective)
              request.objective =
                  objective_of(one_of(s, "objective", *objective,
                                      {"max_soz_margin", "min_max_utilization", "min_total_payout", "min_max_offset"}));
            if (algorithm)
              request.algorithm = algorithm_of(one_of(s, "algorithm", *algorithm, {"slsqp", "ccsaq", "cobyla"}));
            if (damaged)
              request.damaged = one_of(s, "damaged", *damaged, {"load_cases", "every_line"}) == "every_line"
                                    ? design::DamagedConditions::every_line
                                    : design::DamagedConditions::load_cases;
            request.cases = std::move(cases);
            request.max_evaluations = max_evaluations;
            request.threads = threads;
            if (one_of(s, "level", level, {"static", "sc-enhanced"}) == "sc-enhanced")
              request.dynamic = design::DynamicLevelOptions{duration_s, seed};
            return run_interruptible(
                [&](RunMonitor& monitor) {
                  request.progress = monitor.hook();
                  return s.optimize_json(request);
                },
                progress);
          },
          arg("objective"), arg("algorithm"), arg("damaged"), arg("cases"), arg("max_evaluations"), arg("threads"),
          arg("level"), arg("duration"), arg("seed"), arg("progress"))
      .def("save", &ProjectSession::save, arg("path"));
}
