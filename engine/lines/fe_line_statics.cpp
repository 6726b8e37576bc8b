// FE static equilibrium of one line: mesh, initial shape, Newton with line
// search and current continuation, post-processing. Formulation and
// conventions: fe_line_statics.hpp; element kernel: ancf_cable_element.hpp.

#include "engine/lines/fe_line_statics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "engine/common/banded_lu.hpp"
#include "engine/lines/ancf_cable_element.hpp"
#include "engine/lines/fe_line_initial_shape.hpp"

namespace spiral::engine {
namespace {

constexpr int kElementDofs = 12;  // [r_a, r'_a, r_b, r'_b]

[[noreturn]] void invalid(const std::string& what) {
  throw SolverError("FE line statics: invalid input: " + what);
}

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

void validate(const FeLineModel& m, const FeEnvironment& env, const FeLineEnds& ends,
              const FeStaticsOptions& o) {
  if (m.sections.empty()) invalid("sections: at least one section is required, got none");
  for (std::size_t i = 0; i < m.sections.size(); ++i) {
    const auto& s = m.sections[i];
    auto check = [&](const char* field, double v, bool ok, const char* rule) {
      if (!std::isfinite(v) || !ok) invalid(fmt::format("sections[{}].{}: must be {}, got {}", i, field, rule, v));
    };
    check("length_m", s.length_m, s.length_m > 0.0, "> 0");
    check("EA_N", s.EA_N, s.EA_N > 0.0, "> 0");
    check("EI_Nm2", s.EI_Nm2, s.EI_Nm2 >= 0.0, ">= 0");
    check("mass_kg_per_m", s.mass_kg_per_m, s.mass_kg_per_m >= 0.0, ">= 0");
    check("weight_N_per_m", s.weight_N_per_m, true, "finite");
    check("hydro_diameter_m", s.hydro_diameter_m, s.hydro_diameter_m >= 0.0, ">= 0");
    check("drag_normal", s.drag_normal, s.drag_normal >= 0.0, ">= 0");
    check("drag_tangential", s.drag_tangential, s.drag_tangential >= 0.0, ">= 0");
    check("element_length_m", s.element_length_m, s.element_length_m > 0.0, "> 0");
  }
  if (!m.joint_load_N.empty() && m.joint_load_N.size() + 1 != m.sections.size()) {
    invalid(fmt::format("joint_load_N: needs {} entries (one per joint) or none, got {}",
                        m.sections.size() - 1, m.joint_load_N.size()));
  }
  for (std::size_t i = 0; i < m.joint_load_N.size(); ++i) {
    if (!std::isfinite(m.joint_load_N[i])) invalid(fmt::format("joint_load_N[{}]: must be finite", i));
  }
  if (m.refinement) {
    const auto& z = *m.refinement;
    if (!(z.length_m > 0.0) || !(z.element_length_m > 0.0) || !std::isfinite(z.start_arc_length_m)) {
      invalid(fmt::format("refinement: needs length_m > 0 and element_length_m > 0, got {} and {}",
                          z.length_m, z.element_length_m));
    }
  }
  if (!(env.water_density_kg_per_m3 > 0.0) || !std::isfinite(env.water_density_kg_per_m3)) {
    invalid(fmt::format("water_density_kg_per_m3: must be > 0, got {}", env.water_density_kg_per_m3));
  }
  if (!(env.seabed_stiffness_N_per_m2 >= 0.0) || !std::isfinite(env.seabed_stiffness_N_per_m2)) {
    invalid(fmt::format("seabed_stiffness_N_per_m2: must be >= 0, got {}", env.seabed_stiffness_N_per_m2));
  }
  if (std::isnan(env.seabed_z_m)) invalid("seabed_z_m: is NaN");
  for (std::size_t i = 0; i < env.current.size(); ++i) {
    if (!std::isfinite(env.current[i].z_m) || !finite(env.current[i].velocity_m_per_s)) {
      invalid(fmt::format("current[{}]: z and velocity must be finite", i));
    }
    if (i > 0 && !(env.current[i].z_m > env.current[i - 1].z_m)) {
      invalid(fmt::format("current[{}].z_m: must increase, got {} after {}", i, env.current[i].z_m,
                          env.current[i - 1].z_m));
    }
  }
  if (!finite(ends.end_A_m) || !finite(ends.end_B_m)) invalid("end positions must be finite");
  if ((ends.end_A_m - ends.end_B_m).norm() == 0.0) invalid("end_A_m and end_B_m coincide");
  if (!(o.relative_force_tolerance > 0.0) || o.max_iterations < 1) {
    invalid(fmt::format("options: relative_force_tolerance must be > 0 and max_iterations >= 1, got {} and {}",
                        o.relative_force_tolerance, o.max_iterations));
  }
}

struct Mesh {
  std::vector<double> s;                  // node arc lengths
  std::vector<int> section;               // section of each element
  std::vector<std::pair<int, double>> point_loads;  // (node, downward N)
};

Mesh build_mesh(const FeLineModel& m) {
  Mesh mesh;
  mesh.s.push_back(0.0);
  double s0 = 0.0;
  for (std::size_t i = 0; i < m.sections.size(); ++i) {
    const auto& sec = m.sections[i];
    const double s1 = s0 + sec.length_m;
    // Break points: the section ends and the refinement zone ends inside it.
    std::vector<double> cuts = {s0, s1};
    if (m.refinement) {
      const double z0 = m.refinement->start_arc_length_m;
      const double z1 = z0 + m.refinement->length_m;
      for (double c : {z0, z1}) {
        if (c > s0 && c < s1) cuts.push_back(c);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double a = cuts[k], b = cuts[k + 1];
      double h = sec.element_length_m;
      if (m.refinement) {
        const double mid = 0.5 * (a + b);
        const double z0 = m.refinement->start_arc_length_m;
        if (mid > z0 && mid < z0 + m.refinement->length_m) h = std::min(h, m.refinement->element_length_m);
      }
      // Round to the nearest count (no sliver elements), at least one.
      const int n = std::max(1, static_cast<int>(std::ceil((b - a) / h - 1e-6)));
      for (int e = 1; e <= n; ++e) {
        mesh.s.push_back(e == n ? b : a + (b - a) * e / n);
        mesh.section.push_back(static_cast<int>(i));
      }
    }
    if (i + 1 < m.sections.size() && !m.joint_load_N.empty() && m.joint_load_N[i] != 0.0) {
      mesh.point_loads.emplace_back(static_cast<int>(mesh.s.size()) - 1, m.joint_load_N[i]);
    }
    s0 = s1;
  }
  return mesh;
}

/// Everything the residual needs, built once per solve (workspace).
struct Problem {
  Mesh mesh;
  std::vector<ancf::ElementProperties> elements;
  ancf::LoadContext load;
  int n_nodes = 0;
  int n_dofs = 0;
  double line_length_m = 0.0;
  double load_scale_N = 0.0;  // total |weight| + |point loads| + drag estimate
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

void update_lengths(Problem& p) {
  const auto& s = p.mesh.s;
  for (std::size_t e = 0; e < p.elements.size(); ++e) p.elements[e].length_m = s[e + 1] - s[e];
  for (int i = 0; i < p.n_nodes; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    double sum = 0.0;
    int cnt = 0;
    if (i > 0) sum += s[ui] - s[ui - 1], ++cnt;
    if (i + 1 < p.n_nodes) sum += s[ui + 1] - s[ui], ++cnt;
    p.node_length_m[ui] = sum / cnt;
    for (int k = 0; k < 3; ++k) {
      p.dof_scale[static_cast<std::size_t>(p.t_in[ui] + k)] = 1.0 / p.node_length_m[ui];
      p.dof_scale[static_cast<std::size_t>(p.t_out[ui] + k)] = 1.0 / p.node_length_m[ui];
    }
  }
}

/// First DOF of each 3-block of element e: r_a, r'_a, r_b, r'_b.
std::array<int, 4> element_blocks(const Problem& p, std::size_t e) {
  return {p.r_dof[e], p.t_out[e], p.r_dof[e + 1], p.t_in[e + 1]};
}

/// The element's 12 DOF values.
Eigen::Matrix<double, kElementDofs, 1> gather(const Problem& p, const Eigen::VectorXd& q, std::size_t e) {
  Eigen::Matrix<double, kElementDofs, 1> qe;
  const auto b = element_blocks(p, e);
  for (int k = 0; k < 4; ++k) qe.segment<3>(3 * k) = q.segment<3>(b[static_cast<std::size_t>(k)]);
  return qe;
}

Problem make_problem(const FeLineModel& m, const FeEnvironment& env, const FeLineEnds& ends) {
  Problem p;
  p.mesh = build_mesh(m);
  p.n_nodes = static_cast<int>(p.mesh.s.size());
  p.line_length_m = p.mesh.s.back();
  double u_max = 0.0;
  for (const auto& c : env.current) u_max = std::max(u_max, c.velocity_m_per_s.norm());
  const double rho = env.water_density_kg_per_m3;
  for (std::size_t e = 0; e < p.mesh.section.size(); ++e) {
    const auto& sec = m.sections[static_cast<std::size_t>(p.mesh.section[e])];
    ancf::ElementProperties ep;
    ep.length_m = p.mesh.s[e + 1] - p.mesh.s[e];
    ep.EA_N = sec.EA_N;
    ep.EI_Nm2 = sec.EI_Nm2;
    ep.weight_N_per_m = sec.weight_N_per_m;
    ep.normal_drag_N_s2_per_m3 = 0.5 * rho * sec.drag_normal * sec.hydro_diameter_m;
    ep.tangential_drag_N_s2_per_m3 = 0.5 * rho * sec.drag_tangential * M_PI * sec.hydro_diameter_m;
    p.elements.push_back(ep);
    p.EA_true_N.push_back(ep.EA_N);
    p.load_scale_N += ep.length_m * (std::abs(ep.weight_N_per_m) + ep.normal_drag_N_s2_per_m3 * u_max * u_max);
  }
  for (const auto& [node, f] : p.mesh.point_loads) p.load_scale_N += std::abs(f);
  // Section joints are hinges with a slope on each side unless both sides
  // bend (EI > 0): the stretch |r'| = 1 + T/EA jumps where EA does, and a
  // clump or buoy kinks a cable; one shared slope would force a spurious
  // strain on the elements next to the joint (0.15 % tension error on a
  // chain–polyester line). Joints between two bending sections keep one
  // slope, for moment continuity; their strain jump is then smeared over the
  // adjacent elements, a local effect on risers whose EA varies little.
  const auto n = static_cast<std::size_t>(p.n_nodes);
  p.r_dof.resize(n);
  p.t_in.resize(n);
  p.t_out.resize(n);
  int next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    p.r_dof[i] = next;
    p.t_in[i] = next + 3;
    next += 6;
    const bool joint = i > 0 && i + 1 < n && p.mesh.section[i - 1] != p.mesh.section[i];
    const bool hinge = joint && !(p.elements[i - 1].EI_Nm2 > 0.0 && p.elements[i].EI_Nm2 > 0.0);
    if (hinge) {
      p.t_out[i] = next;
      next += 3;
      p.band = 14;  // r_a, r'_a in, r'_a out, r_b, r'_b: 15 DOFs
    } else {
      p.t_out[i] = p.t_in[i];
    }
  }
  p.n_dofs = next;
  p.fixed.assign(static_cast<std::size_t>(next), 0);
  for (int k = 0; k < 3; ++k) {
    p.fixed[static_cast<std::size_t>(p.r_dof.front() + k)] = 1;
    p.fixed[static_cast<std::size_t>(p.r_dof.back() + k)] = 1;
  }
  p.node_length_m.assign(n, 0.0);
  p.dof_scale.assign(static_cast<std::size_t>(next), 1.0);
  update_lengths(p);
  double coordinate_m = 0.0, ea_over_h = 0.0;
  for (const auto& e : p.elements) ea_over_h = std::max(ea_over_h, e.EA_N / e.length_m);
  coordinate_m = std::max({ends.end_A_m.cwiseAbs().maxCoeff(), ends.end_B_m.cwiseAbs().maxCoeff(), p.line_length_m});
  p.round_off_floor_N = 10.0 * std::numeric_limits<double>::epsilon() * ea_over_h * coordinate_m;
  p.load.current = &env.current;
  p.load.seabed_z_m = env.seabed_z_m;
  p.load.seabed_stiffness_N_per_m2 = env.seabed_stiffness_N_per_m2;
  return p;
}

bool is_fixed(const Problem& p, int dof) { return p.fixed[static_cast<std::size_t>(dof)] != 0; }

/// Net generalised forces g(q) (6 per node) and, if jac != nullptr, the
/// Jacobian ∂g/∂q in band storage. Returns false if a non-finite value appears.
bool assemble(const Problem& p, const Eigen::VectorXd& q, Eigen::VectorXd& g, BandMatrix* jac,
              bool drag_jacobian = true) {
  ancf::LoadContext load = p.load;
  load.drag_jacobian = drag_jacobian;
  g.setZero(p.n_dofs);
  if (jac) *jac = BandMatrix(p.n_dofs, p.band, p.band);
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    const auto blocks = element_blocks(p, e);
    std::array<int, kElementDofs> dof;
    for (int k = 0; k < kElementDofs; ++k) dof[k] = blocks[static_cast<std::size_t>(k / 3)] + k % 3;
    if (jac) {
      using D = Dual<kElementDofs>;
      std::array<D, kElementDofs> qd, gd;
      for (int k = 0; k < kElementDofs; ++k) qd[k] = D::seed(q[dof[k]], k);
      ancf::element_forces<D>(p.elements[e], load, qd.data(), gd.data());
      for (int i = 0; i < kElementDofs; ++i) {
        g[dof[i]] += gd[i].v;
        for (int j = 0; j < kElementDofs; ++j) jac->at(dof[i], dof[j]) += gd[i].d[j];
      }
    } else {
      std::array<double, kElementDofs> qe, ge;
      for (int k = 0; k < kElementDofs; ++k) qe[k] = q[dof[k]];
      ancf::element_forces<double>(p.elements[e], p.load, qe.data(), ge.data());
      for (int i = 0; i < kElementDofs; ++i) g[dof[i]] += ge[i];
    }
  }
  for (const auto& [node, f] : p.mesh.point_loads) g[p.r_dof[static_cast<std::size_t>(node)] + 2] -= f;
  return g.allFinite();
}

/// Max force residual over free DOFs, slope residuals (N·m) divided by the
/// local element length so that both are forces.
double residual_norm(const Problem& p, const Eigen::VectorXd& g) {
  double r = 0.0;
  for (int i = 0; i < p.n_dofs; ++i) {
    if (!is_fixed(p, i)) r = std::max(r, std::abs(g[i]) * p.dof_scale[static_cast<std::size_t>(i)]);
  }
  return r;
}

double merit(const Problem& p, const Eigen::VectorXd& g) {
  double m = 0.0;
  for (int i = 0; i < p.n_dofs; ++i) {
    if (is_fixed(p, i)) continue;
    const double f = g[i] * p.dof_scale[static_cast<std::size_t>(i)];
    m += f * f;
  }
  return m;
}

double max_axial_force(const Problem& p, const Eigen::VectorXd& q) {
  double t = 0.0;
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    const double EA = p.elements[e].EA_N;
    t = std::max(t, std::abs(EA * (q.segment<3>(p.t_out[e]).norm() - 1.0)));
    t = std::max(t, std::abs(EA * (q.segment<3>(p.t_in[e + 1]).norm() - 1.0)));
  }
  return t;
}

constexpr double kShortStep = 0.05;
constexpr int kWatchdogSteps = 2;
constexpr double kSevereStepLimit = 0.1;
constexpr double kFirstAxialCap = 10.0;  // × the largest tension
constexpr int kMaxShortSteps = 4;

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
  double residual_N = 0.0;
  double scale_N = 0.0;
};

