#pragma once
// A thin RAII adapter around SUNDIALS CVODE (6.4.1, serial N_Vector) for
// ordinary differential equations y' = f(t, y) with a dense state of a few to
// a few hundred entries (STYLE.md rule 4).
//
// Methods (CVODE user guide, "Mathematical considerations"):
//   bdf_newton_dense   variable-order BDF (1..5), Newton iteration with a dense
//                      difference-quotient Jacobian: stiff problems.
//   adams_newton_dense variable-order Adams–Moulton (1..12), Newton + dense
//                      Jacobian: non-stiff problems with tight tolerances.
//   adams_fixed_point  Adams–Moulton with fixed-point ("functional")
//                      iteration: non-stiff problems, no Jacobian at all.
//
// Right-hand side errors. The RHS is a std::function that may throw:
//   * SolverError (e.g. a line solver that does not converge at a trial state
//     of a too-large step) and a non-finite derivative are *recoverable*: the
//     callback returns +1 and CVODE retries with a smaller step;
//   * any other exception is *fatal*: the callback returns −1, CVODE stops,
//     and the adapter rethrows the original exception after CVode returns.
// If CVODE gives up after repeated recoverable failures, an IntegrationError
// is thrown whose text includes the last stored RHS message.
//
// Failures of the integrator itself (CV_TOO_MUCH_WORK, CV_ERR_FAILURE,
// CV_CONV_FAILURE, step size collapse …) throw IntegrationError (a
// SolverError) with the time reached, the last step size and a hint.
// Invalid options throw std::invalid_argument.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "engine/common/solver_error.hpp"

namespace spiral::engine {

/// y' = f(t, y): writes ydot (already sized like y). t in s.
using OdeRightHandSide = std::function<void(double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot)>;

enum class CvodeMethod { bdf_newton_dense, adams_newton_dense, adams_fixed_point };

/// Options of one CVODE run. Tolerances follow CVODE's weighted RMS norm:
/// the local error of y_i is kept below rtol·|y_i| + atol_i.
struct CvodeOptions {
  CvodeMethod method = CvodeMethod::adams_newton_dense;
  double relative_tolerance = 1e-8;                    ///< > 0 (CVODE warns below ~1e-15)
  double absolute_tolerance = 1e-10;                   ///< > 0, in the unit of every state; used if no vector
  std::optional<Eigen::VectorXd> absolute_tolerances;  ///< per state, > 0, size of y
  std::optional<double> max_step_s;                    ///< > 0; none = unbounded
  std::optional<double> initial_step_s;                ///< > 0; none = CVODE's estimate
  long max_steps_between_outputs = 500000;             ///< CVodeSetMaxNumSteps (> 0)
  std::optional<int> max_order;                        ///< CVodeSetMaxOrd: 1..5 (BDF), 1..12 (Adams); none = maximum
};

/// Counters of a CVODE run (cumulative since construction).
struct CvodeStatistics {
  long steps = 0;                           ///< internal time steps
  long rhs_evaluations = 0;                 ///< f(t, y) calls by the integrator
  long jacobian_evaluations = 0;            ///< dense Jacobian evaluations (Newton only)
  long rhs_evaluations_for_jacobian = 0;    ///< f calls spent on difference-quotient Jacobians
  long error_test_failures = 0;             ///< local error test failures
  long nonlinear_iterations = 0;            ///< Newton / fixed-point iterations
  long nonlinear_convergence_failures = 0;  ///< nonlinear solver convergence failures
  long recoverable_rhs_failures = 0;        ///< RHS calls that returned +1
  double last_step_s = 0.0;                 ///< last internal step size used
  double current_time_s = 0.0;              ///< time reached by the integrator
  int last_order = 0;                       ///< method order of the last step
};

/// CVODE failed: carries how far it got.
class IntegrationError : public SolverError {
 public:
  IntegrationError(const std::string& message, double time_reached_s, double last_step_s, int cvode_flag,
                   SolverDiagnostics diagnostics)
      : SolverError(message, std::move(diagnostics)),
        time_reached_s_(time_reached_s),
        last_step_s_(last_step_s),
        cvode_flag_(cvode_flag) {}
  double time_reached_s() const { return time_reached_s_; }
  double last_step_s() const { return last_step_s_; }
  int cvode_flag() const { return cvode_flag_; }

 private:
  double time_reached_s_;
  double last_step_s_;
  int cvode_flag_;
};

/// One CVODE integration. Owns the SUNContext, N_Vector, dense matrix, linear
/// solver and CVODE memory; not copyable, movable. Not thread-safe: one
/// integrator per thread (the RHS may run load cases in parallel with its
/// own integrators).
class CvodeIntegrator {
 public:
  /// Throws std::invalid_argument for an empty y0, non-finite y0 / t0 or
  /// invalid options; SolverError if a SUNDIALS object cannot be created.
  CvodeIntegrator(OdeRightHandSide rhs, double t0_s, const Eigen::VectorXd& y0, const CvodeOptions& options = {});
  ~CvodeIntegrator();
  CvodeIntegrator(CvodeIntegrator&&) noexcept;
  CvodeIntegrator& operator=(CvodeIntegrator&&) noexcept;
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  /// Integrates to t_out_s (> current output time) and returns y(t_out_s),
  /// interpolated by CVODE from its internal steps (which may pass t_out_s
  /// unless a stop time holds them). Throws IntegrationError or the RHS's
  /// fatal exception.
  const Eigen::VectorXd& advance_to(double t_out_s);

  /// CVODE will not step past tstop_s (>= its internal time): set it where
  /// the RHS changes, e.g. at a history update. Reaching it ends one advance.
  void set_stop_time(double tstop_s);

  double time_s() const;
  const Eigen::VectorXd& state() const;
  CvodeStatistics statistics() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A solution sampled at output times: states(:, k) = y(times_s(k)).
struct OdeSolution {
  Eigen::VectorXd times_s;
  Eigen::MatrixXd states;  ///< n_states × n_times
  CvodeStatistics statistics;
};

/// Integrates from (t0, y0) and samples y at every output time (strictly
/// increasing, all > t0; an output time equal to t0 is returned as y0).
OdeSolution integrate_ode(const OdeRightHandSide& rhs, double t0_s, const Eigen::VectorXd& y0,
                          std::span<const double> output_times_s, const CvodeOptions& options = {});

}  // namespace spiral::engine
