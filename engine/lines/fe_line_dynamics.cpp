// FE line dynamics: the DAE of fe_line_dynamics.hpp (fe_dynamic_line.hpp),
// its consistent initial values and integrator settings, and the outputs of
// a line integrated on its own.

#include "engine/lines/fe_line_dynamics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/lines/fe_dynamic_line.hpp"

namespace spiral::engine {

namespace fe_detail {
namespace {

void validate_dynamics(const FeLineModel& model, const FeDynamicEnvironment& env, const FeDynamicsOptions& o) {
  for (std::size_t i = 0; i < model.sections.size(); ++i) {
    const auto& s = model.sections[i];
    auto check = [&](const char* field, double v, const char* unit) {
      if (!std::isfinite(v) || v < 0.0)
        invalid_dynamics(fmt::format("sections[{}].{}: must be >= 0 {}, got {}", i, field, unit, v));
    };
    check("displaced_area_m2", s.displaced_area_m2, "m2");
    check("added_mass_normal", s.added_mass_normal, "");
    check("added_mass_tangential", s.added_mass_tangential, "");
    check("axial_damping_Ns", s.axial_damping_Ns, "N s");
    check("EA_dynamic_N", s.EA_dynamic_N, "N");
    if (!(s.mass_kg_per_m > 0.0) && !(s.added_mass_normal * s.displaced_area_m2 > 0.0)) {
      invalid_dynamics(
          fmt::format("sections[{}].mass_kg_per_m: must be > 0 kg/m for dynamics, got {}", i, s.mass_kg_per_m));
    }
  }
  auto check_env = [](const char* field, double v, bool ok, const char* rule) {
    if (!std::isfinite(v) || !ok) invalid_dynamics(fmt::format("{}: must be {}, got {}", field, rule, v));
  };
  check_env("seabed_lateral_friction", env.seabed_lateral_friction, env.seabed_lateral_friction >= 0.0, ">= 0");
  check_env("seabed_axial_friction", env.statics.seabed_axial_friction, env.statics.seabed_axial_friction >= 0.0,
            ">= 0");
  check_env("seabed_damping_N_s_per_m2", env.seabed_damping_N_s_per_m2, env.seabed_damping_N_s_per_m2 >= 0.0,
            ">= 0 N s/m2");
  check_env("friction_velocity_m_per_s", env.friction_velocity_m_per_s, env.friction_velocity_m_per_s > 0.0, "> 0 m/s");
  check_env("sea_ramp_s", env.sea_ramp_s, env.sea_ramp_s >= 0.0, ">= 0 s");
  if (env.sea_sample_interval_s) {
    check_env("sea_sample_interval_s", *env.sea_sample_interval_s, *env.sea_sample_interval_s >= 0.0, ">= 0 s");
  }
  if (o.end_B == FeEndCondition::prescribed && !o.end_B_motion)
    invalid_dynamics("end_B_motion: required when end B is prescribed");
  if (o.end_A == FeEndCondition::prescribed) invalid_dynamics("end_A: may be fixed or free (prescribe end B)");
  if (o.end_A == FeEndCondition::free && o.end_B == FeEndCondition::free)
    invalid_dynamics("end_A, end_B: at least one end must be held");
  check_env("relative_tolerance", o.relative_tolerance, o.relative_tolerance > 0.0, "> 0");
  check_env("position_tolerance_m", o.position_tolerance_m, o.position_tolerance_m > 0.0, "> 0 m");
  check_env("slope_tolerance", o.slope_tolerance, o.slope_tolerance > 0.0, "> 0");
  check_env("velocity_tolerance_m_per_s", o.velocity_tolerance_m_per_s, o.velocity_tolerance_m_per_s > 0.0, "> 0 m/s");
}

}  // namespace

DynamicLine::Start DynamicLine::initialize(const FeLineModel& model, const FeDynamicEnvironment& environment,
                                           const FeStaticsResult& initial, const FeDynamicsOptions& options) {
  DynamicLine& m = *this;
  validate_dynamics(model, environment, options);
  if (initial.node_position_m.size() < 2) invalid_dynamics("initial: not a static solution (no nodes)");
  const FeLineEnds ends{initial.node_position_m.front(), initial.node_position_m.back()};
  fe_detail::validate(model, environment.statics, ends, FeStaticsOptions{});
  m.options = options;
  m.p = fe_detail::make_problem(model, environment.statics, ends);
  m.n = m.p.n_dofs;
  if (initial.state.size() != m.n || !initial.state.allFinite()) {
    invalid_dynamics(fmt::format("initial.state: needs {} finite entries (a static solution of this model), got {}",
                                 m.n, initial.state.size()));
  }
  fe_detail::set_node_arc_lengths(m.p, initial.node_arc_length_m);
  m.end_A_rest_m = ends.end_A_m;
  m.end_B_rest_m = ends.end_B_m;
  if (options.end_B == FeEndCondition::attached) m.end_B_attached = EndKinematics{ends.end_B_m};
  for (int k = 0; k < 3; ++k) {
    if (options.end_A == FeEndCondition::free) m.p.fixed[static_cast<std::size_t>(m.p.r_dof.front() + k)] = 0;
    if (options.end_B == FeEndCondition::free) m.p.fixed[static_cast<std::size_t>(m.p.r_dof.back() + k)] = 0;
  }
  m.current = environment.statics.current;
  m.current_ctx.current = &m.current;
  m.static_ctx = m.p.load;
  m.static_ctx.current = nullptr;
  m.bed.damping_N_s_per_m2 = environment.seabed_damping_N_s_per_m2;
  m.bed.axial_friction = environment.statics.seabed_axial_friction;
  m.bed.lateral_friction = environment.seabed_lateral_friction;
  m.bed.friction_velocity_m_per_s = environment.friction_velocity_m_per_s;
  m.waves = environment.waves;
  m.still_water = m.current.empty() && !m.waves && !environment.sea;

  // Element dynamic properties; a dynamic EA takes over from the static one
  // with the force offset that keeps the static state in equilibrium.
  const Eigen::VectorXd& q0 = initial.state;
  const double rho = environment.statics.water_density_kg_per_m3;
  m.dyn.resize(m.p.elements.size());
  m.end_force_offset_N.assign(m.p.elements.size(), {0.0, 0.0});
  for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
    const FeLineSection& s = model.sections[static_cast<std::size_t>(m.p.mesh.section[e])];
    ancf::DynamicElementProperties& d = m.dyn[e];
    d.mass_kg_per_m = s.mass_kg_per_m;
    d.displaced_mass_kg_per_m = rho * s.displaced_area_m2;
    d.added_mass_normal_kg_per_m = rho * s.displaced_area_m2 * s.added_mass_normal;
    d.added_mass_tangential_kg_per_m = rho * s.displaced_area_m2 * s.added_mass_tangential;
    d.axial_damping_Ns = s.axial_damping_Ns;
    if (s.EA_dynamic_N > 0.0 && s.EA_dynamic_N != s.EA_N) {
      const fe_detail::ElementState qe = fe_detail::gather(m.p, q0, e);
      const double L = m.p.elements[e].length_m;
      auto offset_at = [&](double xi) {
        const double strain = fe_detail::slope(ancf::shape_at(xi, L), qe).norm() - 1.0;
        return (s.EA_dynamic_N - s.EA_N) * strain;
      };
      for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp)
        d.axial_force_offset_N[gp] = offset_at(ancf::kGaussXi[gp]);
      m.end_force_offset_N[e] = {offset_at(0.0), offset_at(1.0)};
      m.p.elements[e].EA_N = s.EA_dynamic_N;
    }
  }

