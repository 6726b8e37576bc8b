#include "engine/numerics/sundials_ida.hpp"

#include "engine/numerics/fast_nvector.hpp"

#include <fmt/format.h>
#include <ida/ida.h>
#include <ida/ida_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sunnonlinsol/sunnonlinsol_newton.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <utility>

namespace spiral::engine {
namespace {

// IDAResFn return codes: 0 success, > 0 recoverable, < 0 fatal.
constexpr int kResidualSuccess = 0;
constexpr int kResidualRecoverable = 1;
constexpr int kResidualFatal = -1;
// IDA's default c_j change that triggers a Newton-matrix refresh (IDASetDeltaCjLSetup).
constexpr double kCjChangeForSetup = 0.25;
// Constants of IDA's Newton convergence test (ida_nls.c, ida.c): the rate
// factor after a matrix setup and after a c_j change, the largest accepted
// rate, and the first-correction norm accepted at once (1e-4 · toldel with
// toldel = 1e-4 · epsNewt).
constexpr double kRateFactorAfterSetup = 20.0;
constexpr double kRateFactorAfterCjChange = 100.0;
constexpr double kMaxConvergenceRate = 0.9;
constexpr double kImmediateConvergence = 1e-8;
// Newton iterations on one matrix (IDASetMaxNonlinIters default, maxcor).
// The nonlinear solver is allowed twice as many so that a solve restarted on
// a fresh matrix (convergence_test) gets its own full count, as SUNDIALS'
// Newton gives a solve it restarts after a setup.
constexpr int kNewtonIterationsPerMatrix = 4;

std::string flag_name(int flag) {
  char* name = IDAGetReturnFlagName(flag);  // malloc'ed by IDA
  std::string s = name != nullptr ? name : fmt::format("flag {}", flag);
  std::free(name);
  return s;
}

std::string hint_for(int flag) {
  switch (flag) {
    case IDA_TOO_MUCH_WORK:
      return "raise max_steps_between_outputs, shorten the output interval, or check the model for "
             "an "
             "unbounded (unstable) response";
    case IDA_TOO_MUCH_ACC:
      return "the tolerances are below what double precision can deliver: relax them";
    case IDA_ERR_FAIL:
      return "the step size collapsed on the error test: look for a discontinuity or a non-smooth "
             "force "
             "(contact, snap loads), or loosen the tolerances";
    case IDA_CONV_FAIL:
    case IDA_LSOLVE_FAIL:
      return "the Newton iteration failed repeatedly at ever smaller steps: the state may be "
             "unphysical "
             "(a line in compression, a node far below the seabed) or the Newton matrix singular";
    case IDA_RES_FAIL:
    case IDA_REP_RES_ERR:
    case IDA_FIRST_RES_FAIL:
      return "the residual failed (see its message): check the state it was given";
    default:
      return "check the model inputs and the integrator options";
  }
}

}  // namespace

struct IdaIntegrator::Impl {
  ImplicitSystem* system = nullptr;
  IdaOptions options;
  SUNContext context = nullptr;
  N_Vector y = nullptr, yp = nullptr, atol = nullptr, id = nullptr;
  // Scratch for group_local_errors, made once: a coupled run asks at every
  // output, and new state-sized vectors there (1.4 MB each on the deep-water
  // system) cost a page fault per 4 kB touched, millions over a storm.
  N_Vector local_error = nullptr, error_weight = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  SUNNonlinearSolver nonlinear_solver = nullptr;
  void* ida = nullptr;

  Eigen::VectorXd y_out, yp_out;
  double t_out = 0.0;

  // Newton-matrix refresh bookkeeping.
  bool factored = false;
  double cj_at_setup = 0.0;
  long steps_at_setup = 0;
  long convergence_failures_at_setup = 0;
  long setups = 0;
  long updates = 0;
  long solves = 0;
  enum class Refresh { none, partial, full };
  Refresh refresh_since_test = Refresh::none;  // Newton-matrix refresh since the last solve
  bool setup_requested = false;                // by convergence_test, for the next linear solve
  bool matrix_current = false;                 // set up at this nonlinear solve's predictor or iterate (SUNDIALS' jcur)
  int restart_iteration = 0;                   // the Newton iteration this solve (re)started counting from
  long newton_restarts = 0;