/// Newton–Raphson with backtracking line search. With give_up_when_crawling,
/// returns unconverged after kMaxShortSteps consecutive steps shorter than
/// kShortStep of the Newton step: the linear step of a large rotation (a line
/// swung by a cross current) stretches the line spuriously, the line search
/// cuts it to a sliver, and Newton would crawl — the caller then continues the
/// load in smaller increments instead.
NewtonOutcome newton(const Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q,
                     bool give_up_when_crawling = false) {
  NewtonOutcome out;
  int short_steps = 0;
  Eigen::VectorXd g(p.n_dofs), g_trial(p.n_dofs), q_trial(p.n_dofs), dq(p.n_dofs);
  BandMatrix jac;
  if (!assemble(p, q, g, &jac)) return out;
  for (int it = 0;; ++it) {
    out.scale_N = std::max(p.load_scale_N, max_axial_force(p, q));
    out.residual_N = residual_norm(p, g);
    out.iterations = it;
    if (out.residual_N <= std::max(o.relative_force_tolerance * out.scale_N, p.round_off_floor_N)) {
      out.converged = true;
      return out;
    }
    if (it >= o.max_iterations) return out;
    for (int i = 0; i < p.n_dofs; ++i) {
      if (is_fixed(p, i)) jac.set_identity_row(i);
    }
    dq = -g;
    for (int i = 0; i < p.n_dofs; ++i) {
      if (is_fixed(p, i)) dq[i] = 0.0;
    }
    if (!jac.factorize()) return out;
    jac.solve_in_place(dq);
    if (!dq.allFinite()) return out;
    // Step limits: nodes move at most a tenth of the line length, slopes change
    // by at most 0.5 per step (keeps |r'| away from 0, where the strain measure
    // and the tangent are undefined).
    auto step_limit = [&p](const Eigen::VectorXd& d) {
      double limit = 1.0;
      for (std::size_t n = 0; n < static_cast<std::size_t>(p.n_nodes); ++n) {
        const double dr = d.segment<3>(p.r_dof[n]).norm();
        const double dt = std::max(d.segment<3>(p.t_in[n]).norm(), d.segment<3>(p.t_out[n]).norm());
        limit = std::min(limit, 0.1 * p.line_length_m / std::max(dr, 1e-300));
        limit = std::min(limit, 0.5 / std::max(dt, 1e-300));
      }
      return limit;
    };
    double limit = step_limit(dq);
    if (limit < kSevereStepLimit && p.load.current != nullptr && !p.load.current->empty() &&
        p.load.current_factor > 0.0) {
      // A near-singular tangent: the drag's dependence on the line's
      // orientation (a follower-load stiffness, not symmetric) can cancel the
      // small swing stiffness that gravity gives a hanging line, so the
      // Newton step explodes. Far from equilibrium, step with the drag held
      // as a dead load instead (structure + gravity + seabed tangent); the
      // full tangent returns, with quadratic convergence, once steps are sane.
      BandMatrix jac_dead;
      Eigen::VectorXd g_dead(p.n_dofs), dq_dead(p.n_dofs);
      if (assemble(p, q, g_dead, &jac_dead, false)) {
        for (int i = 0; i < p.n_dofs; ++i) {
          if (is_fixed(p, i)) jac_dead.set_identity_row(i);
        }
        dq_dead = -g;
        for (int i = 0; i < p.n_dofs; ++i) {
          if (is_fixed(p, i)) dq_dead[i] = 0.0;
        }
        if (jac_dead.factorize()) {
          jac_dead.solve_in_place(dq_dead);
          if (dq_dead.allFinite() && step_limit(dq_dead) > limit) {
            dq = dq_dead;
            limit = step_limit(dq);
            jac = std::move(jac_dead);
          }
        }
      }
    }
    // Step acceptance: the full step if it descends (Armijo on the scaled
    // residual); else a watchdog (Chamberlain et al., Math. Prog. Study 16,
    // 1982): up to kWatchdogSteps more full Newton steps, kept if the residual
    // has come below the starting one by then — the full step of a large
    // rotation leaves a spurious axial strain (≈ θ²/2 times EA) that makes
    // the residual jump although the step is right, and the next Newton step
    // removes it; else back to the starting point and backtracking (halving).
    const double m0 = merit(p, g);
    double alpha = limit;
    bool accepted = false;
    q_trial = q + limit * dq;
    const bool full_ok = assemble(p, q_trial, g_trial, nullptr);
    if (full_ok && merit(p, g_trial) <= (1.0 - 1e-4 * limit) * m0) {
      accepted = true;
    } else if (full_ok && limit == 1.0) {
      Eigen::VectorXd q_w = q_trial, g_w(p.n_dofs), dq_w(p.n_dofs);
      BandMatrix jac_w;
      for (int k = 0; k < kWatchdogSteps && !accepted; ++k) {
        if (!assemble(p, q_w, g_w, &jac_w)) break;
        for (int i = 0; i < p.n_dofs; ++i) {
          if (is_fixed(p, i)) jac_w.set_identity_row(i);
        }
        dq_w = -g_w;
        for (int i = 0; i < p.n_dofs; ++i) {
          if (is_fixed(p, i)) dq_w[i] = 0.0;
        }
        if (!jac_w.factorize()) break;
        jac_w.solve_in_place(dq_w);
        if (!dq_w.allFinite()) break;
        q_w += dq_w;
        ++it;  // a Newton iteration spent
        if (assemble(p, q_w, g_w, nullptr) && merit(p, g_w) <= (1.0 - 1e-4) * m0) {
          q_trial = q_w;
          g_trial = g_w;
          accepted = true;
        }
      }
    }
    for (int ls = 0; !accepted && ls < 30; ++ls, alpha *= 0.5) {
      q_trial = q + alpha * dq;
      if (!assemble(p, q_trial, g_trial, nullptr)) continue;
      if (merit(p, g_trial) <= (1.0 - 1e-4 * alpha) * m0) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      // No descent: at round-off level this is convergence in all but name;
      // otherwise report the failure to the caller.
      out.converged = out.residual_N <= 1e3 * o.relative_force_tolerance * out.scale_N;
      return out;
    }
    q = q_trial;
    short_steps = alpha < kShortStep ? short_steps + 1 : 0;
    if (give_up_when_crawling && short_steps >= kMaxShortSteps) {
      out.residual_N = residual_norm(p, g_trial);
      return out;
    }
    if (!assemble(p, q, g, &jac)) return out;
  }
}