  if (environment.sea) {
    std::vector<Eigen::Vector3d> points;
    m.wave_point_start.assign(1, 0);
    for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
      const fe_detail::ElementState qe = fe_detail::gather(m.p, q0, e);
      const double L = m.p.elements[e].length_m;
      const auto at = [&](double xi) { return fe_detail::position(ancf::shape_at(xi, L), qe); };
      const double top_z_m = std::max(at(0.0).z(), at(1.0).z());
      if (FixedPointWaveKinematics::midpoint_error(*environment.sea, top_z_m, L) >
          FixedPointWaveKinematics::kWaveZoneMidpointError) {
        for (double xi : ancf::kGaussXi) points.push_back(at(xi));
      } else {
        points.push_back(at(0.5));
      }
      m.wave_point_start.push_back(points.size());
    }
    const double interval_s = environment.sea_sample_interval_s.value_or(
        FixedPointWaveKinematics::default_sample_interval_s(*environment.sea));
    m.element_waves = std::make_unique<FixedPointWaveKinematics>(environment.sea, points, 1e-3, interval_s);
    m.sea_ramp_s = environment.sea_ramp_s;
  }
  m.element_dofs.resize(m.p.elements.size());
  m.shapes.resize(m.p.elements.size());
  for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
    const auto blocks = fe_detail::element_blocks(m.p, e);
    for (int k = 0; k < kElementDofs; ++k)
      m.element_dofs[e][static_cast<std::size_t>(k)] = blocks[static_cast<std::size_t>(k / 3)] + k % 3;
    m.shapes[e] = ancf::gauss_shapes(m.p.elements[e].length_m);
  }
  for (int i = 0; i < m.n; ++i) {
    if (m.fixed(i)) m.fixed_dofs.push_back(i);
  }
  if (m.end_dof(DynamicLine::kEndBLocal) != m.p.r_dof.back())
    invalid_dynamics("mesh: the last element does not end at end B");
  m.element_matrices.resize(m.p.elements.size());
  m.lower_entries.resize(m.p.elements.size());
  m.column_elements.assign(static_cast<std::size_t>(m.n), {});
  for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
    const auto& dof = m.element_dofs[e];
    for (int i = 0; i < kElementDofs; ++i) {
      for (int j = 0; j < kElementDofs; ++j) {
        const int gi = dof[static_cast<std::size_t>(i)], gj = dof[static_cast<std::size_t>(j)];
        if (gj > gi || m.fixed(gi) || m.fixed(gj)) continue;
        m.lower_entries[e].push_back(
            {kElementDofs * i + j, static_cast<int>(SymmetricBand::offset(gi, gj, m.p.band)), gj});
        auto& list = m.column_elements[static_cast<std::size_t>(gj)];
        if (list.empty() || list.back() != static_cast<int>(e)) list.push_back(static_cast<int>(e));
      }
    }
  }
  m.element_changed.assign(m.p.elements.size(), 1);
  m.element_touched.assign(m.p.elements.size(), 0);
  m.dirty_column.assign(static_cast<std::size_t>(m.n), 0);
  m.element_stale.assign(m.p.elements.size(), 0);
  m.contact_at_setup.assign(m.p.elements.size(), 0.0);
  m.contact_now.assign(m.p.elements.size(), 0.0);

  // Initial state, velocity and a consistent acceleration: M a0 = G(q0, v0, a = 0).
  Eigen::VectorXd v0 = Eigen::VectorXd::Zero(m.n), a0 = Eigen::VectorXd::Zero(m.n);
  if (options.initial_velocity) {
    const double delta = 1e-6 * m.p.line_length_m;
    for (std::size_t i = 0; i < static_cast<std::size_t>(m.p.n_nodes); ++i) {
      const double s = m.p.mesh.s[i];
      v0.segment<3>(m.p.r_dof[i]) = options.initial_velocity(s);
      const double s0 = std::max(0.0, s - delta), s1 = std::min(m.p.line_length_m, s + delta);
      const Eigen::Vector3d rate = (options.initial_velocity(s1) - options.initial_velocity(s0)) / (s1 - s0);
      v0.segment<3>(m.p.t_in[i]) = rate;
      v0.segment<3>(m.p.t_out[i]) = rate;
    }
    if (!v0.allFinite()) invalid_dynamics("initial_velocity: returned non-finite values");
  }
  Eigen::VectorXd q_start = q0;
  {
    Eigen::VectorXd q_check = q0, v_check = v0, a_check = a0;
    m.apply_prescribed(options.start_time_s, q_check, v_check, a_check);
    const double mismatch = (q_check - q0).cwiseAbs().maxCoeff();
    if (mismatch > 1e-6 * std::max(1.0, m.p.line_length_m)) {
      invalid_dynamics(
          fmt::format("end_B_motion: at the start time {} s the end is {:.6g} m from the static "
                      "solution's end; start the motion from the static position",
                      options.start_time_s, mismatch));
    }
    q_start = q_check;
    v0 = v_check;
    a0 = a_check;
  }
  m.assemble_forces(options.start_time_s, q_start, v0, a0, m.G);
  for (std::size_t e = 0; e < m.p.elements.size(); ++e)
    m.evaluate_element_matrices(options.start_time_s, e, q_start, v0);
  m.combine_matrices(1.0, 0.0, 0.0, std::nullopt);
  m.rhs = m.G;
  for (int i = 0; i < m.n; ++i) {
    if (m.fixed(i)) m.rhs[i] = 0.0;
  }
  if (!m.S.factorize()) invalid_dynamics("mass matrix: singular (a section without mass?)");
  m.S.solve_in_place(m.rhs);
  for (int i = 0; i < m.n; ++i) {
    if (!m.fixed(i)) a0[i] = m.rhs[i];
  }

  Eigen::VectorXd y0(2 * m.n), yp0(2 * m.n), atol(2 * m.n), id = Eigen::VectorXd::Ones(2 * m.n);
  y0 << q_start, v0;
  yp0 << v0, a0;
  std::vector<char> is_position(static_cast<std::size_t>(m.n), 0);
  for (int r : m.p.r_dof) {
    for (int k = 0; k < 3; ++k) is_position[static_cast<std::size_t>(r + k)] = 1;
  }
  const double slope_rate_tolerance =
      options.slope_tolerance * options.velocity_tolerance_m_per_s / options.position_tolerance_m;
  for (int i = 0; i < m.n; ++i) {
    const bool pos = is_position[static_cast<std::size_t>(i)] != 0;
    atol[i] = pos ? options.position_tolerance_m : options.slope_tolerance;
    atol[m.n + i] = pos ? options.velocity_tolerance_m_per_s : slope_rate_tolerance;
    if (m.fixed(i)) id[i] = id[m.n + i] = 0.0;
  }
  IdaOptions io;
  io.relative_tolerance = options.relative_tolerance;
  io.absolute_tolerances = atol;
  io.differential_id = id;
  io.max_order = options.max_order;
  io.max_step_s = options.max_step_s;
  io.initial_step_s = options.initial_step_s;
  io.max_steps_between_outputs = options.max_steps_between_outputs;
  return Start{y0, yp0, io};
}

}  // namespace fe_detail