  // Newton convergence test state (see convergence_test).
  double rate_factor = kRateFactorAfterSetup;  // IDA's ss: rate / (1 − rate)
  double first_correction_norm = 0.0;          // IDA's oldnrm
  double cj_at_last_solve = 0.0;

  std::exception_ptr fatal_exception;
  std::string last_residual_message;
  std::string last_ida_message;
  long recoverable_failures = 0;
  std::vector<Eigen::Index> error_groups;

  ~Impl() {
    if (ida != nullptr) IDAFree(&ida);
    if (nonlinear_solver != nullptr) SUNNonlinSolFree(nonlinear_solver);
    if (linear_solver != nullptr) {
      linear_solver->content = nullptr;
      SUNLinSolFreeEmpty(linear_solver);
    }
    for (N_Vector* v : {&y, &yp, &atol, &id, &local_error, &error_weight}) {
      if (*v != nullptr) N_VDestroy(*v);
    }
    if (context != nullptr) SUNContext_Free(&context);
  }

  static Eigen::Map<Eigen::VectorXd> map(N_Vector v) {
    return {N_VGetArrayPointer_Serial(v), static_cast<Eigen::Index>(N_VGetLength_Serial(v))};
  }

  static int residual_callback(realtype t, N_Vector y, N_Vector yp, N_Vector r, void* user_data) {
    auto* self = static_cast<Impl*>(user_data);
    // The system reads and writes IDA's vectors in place (no copies: on the
    // deep-water coupled system each is 1.4 MB, copied serially three times per residual).
    auto r_out = map(r);
    try {
      self->system->residual(t, map(y), map(yp), r_out);
      if (!r_out.allFinite()) {
        self->last_residual_message = fmt::format("non-finite residual at t = {} s", t);
        ++self->recoverable_failures;
        return kResidualRecoverable;
      }
    } catch (const SolverError& e) {
      self->last_residual_message = e.what();
      ++self->recoverable_failures;
      return kResidualRecoverable;
    } catch (...) {
      self->fatal_exception = std::current_exception();
      return kResidualFatal;
    }
    return kResidualSuccess;
  }

  static SUNLinearSolver_Type solver_type(SUNLinearSolver) { return SUNLINEARSOLVER_MATRIX_EMBEDDED; }

  static int solve_callback(SUNLinearSolver ls, SUNMatrix, N_Vector x, N_Vector b, realtype) {
    auto* self = static_cast<Impl*>(ls->content);
    realtype t = 0.0, cj = 0.0;
    N_Vector yy_pred, yp_pred, yy, yp, res;
    void* user_data = nullptr;
    if (IDAGetNonlinearSystemData(self->ida, &t, &yy_pred, &yp_pred, &yy, &yp, &res, &cj, &user_data) != 0) {
      return SUNLS_PACKAGE_FAIL_UNREC;
    }
    try {
      long steps = 0, failures = 0;
      IDAGetNumSteps(self->ida, &steps);
      IDAGetNumNonlinSolvConvFails(self->ida, &failures);
      const bool full = !self->factored || failures > self->convergence_failures_at_setup || self->setup_requested ||
                        steps - self->steps_at_setup >= self->options.max_steps_between_setups;
      const bool update =
          !full && (std::abs(cj / self->cj_at_setup - 1.0) > kCjChangeForSetup || self->system->newton_matrix_stale());
      if (full || update) {
        ++self->setups;
        if (full) {
          self->factored = self->system->setup_newton_matrix(t, map(yy), map(yp), cj);
          self->steps_at_setup = steps;
          self->convergence_failures_at_setup = failures;
        } else {
          ++self->updates;
          self->factored = self->system->update_newton_matrix(t, map(yy), map(yp), cj);
        }
        self->refresh_since_test = full ? Refresh::full : Refresh::partial;
        self->setup_requested = false;
        self->cj_at_setup = cj;
        if (!self->factored) return SUNLS_PACKAGE_FAIL_REC;
      }
      auto solution = map(x);
      if (N_VGetArrayPointer_Serial(x) != N_VGetArrayPointer_Serial(b)) solution = map(b);
      self->system->solve_newton_system(cj, solution);
      ++self->solves;
      if (!solution.allFinite()) {
        self->factored = false;
        return SUNLS_PACKAGE_FAIL_REC;
      }
    } catch (const SolverError& e) {
      self->last_residual_message = e.what();
      self->factored = false;
      return SUNLS_PACKAGE_FAIL_REC;
    } catch (...) {
      self->fatal_exception = std::current_exception();
      return SUNLS_PACKAGE_FAIL_UNREC;
    }
    return SUNLS_SUCCESS;
  }