/// Adopts node arc lengths from a previous solution of the same model: same
/// node count and the same section joints (only interior nodes may differ).
void set_node_arc_lengths(Problem& p, const std::vector<double>& s) {
  const auto n = static_cast<std::size_t>(p.n_nodes);
  bool ok = s.size() == n && s.front() == p.mesh.s.front() && s.back() == p.mesh.s.back();
  for (std::size_t i = 1; ok && i < n; ++i) {
    ok = s[i] > s[i - 1];
    if (i + 1 < n && p.mesh.section[i - 1] != p.mesh.section[i]) ok = ok && s[i] == p.mesh.s[i];
  }
  if (!ok) {
    invalid(fmt::format("warm_start_node_arc_length_m: must be the {} increasing node arc lengths of a "
                        "solution of this model, got {} values",
                        n, s.size()));
  }
  p.mesh.s = s;
  update_lengths(p);
}

Eigen::VectorXd initial_state(Problem& p, const FeLineModel& m, const FeEnvironment& env,
                              const FeLineEnds& ends, const FeStaticsOptions& o) {
  Eigen::VectorXd q(p.n_dofs);
  if (o.warm_start_state) {
    if (o.warm_start_state->size() != p.n_dofs || !o.warm_start_state->allFinite()) {
      invalid(fmt::format("warm_start_state: needs {} finite entries (this model's mesh), got {}", p.n_dofs,
                          o.warm_start_state->size()));
    }
    q = *o.warm_start_state;
    if (!o.warm_start_node_arc_length_m.empty()) set_node_arc_lengths(p, o.warm_start_node_arc_length_m);
    // Predictor: spread the end displacements along the line, linearly in arc
    // length, instead of moving the end nodes alone (which would strain the
    // end elements by the whole offset and cost Newton damped steps).
    const Eigen::Vector3d dA = ends.end_A_m - q.segment<3>(p.r_dof.front());
    const Eigen::Vector3d dB = ends.end_B_m - q.segment<3>(p.r_dof.back());
    for (std::size_t i = 0; i < static_cast<std::size_t>(p.n_nodes); ++i) {
      const double f = p.mesh.s[i] / p.line_length_m;
      q.segment<3>(p.r_dof[i]) += (1.0 - f) * dA + f * dB;
    }
  } else {
    const InitialShape catenary = default_initial_shape(m, env, ends.end_A_m, ends.end_B_m);
    std::function<Eigen::Vector3d(double)> shape = o.initial_shape ? o.initial_shape : catenary.position_m;
    for (std::size_t i = 0; i < static_cast<std::size_t>(p.n_nodes); ++i) q.segment<3>(p.r_dof[i]) = shape(p.mesh.s[i]);
    // Slopes: the derivative of the shape with respect to unstretched arc
    // length (central difference), which carries the stretch of a shape laid
    // out at its stretched length (the default ones are). Stretch and
    // positions must agree to ≪ T/EA, or the elements start in compression
    // and Newton crawls on an indefinite Jacobian. A user shape may be
    // inextensible (slack): then the stretch of the catenary tension H / cos θ
    // (capped at 10 H near vertical) is imposed if larger.
    const double delta = 1e-6 * p.line_length_m;
    for (std::size_t i = 0; i < static_cast<std::size_t>(p.n_nodes); ++i) {
      const double s0 = std::max(0.0, p.mesh.s[i] - delta), s1 = std::min(p.line_length_m, p.mesh.s[i] + delta);
      // One-sided at section joints (the stretch jumps with EA there).
      const bool joint = i > 0 && i + 1 < static_cast<std::size_t>(p.n_nodes) && p.t_in[i] != p.t_out[i];
      const Eigen::Vector3d d_in = (shape(p.mesh.s[i]) - shape(s0)) / (p.mesh.s[i] - s0 > 0 ? p.mesh.s[i] - s0 : 1.0);
      const Eigen::Vector3d d_out = (shape(s1) - shape(p.mesh.s[i])) / (s1 - p.mesh.s[i] > 0 ? s1 - p.mesh.s[i] : 1.0);
      const Eigen::Vector3d central = (shape(s1) - shape(s0)) / (s1 - s0);
      Eigen::Vector3d t_in = joint ? d_in : central, t_out = joint ? d_out : central;
      if (i == 0) t_in = t_out = d_out;
      if (i + 1 == static_cast<std::size_t>(p.n_nodes)) t_in = t_out = d_in;
      if (o.initial_shape) {
        auto seeded = [&](const Eigen::Vector3d& t, std::size_t e) {
          const Eigen::Vector3d u = t.normalized();
          const double cos_theta = std::max(std::hypot(u.x(), u.y()), 0.1);
          const double stretch = 1.0 + catenary.horizontal_tension_N / cos_theta / p.elements[e].EA_N;
          return Eigen::Vector3d(u * std::max(stretch, t.norm()));
        };
        t_in = seeded(t_in, i > 0 ? i - 1 : 0);
        t_out = seeded(t_out, std::min(i, p.elements.size() - 1));
      }
      q.segment<3>(p.t_in[i]) = t_in;
      q.segment<3>(p.t_out[i]) = t_out;
    }
    if (!q.allFinite()) invalid("initial_shape: returned non-finite positions");
  }
  // The ends are where the caller holds them.
  q.segment<3>(p.r_dof.front()) = ends.end_A_m;
  q.segment<3>(p.r_dof.back()) = ends.end_B_m;
  return q;
}

