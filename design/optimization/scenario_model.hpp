#pragma once
// One scenario of the pretension optimization — a load case, intact or with
// one mooring line removed — as a static model built once and evaluated at
// many payout vectors: the coupled equilibrium of hull and lines (risers
// included, with the case's current), and what the constraints need from it
// with their derivatives with respect to the group payouts.
//
// Sensitivities (catenary mooring lines). At the equilibrium R(q, ΔL) = 0 of
// the hull displacement q (δu, δθ), the implicit-function theorem gives
//   dq/dΔL_g = K_t⁻¹ Σ_{i ∈ g} ∂F_i/∂L_i,   K_t = K_hydrostatic + K_lines T − ∂F_env/∂q,
// q the offset with roll, pitch and yaw (the equilibrium's unknowns), K_lines
// the analytic line-array tangent the equilibrium already has (line_array.hpp,
// per small global rotation ω, hence T = dω/d(roll, pitch, yaw)), ∂F_env/∂q by central differences of the mean
// environmental load (a function evaluation, no solve), and each line's
// ∂F_i/∂L_i from its catenary tangent (engine/lines/catenary_payout.hpp). A
// line's fairlead then moves by δu + δθ × a_i, which changes its fairlead
// forces through the same tangent, and a point lower on the line carries the
// added weight w_top δL. Tensions, utilizations and laid lengths follow
// without another equilibrium: one solve per evaluation instead of 2 per
// group for central differences. Points resting on the seabed take the
// horizontal tension's change (friction's shift of the touchdown point is
// neglected: such points do not govern a line's utilization in practice).
//
// A scenario with FE mooring lines (`model: fe`) has no catenary tangent:
// its gradients are central differences of whole equilibria (slower, same
// results to the solver tolerance).

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "design/model/hull_model.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/payout_groups.hpp"
#include "design/project/project.hpp"
#include "engine/analysis/static_equilibrium.hpp"

namespace spiral::design {

/// A load case in one line-integrity condition.
struct Scenario {
  std::string case_name;
  std::optional<std::string> damaged_line;
  DesignCondition condition = DesignCondition::extreme;  ///< of the load case (riser design factor)
  /// The line was removed by the study (damaged: every_line), not by the load case itself.
  bool removed_by_study = false;
  /// The label tables and messages use: the case, or "case without L3" for a line the study removed.
  std::string label() const;
};

/// A line's quantities at the scenario's equilibrium, with their gradients
/// over the group payouts (empty without gradients).
struct LineResponse {
  std::string name;
  double fairlead_tension_N = 0.0;
  /// Largest over the segments of T_max · SF / MBL, SF the code's
  /// quasi-static factor for the scenario's integrity (mooring_checks.hpp).
  double utilization = 0.0;
  std::string governing_segment_type;
  double laid_length_m = 0.0;
  Eigen::VectorXd d_fairlead_tension_N;
  Eigen::VectorXd d_utilization;
  Eigen::VectorXd d_laid_length_m;
};

struct ScenarioResponse {
  engine::Vector6d offset = engine::Vector6d::Zero();  ///< m, rad
  /// d(offset x, y)/dΔL per group (rows x, y), m/m; empty without gradients.
  Eigen::Matrix<double, 2, Eigen::Dynamic> d_horizontal_offset;
  std::vector<LineResponse> lines;  ///< the scenario's mooring lines, project order
  int equilibrium_iterations = 0;
};

class ScenarioModel {
 public:
  /// Builds the scenario's lines (risers with the case's current). `hull`
  /// and `groups` must outlive the model. `environment_load`: the mean
  /// environmental load on the hull in the case's environment
  /// (mean_environment_load; computed here when empty), which the scenarios
  /// of one environment can share: its drift integral costs more than
  /// building the scenario's lines.
  ScenarioModel(const Project& project, const HullModel& hull, const std::vector<PayoutGroup>& groups,
                Scenario scenario, engine::ExternalLoad environment_load = {});
  ScenarioModel(ScenarioModel&&) noexcept;
  ~ScenarioModel();

  const Scenario& scenario() const { return scenario_; }

  /// The equilibrium at `payouts_m` (one per group), warm-started from the
  /// previous one. Throws engine::SolverError naming the scenario.
  ScenarioResponse evaluate(const Eigen::VectorXd& payouts_m, bool with_gradient);

  /// Starts the next evaluation from `source`'s last equilibrium: its hull
  /// offset and its risers' FE solutions. `source` must be in the same
  /// environment (same risers, same current), already evaluated.
  void start_from(const ScenarioModel& source);
  /// Only the risers: they start warm from `source`'s last solutions (same
  /// requirements); the hull's start stays.
  void start_risers_from(const ScenarioModel& source);

  /// The hull's equilibrium at `payouts_m` with the FE risers linearized
  /// where they were last solved (no riser solve); the next evaluate()
  /// starts its full solve there. None before the first evaluation, without
  /// FE risers, or when that linear solve fails (evaluate() then starts
  /// where the last one ended).
  std::optional<engine::HullPose> predict(const Eigen::VectorXd& payouts_m);
  /// The FE risers' tops at `pose`, in line order.
  std::vector<Eigen::Vector3d> riser_tops_g(const engine::HullPose& pose) const;
  /// Where the FE risers were last solved, in line order; empty if any has
  /// no solution.
  std::vector<Eigen::Vector3d> solved_riser_tops_g() const;
  /// Gives the risers' last solutions their end stiffness (no new solve:
  /// engine::with_end_B_stiffness), so that the scenarios that start_from
  /// this one linearize them without a factorisation each.
  void complete_expensive_lines();

  /// Replaces every expensive line that is not a variable (the FE risers) by
  /// its linearization about where the last evaluation left it
  /// (engine/analysis/linearized_line.hpp); restore_expensive_lines() puts
  /// the full lines back, warm starts intact. For the optimizer's inner
  /// iterations: the hull moves little between them, and the risers' force
  /// changes are small and smooth against the mooring's.
  void linearize_expensive_lines();
  void restore_expensive_lines();

  /// Same, gradients always by central differences of whole equilibria with
  /// payout step `step_m` (the reference the analytic gradients are tested
  /// against, and the route for FE mooring lines).
  ScenarioResponse evaluate_by_differences(const Eigen::VectorXd& payouts_m, double step_m = 5e-2);

 private:
  /// predict()'s offset, without keeping it.
  std::optional<engine::Vector6d> predicted_offset(const Eigen::VectorXd& payouts_m);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  Scenario scenario_;
};

}  // namespace spiral::design