struct FeLineDynamics::Impl {
  fe_detail::DynamicLine line;
  std::unique_ptr<IdaIntegrator> ida;
};

FeLineDynamics::FeLineDynamics(const FeLineModel& model, const FeDynamicEnvironment& environment,
                               const FeStaticsResult& initial, const FeDynamicsOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (options.end_B == FeEndCondition::attached)
    fe_detail::invalid_dynamics("end_B: attached ends belong to a coupled system");
  const fe_detail::DynamicLine::Start start = impl_->line.initialize(model, environment, initial, options);
  impl_->ida = std::make_unique<IdaIntegrator>(impl_->line, options.start_time_s, start.y0, start.yp0, start.ida);
}

FeLineDynamics::~FeLineDynamics() = default;
FeLineDynamics::FeLineDynamics(FeLineDynamics&&) noexcept = default;
FeLineDynamics& FeLineDynamics::operator=(FeLineDynamics&&) noexcept = default;

void FeLineDynamics::advance_to(double t_s) {
  impl_->ida->advance_to(t_s);
  impl_->line.follow_elements(impl_->ida->state().head(impl_->line.n));
}
double FeLineDynamics::time_s() const { return impl_->ida->time_s(); }
IdaStatistics FeLineDynamics::statistics() const { return impl_->ida->statistics(); }

