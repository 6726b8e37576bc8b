#include "engine/numerics/sundials_cvode.hpp"

#include "engine/numerics/fast_dense.hpp"
#include "engine/numerics/fast_nvector.hpp"

#include <cvode/cvode.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <stdexcept>
#include <utility>

namespace spiral::engine {
namespace {

// CVRhsFn return codes (CVODE user guide, "Right-hand side function"):
// 0 success, > 0 recoverable (CVODE retries with a smaller step), < 0 fatal.
constexpr int kRhsSuccess = 0;
constexpr int kRhsRecoverable = 1;
constexpr int kRhsFatal = -1;

std::string flag_name(int flag) {
  char* name = CVodeGetReturnFlagName(flag);  // malloc'ed by CVODE
  std::string s = name != nullptr ? name : fmt::format("flag {}", flag);
  std::free(name);
  return s;
}

std::string hint_for(int flag) {
  switch (flag) {
    case CV_TOO_MUCH_WORK:
      return "raise max_steps_between_outputs, shorten the output interval, or check the model "
             "for an unbounded (unstable) response";
    case CV_TOO_MUCH_ACC:
      return "the tolerances are below what double precision can deliver: relax rtol/atol";
    case CV_ERR_FAILURE:
      return "the step size collapsed on the error test: look for a discontinuity or a "
             "non-smooth force in the right-hand side, or loosen the tolerances";
    case CV_CONV_FAILURE:
      return "the nonlinear iteration failed repeatedly: use bdf_newton_dense for a stiff "
             "system, or check the right-hand side for discontinuities";
    case CV_RHSFUNC_FAIL:
    case CV_REPTD_RHSFUNC_ERR:
    case CV_UNREC_RHSFUNC_ERR:
    case CV_FIRST_RHSFUNC_ERR:
      return "the right-hand side failed (see its message): check the state it was given";
    default:
      return "check the model inputs and the integrator options";
  }
}

}  // namespace

struct CvodeIntegrator::Impl {
  OdeRightHandSide rhs;
  CvodeOptions options;
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  N_Vector atol = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  SUNNonlinearSolver nonlinear_solver = nullptr;
  void* cvode = nullptr;

  // Workspace for the RHS (avoids an allocation per call).
  Eigen::VectorXd y_work;
  Eigen::VectorXd ydot_work;
  Eigen::VectorXd y_out;  // state at the last output time
  double t_out = 0.0;

  // Exception of the RHS, rethrown after CVode returns.
  std::exception_ptr fatal_exception;
  std::string last_rhs_message;
  long recoverable_failures = 0;
  std::string last_cvode_message;

  ~Impl() {
    if (cvode != nullptr) CVodeFree(&cvode);
    if (nonlinear_solver != nullptr) SUNNonlinSolFree(nonlinear_solver);
    if (linear_solver != nullptr) SUNLinSolFree(linear_solver);
    if (matrix != nullptr) SUNMatDestroy(matrix);
    if (atol != nullptr) N_VDestroy(atol);
    if (y != nullptr) N_VDestroy(y);
    if (context != nullptr) SUNContext_Free(&context);
  }

