#include "engine/analysis/hull_dynamics.hpp"
#include "engine/common/stopwatch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace spiral::engine {
namespace {

void require_finite(const auto& m, const char* what) {
  if (!m.allFinite()) {
    throw std::invalid_argument(fmt::format("hull dynamics: {} has non-finite entries", what));
  }
}

}  // namespace

Vector6d radiation_memory_force(const RetardationKernel& kernel, const VelocityHistory& history, double t_s,
                                const Vector6d& velocity) {
  const double dt = kernel.time_step_s;
  const Eigen::Index n_kernel = kernel.size();
  Vector6d mu = Vector6d::Zero();
  if (history.count == 0 || n_kernel < 2) return mu;
  const Eigen::Index last = history.count - 1;
  const double t_last = history.start_time_s + static_cast<double>(last) * dt;
  // s = t − t_last >= 0: the first interval [0, s] joins the current velocity
  // to the newest stored sample.
  const double s = std::max(0.0, t_s - t_last);
  const auto m = static_cast<Eigen::Index>(std::floor(s / dt));
  const double a = s / dt - static_cast<double>(m);
  auto kernel_at = [&](Eigen::Index j) -> Matrix6d {  // K(s + j dt), linear interpolation
    const Eigen::Index i = j + m;
    if (i + 1 >= n_kernel) return i + 1 == n_kernel ? kernel.at_index(i) : Matrix6d::Zero();
    return (1.0 - a) * kernel.at_index(i) + a * kernel.at_index(i + 1);
  };
  if (s <= dt) {
    mu += 0.5 * s * (kernel.at_index(0) * velocity + kernel_at(0) * history.velocities.col(last));
  } else {
    // A history that lags by more than a step (the coupled driver stores it
    // at its output times): the velocity is joined linearly across [0, s],
    // and the trapezoid follows the kernel's grid inside it.
    const Vector6d newest = history.velocities.col(last);
    auto term = [&](double tau) -> Vector6d {
      const double u = tau / dt;
      const auto i = static_cast<Eigen::Index>(std::floor(u));
      if (i + 1 >= n_kernel) return Vector6d::Zero();
      const Matrix6d k = (1.0 - (u - static_cast<double>(i))) * kernel.at_index(i) +
                         (u - static_cast<double>(i)) * kernel.at_index(i + 1);
      return k * (velocity + (tau / s) * (newest - velocity));
    };
    double tau = 0.0;
    Vector6d f_tau = kernel.at_index(0) * velocity;
    for (Eigen::Index i = 1; static_cast<double>(i) * dt < s; ++i) {
      const double next = static_cast<double>(i) * dt;
      const Vector6d f_next = term(next);
      mu += 0.5 * (next - tau) * (f_tau + f_next);
      tau = next;
      f_tau = f_next;
    }
    mu += 0.5 * (s - tau) * (f_tau + kernel_at(0) * newest);
  }
  // Trapezoid over the stored samples, up to t_max or the start of the history.
  // Sample j sits at tau_j = s + j dt <= t_max.
  const Eigen::Index j_max = std::min(last, n_kernel - 1 - m - (a > 0.0 ? 1 : 0));
  for (Eigen::Index j = 0; j_max > 0 && j <= j_max; ++j) {
    const double weight = (j == 0 || j == j_max) ? 0.5 : 1.0;
    mu += weight * dt * (kernel_at(j) * history.velocities.col(last - j));
  }
  return mu;
}

HullEquations make_hull_equations(const HullDynamicsModel& model, const HullLoads& loads) {
  require_finite(model.mass, "mass");
  require_finite(model.added_mass, "added_mass");
  require_finite(model.linear_damping, "linear_damping");
  require_finite(model.quadratic_damping, "quadratic_damping");
  require_finite(model.hydrostatic_stiffness, "hydrostatic_stiffness");
  require_finite(model.hydrostatic_force_at_rest, "hydrostatic_force_at_rest");
  if ((model.quadratic_damping.array() < 0.0).any()) {
    throw std::invalid_argument("hull dynamics: quadratic_damping must be >= 0 in every DOF");
  }
  HullEquations eq{model, loads, model.mass + model.added_mass, {}, model.linear_damping};
  if (const auto* lin = std::get_if<LinearizedLines>(&loads.lines)) {
    require_finite(lin->force_at_equilibrium, "lines.force_at_equilibrium");
    require_finite(lin->stiffness, "lines.stiffness");
    require_finite(lin->equilibrium_offset, "lines.equilibrium_offset");
    if (lin->added_mass) {
      require_finite(*lin->added_mass, "lines.added_mass");
      eq.total_mass += *lin->added_mass;
    }
    if (lin->damping) {
      require_finite(*lin->damping, "lines.damping");
      eq.total_linear_damping += *lin->damping;
    }
    for (const LineRelaxation& r : lin->relaxations) {
      require_finite(r.stiffness, "lines.relaxations[].stiffness");
      if (!(r.time_constant_s > 0.0) || !std::isfinite(r.time_constant_s)) {
        throw std::invalid_argument(
            fmt::format("hull dynamics: a line relaxation needs a time constant > 0 s, got {}", r.time_constant_s));
      }
    }
  } else if (!std::get<NonlinearLineForce>(loads.lines)) {
    throw std::invalid_argument("hull dynamics: the nonlinear line force callback is empty");
  }
  // A physical total mass is symmetric positive definite; check the
  // symmetric part (added mass may be slightly non-symmetric from BEM).
  const Matrix6d sym = 0.5 * (eq.total_mass + eq.total_mass.transpose());
  if (Eigen::LLT<Matrix6d>(sym).info() != Eigen::Success) {
    throw std::invalid_argument(
        "hull dynamics: M + A (+ line added mass) is not positive definite: check the mass, "
        "inertia and added-mass inputs (units kg, kg·m, kg·m²)");
  }
  eq.total_mass_lu.compute(eq.total_mass);
  return eq;
}

