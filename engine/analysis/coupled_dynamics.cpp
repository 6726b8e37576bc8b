// The coupled hull + lines implicit system of coupled_dynamics.hpp: its
// residual, the Newton matrix condensed onto the hull, and the driver.

#include "engine/analysis/coupled_dynamics.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/analysis/line_array.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/common/worker_pool.hpp"
#include "engine/lines/fe_dynamic_line.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::engine {
namespace {

/// Where a line's end B is on the hull, and how it moves with it.
struct Attachment {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 3, 6> jacobian = Eigen::Matrix<double, 3, 6>::Zero();  // P = ∂p/∂q̃
};

Eigen::Vector3d attachment_point(const Eigen::Vector3d& reference_g, const Eigen::Vector3d& r_b,
                                 const Vector6d& offset) {
  const HullPose pose = pose_from_offset(reference_g, offset);
  return pose.reference_point_g + pose.rotation * r_b;
}

// Rotation columns of P by central differences of R(roll, pitch, yaw) r_b:
// 1e-6 rad gives P to ≈ 1e-12 relative (the truncation error is O(h²)).
constexpr double kAngleStep_rad = 1e-6;

Attachment attachment(const Eigen::Vector3d& reference_g, const Eigen::Vector3d& r_b, const Vector6d& offset) {
  Attachment a;
  a.position_m = attachment_point(reference_g, r_b, offset);
  a.jacobian.leftCols<3>().setIdentity();
  for (int k = 3; k < 6; ++k) {
    Vector6d plus = offset, minus = offset;
    plus[k] += kAngleStep_rad;
    minus[k] -= kAngleStep_rad;
    a.jacobian.col(k) =
        (attachment_point(reference_g, r_b, plus) - attachment_point(reference_g, r_b, minus)) / (2.0 * kAngleStep_rad);
  }
  return a;
}

/// Ṗ q̃̇ = q̃̇ᵀ (∂²p/∂q̃²) q̃̇: the centripetal part of the end's acceleration,
/// by a second difference of p along the rotation rates.
Eigen::Vector3d centripetal_acceleration(const Eigen::Vector3d& reference_g, const Eigen::Vector3d& r_b,
                                         const Vector6d& offset, const Vector6d& velocity) {
  Vector6d rates = Vector6d::Zero();
  rates.tail<3>() = velocity.tail<3>();
  const double speed = rates.norm();
  if (speed == 0.0) return Eigen::Vector3d::Zero();
  const double h = 1e-4 / speed;  // a 1e-4 rad step along the rotation
  return (attachment_point(reference_g, r_b, offset + h * rates) - 2.0 * attachment_point(reference_g, r_b, offset) +
          attachment_point(reference_g, r_b, offset - h * rates)) /
         (h * h);
}

struct LineBlock {
  const CoupledLine* input = nullptr;
  fe_detail::DynamicLine line;
  Eigen::Index offset = 0;  // of its states in y
  Eigen::Index size = 0;
  Attachment at;                                      // at the last residual or setup
  Eigen::Matrix<double, 3, 6> setup_jacobian;         // P of the setup
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();  // f_i of the last residual
  Eigen::Vector3d beta = Eigen::Vector3d::Zero(), phi = Eigen::Vector3d::Zero();
  double factored_cj = 0.0;  // c_j of its last factorisation
  bool stale = false;        // its contact changed since (newton_matrix_stale)
  bool never_condensed = true;
};

// A line keeps its factorisation over a partial update unless its own
// contact changed or c_j moved by more than IDA's 25 % (sundials_ida.hpp)
// since it was factored: with many lines some line's contact changes at
// almost every step, and refactoring all of them for it cost 60 % of the
// run (measured on the deep-water scenario: 265 updates in 320 steps).
// A line refactored for c_j is condensed again: X and Σ_B are dominated by
// the end element's c_j² M, so keeping the old ones made the hull's Newton
// iteration stall (docs/decisions/coupled-dynamics-performance.md, "End-B
// condensation after a c_j refactor").
constexpr double kLineRefactorCjChange = 0.25;

class CoupledSystem final : public ImplicitSystem {
 public:
  CoupledSystem(const HullDynamicsModel& hull, const HullLoads& loads, const Eigen::Vector3d& reference_g,
                const std::vector<CoupledLine>& lines, const CoupledOptions& options)
      : eq_(make_hull_equations(hull, loads)),
        reference_g_(reference_g),
        options_(options),
        blocks_(lines.size()),
        pool_(std::min<int>(options.threads, static_cast<int>(lines.size()))) {
    for (std::size_t i = 0; i < lines.size(); ++i) blocks_[i].input = &lines[i];
    if (eq_.model.radiation_memory) {
      const double dt = eq_.model.radiation_memory->time_step_s;
      history_.start_time_s = options.start_time_s;
      history_.time_step_s = dt;
      history_.velocities.setZero(
          6, static_cast<Eigen::Index>(std::ceil((options.output_times_s.back() - options.start_time_s) / dt)) + 2);
      history_.count = 1;  // at rest at the start (the coupled run starts from rest)
    }
  }