using ElementState = Eigen::Matrix<double, kElementDofs, 1>;

double curvature(const ancf::ShapeAt& sh, const ElementState& qe) {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    a += sh.dS[k] * qe.segment<3>(3 * k);
    b += sh.ddS[k] * qe.segment<3>(3 * k);
  }
  return a.cross(b).norm() / std::pow(a.norm(), 3);
}

Eigen::Vector3d position(const ancf::ShapeAt& sh, const ElementState& qe) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) r += sh.S[k] * qe.segment<3>(3 * k);
  return r;
}

Eigen::Vector3d slope(const ancf::ShapeAt& sh, const ElementState& qe) {
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) t += sh.dS[k] * qe.segment<3>(3 * k);
  return t;
}

// Penetrations below this fraction of the line length are round-off (an
// anchor placed exactly on the seabed), not contact.
constexpr double kContactRoundOff = 1e-12;

std::optional<FeTouchdown> find_touchdown(const Problem& p, const Eigen::VectorXd& q) {
  if (p.load.seabed_stiffness_N_per_m2 <= 0.0) return std::nullopt;
  const double zs = p.load.seabed_z_m;
  constexpr int kSamples = 64;  // per element, then bisection
  for (int e = static_cast<int>(p.elements.size()) - 1; e >= 0; --e) {
    const double L = p.elements[static_cast<std::size_t>(e)].length_m;
    const ElementState qe = gather(p, q, static_cast<std::size_t>(e));
    for (int j = kSamples; j >= 0; --j) {
      const double xi = static_cast<double>(j) / kSamples;
      if (position(ancf::shape_at(xi, L), qe).z() < zs - kContactRoundOff * p.line_length_m) {
        double lo = xi, hi = std::min(1.0, xi + 1.0 / kSamples);
        if (j == kSamples) hi = lo;
        for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
          const double mid = 0.5 * (lo + hi);
          (position(ancf::shape_at(mid, L), qe).z() < zs - kContactRoundOff * p.line_length_m ? lo : hi) = mid;
        }
        FeTouchdown td;
        td.arc_length_m = p.mesh.s[static_cast<std::size_t>(e)] + lo * L;
        td.position_m = position(ancf::shape_at(lo, L), qe);
        return td;
      }
    }
  }
  return std::nullopt;
}