Vector6d hull_generalized_force(const HullEquations& eq, double t_s, const Vector6d& q, const Vector6d& q_dot,
                                const VelocityHistory* history) {
  const HullDynamicsModel& model = eq.model;
  Vector6d f = model.hydrostatic_force_at_rest - model.hydrostatic_stiffness * q - eq.total_linear_damping * q_dot -
               model.quadratic_damping.cwiseProduct(q_dot.cwiseAbs().cwiseProduct(q_dot));
  if (const auto* lin = std::get_if<LinearizedLines>(&eq.loads.lines)) {
    f += lin->force_at_equilibrium - lin->stiffness * (q - lin->equilibrium_offset);
  } else {
    f += std::get<NonlinearLineForce>(eq.loads.lines)(q);
  }
  if (eq.loads.external) f += eq.loads.external(t_s, q, q_dot);
  if (model.radiation_memory && history != nullptr) {
    f -= radiation_memory_force(*model.radiation_memory, *history, t_s, q_dot);
  }
  return f;
}

void hull_state_derivative(const HullEquations& eq, const VelocityHistory* history, double t_s,
                           const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
  const Vector6d q = y.head<6>();
  const Vector6d q_dot = y.segment<6>(6);
  ydot.resize(y.size());
  ydot.head<6>() = q_dot;
  Vector6d f = hull_generalized_force(eq, t_s, q, q_dot, history);
  if (const auto* lin = std::get_if<LinearizedLines>(&eq.loads.lines)) {
    const Vector6d x = q - lin->equilibrium_offset;
    for (std::size_t j = 0; j < lin->relaxations.size(); ++j) {
      const LineRelaxation& r = lin->relaxations[j];
      const Eigen::Index at = 12 + 6 * static_cast<Eigen::Index>(j);
      const Vector6d unrelaxed = x - y.segment<6>(at);
      f -= r.stiffness * unrelaxed;
      ydot.segment<6>(at) = unrelaxed / r.time_constant_s;
    }
  }
  ydot.segment<6>(6) = eq.total_mass_lu.solve(f);
}

CvodeOptions default_hull_integrator_options() {
  CvodeOptions o;
  o.method = CvodeMethod::adams_newton_dense;
  // See the header: measured on the OC4 model, rtol 1e-8 leaves an energy
  // drift of 9e-5 over 20 surge periods, 1e-10 leaves 7e-7 at about the same
  // step count (Adams raises its order).
  o.relative_tolerance = 1e-10;
  Eigen::VectorXd atol(12);
  atol << 1e-10, 1e-10, 1e-10, 1e-12, 1e-12, 1e-12, 1e-10, 1e-10, 1e-10, 1e-12, 1e-12, 1e-12;
  o.absolute_tolerances = atol;
  return o;
}