  static int rhs_callback(realtype t, N_Vector y, N_Vector ydot, void* user_data) {
    auto* self = static_cast<Impl*>(user_data);
    const auto n = static_cast<Eigen::Index>(N_VGetLength_Serial(y));
    self->y_work = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer_Serial(y), n);
    try {
      self->rhs(t, self->y_work, self->ydot_work);
      if (self->ydot_work.size() != n) {
        throw std::logic_error(
            fmt::format("ODE right-hand side wrote {} derivatives for {} states", self->ydot_work.size(), n));
      }
      if (!self->ydot_work.allFinite()) {
        self->last_rhs_message = fmt::format("non-finite derivative at t = {} s", t);
        ++self->recoverable_failures;
        return kRhsRecoverable;
      }
    } catch (const SolverError& e) {
      self->last_rhs_message = e.what();
      ++self->recoverable_failures;
      return kRhsRecoverable;
    } catch (...) {
      self->fatal_exception = std::current_exception();
      return kRhsFatal;
    }
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer_Serial(ydot), n) = self->ydot_work;
    return kRhsSuccess;
  }

  // Keeps CVODE from printing to stderr: its message goes into the exception.
  static void error_handler(int /*code*/, const char* module, const char* function, char* msg, void* user_data) {
    auto* self = static_cast<Impl*>(user_data);
    self->last_cvode_message = fmt::format("{}/{}: {}", module, function, msg);
  }

  void check(int flag, const char* call) const {
    if (flag < 0) {
      throw SolverError(fmt::format("CVODE setup: {} returned {} ({})", call, flag_name(flag), last_cvode_message));
    }
  }
};

CvodeIntegrator::CvodeIntegrator(OdeRightHandSide rhs, double t0_s, const Eigen::VectorXd& y0,
                                 const CvodeOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (!rhs) throw std::invalid_argument("CVODE: the right-hand side function is empty");
  if (y0.size() == 0) throw std::invalid_argument("CVODE: the initial state is empty");
  if (!y0.allFinite() || !std::isfinite(t0_s)) {
    throw std::invalid_argument("CVODE: the initial time and state must be finite");
  }
  if (!(options.relative_tolerance > 0.0) || !(options.absolute_tolerance > 0.0)) {
    throw std::invalid_argument(
        fmt::format("CVODE: relative_tolerance and absolute_tolerance must be > 0, got {} and {}",
                    options.relative_tolerance, options.absolute_tolerance));
  }
  if (options.absolute_tolerances &&
      (options.absolute_tolerances->size() != y0.size() || !(options.absolute_tolerances->array() > 0.0).all())) {
    throw std::invalid_argument(fmt::format("CVODE: absolute_tolerances must have {} entries, all > 0", y0.size()));
  }
  if (options.max_step_s && !(*options.max_step_s > 0.0)) {
    throw std::invalid_argument(fmt::format("CVODE: max_step_s must be > 0 s, got {} s", *options.max_step_s));
  }
  if (options.initial_step_s && !(*options.initial_step_s > 0.0)) {
    throw std::invalid_argument(fmt::format("CVODE: initial_step_s must be > 0 s, got {} s", *options.initial_step_s));
  }
  if (options.max_order) {
    const int limit = options.method == CvodeMethod::bdf_newton_dense ? 5 : 12;
    if (*options.max_order < 1 || *options.max_order > limit) {
      throw std::invalid_argument(
          fmt::format("CVODE: max_order must be 1..{} for this method, got {}", limit, *options.max_order));
    }
  }
  if (options.max_steps_between_outputs <= 0) {
    throw std::invalid_argument("CVODE: max_steps_between_outputs must be > 0");
  }

  Impl& m = *impl_;
  m.rhs = std::move(rhs);
  m.options = options;
  const auto n = static_cast<sunindextype>(y0.size());
  m.y_work.resize(y0.size());
  m.ydot_work.resize(y0.size());
  m.y_out = y0;
  m.t_out = t0_s;

  if (SUNContext_Create(nullptr, &m.context) != 0) {
    throw SolverError("CVODE setup: SUNContext_Create failed");
  }
  m.y = N_VNew_Serial(n, m.context);
  if (m.y == nullptr) throw SolverError("CVODE setup: N_VNew_Serial failed");
  // Before CVodeInit, so that every vector CVODE clones from y has them.
  fast_nvector::install(m.y, fast_nvector::Arithmetic::library);
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer_Serial(m.y), y0.size()) = y0;

  const int lmm = options.method == CvodeMethod::bdf_newton_dense ? CV_BDF : CV_ADAMS;
  m.cvode = CVodeCreate(lmm, m.context);
  if (m.cvode == nullptr) throw SolverError("CVODE setup: CVodeCreate failed");
  m.check(CVodeSetErrHandlerFn(m.cvode, &Impl::error_handler, &m), "CVodeSetErrHandlerFn");
  m.check(CVodeInit(m.cvode, &Impl::rhs_callback, t0_s, m.y), "CVodeInit");
  m.check(CVodeSetUserData(m.cvode, &m), "CVodeSetUserData");
  if (options.absolute_tolerances) {
    m.atol = N_VNew_Serial(n, m.context);
    if (m.atol == nullptr) throw SolverError("CVODE setup: N_VNew_Serial failed");
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer_Serial(m.atol), y0.size()) = *options.absolute_tolerances;
    m.check(CVodeSVtolerances(m.cvode, options.relative_tolerance, m.atol), "CVodeSVtolerances");
  } else {
    m.check(CVodeSStolerances(m.cvode, options.relative_tolerance, options.absolute_tolerance), "CVodeSStolerances");
  }
  if (options.method == CvodeMethod::adams_fixed_point) {
    m.nonlinear_solver = SUNNonlinSol_FixedPoint(m.y, 0, m.context);
    if (m.nonlinear_solver == nullptr) throw SolverError("CVODE setup: fixed-point solver failed");
    m.check(CVodeSetNonlinearSolver(m.cvode, m.nonlinear_solver), "CVodeSetNonlinearSolver");
  } else {
    m.matrix = SUNDenseMatrix(n, n, m.context);
    m.linear_solver = fast_dense::make_lu_solver(n, m.context);
    if (m.matrix == nullptr || m.linear_solver == nullptr) {
      throw SolverError("CVODE setup: dense matrix / linear solver creation failed");
    }
    fast_dense::install(m.matrix);
    m.check(CVodeSetLinearSolver(m.cvode, m.linear_solver, m.matrix), "CVodeSetLinearSolver");
  }
  m.check(CVodeSetMaxNumSteps(m.cvode, options.max_steps_between_outputs), "CVodeSetMaxNumSteps");
  if (options.max_order) m.check(CVodeSetMaxOrd(m.cvode, *options.max_order), "CVodeSetMaxOrd");
  if (options.max_step_s) m.check(CVodeSetMaxStep(m.cvode, *options.max_step_s), "CVodeSetMaxStep");
  if (options.initial_step_s) {
    m.check(CVodeSetInitStep(m.cvode, *options.initial_step_s), "CVodeSetInitStep");
  }
}