  /// Extends the radiation memory's velocity history (a no-op without one)
  /// over its grid times in (newest sample, t1] by cubic Hermite
  /// interpolation of the hull velocity between two output times, from the
  /// velocities and accelerations IDA returns there: the coupled run stops
  /// at its outputs only (stopping at every kernel step would add steps to
  /// all lines), and the low-frequency velocity is smooth over an output
  /// step (interpolation error ~ (w h)^4 / 384: 1e-6 at 17 s and 0.5 s).
  void extend_history(double t0, const Vector6d& v0, const Vector6d& a0, double t1, const Vector6d& v1,
                      const Vector6d& a1) {
    if (!eq_.model.radiation_memory) return;
    const double dt = history_.time_step_s, h = t1 - t0;
    for (;;) {
      const double t = history_.start_time_s + static_cast<double>(history_.count) * dt;
      if (t > t1 + 1e-9 * dt || history_.count >= history_.velocities.cols()) break;
      const double u = (t - t0) / h, u2 = u * u, u3 = u2 * u;
      history_.velocities.col(history_.count) =
          (2 * u3 - 3 * u2 + 1) * v0 + (u3 - 2 * u2 + u) * h * a0 + (-2 * u3 + 3 * u2) * v1 + (u3 - u2) * h * a1;
      ++history_.count;
    }
  }

  std::vector<LineBlock>& blocks() { return blocks_; }
  /// The radiation memory's velocity history, or null for a hull without one.
  const VelocityHistory* history() const { return eq_.model.radiation_memory ? &history_ : nullptr; }
  WorkerPool& pool() { return pool_; }
  const HullEquations& hull() const { return eq_; }

  /// The total hull motion q̃ = q + q_w(t) and its rates.
  PrescribedHullMotion total_motion(double t, const VectorConstRef& y, const VectorConstRef& yp) const {
    PrescribedHullMotion m;
    if (options_.wave_frequency_motion) m = options_.wave_frequency_motion(t);
    m.position += y.head<6>();
    m.velocity += y.segment<6>(6);
    m.acceleration += yp.segment<6>(6);
    return m;
  }

  /// Sets the line's end B kinematics from the hull state.
  void load_line(LineBlock& b, const PrescribedHullMotion& hull) const {
    b.at = attachment(reference_g_, b.input->attachment_b_m, hull.position);
    EndKinematics& k = b.line.end_B_attached;
    k.position_m = b.at.position_m;
    k.velocity_m_per_s = b.at.jacobian * hull.velocity;
    k.acceleration_m_per_s2 =
        b.at.jacobian * hull.acceleration +
        centripetal_acceleration(reference_g_, b.input->attachment_b_m, hull.position, hull.velocity);
  }

