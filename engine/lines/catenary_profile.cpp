// Profile of a solved catenary: points along the line from the anchor (arc
// length, x, z, effective tension and its components), including segment ends
// and the touchdown point. Runs once after convergence, so it may allocate.

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/lines/catenary.hpp"
#include "engine/lines/catenary_spans.hpp"

namespace spiral::engine {

namespace detail = catenary_detail;

namespace {

/// Integral of the tension over the top `d` metres of a laid piece entered with
/// T_top and losing mu_w per metre, floored at 0 (Jonkman 2007 eq. B-9 per piece).
double laid_tension_integral(double T_top, double d, double mu_w) {
  if (T_top >= mu_w * d) return d * (T_top - 0.5 * mu_w * d);
  return T_top * T_top / (2.0 * mu_w);
}

}  // namespace

void fill_catenary_profile(const CatenaryLine& line, const CatenaryGeometry& geometry, int points_per_segment,
                           CatenarySolution& solution) {
  detail::LineView view;
  view.line = &line;
  view.anchor_on_seabed = geometry.anchor_height_above_seabed_m == 0.0;
  for (const CatenarySegment& s : line.segments) {
    view.total_weight_N += s.weight_N_per_m * s.length_m;
    view.total_length_m += s.length_m;
  }
  for (double P : line.joint_load_N) view.total_weight_N += P;

  const double H = solution.fairlead_horizontal_N;
  const double V_F = solution.fairlead_vertical_N;
  const double mu = line.seabed_friction;
  const int n = static_cast<int>(line.segments.size());
  // Contact fields of the touchdown walk do not depend on H.
  const detail::SpanEvaluation e = detail::evaluate_spans(view, H > 0.0 ? H : 1.0, V_F);
  const bool contact = solution.regime != CatenaryRegime::suspended && e.contact;
  const bool slack = solution.regime == CatenaryRegime::slack_vertical;

  // Laid unstretched length per segment and tension entering each laid piece at its top.
  std::vector<double> laid(n, 0.0), T_top(n, 0.0), V_top(n, 0.0);
  double above = 0.0;
  for (int i = n - 1; i >= 0; --i) {
    V_top[i] = V_F - above;
    above += line.segments[i].weight_N_per_m * line.segments[i].length_m;
    if (i > 0) above += view.joint_load(i - 1);
  }
  if (contact) {
    const int k = e.touchdown_segment;
    double T = H;
    int top = k;
    if (e.touchdown_at_joint) {
      T = std::max(T - mu * e.clump_rest_N, 0.0);
      top = k - 1;
    } else {
      laid[k] = e.touchdown_laid_m;
    }
    for (int i = top; i >= 0; --i) {
      if (i < k || e.touchdown_at_joint) laid[i] = line.segments[i].length_m;
      T_top[i] = T;
      T = std::max(T - mu * line.segments[i].weight_N_per_m * laid[i], 0.0);
      if (i > 0) T = std::max(T - mu * view.joint_load(i - 1), 0.0);
    }
  }
  // Slack on the seabed (H = 0): laid points are spread evenly over the span.
  const double slack_scale =
      slack && solution.laid_length_m > 0.0 ? solution.touchdown_x_m / solution.laid_length_m : 1.0;

  auto& profile = solution.profile;
  profile.clear();
  profile.reserve(static_cast<std::size_t>(n) * (points_per_segment + 3));
  double x_bottom = 0.0, z_bottom = 0.0, s_bottom = 0.0;
  for (int i = 0; i < n; ++i) {
    const CatenarySegment& seg = line.segments[i];
    const double w = seg.weight_N_per_m, EA = seg.EA_N, mu_w = mu * w;
    const double ell = laid[i];
    // Laid piece: horizontal length of the whole piece.
    const double x_laid_piece = slack ? ell * slack_scale : ell + laid_tension_integral(T_top[i], ell, mu_w) / EA;
    const bool td_piece = contact && ell > 0.0 && ell < seg.length_m;
    const double V_susp_bottom = td_piece ? 0.0 : V_top[i] - w * seg.length_m;

    std::vector<double> local;
    // Both ends of every segment: a joint appears once per adjacent segment
    // (the tension jumps across a clump or buoy).
    for (int j = 0; j <= points_per_segment; ++j) {
      local.push_back(seg.length_m * j / points_per_segment);
    }
    if (td_piece) local.push_back(ell);
    std::sort(local.begin(), local.end());

    for (double at : local) {
      CatenaryProfilePoint p;
      p.arc_length_m = s_bottom + at;
      p.segment = i;
      if (at <= ell && ell > 0.0) {
        const double d = ell - at;  // distance below the laid piece's top
        const double T = std::max(T_top[i] - mu_w * d, 0.0);
        p.x_m = slack
                    ? x_bottom + at * slack_scale
                    : x_bottom + at +
                          (laid_tension_integral(T_top[i], ell, mu_w) - laid_tension_integral(T_top[i], d, mu_w)) / EA;
        p.z_m = z_bottom;
        p.tension_N = p.horizontal_N = T;
        p.on_seabed = true;
      } else {
        const double up = at - ell;  // distance above the suspended piece's bottom
        const double V = V_susp_bottom + w * up;
        double dx = 0.0, dz = 0.0;
        if (H > 0.0) {
          const detail::PieceSpans sp = detail::suspended_piece(H, V, up, w, EA);
          dx = sp.x_m;
          dz = sp.z_m;
        } else {
          dz = up + 0.5 * (V + V_susp_bottom) * up / EA;  // vertical line, Irvine eq. 1.44
        }
        p.x_m = x_bottom + x_laid_piece + dx;
        p.z_m = z_bottom + dz;
        p.horizontal_N = H;
        p.vertical_N = V;
        p.tension_N = std::hypot(H, V);
      }
      profile.push_back(p);
    }
    // Move to the segment's top.
    const double up_total = seg.length_m - ell;
    double dx = 0.0, dz = 0.0;
    if (up_total > 0.0) {
      if (H > 0.0) {
        const detail::PieceSpans sp = detail::suspended_piece(H, V_susp_bottom + w * up_total, up_total, w, EA);
        dx = sp.x_m;
        dz = sp.z_m;
      } else {
        dz = up_total + 0.5 * (2.0 * V_susp_bottom + w * up_total) * up_total / EA;
      }
    }
    x_bottom += x_laid_piece + dx;
    z_bottom += dz;
    s_bottom += seg.length_m;
  }
}

}  // namespace spiral::engine
