#pragma once
// Internal to the FE line statics (not a public engine API): the discrete
// problem — mesh, DOF map and element properties built once per solve (the
// workspace), its assembly and the state helpers shared by the Newton
// driver (fe_line_newton) and the entry point (fe_line_statics).

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "engine/common/banded_lu.hpp"
#include "engine/lines/ancf_cable_element.hpp"
#include "engine/lines/fe_line_statics.hpp"

namespace spiral::engine {

/// Factorised Jacobian of a converged FE line state (with the prescribed
/// DOFs' rows replaced by identity rows), handed from one solve to the next
/// warm-started one (FeStaticsResult::tangent → FeStaticsOptions::
/// warm_start_tangent).
struct FeLineTangent {
  BandMatrix lu;
};

}  // namespace spiral::engine

namespace spiral::engine::fe_detail {

inline constexpr int kElementDofs = 12;  // [r_a, r'_a, r_b, r'_b]
using ElementState = Eigen::Matrix<double, kElementDofs, 1>;

// Penetrations below this fraction of the line length are round-off (an
// anchor placed exactly on the seabed), not contact.
inline constexpr double kContactRoundOff = 1e-12;

struct Mesh {
  std::vector<double> s;                            // node arc lengths
  std::vector<int> section;                         // section of each element
  std::vector<std::pair<int, double>> point_loads;  // (node, downward N)
};

/// Everything the residual needs, built once per solve (workspace).
struct Problem {
  Mesh mesh;
  std::vector<ancf::ElementProperties> elements;
  ancf::LoadContext load;
  int n_nodes = 0;
  int n_dofs = 0;
  double line_length_m = 0.0;
  double load_scale_N = 0.0;          // total |weight| + |point loads| + drag estimate
  std::vector<double> node_length_m;  // mean adjacent element length (slope residual scale)
  // DOF map. Each node has a position r and a slope r'; at a section joint
  // that is a hinge (see make_problem) the two elements have their own
  // slopes: t_in is the one of the element ending at the node, t_out of the
  // element starting there (equal elsewhere). Indices of 3-blocks.
  std::vector<int> r_dof, t_in, t_out;
  std::vector<char> fixed;        // per DOF: prescribed (end positions)
  std::vector<double> dof_scale;  // per DOF: 1 (forces) or 1/h (slope residuals, N·m → N)
  int band = 11;                  // half bandwidth
  std::vector<double> EA_true_N;  // per element: the model's EA (elements[e].EA_N may be capped in a stage)
  // Smallest force residual double precision can resolve: an element force
  // EA (|r'| − 1) with r' from coordinates of size R over a length h carries
  // an error ≈ ε EA R / h; ten times that is accepted as converged.
  double round_off_floor_N = 0.0;
};

/// The factorised Jacobian the Newton iterations step with (workspace of one
/// solve): kept across iterations, continuation stages and touchdown
/// re-solves, and seeded from a warm start (modified Newton, see
/// fe_line_newton.cpp). valid: factor() is a factorisation usable for a step.
struct Tangent {
  /// The factorisation chord steps use: the warm start's (borrowed, not
  /// copied: a band LU is most of a solve's memory traffic) until the solve
  /// factorises a Jacobian of its own.
  const BandMatrix& factor() const { return borrowed ? borrowed->lu : lu; }
  /// The matrix to assemble and factorise a fresh Jacobian into.
  BandMatrix& own() {
    borrowed.reset();
    return lu;
  }
  BandMatrix lu;
  std::shared_ptr<const FeLineTangent> borrowed;
  bool valid = false;
  /// Chord steps allowed: in warm-started solves only. A cold solve goes
  /// through continuations (seabed stiffness, current, axial stiffness)
  /// whose stage decisions depend on how far below the tolerance each stage
  /// lands and on the per-stage iteration budgets; chord steps change both
  /// and made some cold solves take more stages
  /// (docs/decisions/fe-line-statics.md), so cold solves keep full Newton.
  bool chord_steps = false;
  int evaluations = 0;  // Jacobian assemblies + factorisations
  /// The state the last Newton solve converged at and its residual g(q):
  /// the result's end forces and node residuals without assembling g again
  /// (post_process), when the state is still that one.
  Eigen::VectorXd converged_q, converged_residual;
};

/// Throws SolverError("FE line statics: invalid input: " + what).
[[noreturn]] void invalid(const std::string& what);
/// Validation pass: every field with its rule (SolverError naming field and value).
void validate(const FeLineModel& m, const FeEnvironment& env, const FeLineEnds& ends, const FeStaticsOptions& o);
Mesh build_mesh(const FeLineModel& m);
Problem make_problem(const FeLineModel& m, const FeEnvironment& env, const FeLineEnds& ends);
/// Element lengths and residual scales from p.mesh.s (after a node moved).
void update_lengths(Problem& p);
/// Adopts node arc lengths of an earlier solution of the same model.
void set_node_arc_lengths(Problem& p, const std::vector<double>& s);
/// First DOF of each 3-block of element e: r_a, r'_a, r_b, r'_b.
std::array<int, 4> element_blocks(const Problem& p, std::size_t e);
ElementState gather(const Problem& p, const Eigen::VectorXd& q, std::size_t e);
inline bool is_fixed(const Problem& p, int dof) { return p.fixed[static_cast<std::size_t>(dof)] != 0; }
/// Net generalised forces g(q) and, if jac != nullptr, ∂g/∂q (band storage);
/// drag_jacobian false: the drag enters the Jacobian as a dead load. Returns
/// false if a non-finite value appears.
bool assemble(const Problem& p, const Eigen::VectorXd& q, Eigen::VectorXd& g, BandMatrix* jac,
              bool drag_jacobian = true);
/// Max |residual| over free DOFs (slope residuals / element length), N.
double residual_norm(const Problem& p, const Eigen::VectorXd& g);
/// Sum of squares of the scaled free residuals (line-search merit), N².
double merit(const Problem& p, const Eigen::VectorXd& g);
/// Largest |EA (|r'| − 1)| at element ends, N.
double max_axial_force(const Problem& p, const Eigen::VectorXd& q);
/// Warm state, given shape or default catenary; ends set to their positions.
Eigen::VectorXd initial_state(Problem& p, const FeLineModel& m, const FeEnvironment& env, const FeLineEnds& ends,
                              const FeStaticsOptions& o);
double curvature(const ancf::ShapeAt& sh, const ElementState& qe);
Eigen::Vector3d position(const ancf::ShapeAt& sh, const ElementState& qe);
Eigen::Vector3d slope(const ancf::ShapeAt& sh, const ElementState& qe);
/// Curvature κ and bending moment EI κ at every node: the mean of the
/// adjacent element ends (one end at the line's ends).
struct NodeBending {
  std::vector<double> curvature_per_m;
  std::vector<double> moment_Nm;
};
NodeBending node_bending(const Problem& p, const Eigen::VectorXd& q);
/// Last point along the line from A below the seabed (lift-off point).
std::optional<FeTouchdown> find_touchdown(const Problem& p, const Eigen::VectorXd& q);
/// Caps every element's EA at cap_N (infinity restores the model's EA).
void cap_axial_stiffness(Problem& p, double cap_N);

}  // namespace spiral::engine::fe_detail