  // IDA's Newton convergence test (idaNlsConvTest, SUNDIALS 6.4.1) with the
  // bookkeeping IDA does only for linear solvers it sets up itself: with a
  // matrix-embedded solver IDA never calls a setup, so its rate estimate ss
  // is never reset and keeps whatever the first two-iteration solve
  // measured; a small ss then accepts every first Newton correction however
  // stale the matrix (measured on the OC4 line: ss = 1.3e-3 for the whole
  // run, first corrections up to 8× the tolerance, one iteration per step).
  // Here ss is reset to 20 after a full setup and to 100 when c_j changed
  // without a refresh, as IDA does, and kept over a partial update (the
  // rest of the matrix, whose rate was measured, is unchanged). Measured
  // effect: the energy drift of the undamped chain test falls 10× at rtol
  // 1e-8, and the OC4 benchmark's Newton divergences (rate > 0.9 after a
  // contact change) are caught instead of accepted.
  //
  // The same missing setup costs SUNDIALS' Newton its retry: when a solve
  // fails (rate > 0.9 or the iteration cap) on a matrix older than the step,
  // SUNNonlinSolSolve_Newton sets up again and iterates afresh — without a
  // setup to call it returns the failure, and IDA cuts the step 4×. Here the
  // test does the retry itself, once per solve: a full setup requested for
  // the next linear solve, the rate measured afresh from there. Unlike
  // SUNDIALS it keeps the iterate instead of going back to the predictor:
  // the corrections so far carry what the old matrix got right (on the
  // coupled lines, the node positions; what diverges is the fairlead slope,
  // whose small stiffness the old tangent mixes with EA·δε). Measured on the
  // default scenario with wave-frequency hull motion, 100 s: main 975 steps,
  // 44 failed solves, 17.7–18.9 s; keeping the iterate 957 steps, 23
  // restarts, 5 failed, 16.5–18.3 s; back to the predictor 787 steps but 144
  // restarts (longer steps, more stale divergences), 20.6–21.3 s
  // (docs/decisions/coupled-dynamics-performance.md).
  static int convergence_test(SUNNonlinearSolver nls, N_Vector, N_Vector del, realtype tol, N_Vector ewt, void* data) {
    auto* self = static_cast<Impl*>(data);
    const double norm = N_VWrmsNorm(del, ewt);
    int m = 0;
    if (SUNNonlinSolGetCurIter(nls, &m) != 0) return -1;
    if (m == 0) {
      self->restart_iteration = 0;
      self->matrix_current = self->refresh_since_test == Refresh::full;
    }
    const int iteration = m - self->restart_iteration;  // on the present matrix
    if (iteration == 0) {
      realtype cj = 0.0;
      IDAGetCurrentCj(self->ida, &cj);
      if (self->refresh_since_test == Refresh::full) {
        self->rate_factor = kRateFactorAfterSetup;
      } else if (self->refresh_since_test == Refresh::none && cj != self->cj_at_last_solve) {
        self->rate_factor = kRateFactorAfterCjChange;
      }
      self->refresh_since_test = Refresh::none;
      self->cj_at_last_solve = cj;
      self->first_correction_norm = norm;
      if (norm <= kImmediateConvergence * tol) return SUN_NLS_SUCCESS;
    } else {
      const double rate = std::pow(norm / self->first_correction_norm, 1.0 / iteration);
      if (rate > kMaxConvergenceRate) return self->restart_or_fail(m);
      self->rate_factor = rate / (1.0 - rate);
    }
    if (self->rate_factor * norm <= tol) return SUN_NLS_SUCCESS;
    return iteration + 1 < kNewtonIterationsPerMatrix ? SUN_NLS_CONTINUE : self->restart_or_fail(m);
  }