  // Each line reads its states from y, y' and writes its residual into r in
  // place (its own segments).
  void residual(double t, const VectorConstRef& y, const VectorConstRef& yp, VectorRef r) override {
    const PrescribedHullMotion hull = total_motion(t, y, yp);
    for_each_line([&](LineBlock& b) {
      load_line(b, hull);
      auto r_line = r.segment(b.offset, b.size);
      b.line.residual(t, y.segment(b.offset, b.size), yp.segment(b.offset, b.size), r_line);
      if (!r_line.allFinite())
        throw SolverError(fmt::format("line {}: non-finite forces at t = {} s", b.input->name, t));
      b.force_N = b.line.end_B_force_of_residual();
    });
    const Vector6d q = y.head<6>(), q_dot = y.segment<6>(6);
    Vector6d net = hull_generalized_force(eq_, t, q, q_dot, history());
    for (const LineBlock& b : blocks_) net += b.at.jacobian.transpose() * b.force_N;
    r.head<6>() = yp.head<6>() - q_dot;
    r.segment<6>(6) = eq_.total_mass * yp.segment<6>(6) - net;
  }

  /// Every line's force on the hull at (t, y, y') from its end element alone
  /// (the only element at end B: the value the full residual would give).
  void end_forces(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    const PrescribedHullMotion hull = total_motion(t, y, yp);
    for_each_line([&](LineBlock& b) {
      load_line(b, hull);
      fe_detail::DynamicLine& l = b.line;
      l.load_state(t, y.segment(b.offset, b.size), yp.segment(b.offset, b.size));
      b.force_N = l.end_force(true, l.qw, l.vw, l.aw, t);
    });
  }

  bool newton_matrix_stale() override {
    bool any = false;
    for (LineBlock& b : blocks_) {
      b.stale = b.line.newton_matrix_stale();
      any = any || b.stale;
    }
    return any;
  }

  bool setup_newton_matrix(double t, const VectorConstRef& y, const VectorConstRef& yp, double cj) override {
    hull_tangents(t, y);
    return refactor(t, y, yp, cj, /*full=*/true);
  }

  bool update_newton_matrix(double t, const VectorConstRef& y, const VectorConstRef& yp, double cj) override {
    return refactor(t, y, yp, cj, /*full=*/false);
  }

  void solve_newton_system(double cj, Eigen::Ref<Eigen::VectorXd> b) override {
    const Vector6d b_q = b.head<6>(), b_v = b.segment<6>(6);
    for_each_line([&](LineBlock& blk) {
      blk.beta = blk.setup_jacobian * b_q;
      blk.phi = blk.line.solve_free(b.segment(blk.offset, blk.size), blk.beta);
    });
    Vector6d rhs = b_v + hull_D_ * b_q;
    for (const LineBlock& blk : blocks_) rhs += blk.setup_jacobian.transpose() * blk.phi;
    const Vector6d dq = hull_lu_.solve(rhs);
    for_each_line([&](LineBlock& blk) {
      blk.line.finish_solve(cj, b.segment(blk.offset, blk.size), blk.setup_jacobian * dq, blk.beta);
    });
    b.head<6>() = dq;
    b.segment<6>(6) = cj * dq - b_q;
  }

  /// Largest lines first (longest-processing-time order): with the 12 risers
  /// holding 70 % of the deep-water states, running them last left one
  /// thread idle at the end of every loop.
  void order_lines_by_size() {
    schedule_.resize(blocks_.size());
    for (std::size_t i = 0; i < blocks_.size(); ++i) schedule_[i] = i;
    std::stable_sort(schedule_.begin(), schedule_.end(),
                     [&](std::size_t a, std::size_t b) { return blocks_[a].size > blocks_[b].size; });
  }

  template <class F>
  void for_each_line(const F& f) {
    pool_.run(static_cast<int>(blocks_.size()), [&](int i) {
      const std::size_t k = schedule_.empty() ? static_cast<std::size_t>(i) : schedule_[static_cast<std::size_t>(i)];
      f(blocks_[k]);
    });
  }

 private:
  // B_h = −∂F_hull/∂q̇, K_h = −∂F_hull/∂q by forward differences at the setup
  // (steps 1e-6 of the scale of each DOF: the forces are smooth, and a
  // Newton matrix needs no more than a few digits).
  void hull_tangents(double t, const VectorConstRef& y) {
    const Vector6d q = y.head<6>(), q_dot = y.segment<6>(6);
    const Vector6d f0 = hull_generalized_force(eq_, t, q, q_dot, history());
    for (int k = 0; k < 6; ++k) {
      const double hq = k < 3 ? 1e-5 : 1e-7, hv = k < 3 ? 1e-5 : 1e-7;
      Vector6d qp = q, vp = q_dot;
      qp[k] += hq;
      vp[k] += hv;
      hull_K_.col(k) = -(hull_generalized_force(eq_, t, qp, q_dot, history()) - f0) / hq;
      hull_B_.col(k) = -(hull_generalized_force(eq_, t, q, vp, history()) - f0) / hv;
    }
  }