HullTimeSeries simulate_hull(const HullDynamicsModel& model, const HullLoads& loads, const Vector6d& initial_position,
                             const Vector6d& initial_velocity, const HullSimulationOptions& options) {
  Stopwatch wall_start;
  require_finite(initial_position, "initial_position");
  require_finite(initial_velocity, "initial_velocity");
  const HullEquations eq = make_hull_equations(model, loads);
  const auto& times = options.output_times_s;
  const double t0 = options.start_time_s;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!(times[k] >= t0) || (k > 0 && !(times[k] > times[k - 1]))) {
      throw std::invalid_argument(
          fmt::format("simulate_hull: output times must be strictly increasing and >= the start time {} s; "
                      "output_times_s[{}] = {} s",
                      t0, k, times[k]));
    }
  }
  // The lines' relaxations start relaxed (z = x: no force).
  const auto* lin = std::get_if<LinearizedLines>(&loads.lines);
  const Eigen::Index relaxations = lin != nullptr ? static_cast<Eigen::Index>(lin->relaxations.size()) : 0;
  Eigen::VectorXd y0(12 + 6 * relaxations);
  y0.head<12>() << initial_position, initial_velocity;
  for (Eigen::Index j = 0; j < relaxations; ++j) y0.segment<6>(12 + 6 * j) = initial_position - lin->equilibrium_offset;
  CvodeOptions integrator_options = options.integrator;
  if (relaxations > 0 && integrator_options.absolute_tolerances &&
      integrator_options.absolute_tolerances->size() == 12) {
    // The relaxation states are positions: the positions' tolerances.
    Eigen::VectorXd atol(y0.size());
    atol.head<12>() = *integrator_options.absolute_tolerances;
    for (Eigen::Index j = 0; j < relaxations; ++j) atol.segment<6>(12 + 6 * j) = atol.head<6>();
    integrator_options.absolute_tolerances = atol;
  }

  // The history is an input of the derivative; only this driver writes it,
  // between CVODE advances that stop exactly at the history times.
  VelocityHistory history;
  const VelocityHistory* history_ptr = nullptr;
  if (model.radiation_memory) {
    const double dt = model.radiation_memory->time_step_s;
    const double t_end = times.empty() ? t0 : times.back();
    history.start_time_s = t0;
    history.time_step_s = dt;
    history.velocities.resize(6, static_cast<Eigen::Index>(std::ceil((t_end - t0) / dt)) + 2);
    history.velocities.col(0) = initial_velocity;
    history.count = 1;
    history_ptr = &history;
  }

  CvodeIntegrator integrator(
      [&eq, history_ptr](double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
        hull_state_derivative(eq, history_ptr, t, y, ydot);
      },
      t0, y0, integrator_options);

  HullTimeSeries out;
  const auto n_out = static_cast<Eigen::Index>(times.size());
  out.times_s = Eigen::Map<const Eigen::VectorXd>(times.data(), n_out);
  out.position.resize(6, n_out);
  out.velocity.resize(6, n_out);
  for (Eigen::Index k = 0; k < n_out; ++k) {
    const double t_target = times[static_cast<std::size_t>(k)];
    if (history_ptr != nullptr) {
      // Advance history step by history step up to t_target.
      const double dt = history.time_step_s;
      for (;;) {
        const double t_next = t0 + static_cast<double>(history.count) * dt;
        if (t_next > t_target + 1e-9 * dt) break;
        if (t_next > integrator.time_s()) {
          integrator.set_stop_time(t_next);
          integrator.advance_to(t_next);
        }
        history.velocities.col(history.count) = integrator.state().segment<6>(6);
        ++history.count;
      }
      if (t_target > integrator.time_s()) {
        integrator.set_stop_time(t0 + static_cast<double>(history.count) * dt);
        integrator.advance_to(t_target);
      }
    } else if (t_target > integrator.time_s()) {
      integrator.advance_to(t_target);
    }
    const Eigen::VectorXd& y = t_target == t0 ? y0 : integrator.state();
    out.position.col(k) = y.head<6>();
    out.velocity.col(k) = y.segment<6>(6);
  }
  out.statistics = integrator.statistics();
  out.wall_clock_s = wall_start.seconds();
  return out;
}

HullTimeSeries free_decay(const HullDynamicsModel& model, const LineForceModel& lines, int dof,
                          double initial_displacement, double duration_s, double output_step_s,
                          const CvodeOptions& integrator) {
  if (dof < 0 || dof > 5) {
    throw std::invalid_argument(fmt::format("free_decay: dof must be 0..5, got {}", dof));
  }
  if (!(duration_s > 0.0) || !(output_step_s > 0.0) || !std::isfinite(initial_displacement)) {
    throw std::invalid_argument(
        fmt::format("free_decay: need duration_s > 0, output_step_s > 0 and a finite displacement; got {} s, "
                    "{} s, {}",
                    duration_s, output_step_s, initial_displacement));
  }
  Vector6d q0 = Vector6d::Zero();
  if (const auto* lin = std::get_if<LinearizedLines>(&lines)) q0 = lin->equilibrium_offset;
  q0(dof) += initial_displacement;
  HullSimulationOptions options;
  options.integrator = integrator;
  const auto n = static_cast<std::size_t>(std::floor(duration_s / output_step_s + 1e-9));
  options.output_times_s.reserve(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    options.output_times_s.push_back(static_cast<double>(k) * output_step_s);
  }
  return simulate_hull(model, HullLoads{lines, {}}, q0, Vector6d::Zero(), options);
}

}  // namespace spiral::engine