FeStaticsResult post_process(const Problem& p, const FeStaticsOptions& o, const Eigen::VectorXd& q) {
  FeStaticsResult r;
  const int nn = p.n_nodes;
  r.state = q;
  r.node_arc_length_m = p.mesh.s;
  Eigen::VectorXd g(p.n_dofs);
  BandMatrix jac;
  assemble(p, q, g, o.compute_end_B_stiffness ? &jac : nullptr);
  r.node_position_m.resize(static_cast<std::size_t>(nn));
  r.node_tension_N.resize(static_cast<std::size_t>(nn));
  r.node_force_residual_N.resize(static_cast<std::size_t>(nn));
  r.node_curvature_per_m.assign(static_cast<std::size_t>(nn), 0.0);
  r.node_bending_moment_Nm.assign(static_cast<std::size_t>(nn), 0.0);
  std::vector<int> count(static_cast<std::size_t>(nn), 0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(nn); ++i) {
    r.node_position_m[i] = q.segment<3>(p.r_dof[i]);
    r.node_force_residual_N[i] = g.segment<3>(p.r_dof[i]);
    // Mean of the two sides' EA (|r'| − 1) (equal up to the discretisation;
    // at a hinge joint each side has its own EA and slope).
    double sum = 0.0;
    int cnt = 0;
    if (i > 0) sum += p.elements[i - 1].EA_N * (q.segment<3>(p.t_in[i]).norm() - 1.0), ++cnt;
    if (i + 1 < static_cast<std::size_t>(nn)) sum += p.elements[i].EA_N * (q.segment<3>(p.t_out[i]).norm() - 1.0), ++cnt;
    r.node_tension_N[i] = sum / cnt;
  }
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    const double L = p.elements[e].length_m;
    const ElementState qe = gather(p, q, e);
    r.element_tension_N.push_back(p.elements[e].EA_N * (slope(ancf::shape_at(0.5, L), qe).norm() - 1.0));
    for (int end = 0; end < 2; ++end) {
      const std::size_t node = e + static_cast<std::size_t>(end);
      const double k = curvature(ancf::shape_at(end, L), qe);
      r.node_curvature_per_m[node] += k;
      r.node_bending_moment_Nm[node] += p.elements[e].EI_Nm2 * k;
      ++count[node];
    }
  }
  for (int i = 0; i < nn; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    r.node_curvature_per_m[ui] /= count[ui];
    r.node_bending_moment_Nm[ui] /= count[ui];
  }
  r.end_A_force_N = r.node_force_residual_N.front();
  r.end_B_force_N = r.node_force_residual_N.back();
  // End tensions: axial components of the end reactions (more accurate than
  // the strain of the free end slope, which converges more slowly).
  r.node_tension_N.front() = r.end_A_force_N.dot(q.segment<3>(p.t_out.front()).normalized());
  r.node_tension_N.back() = -r.end_B_force_N.dot(q.segment<3>(p.t_in.back()).normalized());
  r.touchdown = find_touchdown(p, q);

  if (o.compute_end_B_stiffness) {
    // Static condensation: K = J_bb − J_bf J_ff⁻¹ J_fb (b: end-B position DOFs).
    const int b0 = p.r_dof.back();
    Eigen::Matrix<double, 3, Eigen::Dynamic> rows_b(3, p.n_dofs);
    rows_b.setZero();
    Eigen::MatrixXd cols_b = Eigen::MatrixXd::Zero(p.n_dofs, 3);
    for (int k = 0; k < 3; ++k) {
      for (int j = 0; j < p.n_dofs; ++j) {
        if (jac.in_band(b0 + k, j)) rows_b(k, j) = jac.at(b0 + k, j);
        if (jac.in_band(j, b0 + k) && !is_fixed(p, j)) cols_b(j, k) = jac.at(j, b0 + k);
      }
    }
    for (int i = 0; i < p.n_dofs; ++i) {
      if (is_fixed(p, i)) jac.set_identity_row(i);
    }
    Eigen::Matrix3d k_bb = rows_b.middleCols<3>(b0);
    if (jac.factorize()) {
      for (int k = 0; k < 3; ++k) jac.solve_in_place(cols_b.col(k));
      r.end_B_stiffness_N_per_m = k_bb - rows_b * cols_b;
    }
  }
  return r;
}