  bool refactor(double t, const VectorConstRef& y, const VectorConstRef& yp, double cj, bool full) {
    const PrescribedHullMotion hull = total_motion(t, y, yp);
    std::vector<char> ok(blocks_.size(), 0);
    for_each_line([&](LineBlock& b) {
      const std::size_t i = static_cast<std::size_t>(&b - blocks_.data());
      ok[i] = 1;
      const bool cj_moved = std::abs(cj / b.factored_cj - 1.0) > kLineRefactorCjChange;
      if (!full && !b.stale && !cj_moved) return;
      load_line(b, hull);
      const auto y_line = y.segment(b.offset, b.size), yp_line = yp.segment(b.offset, b.size);
      const bool factored = full ? b.line.setup_newton_matrix(t, y_line, yp_line, cj)
                                 : b.line.update_newton_matrix(t, y_line, yp_line, cj);
      if (factored) {
        b.line.prepare_end_B_matrices(cj);
        if (full || b.never_condensed || cj_moved) b.line.condense_end_B();
        b.never_condensed = false;
      }
      b.setup_jacobian = b.at.jacobian;
      b.factored_cj = cj;
      b.stale = false;
      ok[i] = factored ? 1 : 0;
    });
    for (char c : ok) {
      if (c == 0) return false;
    }
    Matrix6d A = cj * cj * eq_.total_mass + cj * hull_B_ + hull_K_;
    for (const LineBlock& b : blocks_) {
      A += b.setup_jacobian.transpose() * b.line.end_B_schur * b.setup_jacobian;
      // K_geo: −∂(Pᵀ f)/∂q̃ at fixed f (the lever arms turning with the hull).
      for (int k = 3; k < 6; ++k) {
        Vector6d plus = hull.position, minus = hull.position;
        plus[k] += 1e-5;
        minus[k] -= 1e-5;
        const Eigen::Matrix<double, 3, 6> dP = (attachment(reference_g_, b.input->attachment_b_m, plus).jacobian -
                                                attachment(reference_g_, b.input->attachment_b_m, minus).jacobian) /
                                               2e-5;
        A.col(k) -= dP.transpose() * b.force_N;
      }
    }
    hull_D_ = cj * eq_.total_mass + hull_B_;
    hull_lu_.compute(A);
    return std::isfinite(hull_lu_.rcond()) && hull_lu_.rcond() > 1e-14;
  }

  HullEquations eq_;
  Eigen::Vector3d reference_g_;
  CoupledOptions options_;
  std::vector<LineBlock> blocks_;
  Matrix6d hull_K_ = Matrix6d::Zero(), hull_B_ = Matrix6d::Zero(), hull_D_ = Matrix6d::Zero();
  Eigen::PartialPivLU<Matrix6d> hull_lu_;
  std::vector<std::size_t> schedule_;  // for_each_line's order (empty: as given)
  VelocityHistory history_;            // the radiation memory's, written between outputs only
  WorkerPool pool_;                    // last: its threads stop before the blocks go
};

void validate(const HullLoads& loads, const std::vector<CoupledLine>& lines, const CoupledOptions& o) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("coupled dynamics: " + what); };
  if (!std::holds_alternative<LinearizedLines>(loads.lines))
    fail("loads.lines: the FE lines replace a nonlinear line model (give LinearizedLines)");
  if (lines.empty()) fail("lines: at least one line is needed");
  if (o.threads < 1) fail(fmt::format("threads: must be >= 1, got {}", o.threads));
  if (o.steps_between_full_setups < 1)
    fail(fmt::format("steps_between_full_setups: must be >= 1, got {}", o.steps_between_full_setups));
  if (!(o.element_refresh_slope >= 0.0))
    fail(fmt::format("element_refresh_slope: must be >= 0, got {}", o.element_refresh_slope));
  if (!(o.element_refresh_velocity_m_per_s >= 0.0))
    fail(fmt::format("element_refresh_velocity_m_per_s: must be >= 0 m/s, got {} m/s",
                     o.element_refresh_velocity_m_per_s));
  if (o.output_times_s.empty()) fail("output_times_s: empty");
  double last = o.start_time_s;
  for (double t : o.output_times_s) {
    if (!(t > last)) fail("output_times_s: must increase strictly from the start time");
    last = t;
  }
  for (const CoupledLine& l : lines) {
    if (l.end_A == FeEndCondition::prescribed || l.end_A == FeEndCondition::attached)
      fail(fmt::format("line {}: end A may be fixed or free", l.name));
  }
}

}  // namespace

