// The discrete FE line problem: input validation, mesh, DOF map, initial
// state, assembly of the nodal forces and their Jacobian, touchdown search.
// See fe_line_problem.hpp (internal) and fe_line_statics.hpp (formulation).

#include "engine/lines/fe_line_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "engine/lines/fe_line_initial_shape.hpp"

namespace spiral::engine::fe_detail {
namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

}  // namespace

[[noreturn]] void invalid(const std::string& what) { throw SolverError("FE line statics: invalid input: " + what); }

void validate(const FeLineModel& m, const FeEnvironment& env, const FeLineEnds& ends, const FeStaticsOptions& o) {
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
    invalid(fmt::format("joint_load_N: needs {} entries (one per joint) or none, got {}", m.sections.size() - 1,
                        m.joint_load_N.size()));
  }
  for (std::size_t i = 0; i < m.joint_load_N.size(); ++i) {
    if (!std::isfinite(m.joint_load_N[i])) invalid(fmt::format("joint_load_N[{}]: must be finite", i));
  }
  if (m.refinement) {
    const auto& z = *m.refinement;
    if (!(z.length_m > 0.0) || !(z.element_length_m > 0.0) || !std::isfinite(z.start_arc_length_m)) {
      invalid(fmt::format("refinement: needs length_m > 0 and element_length_m > 0, got {} and {}", z.length_m,
                          z.element_length_m));
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
ElementState gather(const Problem& p, const Eigen::VectorXd& q, std::size_t e) {
  ElementState qe;
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

/// Net generalised forces g(q) (6 per node) and, if jac != nullptr, the
/// Jacobian ∂g/∂q in band storage. Returns false if a non-finite value appears.
bool assemble(const Problem& p, const Eigen::VectorXd& q, Eigen::VectorXd& g, BandMatrix* jac, bool drag_jacobian) {
  ancf::LoadContext load = p.load;
  load.drag_jacobian = drag_jacobian;
  g.setZero(p.n_dofs);
  if (jac) jac->reset(p.n_dofs, p.band, p.band);
  ancf::ElementTangent ke;
  // A line's elements mostly share a length (a section's mesh is uniform
  // away from the touchdown node): the shapes are laid out once per length.
  ancf::GaussPointRows rows;
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    const auto blocks = element_blocks(p, e);
    std::array<int, kElementDofs> dof;
    std::array<double, kElementDofs> qe, ge;
    for (int k = 0; k < kElementDofs; ++k) {
      dof[k] = blocks[static_cast<std::size_t>(k / 3)] + k % 3;
      qe[k] = q[dof[k]];
    }
    if (jac) {
      ancf::element_forces_and_tangent(p.elements[e], load, qe.data(), ge.data(), ke);
      for (int i = 0; i < kElementDofs; ++i) {
        g[dof[i]] += ge[i];
        for (int j = 0; j < kElementDofs; ++j)
          jac->at(dof[i], dof[j]) += ke[static_cast<std::size_t>(kElementDofs * i + j)];
      }
    } else {
      if (rows.length_m != p.elements[e].length_m) rows.set(p.elements[e].length_m);
      ancf::element_forces_side_by_side(p.elements[e], p.load, rows, qe.data(), ge.data());
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
    invalid(
        fmt::format("warm_start_node_arc_length_m: must be the {} increasing node arc lengths of a "
                    "solution of this model, got {} values",
                    n, s.size()));
  }
  p.mesh.s = s;
  update_lengths(p);
}

Eigen::VectorXd initial_state(Problem& p, const FeLineModel& m, const FeEnvironment& env, const FeLineEnds& ends,
                              const FeStaticsOptions& o) {
  Eigen::VectorXd q(p.n_dofs);
  if (o.warm_start_state) {
    if (o.warm_start_state->size() != p.n_dofs || !o.warm_start_state->allFinite()) {
      invalid(fmt::format("warm_start_state: needs {} finite entries (this model's mesh), got {}", p.n_dofs,
                          o.warm_start_state->size()));
    }
    q = *o.warm_start_state;
    if (!o.warm_start_node_arc_length_m.empty()) set_node_arc_lengths(p, o.warm_start_node_arc_length_m);
    // Predictor: the first-order response to the end displacements, from the
    // warm solution's factorised tangent (its prescribed rows are identity
    // rows, so J δq = [0; δ_ends] gives δq_free = −J_ff⁻¹ J_fe δ_ends: one
    // back-substitution; the Euler predictor of a continuation in the end
    // positions). Without that tangent: the end displacements spread along
    // the line, linearly in arc length, instead of moving the end nodes alone
    // (which would strain the end elements by the whole offset and cost
    // Newton damped steps).
    const Eigen::Vector3d dA = ends.end_A_m - q.segment<3>(p.r_dof.front());
    const Eigen::Vector3d dB = ends.end_B_m - q.segment<3>(p.r_dof.back());
    Eigen::VectorXd dq = Eigen::VectorXd::Zero(p.n_dofs);
    const bool tangent = o.warm_start_tangent && o.warm_start_tangent->lu.size() == p.n_dofs;
    if (tangent) {
      dq.segment<3>(p.r_dof.front()) = dA;
      dq.segment<3>(p.r_dof.back()) = dB;
      o.warm_start_tangent->lu.solve_in_place(dq);
    }
    if (tangent && dq.allFinite()) {
      q += dq;
    } else {
      for (std::size_t i = 0; i < static_cast<std::size_t>(p.n_nodes); ++i) {
        const double f = p.mesh.s[i] / p.line_length_m;
        q.segment<3>(p.r_dof[i]) += (1.0 - f) * dA + f * dB;
      }
    }
  } else {
    const InitialShape catenary = default_initial_shape(m, env, ends.end_A_m, ends.end_B_m);
    std::function<Eigen::Vector3d(double)> shape = o.initial_shape ? o.initial_shape : catenary.position_m;
    const bool equilibrium = o.initial_shape && o.initial_shape_is_equilibrium;
    if (equilibrium && !o.warm_start_node_arc_length_m.empty()) set_node_arc_lengths(p, o.warm_start_node_arc_length_m);
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
      // An equilibrium's shape carries its own stretch.
      if (o.initial_shape && !equilibrium) {
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

NodeBending node_bending(const Problem& p, const Eigen::VectorXd& q) {
  const auto nn = static_cast<std::size_t>(p.n_nodes);
  NodeBending b;
  b.curvature_per_m.assign(nn, 0.0);
  b.moment_Nm.assign(nn, 0.0);
  std::vector<int> count(nn, 0);
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    const double L = p.elements[e].length_m;
    const ElementState qe = gather(p, q, e);
    for (int end = 0; end < 2; ++end) {
      const std::size_t node = e + static_cast<std::size_t>(end);
      const double k = curvature(ancf::shape_at(end, L), qe);
      b.curvature_per_m[node] += k;
      b.moment_Nm[node] += p.elements[e].EI_Nm2 * k;
      ++count[node];
    }
  }
  for (std::size_t i = 0; i < nn; ++i) {
    b.curvature_per_m[i] /= count[i];
    b.moment_Nm[i] /= count[i];
  }
  return b;
}

std::optional<FeTouchdown> find_touchdown(const Problem& p, const Eigen::VectorXd& q) {
  if (p.load.seabed_stiffness_N_per_m2 <= 0.0) return std::nullopt;
  const double zs = p.load.seabed_z_m;
  constexpr int kSamples = 64;  // per element, then bisection
  const double z_contact = zs - kContactRoundOff * p.line_length_m;
  for (int e = static_cast<int>(p.elements.size()) - 1; e >= 0; --e) {
    const double L = p.elements[static_cast<std::size_t>(e)].length_m;
    const ElementState qe = gather(p, q, static_cast<std::size_t>(e));
    // The cubic lies in the convex hull of its Bézier points r_a, r_a + L/3
    // r'_a, r_b − L/3 r'_b, r_b: none below the seabed, no sample can be.
    const double z_min = std::min({qe[2], qe[2] + L / 3.0 * qe[5], qe[8] - L / 3.0 * qe[11], qe[8]});
    if (z_min >= z_contact) continue;
    for (int j = kSamples; j >= 0; --j) {
      const double xi = static_cast<double>(j) / kSamples;
      if (position(ancf::shape_at(xi, L), qe).z() < z_contact) {
        double lo = xi, hi = std::min(1.0, xi + 1.0 / kSamples);
        if (j == kSamples) hi = lo;
        for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
          const double mid = 0.5 * (lo + hi);
          (position(ancf::shape_at(mid, L), qe).z() < z_contact ? lo : hi) = mid;
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

/// Caps every element's EA at cap_N (infinity restores the model's EA).
void cap_axial_stiffness(Problem& p, double cap_N) {
  for (std::size_t e = 0; e < p.elements.size(); ++e) p.elements[e].EA_N = std::min(p.EA_true_N[e], cap_N);
}

}  // namespace spiral::engine::fe_detail
