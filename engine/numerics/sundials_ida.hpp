#pragma once
// A thin RAII adapter around SUNDIALS IDA (6.4.1, serial N_Vector) for
// implicit differential(-algebraic) systems F(t, y, y') = 0 whose Newton
// matrix J = ∂F/∂y + c_j ∂F/∂y' the system factors and solves itself
// (IDA's "matrix-embedded" linear solver, IDA user guide §"SUNLinearSolver:
// matrix-embedded"): a structural model knows its matrix structure (banded
// per line, a second-order reduction, a Schur complement for a hull) far
// better than a generic SUNMatrix.
//
// Method: variable-order, variable-step BDF (orders 1..5, IDA user guide
// "Mathematical considerations"). For undamped oscillatory systems orders
// above 2 are not A-stable (their stability regions miss part of the
// imaginary axis), so structural models usually cap the order at 2, where
// BDF is A-stable and damps unresolved high-frequency modes.
//
// Newton matrix updates. With a matrix-embedded solver IDA calls no setup;
// the adapter decides when the system refreshes its factorisation (the rule
// of IDA's own direct solvers, with their default thresholds): a full setup
// before the first solve, after a nonlinear convergence failure and at least
// every `max_steps_between_setups` steps; an update (the system may reuse
// what did not change) when c_j has changed by more than 25 % since the last
// refresh (IDASetDeltaCjLSetup default) or the system reports its matrix
// stale (newton_matrix_stale: a contact set that changed, say).
//
// A Newton solve that fails (diverges, or reaches the iteration cap) on a
// matrix set up before this step goes on once from its iterate with a full
// setup there, as SUNDIALS' Newton solver retries for the linear solvers that
// have a setup function; only a failure on a current matrix fails the step.
//
// Newton convergence test: IDA's own (rate-based, ss·|δ| ≤ 0.33), with the
// rate estimate ss reset as IDA resets it for the solvers it sets up itself
// — 20 after a full setup, 100 when c_j changed without a refresh — and
// kept over a partial update. IDA skips these resets for a matrix-embedded
// solver, so without them ss keeps the value of the first two-iteration
// solve for the whole run and first corrections far above the tolerance are
// accepted unchecked (docs/decisions/ida-convergence-test.md).
//
// Residual errors, as in the CVODE adapter: a SolverError or a non-finite
// residual is recoverable (IDA retries with a smaller step); any other
// exception is fatal and rethrown after IDASolve returns. IDA failures throw
// IntegrationError (engine/numerics/sundials_cvode.hpp) with the time
// reached, the last step and a hint.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/numerics/sundials_cvode.hpp"

