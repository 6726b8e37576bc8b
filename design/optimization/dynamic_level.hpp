#pragma once
// The dynamic level of the pretension optimization (`spiral optimize --level
// sc-enhanced`): the constraints of pretension_optimizer.hpp on the 3-h
// extremes of each scenario's enhanced S-C storm instead of its static
// equilibrium — the MPM of the offset ratio |d(t)| / A(θ(t)) against the
// platform SOZ (Weibull, the extreme-offset rule of soz_check.cpp), the MPM
// offset against the offset limit, and each line's dynamic code check on its
// mean and MPM tension (mooring_checks.hpp; Gumbel MPM, as the stages).
// Each evaluation runs one storm per scenario with the payouts applied to
// the project (same sea, same seed, every evaluation): no gradients, so the
// optimizer uses COBYLA.

#include <cstdint>
#include <memory>
#include <vector>

#include "design/optimization/pretension_problem.hpp"

namespace spiral::design {

class DynamicLevel {
 public:
  DynamicLevel(const ValidatedProject& project, DynamicLevelOptions options, int threads);

  /// Replaces the static constraints and objective measures of `evaluation`
  /// by the dynamic ones of every scenario (no gradients) and fills its
  /// `dynamic` measures.
  void apply(const PretensionProblem& problem, const Eigen::VectorXd& payouts_m, ProblemEvaluation& evaluation) const;

 private:
  const ValidatedProject& project_;
  DynamicLevelOptions options_;
  int threads_ = 1;
};

}  // namespace spiral::design