struct Counters {
  int iterations = 0;
  int load_steps = 0;
  int remeshes = 0;
};

/// Newton at the full current; if that fails, continuation on the current
/// factor from 0 with adaptive steps (the drag load is what moves the line far
/// from its initial shape).
/// Caps every element's EA at cap_N (infinity restores the model's EA).
void cap_axial_stiffness(Problem& p, double cap_N) {
  for (std::size_t e = 0; e < p.elements.size(); ++e) p.elements[e].EA_N = std::min(p.EA_true_N[e], cap_N);
}

/// Continuation on the current velocity factor λ (drag ∝ λ²) from the state
/// converged at λ = 0: steps grow by half after a success, halve after a
/// failure. Leaves current_factor at 1.
NewtonOutcome current_continuation(Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q,
                                   Counters& counters) {
  p.load.current_factor = 0.0;
  NewtonOutcome last = newton(p, o, q);
  counters.iterations += last.iterations;
  ++counters.load_steps;
  double lambda = 0.0, step = 0.25;
  int halvings = 0;
  while (last.converged && lambda < 1.0) {
    const Eigen::VectorXd q_prev = q;
    p.load.current_factor = std::min(1.0, lambda + step);
    last = newton(p, o, q, true);
    counters.iterations += last.iterations;
    ++counters.load_steps;
    if (last.converged) {
      lambda = p.load.current_factor;
      step *= 1.5;
    } else if (halvings < o.max_load_step_halvings) {
      q = q_prev;
      step *= 0.5;
      ++halvings;
      last.converged = true;  // retry with the smaller step
    }
  }
  p.load.current_factor = 1.0;
  return last;
}

