#include "engine/analysis/static_line.hpp"

#include <cmath>

#include <fmt/format.h>

namespace spiral::engine {

namespace {
// Below this horizontal span (m) the line is vertical: its horizontal
// direction is undefined and its lateral string stiffness H / XF is zero
// because H is zero for a vertical line.
constexpr double kVerticalSpan_m = 1e-9;
}  // namespace

const char* to_string(LineRegime regime) {
  switch (regime) {
    case LineRegime::suspended:
      return "suspended";
    case LineRegime::touchdown:
      return "touchdown";
    case LineRegime::slack:
      return "slack";
  }
  return "?";
}

Eigen::Matrix3d catenary_fairlead_stiffness(const Eigen::Matrix2d& tangent, double horizontal_force_N,
                                            double horizontal_span_m, const Eigen::Vector3d& e) {
  // Force on the fairlead: f = −H e − V ẑ, with H(XF, ZF), V(XF, ZF),
  // XF = e·Δx_h, ZF = Δz and δe = (I − e eᵀ) δx_h / XF. K = −df/dx:
  //   K_hh = dH/dXF e eᵀ + H/XF (I_h − e eᵀ),  K_hz = dH/dZF e,
  //   K_zh = dV/dXF eᵀ,                         K_zz = dV/dZF.
  const Eigen::Vector3d eh(e.x(), e.y(), 0.0);
  Eigen::Matrix3d k = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d lateral = Eigen::Matrix3d::Zero();
  lateral.topLeftCorner<2, 2>() = Eigen::Matrix2d::Identity() - eh.head<2>() * eh.head<2>().transpose();
  const double string_stiffness = horizontal_span_m > kVerticalSpan_m ? horizontal_force_N / horizontal_span_m : 0.0;
  k += tangent(0, 0) * eh * eh.transpose() + string_stiffness * lateral;
  k.block<2, 1>(0, 2) = tangent(0, 1) * eh.head<2>();
  k.block<1, 2>(2, 0) = tangent(1, 0) * eh.head<2>().transpose();
  k(2, 2) = tangent(1, 1);
  return k;
}

CatenaryStaticLine::CatenaryStaticLine(std::string name, Eigen::Vector3d anchor_g, Eigen::Vector3d attachment_b,
                                       double anchor_height_above_seabed_m, CatenaryLine line, CatenaryOptions options)
    : name_(std::move(name)),
      anchor_g_(std::move(anchor_g)),
      attachment_b_(std::move(attachment_b)),
      anchor_height_above_seabed_m_(anchor_height_above_seabed_m),
      line_(std::move(line)),
      options_(options) {}

CatenaryStaticLine::Plane CatenaryStaticLine::plane_of(const Eigen::Vector3d& attachment_g) const {
  const Eigen::Vector3d chord = attachment_g - anchor_g_;
  const double span = std::hypot(chord.x(), chord.y());
  // A vertical line has no plane of its own: keep the one of its rest layout.
  const Eigen::Vector3d direction =
      span > kVerticalSpan_m ? Eigen::Vector3d(chord.x() / span, chord.y() / span, 0.0) : Eigen::Vector3d::UnitX();
  return {span, direction};
}

LineEndResponse CatenaryStaticLine::solve_in_plane(const Plane& plane, double vertical_span_m,
                                                   const CatenaryOptions& options) {
  try {
    last_ = solve_catenary(line_, {plane.span_m, vertical_span_m, anchor_height_above_seabed_m_}, options, warm_start_);
  } catch (const SolverError& error) {
    throw SolverError(fmt::format("line '{}': {}", name_, error.what()), error.diagnostics());
  }
  warm_start_ = CatenaryGuess{last_.fairlead_horizontal_N, last_.fairlead_vertical_N};
  last_direction_g_ = plane.direction_g;

  const Eigen::Vector3d& e = plane.direction_g;
  LineEndResponse response;
  response.force_g = -last_.fairlead_horizontal_N * e - last_.fairlead_vertical_N * Eigen::Vector3d::UnitZ();
  response.stiffness_g =
      catenary_fairlead_stiffness(last_.tangent_stiffness, last_.fairlead_horizontal_N, plane.span_m, e);
  response.top_tension_N = last_.fairlead_tension_N;
  response.iterations = last_.iterations;
  return response;
}

LineEndResponse CatenaryStaticLine::solve(const Eigen::Vector3d& attachment_g) {
  return solve_in_plane(plane_of(attachment_g), attachment_g.z() - anchor_g_.z(), options_);
}

LineState CatenaryStaticLine::state(const Eigen::Vector3d& attachment_g, int points_per_segment) {
  const Plane plane = plane_of(attachment_g);
  CatenaryOptions options = options_;
  options.profile_points_per_segment = points_per_segment;
  LineState state;
  state.top = solve_in_plane(plane, attachment_g.z() - anchor_g_.z(), options);
  const Eigen::Vector3d& e = plane.direction_g;
  state.bottom_force_g = last_.anchor_horizontal_N * e + last_.anchor_vertical_N * Eigen::Vector3d::UnitZ();
  state.laid_length_m = last_.laid_length_m;
  state.touchdown_distance_m = last_.touchdown_x_m;
  switch (last_.regime) {
    case CatenaryRegime::suspended:
      state.regime = LineRegime::suspended;
      break;
    case CatenaryRegime::touchdown:
      state.regime = LineRegime::touchdown;
      break;
    case CatenaryRegime::slack_vertical:
      state.regime = LineRegime::slack;
      break;
  }
  state.profile.reserve(last_.profile.size());
  for (const CatenaryProfilePoint& p : last_.profile) {
    state.profile.push_back({anchor_g_ + p.x_m * e + p.z_m * Eigen::Vector3d::UnitZ(), p.arc_length_m, p.tension_N,
                             p.segment, p.on_seabed});
  }
  return state;
}

Eigen::Matrix3d CatenaryStaticLine::incremental_stiffness_g(const Eigen::Vector3d& attachment_g,
                                                            const std::vector<double>& incremental_EA_N) {
  const Plane plane = plane_of(attachment_g);
  const CatenaryGeometry geometry{plane.span_m, attachment_g.z() - anchor_g_.z(), anchor_height_above_seabed_m_};
  solve_in_plane(plane, geometry.vertical_span_m, options_);
  const Eigen::Matrix2d tangent = catenary_incremental_tangent(line_, geometry, last_, incremental_EA_N);
  return catenary_fairlead_stiffness(tangent, last_.fairlead_horizontal_N, plane.span_m, plane.direction_g);
}

}  // namespace spiral::engine