CvodeIntegrator::~CvodeIntegrator() = default;
CvodeIntegrator::CvodeIntegrator(CvodeIntegrator&&) noexcept = default;
CvodeIntegrator& CvodeIntegrator::operator=(CvodeIntegrator&&) noexcept = default;

void CvodeIntegrator::set_stop_time(double tstop_s) {
  impl_->check(CVodeSetStopTime(impl_->cvode, tstop_s), "CVodeSetStopTime");
}

const Eigen::VectorXd& CvodeIntegrator::advance_to(double t_out_s) {
  Impl& m = *impl_;
  if (!(t_out_s > m.t_out)) {
    throw std::invalid_argument(
        fmt::format("CVODE: output time {} s must be after the current output time {} s", t_out_s, m.t_out));
  }
  realtype t_reached = m.t_out;
  const int flag = CVode(m.cvode, t_out_s, m.y, &t_reached, CV_NORMAL);
  if (m.fatal_exception) {
    auto e = std::exchange(m.fatal_exception, nullptr);
    std::rethrow_exception(e);
  }
  if (flag < 0) {
    const CvodeStatistics s = statistics();
    // A step that has shrunk to round-off of t means the solution cannot be
    // continued past this time whatever the step budget (a force that fails
    // or jumps there): say so instead of blaming the step budget.
    constexpr double kCollapsedStepUlps = 1e3;
    const bool collapsed = std::abs(s.last_step_s) < kCollapsedStepUlps * std::numeric_limits<double>::epsilon() *
                                                         std::max(1.0, std::abs(s.current_time_s));
    std::string message = fmt::format(
        "CVODE failed at t = {:.6g} s on the way to t = {:.6g} s: {}{} after {} steps, last step "
        "h = {:.3g} s (order {}). {}{}. Hint: {}",
        s.current_time_s, t_out_s, flag_name(flag), collapsed ? " (step size collapsed)" : "", s.steps, s.last_step_s,
        s.last_order, m.last_cvode_message,
        m.last_rhs_message.empty() ? "" : fmt::format(" Last right-hand side error: {}", m.last_rhs_message),
        collapsed ? "the right-hand side fails or is discontinuous at this time: check the "
                    "forces (line solver, tabulated input) at the state reached"
                  : hint_for(flag));
    throw IntegrationError(message, s.current_time_s, s.last_step_s, flag,
                           SolverDiagnostics{static_cast<int>(s.steps), s.last_step_s, "s"});
  }
  m.t_out = t_reached;
  m.y_out = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer_Serial(m.y), m.y_out.size());
  return m.y_out;
}