  int restart_or_fail(int iteration) {
    if (matrix_current || !options.restart_newton_on_fresh_matrix) return SUN_NLS_CONV_RECVR;
    setup_requested = true;
    matrix_current = true;
    restart_iteration = iteration + 1;
    ++newton_restarts;
    return SUN_NLS_CONTINUE;
  }

  static void error_handler(int, const char* module, const char* function, char* msg, void* user_data) {
    static_cast<Impl*>(user_data)->last_ida_message = fmt::format("{}/{}: {}", module, function, msg);
  }

  void check(int flag, const char* call) const {
    if (flag < 0) {
      throw SolverError(fmt::format("IDA setup: {} returned {} ({})", call, flag_name(flag), last_ida_message));
    }
  }
};

IdaIntegrator::IdaIntegrator(ImplicitSystem& system, double t0_s, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0,
                             const IdaOptions& options)
    : impl_(std::make_unique<Impl>()) {
  const Eigen::Index n = y0.size();
  if (n == 0 || yp0.size() != n) {
    throw std::invalid_argument(
        fmt::format("IDA: y0 and yp0 must be non-empty and of one size, got {} and {}", n, yp0.size()));
  }
  if (!y0.allFinite() || !yp0.allFinite() || !std::isfinite(t0_s)) {
    throw std::invalid_argument("IDA: the initial time, state and derivative must be finite");
  }
  if (!(options.relative_tolerance > 0.0) || !(options.absolute_tolerance > 0.0)) {
    throw std::invalid_argument(fmt::format("IDA: relative_tolerance and absolute_tolerance must be > 0, got {} and {}",
                                            options.relative_tolerance, options.absolute_tolerance));
  }
  if (options.absolute_tolerances &&
      (options.absolute_tolerances->size() != n || !(options.absolute_tolerances->array() > 0.0).all())) {
    throw std::invalid_argument(fmt::format("IDA: absolute_tolerances must have {} entries, all > 0", n));
  }
  if (options.differential_id && options.differential_id->size() != n) {
    throw std::invalid_argument(fmt::format("IDA: differential_id must have {} entries", n));
  }
  if (options.max_order < 1 || options.max_order > 5) {
    throw std::invalid_argument(fmt::format("IDA: max_order must be 1..5, got {}", options.max_order));
  }
  if ((options.max_step_s && !(*options.max_step_s > 0.0)) ||
      (options.initial_step_s && !(*options.initial_step_s > 0.0))) {
    throw std::invalid_argument("IDA: max_step_s and initial_step_s must be > 0 s");
  }
  if (options.max_steps_between_outputs <= 0 || options.max_steps_between_setups <= 0) {
    throw std::invalid_argument("IDA: max_steps_between_outputs and max_steps_between_setups must be > 0");
  }

  if (!options.error_group_starts.empty()) {
    const auto& g = options.error_group_starts;
    bool ok = g.front() == 0;
    for (std::size_t i = 1; i < g.size(); ++i) ok = ok && g[i] > g[i - 1];
    if (!ok || g.back() >= n)
      throw std::invalid_argument("IDA: error_group_starts must start at 0 and increase strictly below the state size");
  }

  Impl& m = *impl_;
  m.system = &system;
  m.options = options;
  m.error_groups = options.error_group_starts;
  m.y_out = y0;
  m.yp_out = yp0;
  m.t_out = t0_s;

  if (SUNContext_Create(nullptr, &m.context) != 0) throw SolverError("IDA setup: SUNContext_Create failed");
  const auto len = static_cast<sunindextype>(n);
  for (N_Vector* v : {&m.y, &m.yp}) {
    *v = N_VNew_Serial(len, m.context);
    if (*v == nullptr) throw SolverError("IDA setup: N_VNew_Serial failed");
    fast_nvector::install(*v);
  }
  Impl::map(m.y) = y0;
  Impl::map(m.yp) = yp0;

  m.ida = IDACreate(m.context);
  if (m.ida == nullptr) throw SolverError("IDA setup: IDACreate failed");
  m.check(IDASetErrHandlerFn(m.ida, &Impl::error_handler, &m), "IDASetErrHandlerFn");
  m.check(IDAInit(m.ida, &Impl::residual_callback, t0_s, m.y, m.yp), "IDAInit");
  m.check(IDASetUserData(m.ida, &m), "IDASetUserData");
  if (options.absolute_tolerances) {
    m.atol = N_VNew_Serial(len, m.context);
    if (m.atol == nullptr) throw SolverError("IDA setup: N_VNew_Serial failed");
    Impl::map(m.atol) = *options.absolute_tolerances;
    m.check(IDASVtolerances(m.ida, options.relative_tolerance, m.atol), "IDASVtolerances");
  } else {
    m.check(IDASStolerances(m.ida, options.relative_tolerance, options.absolute_tolerance), "IDASStolerances");
  }
  if (options.differential_id) {
    m.id = N_VNew_Serial(len, m.context);
    if (m.id == nullptr) throw SolverError("IDA setup: N_VNew_Serial failed");
    Impl::map(m.id) = *options.differential_id;
    m.check(IDASetId(m.ida, m.id), "IDASetId");
    m.check(IDASetSuppressAlg(m.ida, SUNTRUE), "IDASetSuppressAlg");
  }
  m.linear_solver = SUNLinSolNewEmpty(m.context);
  if (m.linear_solver == nullptr) throw SolverError("IDA setup: SUNLinSolNewEmpty failed");
  m.linear_solver->content = &m;
  m.linear_solver->ops->gettype = &Impl::solver_type;
  m.linear_solver->ops->solve = &Impl::solve_callback;
  m.check(IDASetLinearSolver(m.ida, m.linear_solver, nullptr), "IDASetLinearSolver");
  m.nonlinear_solver = SUNNonlinSol_Newton(m.y, m.context);
  if (m.nonlinear_solver == nullptr) throw SolverError("IDA setup: SUNNonlinSol_Newton failed");
  m.check(IDASetNonlinearSolver(m.ida, m.nonlinear_solver), "IDASetNonlinearSolver");
  // After IDASetNonlinearSolver, which installs IDA's own test.
  m.check(SUNNonlinSolSetConvTestFn(m.nonlinear_solver, &Impl::convergence_test, &m), "SUNNonlinSolSetConvTestFn");
  m.check(IDASetMaxNonlinIters(m.ida, 2 * kNewtonIterationsPerMatrix), "IDASetMaxNonlinIters");
  m.check(IDASetMaxOrd(m.ida, options.max_order), "IDASetMaxOrd");
  m.check(IDASetMaxNumSteps(m.ida, options.max_steps_between_outputs), "IDASetMaxNumSteps");
  if (options.max_step_s) m.check(IDASetMaxStep(m.ida, *options.max_step_s), "IDASetMaxStep");
  if (options.initial_step_s) m.check(IDASetInitStep(m.ida, *options.initial_step_s), "IDASetInitStep");
}

IdaIntegrator::~IdaIntegrator() = default;
IdaIntegrator::IdaIntegrator(IdaIntegrator&&) noexcept = default;
IdaIntegrator& IdaIntegrator::operator=(IdaIntegrator&&) noexcept = default;

void IdaIntegrator::advance_to(double t_out_s) {
  Impl& m = *impl_;
  if (!(t_out_s > m.t_out)) {
    throw std::invalid_argument(fmt::format("IDA: output time {} s must be after {} s", t_out_s, m.t_out));
  }
  realtype t_reached = m.t_out;
  fast_nvector::set_solve_context(m.options.vector_pool, m.error_groups.empty() ? nullptr : &m.error_groups);
  const int flag = IDASolve(m.ida, t_out_s, &t_reached, m.y, m.yp, IDA_NORMAL);
  fast_nvector::set_solve_context(nullptr, nullptr);
  if (m.fatal_exception) {
    std::exception_ptr e = std::exchange(m.fatal_exception, nullptr);
    std::rethrow_exception(e);
  }
  if (flag < 0) {
    realtype h = 0.0, t_cur = 0.0;
    IDAGetLastStep(m.ida, &h);
    IDAGetCurrentTime(m.ida, &t_cur);
    std::string msg =
        fmt::format("IDA failed at t = {:.6g} s (step {:.3g} s): {}; {}", t_cur, h, flag_name(flag), hint_for(flag));
    if (!m.last_residual_message.empty())
      msg += fmt::format(" (last residual/solver message: {})", m.last_residual_message);
    if (!m.last_ida_message.empty()) msg += fmt::format(" [{}]", m.last_ida_message);
    SolverDiagnostics d;
    d.iterations = static_cast<int>(statistics().steps);
    throw IntegrationError(msg, t_cur, h, flag, d);
  }
  m.t_out = t_reached;
  m.y_out = Impl::map(m.y);
  m.yp_out = Impl::map(m.yp);
}

void IdaIntegrator::set_stop_time(double tstop_s) {
  impl_->check(IDASetStopTime(impl_->ida, tstop_s), "IDASetStopTime");
}

double IdaIntegrator::time_s() const { return impl_->t_out; }
const Eigen::VectorXd& IdaIntegrator::state() const { return impl_->y_out; }
const Eigen::VectorXd& IdaIntegrator::state_derivative() const { return impl_->yp_out; }

std::vector<double> IdaIntegrator::group_local_errors() const {
  Impl& m = *impl_;
  const std::vector<Eigen::Index> starts = m.error_groups.empty() ? std::vector<Eigen::Index>{0} : m.error_groups;
  std::vector<double> out(starts.size(), 0.0);
  if (m.local_error == nullptr) {
    m.local_error = N_VClone(m.y);
    m.error_weight = N_VClone(m.y);
    if (m.local_error == nullptr || m.error_weight == nullptr) throw SolverError("IDA: N_VClone failed");
  }
  if (IDAGetEstLocalErrors(m.ida, m.local_error) != IDA_SUCCESS ||
      IDAGetErrWeights(m.ida, m.error_weight) != IDA_SUCCESS)
    return out;
  const auto error = fast_nvector::vec(m.local_error), weight = fast_nvector::vec(m.error_weight);
  for (std::size_t g = 0; g < starts.size(); ++g) {
    const Eigen::Index begin = starts[g], end = g + 1 < starts.size() ? starts[g + 1] : error.size();
    out[g] = error.segment(begin, end - begin).cwiseProduct(weight.segment(begin, end - begin)).cwiseAbs().maxCoeff();
  }
  return out;
}

IdaStatistics IdaIntegrator::statistics() const {
  const Impl& m = *impl_;
  IdaStatistics s;
  IDAGetNumSteps(m.ida, &s.steps);
  IDAGetNumResEvals(m.ida, &s.residual_evaluations);
  IDAGetNumErrTestFails(m.ida, &s.error_test_failures);
  IDAGetNumNonlinSolvIters(m.ida, &s.nonlinear_iterations);
  IDAGetNumNonlinSolvConvFails(m.ida, &s.nonlinear_convergence_failures);
  realtype h = 0.0, t = 0.0;
  IDAGetLastStep(m.ida, &h);
  IDAGetCurrentTime(m.ida, &t);
  IDAGetLastOrder(m.ida, &s.last_order);
  s.last_step_s = h;
  s.current_time_s = t;
  s.newton_matrix_setups = m.setups;
  s.newton_matrix_updates = m.updates;
  s.linear_solves = m.solves;
  s.recoverable_residual_failures = m.recoverable_failures;
  s.newton_restarts = m.newton_restarts;
  return s;
}

}  // namespace spiral::engine
