#pragma once
// Closed-form single-segment elastic catenary (test oracle, independent of
// the engine): J. Jonkman, NREL/TP-500-41958 (2007), App. B, eqs. B-1..B-2
// (suspended) and the seabed-contact form with zero friction (CB = 0);
// H. M. Irvine, "Cable Structures" (1981), ch. 1. Anchor at the origin of the
// line plane; x towards the fairlead, z up. Solved for the fairlead force by
// Newton's method with a finite-difference Jacobian.

#include <cmath>
#include <stdexcept>

namespace spiral::test {

struct ElasticCatenaryReference {
  double H_N = 0.0;  ///< horizontal tension (constant along the line)
  double V_N = 0.0;  ///< fairlead vertical force
  double fairlead_tension_N = 0.0;
  double anchor_tension_N = 0.0;
  double laid_length_m = 0.0;  ///< unstretched
  double touchdown_x_m = 0.0;  ///< horizontal distance anchor → touchdown point (stretched)
};

/// `seabed`: the anchor is on the seabed and the line may lie on it.
inline ElasticCatenaryReference solve_elastic_catenary(double L, double w, double EA, double XF, double ZF,
                                                       bool seabed) {
  auto spans = [&](double H, double V, double& x, double& z) {
    const double Lb = seabed ? L - V / w : 0.0;
    if (seabed && Lb > 0.0) {
      x = Lb + H / w * std::asinh(V / H) + H * L / EA;
      z = H / w * (std::sqrt(1.0 + V * V / (H * H)) - 1.0) + V * V / (2.0 * EA * w);
    } else {
      const double Va = V - w * L;
      x = H / w * (std::asinh(V / H) - std::asinh(Va / H)) + H * L / EA;
      z = H / w * (std::sqrt(1.0 + V * V / (H * H)) - std::sqrt(1.0 + Va * Va / (H * H))) +
          (V * L - 0.5 * w * L * L) / EA;
    }
  };
  double H = 0.5 * w * L, V = 0.5 * w * L;
  for (int it = 0; it < 200; ++it) {
    double x, z;
    spans(H, V, x, z);
    const double rx = x - XF, rz = z - ZF;
    if (std::hypot(rx, rz) < 1e-11 * L) break;
    const double dH = 1e-7 * H, dV = 1e-7 * std::max(V, H);
    double xh, zh, xv, zv;
    spans(H + dH, V, xh, zh);
    spans(H, V + dV, xv, zv);
    const double a = (xh - x) / dH, b = (xv - x) / dV, c = (zh - z) / dH, d = (zv - z) / dV;
    const double det = a * d - b * c;
    double sH = -(d * rx - b * rz) / det, sV = -(-c * rx + a * rz) / det;
    double f = 1.0;
    while (H + f * sH <= 0.0) f *= 0.5;
    H += f * sH;
    V += f * sV;
    if (it == 199) throw std::runtime_error("reference catenary did not converge");
  }
  ElasticCatenaryReference r;
  r.H_N = H;
  r.V_N = V;
  r.fairlead_tension_N = std::hypot(H, V);
  r.laid_length_m = seabed ? std::max(0.0, L - V / w) : 0.0;
  const double Va = seabed && r.laid_length_m > 0.0 ? 0.0 : V - w * L;
  r.anchor_tension_N = std::hypot(H, Va);
  r.touchdown_x_m = r.laid_length_m * (1.0 + H / EA);
  return r;
}

}  // namespace spiral::test
