#include "engine/hull/motion_raos.hpp"

#include <complex>

#include <Eigen/LU>

namespace spiral::engine {

MotionRaoTable motion_raos_from_excitation(const ExcitationTable& x, const HydroCoefficients& r, const Matrix6d& mass,
                                           const Matrix6d& linear_damping, const Matrix6d& stiffness) {
  MotionRaoTable out;
  out.quantity = TransferQuantity::motion_rao;
  out.omega_rad_per_s = x.omega_rad_per_s;
  out.headings_rad = x.headings_rad;
  out.file = x.file + " (RAOs with " + r.file + ")";
  const auto nh = static_cast<Eigen::Index>(x.headings_rad.size());
  const auto nw = static_cast<Eigen::Index>(x.omega_rad_per_s.size());
  for (int d = 0; d < 6; ++d) {
    out.values[static_cast<std::size_t>(d)] = Eigen::MatrixXcd::Zero(nh, nw);
    out.dof_present[static_cast<std::size_t>(d)] = true;
  }
  const std::complex<double> i(0.0, 1.0);
  for (Eigen::Index k = 0; k < nw; ++k) {
    const double w = x.omega_rad_per_s[static_cast<std::size_t>(k)];
    const Eigen::Matrix<std::complex<double>, 6, 6> H =
        (-w * w * (mass + added_mass_at(r, w)) + stiffness).cast<std::complex<double>>() +
        i * w * (damping_at(r, w) + linear_damping).cast<std::complex<double>>();
    const Eigen::PartialPivLU<Eigen::Matrix<std::complex<double>, 6, 6>> lu(H);
    for (Eigen::Index h = 0; h < nh; ++h) {
      Vector6cd X;
      for (int d = 0; d < 6; ++d) X(d) = x.values[static_cast<std::size_t>(d)](h, k);
      const Vector6cd xi = lu.solve(X);
      for (int d = 0; d < 6; ++d) out.values[static_cast<std::size_t>(d)](h, k) = xi(d);
    }
  }
  return out;
}

}  // namespace spiral::engine