/// Newton at the full current; if it crawls or fails:
/// (1) current continuation with EA capped at kFirstAxialCap × the largest
///     tension, then the cap raised ×10 per stage to the model's EA at full
///     current. Why: a current swings the line through a large angle θ, and
///     Newton's linear step for a rotation stretches the elements by ≈ θ²/2;
///     with EA ≫ T that spurious strain dominates the residual and the line
///     search cuts the step to ≈ √(2T/EA)/θ of itself (0.01 rad per step for a
///     flexible riser). With EA ≈ 10 T a step can turn the line by ≈ 0.5 rad;
///     raising EA afterwards changes the shape only by the stretch.
/// (2) if that fails, current continuation with the model's EA.
NewtonOutcome solve_with_current_steps(Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q,
                                       Counters& counters) {
  const bool has_current = p.load.current != nullptr && !p.load.current->empty();
  const Eigen::VectorXd q_start = q;
  p.load.current_factor = 1.0;
  NewtonOutcome last = newton(p, o, q, has_current);
  counters.iterations += last.iterations;
  ++counters.load_steps;
  if (last.converged || !has_current) return last;

  q = q_start;
  const double T_start = max_axial_force(p, q_start);
  const double T_ref = T_start > 0.0 ? T_start : p.load_scale_N;
  const double EA_max = *std::max_element(p.EA_true_N.begin(), p.EA_true_N.end());
  FeStaticsOptions loose = o;
  loose.relative_force_tolerance = std::max(o.relative_force_tolerance, 1e-6);
  cap_axial_stiffness(p, kFirstAxialCap * T_ref);
  last = current_continuation(p, loose, q, counters);
  for (double cap = 10.0 * kFirstAxialCap * T_ref; last.converged; cap *= 10.0) {
    const bool final_stage = cap >= EA_max;
    cap_axial_stiffness(p, final_stage ? INFINITY : cap);
    last = newton(p, final_stage ? o : loose, q, true);
    counters.iterations += last.iterations;
    ++counters.load_steps;
    if (final_stage) break;
  }
  cap_axial_stiffness(p, INFINITY);
  if (last.converged) return last;

  q = q_start;
  return current_continuation(p, o, q, counters);
}

struct TouchdownTarget {
  double arc_length_m = 0.0;
  double tolerance_m = 0.0;
};

/// Where the touchdown node should sit, given the lift-off point s_lift of
/// the current solution. A cable (EI = 0) on a penalty seabed of stiffness k
/// under tension T: on the bed T z'' = k (z − z_b) + w gives a boundary layer
/// ℓ = √(T/k); the suspended cubic leaves its node at z_b − w/k with zero
/// slope and curvature w/T, so it crosses z_b at √(2 w/(k κ)) = √2 ℓ beyond the
/// node: the node goes there. With bending (EI > 0) the beam-on-foundation
/// layer (4EI/k)^¼ (Hetényi 1946) and the TDP boundary layer √(EI/T) (Pesce et
/// al. 1998) are resolved by the mesh, not by this shift: the node goes to the
/// lift-off point. Tolerance: a tenth of the layer, at least 1e-4 element.
TouchdownTarget touchdown_node_target(const Problem& p, const Eigen::VectorXd& q, double s_lift) {
  const double k = p.load.seabed_stiffness_N_per_m2;
  std::size_t e = 0;
  while (e + 1 < p.elements.size() && p.mesh.s[e + 1] < s_lift) ++e;
  const auto& el = p.elements[e];
  const double stretch = q.segment<3>(p.t_out[e]).norm();
  const double T = std::max(0.0, el.EA_N * (stretch - 1.0));
  const double cable_layer = std::sqrt(T / k);
  if (el.EI_Nm2 > 0.0) {
    const double beam_layer = std::max(std::pow(4.0 * el.EI_Nm2 / k, 0.25), cable_layer);
    return {s_lift, 0.1 * beam_layer};
  }
  return {s_lift - std::sqrt(2.0) * cable_layer, 0.01 * cable_layer};
}

/// Moves the interior node nearest to arc length s_new (not an end, not a
/// section joint) onto it, re-interpolating the state with the Hermite shape
/// functions. Returns false if no node moves (already there within 1e-4 of an
/// element or tolerance_m, or no movable node).
/// The interior node nearest to arc length s_new that may move there (not an
/// end, not a section joint, s_new strictly between its neighbours); −1 if none.
int nearest_movable_node(const Problem& p, double s_new) {
  const auto& s = p.mesh.s;
  int best = -1;
  double dist = INFINITY;
  for (int i = 1; i + 1 < p.n_nodes; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    if (p.mesh.section[ui - 1] != p.mesh.section[ui]) continue;  // section joint
    if (s_new <= s[ui - 1] || s_new >= s[ui + 1]) continue;
    if (std::abs(s[ui] - s_new) < dist) {
      dist = std::abs(s[ui] - s_new);
      best = i;
    }
  }
  return best;
}

bool move_node_to(Problem& p, Eigen::VectorXd& q, double s_new, double tolerance_m) {
  auto& s = p.mesh.s;
  const int best = nearest_movable_node(p, s_new);
  if (best < 0) return false;
  const double dist = std::abs(s[static_cast<std::size_t>(best)] - s_new);
  const auto ub = static_cast<std::size_t>(best);
  if (dist < std::max(tolerance_m, 1e-4 * std::min(s[ub] - s[ub - 1], s[ub + 1] - s[ub]))) return false;
  // The new node's state from the element that contains s_new.
  const std::size_t e = s_new < s[ub] ? ub - 1 : ub;
  const double L = s[e + 1] - s[e];
  const auto sh = ancf::shape_at((s_new - s[e]) / L, L);
  const ElementState qe = gather(p, q, e);
  q.segment<3>(p.r_dof[ub]) = position(sh, qe);
  q.segment<3>(p.t_in[ub]) = slope(sh, qe);  // not a joint: t_in == t_out
  s[ub] = s_new;
  update_lengths(p);
  return true;
}

constexpr int kFinalSnapPasses = 10;
constexpr int kDirectAttemptIterations = 12;

/// Touchdown node: move the nearest interior node onto the touchdown point
/// and re-solve, until it stays put (touchdown_node_target). A cubic element
/// cannot follow "flat, then curved" inside itself; with a node there the
/// laid elements are straight and the suspended ones smooth, which restores
/// most of the element's accuracy (header numbers).
NewtonOutcome snap_touchdown(Problem& p, const FeStaticsOptions& o, Eigen::VectorXd& q, Counters& counters,
                             int max_passes) {
  NewtonOutcome last;
  last.converged = true;
  bool moved = false;
  // The node position s solves s = target(s), a contraction with a factor near
  // 0.8 here: secant steps on f(s) = target(s) − s (Aitken) from the second
  // pass on, plain fixed-point steps when the secant is not usable.
  double s_prev = NAN, f_prev = NAN;
  for (int pass = 0; o.snap_node_to_touchdown && pass < max_passes; ++pass) {
    const auto td = find_touchdown(p, q);
    if (!td) break;
    const TouchdownTarget target = touchdown_node_target(p, q, td->arc_length_m);
    const int node = nearest_movable_node(p, target.arc_length_m);
    if (node < 0) break;
    const double s_node = p.mesh.s[static_cast<std::size_t>(node)];
    const double f = target.arc_length_m - s_node;
    double s_new = target.arc_length_m;
    if (std::isfinite(f_prev) && f != f_prev) {
      const double secant = s_node - f * (s_node - s_prev) / (f - f_prev);
      if (std::abs(secant - s_node) < 50.0 * std::abs(f)) s_new = secant;
    }
    s_prev = s_node;
    f_prev = f;
    if (std::abs(f) < target.tolerance_m) break;
    if (!move_node_to(p, q, s_new, 0.0)) break;
    moved = true;
    ++counters.remeshes;
    last = solve_with_current_steps(p, o, q, counters);
    if (!last.converged) break;
  }
  if (!moved) last = newton(p, o, q);  // already converged: returns at once with its diagnostics
  return last;
}

}  // namespace