double CvodeIntegrator::time_s() const { return impl_->t_out; }
const Eigen::VectorXd& CvodeIntegrator::state() const { return impl_->y_out; }

CvodeStatistics CvodeIntegrator::statistics() const {
  const Impl& m = *impl_;
  CvodeStatistics s;
  long nsteps = 0, nfevals = 0, nlinsetups = 0, netfails = 0;
  int qlast = 0, qcur = 0;
  realtype hinused = 0, hlast = 0, hcur = 0, tcur = 0;
  CVodeGetIntegratorStats(m.cvode, &nsteps, &nfevals, &nlinsetups, &netfails, &qlast, &qcur, &hinused, &hlast, &hcur,
                          &tcur);
  s.steps = nsteps;
  s.rhs_evaluations = nfevals;
  s.error_test_failures = netfails;
  s.last_step_s = hlast;
  s.current_time_s = tcur;
  s.last_order = qlast;
  CVodeGetNonlinSolvStats(m.cvode, &s.nonlinear_iterations, &s.nonlinear_convergence_failures);
  if (m.linear_solver != nullptr) {
    CVodeGetNumJacEvals(m.cvode, &s.jacobian_evaluations);
    CVodeGetNumLinRhsEvals(m.cvode, &s.rhs_evaluations_for_jacobian);
  }
  s.recoverable_rhs_failures = m.recoverable_failures;
  return s;
}

OdeSolution integrate_ode(const OdeRightHandSide& rhs, double t0_s, const Eigen::VectorXd& y0,
                          std::span<const double> output_times_s, const CvodeOptions& options) {
  for (std::size_t k = 0; k < output_times_s.size(); ++k) {
    const double prev = k == 0 ? t0_s : output_times_s[k - 1];
    const bool first_at_start = k == 0 && output_times_s[0] == t0_s;
    if (!(output_times_s[k] > prev) && !first_at_start) {
      throw std::invalid_argument(
          fmt::format("integrate_ode: output times must be strictly increasing and after t0 = {} s; "
                      "output_times_s[{}] = {} s",
                      t0_s, k, output_times_s[k]));
    }
  }
  CvodeIntegrator integrator(rhs, t0_s, y0, options);
  OdeSolution out;
  const auto n_out = static_cast<Eigen::Index>(output_times_s.size());
  out.times_s = Eigen::Map<const Eigen::VectorXd>(output_times_s.data(), n_out);
  out.states.resize(y0.size(), n_out);
  for (Eigen::Index k = 0; k < n_out; ++k) {
    out.states.col(k) = output_times_s[k] == t0_s ? y0 : integrator.advance_to(output_times_s[k]);
  }
  out.statistics = integrator.statistics();
  return out;
}

}  // namespace spiral::engine