Eigen::Vector3d FeLineDynamics::end_B_force_N() const {
  fe_detail::DynamicLine& m = impl_->line;
  if (m.options.end_B == FeEndCondition::free) return Eigen::Vector3d::Zero();
  m.load_state(impl_->ida->time_s(), impl_->ida->state(), impl_->ida->state_derivative());
  return m.end_force(true, m.qw, m.vw, m.aw, impl_->ida->time_s());
}

FeLineDynamicSnapshot FeLineDynamics::snapshot() const {
  fe_detail::DynamicLine& m = impl_->line;
  const double t = impl_->ida->time_s();
  m.load_state(t, impl_->ida->state(), impl_->ida->state_derivative());
  FeLineDynamicSnapshot snap;
  snap.time_s = t;
  snap.node_arc_length_m = m.p.mesh.s;
  const auto nn = static_cast<std::size_t>(m.p.n_nodes);
  for (std::size_t i = 0; i < nn; ++i) {
    snap.node_position_m.push_back(m.qw.segment<3>(m.p.r_dof[i]));
    snap.node_velocity_m_per_s.push_back(m.vw.segment<3>(m.p.r_dof[i]));
    double sum = 0.0;
    int count = 0;
    if (i > 0) {
      sum += m.p.elements[i - 1].EA_N * (m.qw.segment<3>(m.p.t_in[i]).norm() - 1.0) - m.end_force_offset_N[i - 1][1];
      ++count;
    }
    if (i + 1 < nn) {
      sum += m.p.elements[i].EA_N * (m.qw.segment<3>(m.p.t_out[i]).norm() - 1.0) - m.end_force_offset_N[i][0];
      ++count;
    }
    snap.node_tension_N.push_back(sum / count);
  }
  fe_detail::NodeBending bending = fe_detail::node_bending(m.p, m.qw);
  snap.node_curvature_per_m = std::move(bending.curvature_per_m);
  snap.node_bending_moment_Nm = std::move(bending.moment_Nm);
  if (m.options.end_A != FeEndCondition::free) snap.end_A_force_N = m.end_force(false, m.qw, m.vw, m.aw, t);
  if (m.options.end_B != FeEndCondition::free) snap.end_B_force_N = m.end_force(true, m.qw, m.vw, m.aw, t);
  snap.touchdown = fe_detail::find_touchdown(m.p, m.qw);
  return snap;
}

