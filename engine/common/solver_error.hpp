#pragma once
// The one exception type the engine throws when a numerical method cannot
// produce a physical answer (impossible geometry, no convergence). It carries
// what the caller needs to say which line/case failed, how far the solver got
// and what to try; the engine never returns NaN as a result.

#include <stdexcept>
#include <string>

namespace spiral::engine {

struct SolverDiagnostics {
  int iterations = 0;         ///< iterations performed before giving up
  double residual = 0.0;      ///< last residual norm, in the solver's stated unit
  std::string residual_unit;  ///< unit of `residual` (e.g. "m")
};

class SolverError : public std::runtime_error {
 public:
  SolverError(const std::string& message, SolverDiagnostics diagnostics = {})
      : std::runtime_error(message), diagnostics_(std::move(diagnostics)) {}
  const SolverDiagnostics& diagnostics() const { return diagnostics_; }

 private:
  SolverDiagnostics diagnostics_;
};

}  // namespace spiral::engine
