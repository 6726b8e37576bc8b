#include "engine/hull/retardation_kernel.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace spiral::engine {

RetardationKernel make_retardation_kernel(std::span<const double> w, std::span<const Matrix6d> B, double time_step_s,
                                          double duration_s) {
  if (w.size() < 2 || w.size() != B.size()) {
    throw std::invalid_argument(
        fmt::format("retardation kernel: need >= 2 frequencies and one 6x6 damping per frequency, got {} "
                    "frequencies and {} matrices",
                    w.size(), B.size()));
  }
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!(w[i] >= 0.0) || (i > 0 && !(w[i] > w[i - 1]))) {
      throw std::invalid_argument(
          fmt::format("retardation kernel: frequencies must be >= 0 rad/s and strictly increasing; "
                      "frequency[{}] = {} rad/s",
                      i, w[i]));
    }
    if (!B[i].allFinite())
      throw std::invalid_argument(
          fmt::format("retardation kernel: radiation damping B(w) at frequency[{}] has non-finite entries", i));
  }
  if (!(time_step_s > 0.0) || !(duration_s >= time_step_s)) {
    throw std::invalid_argument(
        fmt::format("retardation kernel: need time_step_s > 0 and duration_s >= time_step_s, got {} s, {} s",
                    time_step_s, duration_s));
  }
  const auto n = static_cast<Eigen::Index>(std::floor(duration_s / time_step_s + 1e-9)) + 1;
  RetardationKernel k;
  k.time_step_s = time_step_s;
  k.values = Eigen::MatrixXd::Zero(36, n);
  // K(t) = (2/pi) int B(w) cos(wt) dw (Cummins 1962; Ogilvie 1964), trapezoid on the BEM grid.
  for (Eigen::Index j = 0; j < n; ++j) {
    const double t = static_cast<double>(j) * time_step_s;
    Matrix6d sum = Matrix6d::Zero();
    for (std::size_t i = 0; i + 1 < w.size(); ++i) {
      const double dw = w[i + 1] - w[i];
      sum += 0.5 * dw * (B[i] * std::cos(w[i] * t) + B[i + 1] * std::cos(w[i + 1] * t));
    }
    sum *= 2.0 / std::numbers::pi;
    k.values.col(j) = Eigen::Map<const Eigen::Matrix<double, 36, 1>>(sum.data());
  }
  return k;
}

}  // namespace spiral::engine