FeLineEnergy FeLineDynamics::energy() const {
  fe_detail::DynamicLine& m = impl_->line;
  m.load_state(impl_->ida->time_s(), impl_->ida->state(), impl_->ida->state_derivative());
  FeLineEnergy en;
  for (std::size_t e = 0; e < m.p.elements.size(); ++e) {
    const ancf::ElementProperties& ep = m.p.elements[e];
    const fe_detail::ElementState qe = fe_detail::gather(m.p, m.qw, e);
    const fe_detail::ElementState ve = fe_detail::gather(m.p, m.vw, e);
    for (std::size_t gp = 0; gp < ancf::kGaussXi.size(); ++gp) {
      const ancf::ShapeAt& sh = m.shapes[e][gp];
      const double wds = ancf::kGaussW[gp] * ep.length_m;
      const Eigen::Vector3d r = fe_detail::position(sh, qe), a = fe_detail::slope(sh, qe);
      const Eigen::Vector3d rd = fe_detail::position(sh, ve);
      const double strain = a.norm() - 1.0;
      en.kinetic_J += 0.5 * m.dyn[e].mass_kg_per_m * rd.squaredNorm() * wds;
      double density = 0.5 * ep.EA_N * strain * strain - m.dyn[e].axial_force_offset_N[gp] * strain;
      if (ep.EI_Nm2 > 0.0) {
        const double kappa = fe_detail::curvature(sh, qe);
        density += 0.5 * ep.EI_Nm2 * kappa * kappa;
      }
      en.strain_J += density * wds;
      en.gravity_J += ep.weight_N_per_m * r.z() * wds;
    }
    ancf::detail::for_each_contact_point(ep, m.static_ctx, qe.data(), ve.data(),
                                         [&](const ancf::ShapeAt&, double w, double pen, const double*, const double*) {
                                           en.seabed_J += 0.5 * m.static_ctx.seabed_stiffness_N_per_m2 * pen * pen * w;
                                         });
  }
  for (const auto& [node, f] : m.p.mesh.point_loads)
    en.gravity_J += f * m.qw[m.p.r_dof[static_cast<std::size_t>(node)] + 2];
  return en;
}

}  // namespace spiral::engine