CoupledTimeSeries simulate_coupled(const HullDynamicsModel& hull, const HullLoads& loads,
                                   const Eigen::Vector3d& reference_point_at_rest_g, const Vector6d& initial_offset,
                                   const std::vector<CoupledLine>& lines, const CoupledOptions& options) {
  Stopwatch start;
  validate(loads, lines, options);
  CoupledSystem system(hull, loads, reference_point_at_rest_g, lines, options);
  std::vector<LineBlock>& blocks = system.blocks();

  PrescribedHullMotion at_start;
  if (options.wave_frequency_motion) at_start = options.wave_frequency_motion(options.start_time_s);
  at_start.position += initial_offset;

  // Each line from its static solution, its end B where the hull holds it.
  Eigen::Index size = 12;
  std::vector<fe_detail::DynamicLine::Start> starts(blocks.size());
  system.for_each_line([&](LineBlock& b) {
    const CoupledLine& in = *b.input;
    FeDynamicsOptions o;
    o.end_A = in.end_A;
    o.end_B = FeEndCondition::attached;
    o.start_time_s = options.start_time_s;
    o.relative_tolerance = options.relative_tolerance;
    o.position_tolerance_m = options.position_tolerance_m;
    o.slope_tolerance = options.slope_tolerance;
    o.velocity_tolerance_m_per_s = options.velocity_tolerance_m_per_s;
    const Attachment at = attachment(reference_point_at_rest_g, in.attachment_b_m, at_start.position);
    const double gap = (in.initial.node_position_m.back() - at.position_m).norm();
    if (gap > 1e-6 * std::max(1.0, in.initial.node_position_m.back().norm())) {
      throw SolverError(
          fmt::format("line {}: its static solution ends {:.6g} m from its attachment on the hull at the "
                      "start; solve it there",
                      in.name, gap));
    }
    try {
      starts[static_cast<std::size_t>(&b - blocks.data())] = b.line.initialize(in.model, in.environment, in.initial, o);
    } catch (const SolverError& e) {
      throw SolverError(fmt::format("line {}: {}", in.name, e.what()));
    }
  });
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    blocks[i].offset = size;
    blocks[i].size = starts[i].y0.size();
    size += blocks[i].size;
  }
  system.order_lines_by_size();
  for (LineBlock& b : blocks) {
    b.line.refresh_slope_tolerance = options.element_refresh_slope;
    b.line.refresh_velocity_tolerance_m_per_s = options.element_refresh_velocity_m_per_s;
  }

  Eigen::VectorXd y0(size), yp0 = Eigen::VectorXd::Zero(size), atol(size), id(size);
  y0.head<6>() = initial_offset;
  y0.segment<6>(6).setZero();
  const double hp = options.hull_position_tolerance_m, hr = options.hull_rotation_tolerance_rad;
  atol.head<12>() << hp, hp, hp, hr, hr, hr, 10 * hp, 10 * hp, 10 * hp, 10 * hr, 10 * hr, 10 * hr;
  id.head<12>().setOnes();
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const LineBlock& b = blocks[i];
    y0.segment(b.offset, b.size) = starts[i].y0;
    yp0.segment(b.offset, b.size) = starts[i].yp0;
    atol.segment(b.offset, b.size) = *starts[i].ida.absolute_tolerances;
    id.segment(b.offset, b.size) = *starts[i].ida.differential_id;
  }
  // The hull's initial acceleration from the forces at rest (the lines'
  // end forces at their static state, where their end inertia is zero).
  {
    Eigen::VectorXd r(size);
    system.residual(options.start_time_s, y0, yp0, r);
    yp0.segment<6>(6) = system.hull().total_mass_lu.solve(-r.segment<6>(6));
  }

  IdaOptions io;
  io.relative_tolerance = options.relative_tolerance;
  io.absolute_tolerances = atol;
  io.differential_id = id;
  io.max_order = options.max_order;
  // Each line and the hull meet the tolerance by themselves (sundials_ida.hpp).
  io.error_group_starts.push_back(0);
  for (const LineBlock& b : blocks) io.error_group_starts.push_back(b.offset);
  io.max_step_s = options.max_step_s;
  io.max_steps_between_outputs = options.max_steps_between_outputs;
  io.max_steps_between_setups = options.steps_between_full_setups;
  io.vector_pool = &system.pool();  // idle between the system's own loops
  IdaIntegrator ida(system, options.start_time_s, y0, yp0, io);

  CoupledTimeSeries out;
  const auto n_out = static_cast<Eigen::Index>(options.output_times_s.size()) + 1;
  out.times_s.resize(n_out);
  out.position.resize(6, n_out);
  out.velocity.resize(6, n_out);
  out.end_B_force_N.assign(blocks.size(), Eigen::Matrix<double, 3, Eigen::Dynamic>(3, n_out));
  out.state_size = size;
  out.step_limiting_outputs.assign(blocks.size() + 1, 0);
  auto record = [&](Eigen::Index k, double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    system.end_forces(t, y, yp);
    out.times_s[k] = t;
    out.position.col(k) = y.head<6>();
    out.velocity.col(k) = y.segment<6>(6);
    for (std::size_t i = 0; i < blocks.size(); ++i) out.end_B_force_N[i].col(k) = blocks[i].force_N;
  };
  record(0, options.start_time_s, y0, yp0);
  Vector6d previous_acceleration = yp0.segment<6>(6);
  for (Eigen::Index k = 1; k < n_out; ++k) {
    const double t = options.output_times_s[static_cast<std::size_t>(k - 1)];
    try {
      ida.advance_to(t);
    } catch (const IntegrationError& e) {
      // Name the part of the system whose local error is largest at the
      // failure: the line whose dynamics made the step collapse, usually.
      // Group 0 is the hull, group i + 1 line i (io.error_group_starts).
      const std::vector<double> err = ida.group_local_errors();
      std::string where = "the hull";
      double worst = err[0];
      for (std::size_t i = 0; i < blocks.size(); ++i) {
        if (err[i + 1] > worst) worst = err[i + 1], where = "line " + blocks[i].input->name;
      }
      throw IntegrationError(fmt::format("coupled hull + lines: {}; largest local error in {}", e.what(), where),
                             e.time_reached_s(), e.last_step_s(), e.cvode_flag(), e.diagnostics());
    }
    record(k, t, ida.state(), ida.state_derivative());
    system.extend_history(out.times_s[k - 1], out.velocity.col(k - 1), previous_acceleration, t, out.velocity.col(k),
                          ida.state_derivative().segment<6>(6));
    previous_acceleration = ida.state_derivative().segment<6>(6);
    system.for_each_line([&](LineBlock& b) { b.line.follow_elements(ida.state().segment(b.offset, b.line.n)); });
    if (options.take_freed_cores) {
      const int lines = static_cast<int>(blocks.size());
      system.pool().grow_to(std::min(lines, worker_count(lines)));
    }
    const std::vector<double> err = ida.group_local_errors();
    std::size_t worst_part = blocks.size();
    double worst = err[0];
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      if (err[i + 1] > worst) worst = err[i + 1], worst_part = i;
    }
    ++out.step_limiting_outputs[worst_part];
  }
  out.statistics = ida.statistics();
  for (const LineBlock& b : blocks) {
    out.element_matrix_evaluations += b.line.element_evaluations;
    out.element_matrices_kept += b.line.element_matrices_kept;
  }
  out.wall_clock_s = start.seconds();
  return out;
}

}  // namespace spiral::engine