std::vector<double> fe_line_mesh(const FeLineModel& model) {
  validate(model, FeEnvironment{}, FeLineEnds{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()}, {});
  return build_mesh(model).s;
}

FeStaticsResult solve_fe_line_statics(const FeLineModel& model, const FeEnvironment& environment,
                                      const FeLineEnds& ends, const FeStaticsOptions& options) {
  validate(model, environment, ends, options);
  Problem p = make_problem(model, environment, ends);
  Eigen::VectorXd q = initial_state(p, model, environment, ends, options);

  Counters counters;
  NewtonOutcome last;
  const double k_target = environment.seabed_stiffness_N_per_m2;
  bool done = false;
  if (options.warm_start_state) {
    last = solve_with_current_steps(p, options, q, counters);
    if (last.converged) last = snap_touchdown(p, options, q, counters, kFinalSnapPasses);
    done = last.converged;
    if (!done) {
      p = make_problem(model, environment, ends);
      q = initial_state(p, model, environment, ends, FeStaticsOptions{});
    }
  }
  if (!done && k_target > 0.0) {
    // Direct attempt at the final seabed stiffness from the default shape
    // (which already lies on the seabed where the catenary would): usually
    // converges; a bounded number of iterations, then the continuation below.
    const Eigen::VectorXd q0 = q;
    FeStaticsOptions direct = options;
    direct.max_iterations = std::min(options.max_iterations, kDirectAttemptIterations);
    Counters trial;
    last = solve_with_current_steps(p, direct, q, trial);
    if (last.converged) last = snap_touchdown(p, options, q, trial, kFinalSnapPasses);
    counters.iterations += trial.iterations;
    counters.load_steps += trial.load_steps;
    counters.remeshes += trial.remeshes;
    done = last.converged;
    if (!done) {
      p = make_problem(model, environment, ends);
      q = q0;
    }
  }
  if (!done) {
    // Continuation on the seabed stiffness: start soft (penetration ≈ 1 % of
    // an element under the heaviest section's weight), then ×10 per stage,
    // intermediate stages to a loose tolerance. A stiff penalty against a
    // coarse cable mesh is a stiff, non-smooth system; each stage starts
    // inside the next one's convergence basin.
    double k = k_target;
    double h_min = INFINITY;
    if (k_target > 0.0) {
      double w_max = 0.0, h_max = 0.0;
      for (const auto& e : p.elements) {
        w_max = std::max(w_max, std::abs(e.weight_N_per_m));
        h_max = std::max(h_max, e.length_m);
        h_min = std::min(h_min, e.length_m);
      }
      k = std::min(k_target, 100.0 * w_max / h_max);
    }
    FeStaticsOptions stage_options = options;
    stage_options.relative_force_tolerance = std::max(options.relative_force_tolerance, 1e-6);
    for (;;) {
      p.load.seabed_stiffness_N_per_m2 = k;
      const bool final_stage = k >= k_target;
      last = solve_with_current_steps(p, final_stage ? options : stage_options, q, counters);
      if (!last.converged) break;
      if (final_stage) {
        last = snap_touchdown(p, options, q, counters, kFinalSnapPasses);
        break;
      }
      // One early move once the penalty layer fits inside an element, so the
      // final stage starts with the node near the touchdown point.
      const auto td = find_touchdown(p, q);
      if (td && touchdown_node_target(p, q, td->arc_length_m).tolerance_m < 0.01 * h_min) {
        last = snap_touchdown(p, stage_options, q, counters, 1);
        if (!last.converged) break;
      }
      k = std::min(k_target, 10.0 * k);
    }
  }
  if (!last.converged) {
    SolverDiagnostics d{counters.iterations, last.residual_N, "N"};
    // A line on the seabed from A that is longer than span + height has no
    // taut equilibrium on a frictionless seabed (it would have to fold).
    const Eigen::Vector3d AB = ends.end_B_m - ends.end_A_m;
    const double slack_length_m = std::hypot(AB.x(), AB.y()) + AB.z();
    const bool a_on_seabed = environment.seabed_stiffness_N_per_m2 > 0.0 &&
                             ends.end_A_m.z() <= environment.seabed_z_m + 1e-6 * p.line_length_m;
    const std::string slack =
        a_on_seabed && p.line_length_m >= slack_length_m
            ? fmt::format(" The line is slack: its length {:.2f} m is at least its horizontal span plus "
                          "height, {:.2f} m, so it has no taut equilibrium on a frictionless seabed; "
                          "shorten it or move the ends apart.",
                          p.line_length_m, slack_length_m)
            : std::string();
    throw SolverError(
        fmt::format("FE line statics did not converge: {} Newton iterations, {} Newton solves (continuation "
                    "stages), force residual {:.4g} N against a tolerance of {:.4g} N.{} Try: check that the "
                    "end positions are reachable (line length vs. span, no slack or compressed line), "
                    "refine the mesh, give a better initial shape (catenary) or more iterations.",
                    counters.iterations, counters.load_steps, last.residual_N,
                    options.relative_force_tolerance * last.scale_N, slack),
        d);
  }
  FeStaticsResult r = post_process(p, options, q);
  r.iterations = counters.iterations;
  r.load_steps = counters.load_steps;
  r.touchdown_remeshes = counters.remeshes;
  r.residual_N = last.residual_N;
  r.force_scale_N = last.scale_N;
  return r;
}

}  // namespace spiral::engine