namespace spiral::engine {

class WorkerPool;

/// F(t, y, y') = 0 with its own Newton-matrix solver.
using VectorConstRef = Eigen::Ref<const Eigen::VectorXd>;
using VectorRef = Eigen::Ref<Eigen::VectorXd>;

class ImplicitSystem {
 public:
  virtual ~ImplicitSystem() = default;
  /// r = F(t, y, y') (r has the size of y; the integrator's own vectors,
  /// not copies). May throw SolverError (recoverable).
  virtual void residual(double t, const VectorConstRef& y, const VectorConstRef& yp, VectorRef r) = 0;
  /// Builds and factors (an approximation of) J = ∂F/∂y + cj ∂F/∂y' at
  /// (t, y, y'). Returns false if it cannot (singular): IDA then retries
  /// with a smaller step.
  virtual bool setup_newton_matrix(double t, const VectorConstRef& y, const VectorConstRef& yp, double cj) = 0;
  /// Solves J x = b in place with the last factorisation; cj is IDA's
  /// current value (it may differ from the one of the setup).
  virtual void solve_newton_system(double cj, Eigen::Ref<Eigen::VectorXd> b) = 0;
  /// Asked before each Newton solve, after the residual at the current
  /// iterate: true if the last factorisation no longer fits the system there
  /// (a contact set that changed, say); the adapter then updates it.
  virtual bool newton_matrix_stale() { return false; }
  /// Refactors for a new cj and for what newton_matrix_stale reported,
  /// reusing the rest of the last setup (the adapter still calls
  /// setup_newton_matrix before the first solve, after a nonlinear
  /// convergence failure and every max_steps_between_setups steps). Default:
  /// a full setup.
  virtual bool update_newton_matrix(double t, const VectorConstRef& y, const VectorConstRef& yp, double cj) {
    return setup_newton_matrix(t, y, yp, cj);
  }
};

struct IdaOptions {
  double relative_tolerance = 1e-6;                    ///< > 0
  double absolute_tolerance = 1e-8;                    ///< > 0, used if no vector
  std::optional<Eigen::VectorXd> absolute_tolerances;  ///< per state, > 0
  /// Per state: 1 differential, 0 algebraic. Algebraic states are left out of
  /// the local error test (IDASetSuppressAlg).
  std::optional<Eigen::VectorXd> differential_id;
  /// Block error norms: the states split into groups at these indices
  /// (strictly increasing, the first 0); every norm IDA takes (local error
  /// test, Newton convergence) is then the largest of the groups' own WRMS
  /// norms, so each block meets the tolerance by itself however many states
  /// the others have (the one WRMS norm over all N states would let one
  /// block's error through diluted by √(N / n_block)). Empty: one group.
  std::vector<Eigen::Index> error_group_starts;
  /// Threads for IDA's own vector operations over the states (not owned;
  /// it must outlive the integrator and be idle while IDA runs — the
  /// system's own pool between its loops): elementwise ones split into one
  /// range per thread, the block norms one block per task, so the results
  /// are the same with or without it. Null: on the calling thread.
  WorkerPool* vector_pool = nullptr;
  int max_order = 5;                        ///< 1..5
  std::optional<double> max_step_s;         ///< > 0
  std::optional<double> initial_step_s;     ///< > 0
  long max_steps_between_outputs = 500000;  ///< > 0
  int max_steps_between_setups = 20;        ///< > 0: Newton matrix refreshed at least this often
  /// A Newton solve that fails on a matrix older than the step goes on once
  /// on a fresh one instead of failing the step (what SUNDIALS' Newton does
  /// when it has a setup to call; see the header).
  bool restart_newton_on_fresh_matrix = true;
};

struct IdaStatistics {
  long steps = 0;
  long residual_evaluations = 0;
  long newton_matrix_setups = 0;   ///< factorisations (the "Jacobian evaluations")
  long newton_matrix_updates = 0;  ///< of those, partial ones (update_newton_matrix)
  long linear_solves = 0;
  long error_test_failures = 0;
  long nonlinear_iterations = 0;
  long nonlinear_convergence_failures = 0;  ///< Newton solves that failed (each a step retried smaller)
  long newton_restarts = 0;                 ///< Newton solves restarted on a fresh matrix (not failures)
  long recoverable_residual_failures = 0;
  double last_step_s = 0.0;
  double current_time_s = 0.0;
  int last_order = 0;
};

/// One IDA integration of a system (not owned: it must outlive the
/// integrator). Not thread-safe: one integrator per thread.
class IdaIntegrator {
 public:
  /// y0, yp0: consistent initial values (F(t0, y0, yp0) ≈ 0). Throws
  /// std::invalid_argument for bad sizes, non-finite values or options.
  IdaIntegrator(ImplicitSystem& system, double t0_s, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0,
                const IdaOptions& options = {});
  ~IdaIntegrator();
  IdaIntegrator(IdaIntegrator&&) noexcept;
  IdaIntegrator& operator=(IdaIntegrator&&) noexcept;
  IdaIntegrator(const IdaIntegrator&) = delete;
  IdaIntegrator& operator=(const IdaIntegrator&) = delete;

  /// Integrates to t_out_s (> the last output time); y, y' at t_out_s are
  /// then state() and state_derivative() (interpolated by IDA). Throws
  /// IntegrationError or the residual's fatal exception.
  void advance_to(double t_out_s);
  /// IDA will not step past tstop_s (IDASetStopTime).
  void set_stop_time(double tstop_s);

  double time_s() const;
  const Eigen::VectorXd& state() const;
  const Eigen::VectorXd& state_derivative() const;
  IdaStatistics statistics() const;
  /// Per error group (IdaOptions::error_group_starts; one group without
  /// them) the largest |local error estimate| × error weight of its states
  /// at the last step (IDAGetEstLocalErrors, IDAGetErrWeights): which block
  /// limits the step, or made it collapse. Zeros before the first step.
  std::vector<double> group_local_errors() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace spiral::engine
