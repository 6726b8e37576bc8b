#include "engine/analysis/fe_static_line.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace spiral::engine {

namespace {
// A node counts as resting on the seabed within this distance above it (m):
// the penalty contact lets the laid part sink by w/k (millimetres).
constexpr double kOnSeabedTolerance_m = 0.05;
// Arc-length slack (m) when assigning a node on a joint to a section.
constexpr double kJointSlack_m = 1e-9;
}  // namespace

std::vector<int> node_sections(const FeLineModel& model, const FeStaticsResult& result) {
  std::vector<int> sections;
  sections.reserve(result.node_arc_length_m.size());
  double section_end_m = model.sections.empty() ? 0.0 : model.sections.front().length_m;
  std::size_t section = 0;
  for (const double arc : result.node_arc_length_m) {
    while (section + 1 < model.sections.size() && arc > section_end_m + kJointSlack_m) {
      section_end_m += model.sections[++section].length_m;
    }
    sections.push_back(static_cast<int>(section));
  }
  return sections;
}

FeStaticLine::FeStaticLine(std::string name, Eigen::Vector3d end_A_g, Eigen::Vector3d attachment_b, FeLineModel model,
                           FeEnvironment environment, FeStaticsOptions options)
    : name_(std::move(name)),
      end_A_g_(std::move(end_A_g)),
      attachment_b_(std::move(attachment_b)),
      model_(std::move(model)),
      environment_(std::move(environment)),
      options_(std::move(options)) {}

const FeStaticsResult& FeStaticLine::keep(const Eigen::Vector3d& attachment_g, FeStaticsResult solution) {
  if (solution.has_end_B_stiffness) {
    recent_stiffness_ = solution.end_B_stiffness_N_per_m;
    recent_stiffness_at_g_ = attachment_g;
  }
  last_ = std::make_shared<const FeStaticsResult>(std::move(solution));
  last_attachment_g_ = attachment_g;
  warm_ = last_;
  return *last_;
}

const FeStaticsResult& FeStaticLine::solve_at(const Eigen::Vector3d& attachment_g, bool stiffness) {
  if (last_ && attachment_g == last_attachment_g_) {
    if (!stiffness || last_->has_end_B_stiffness) return *last_;
    try {
      return keep(attachment_g, with_end_B_stiffness(model_, environment_, *last_));
    } catch (const SolverError& error) {
      throw SolverError(fmt::format("line '{}': {}", name_, error.what()), error.diagnostics());
    }
  }
  // A failed trial (e.g. a hull line-search step too far) leaves the warm
  // start at the last converged solution, not at a cold start.
  FeStaticsOptions options = options_;
  options.compute_end_B_stiffness = stiffness;
  if (warm_) warm_start_from(options, *warm_);
  last_.reset();
  try {
    return keep(attachment_g, solve_fe_line_statics(model_, environment_, {end_A_g_, attachment_g}, options));
  } catch (const SolverError& error) {
    throw SolverError(fmt::format("line '{}': {}", name_, error.what()), error.diagnostics());
  }
}

void FeStaticLine::adopt(const Eigen::Vector3d& attachment_g, FeStaticsResult solution) {
  if (solution.node_arc_length_m.size() != fe_line_mesh(model_).size()) {
    throw std::invalid_argument(fmt::format("line '{}': adopted solution has {} nodes, the model {}", name_,
                                            solution.node_arc_length_m.size(), fe_line_mesh(model_).size()));
  }
  keep(attachment_g, std::move(solution));
}

void FeStaticLine::adopt(const FeStaticLine& source) {
  if (!source.last_) throw std::invalid_argument(fmt::format("line '{}': the adopted line has no solve", name_));
  adopt(source.last_attachment_g_, *source.last_);
  if (!source.last_->has_end_B_stiffness && source.recent_stiffness_) {
    recent_stiffness_ = source.recent_stiffness_;
    recent_stiffness_at_g_ = source.recent_stiffness_at_g_;
  }
}

LineEndResponse FeStaticLine::solve(const Eigen::Vector3d& attachment_g) {
  const bool reuse = stiffness_reuse_distance_m_ > 0.0 && recent_stiffness_ &&
                     (attachment_g - recent_stiffness_at_g_).norm() <= stiffness_reuse_distance_m_;
  const FeStaticsResult& r = solve_at(attachment_g, !reuse);
  LineEndResponse response;
  response.force_g = r.end_B_force_N;
  // The FE solver gives dF_B/dx_B; the line array uses K = −dF/dx.
  response.stiffness_g =
      r.has_end_B_stiffness ? Eigen::Matrix3d(-r.end_B_stiffness_N_per_m) : Eigen::Matrix3d(-*recent_stiffness_);
  response.top_tension_N = r.end_B_force_N.norm();
  response.iterations = r.iterations;
  return response;
}

Eigen::Vector3d FeStaticLine::solve_force(const Eigen::Vector3d& attachment_g) {
  return solve_at(attachment_g, false).end_B_force_N;
}

LineEndResponse FeStaticLine::linearization(const Eigen::Vector3d& attachment_g) {
  if (!recent_stiffness_) return solve(attachment_g);
  LineEndResponse response;
  response.force_g = solve_force(attachment_g);
  response.stiffness_g = -*recent_stiffness_;
  response.top_tension_N = response.force_g.norm();
  response.iterations = last_->iterations;
  return response;
}

LineState FeStaticLine::state(const Eigen::Vector3d& attachment_g, int /*points_per_segment*/) {
  LineState state;
  state.top = solve(attachment_g);
  const FeStaticsResult& r = *last_;
  state.bottom_force_g = r.end_A_force_N;
  if (r.touchdown) {
    state.laid_length_m = r.touchdown->arc_length_m;
    state.touchdown_distance_m = (r.touchdown->position_m - end_A_g_).head<2>().norm();
    state.regime = LineRegime::touchdown;
  } else {
    state.regime = LineRegime::suspended;
  }
  const std::vector<int> sections = node_sections(model_, r);
  for (std::size_t i = 0; i < r.node_position_m.size(); ++i) {
    const bool on_seabed = r.node_position_m[i].z() <= environment_.seabed_z_m + kOnSeabedTolerance_m;
    state.profile.push_back(
        {r.node_position_m[i], r.node_arc_length_m[i], r.node_tension_N[i], sections[i], on_seabed});
  }
  return state;
}

Eigen::Matrix3d FeStaticLine::incremental_stiffness_g(const Eigen::Vector3d& attachment_g,
                                                      const std::vector<double>& incremental_EA_N) {
  const FeStaticsResult& r = solve_at(attachment_g, false);
  try {
    return -fe_line_incremental_end_B_stiffness(model_, environment_, r, incremental_EA_N);
  } catch (const SolverError& error) {
    throw SolverError(fmt::format("line '{}': {}", name_, error.what()), error.diagnostics());
  }
}

}  // namespace spiral::engine
