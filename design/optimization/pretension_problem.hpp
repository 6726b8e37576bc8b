#pragma once
// The pretension optimization problem of a project, shared by the optimizer
// and the pretension study: the variables (groups and bounds), the scenarios
// (load cases × line integrity), the platform zones they are checked
// against, and the constraints and objective measures at a payout vector,
// with gradients (pretension_optimizer.hpp for their definitions).

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "design/model/hull_model.hpp"
#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/smooth_zone.hpp"

namespace spiral::design {

/// A constraint g ≤ 0 (ratios − 1) holds within this: 1e-6 of a ratio is
/// micrometres of offset and newtons of tension, below what the equilibrium
/// (1e-9 relative) and the catenary (1e-9 m) resolve in the outputs.
inline constexpr double kConstraintTolerance = 1e-6;

/// The optimizer holds every constraint this far inside its limit (g ≤ −1e-5,
/// a thousandth of a percent of utilization or offset ratio), so that the
/// design it writes — lengths printed to 0.1 mm, solved again by the stages'
/// own equilibria — still passes a check the optimum makes active (spiral
/// run's feedback checks it with g ≤ 0, without tolerance).
inline constexpr double kDesignMargin = 1e-5;

/// A function of the payouts with its gradient (per group, 1/m).
struct Measure {
  ConstraintValue value;
  Eigen::VectorXd gradient;
};

/// A scenario's dynamic measures (dynamic level), for its summary.
struct DynamicScenarioMeasures {
  double mpm_offset_m = 0.0;
  std::optional<double> mpm_soz_ratio;
  double worst_utilization = 0.0;
  std::string worst_line;
};

struct ProblemEvaluation {
  std::vector<ScenarioResponse> responses;       ///< per scenario (static equilibria)
  std::vector<DynamicScenarioMeasures> dynamic;  ///< per scenario, dynamic level only
  std::vector<Measure> constraints;              ///< g ≤ 0
  /// The quantities the minimax objective bounds (empty for min_total_payout).
  std::vector<Measure> objective_measures;
};

class DynamicLevel;

class PretensionProblem {
 public:
  PretensionProblem(const ValidatedProject& project, const OptimizationRequest& request);
  ~PretensionProblem();

  const Project& project() const { return project_; }
  const Optimization& settings() const { return settings_; }
  const std::vector<GroupVariable>& groups() const { return groups_; }
  const std::vector<Scenario>& scenarios() const { return scenarios_; }
  const std::vector<std::string>& findings() const { return findings_; }
  const std::vector<std::string>& notes() const { return notes_; }
  double zone_conservatism_m() const { return zone_conservatism_m_; }
  double zone_wall_s() const { return zone_wall_s_; }
  /// What the objective measures are in (the history's objective column).
  std::string objective_unit() const;

  /// Every scenario at `payouts_m` (in parallel), with the constraints and
  /// measures. Gradients when asked. Throws engine::SolverError naming the
  /// scenario.
  ProblemEvaluation evaluate(const Eigen::VectorXd& payouts_m, bool with_gradient);

  /// The objective at an evaluation (for minimax: the largest measure).
  double objective_of(const ProblemEvaluation& evaluation, const Eigen::VectorXd& payouts_m) const;

  /// The scenario's summary at an evaluation (with the dynamic measures when it has them).
  ScenarioSummary summarize(std::size_t scenario, const ProblemEvaluation& evaluation) const;

  /// The zone scenario `s` is checked against (none: no risers, or no zone),
  /// and the riser governing it at direction θ (rad).
  const SmoothZone* zone_of(std::size_t s) const { return zones_[s].zone.get(); }
  std::string governing_riser(std::size_t s, double direction_rad) const;
  bool dynamic() const { return dynamic_ != nullptr; }

  /// Every distinct zone, sampled every 2°.
  std::vector<ZoneOutline> zone_outlines() const;

  /// Whether any scenario has expensive lines that are not variables (FE risers).
  bool has_expensive_lines() const;
  /// ScenarioModel::linearize_expensive_lines / restore_expensive_lines of every scenario.
  void linearize_expensive_lines();
  void restore_expensive_lines();

 private:
  /// The environment of scenario `s` (scenarios of one environment share
  /// their risers: same models, same current).
  const std::string& environment_of(std::size_t s) const;
  /// Evaluates scenarios `which` (each already evaluated once, or started
  /// from another) in waves of warm starts (warm_start_plan.hpp). False,
  /// with nothing solved, when a scenario's risers have no solution to plan
  /// from (they then start from their own state).
  bool evaluate_in_waves(const std::vector<std::size_t>& which, const Eigen::VectorXd& payouts_m, bool with_gradient,
                         ProblemEvaluation& out);

  struct ZoneOfScenario {
    std::string name;
    std::shared_ptr<const SmoothZone> zone;  ///< none: no risers, or the zone was dropped (findings)
    std::vector<double> directions_deg;
    std::vector<std::string> governing_riser;
  };
  const Project& project_;
  Optimization settings_;
  std::vector<PayoutGroup> payout_groups_;
  std::vector<GroupVariable> groups_;
  std::vector<Scenario> scenarios_;
  std::vector<ZoneOfScenario> zones_;
  std::vector<ScenarioModel> models_;
  /// False until the models' first evaluation, which starts each scenario
  /// the study removed a line from at its load case's intact equilibrium.
  bool models_started_ = false;
  bool linearized_ = false;  ///< between linearize_expensive_lines() and restore_expensive_lines()
  std::unique_ptr<DynamicLevel> dynamic_;
  HullModel hull_;
  std::vector<std::string> findings_, notes_;
  double zone_conservatism_m_ = 0.0;
  double zone_wall_s_ = 0.0;
  int threads_ = 1;

  void build_models();
  void add_scenario_constraints(std::size_t s, const ScenarioResponse& r, bool with_gradient,
                                ProblemEvaluation& out) const;
};

}  // namespace spiral::design
