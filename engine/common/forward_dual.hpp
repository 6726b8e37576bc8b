#pragma once
// Forward-mode automatic differentiation with a fixed number of directional
// derivatives, for exact element Jacobians of hand-written force kernels
// (the kernel is written once as a template on its scalar type and evaluated
// with `double` for residuals and with `Dual<N>` for Jacobian columns).
// Reference: A. Griewank and A. Walther, "Evaluating Derivatives", 2nd ed.,
// SIAM (2008), ch. 3 (tangent mode).
//
// Only the operations the kernels use are provided. Functions that are not
// differentiable at a point (sqrt at 0) are given the one-sided derivative
// the kernels need by dedicated helpers in the kernels, never silently here:
// sqrt(0) returns a NaN derivative on purpose so a misuse shows up in tests.

#include <array>
#include <cmath>

namespace spiral::engine {

template <int N>
struct Dual {
  double v = 0.0;             ///< value
  std::array<double, N> d{};  ///< derivatives with respect to the N seeds

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT(google-explicit-constructor): constants mix freely
  static Dual seed(double value, int i) {
    Dual x(value);
    x.d[static_cast<std::size_t>(i)] = 1.0;
    return x;
  }
};

template <int N>
inline Dual<N> operator+(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v + b.v);
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
template <int N>
inline Dual<N> operator-(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v - b.v);
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
template <int N>
inline Dual<N> operator-(const Dual<N>& a) {
  Dual<N> r(-a.v);
  for (int i = 0; i < N; ++i) r.d[i] = -a.d[i];
  return r;
}
template <int N>
inline Dual<N> operator*(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v * b.v);
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}
template <int N>
inline Dual<N> operator*(double a, const Dual<N>& b) {
  Dual<N> r(a * b.v);
  for (int i = 0; i < N; ++i) r.d[i] = a * b.d[i];
  return r;
}
template <int N>
inline Dual<N> operator*(const Dual<N>& a, double b) {
  return b * a;
}
template <int N>
inline Dual<N> operator/(const Dual<N>& a, const Dual<N>& b) {
  const double inv = 1.0 / b.v;
  Dual<N> r(a.v * inv);
  for (int i = 0; i < N; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) * inv;
  return r;
}
template <int N>
inline Dual<N> operator/(const Dual<N>& a, double b) {
  return a * (1.0 / b);
}
template <int N>
inline Dual<N> operator/(double a, const Dual<N>& b) {
  return Dual<N>(a) / b;
}
template <int N>
inline Dual<N> operator+(const Dual<N>& a, double b) {
  Dual<N> r(a);
  r.v += b;
  return r;
}
template <int N>
inline Dual<N> operator+(double a, const Dual<N>& b) {
  return b + a;
}
template <int N>
inline Dual<N> operator-(const Dual<N>& a, double b) {
  return a + (-b);
}
template <int N>
inline Dual<N> operator-(double a, const Dual<N>& b) {
  return (-b) + a;
}
template <int N>
inline Dual<N>& operator+=(Dual<N>& a, const Dual<N>& b) {
  a.v += b.v;
  for (int i = 0; i < N; ++i) a.d[i] += b.d[i];
  return a;
}
template <int N>
inline Dual<N>& operator-=(Dual<N>& a, const Dual<N>& b) {
  a.v -= b.v;
  for (int i = 0; i < N; ++i) a.d[i] -= b.d[i];
  return a;
}
template <int N>
inline Dual<N> sqrt(const Dual<N>& a) {
  const double s = std::sqrt(a.v);
  Dual<N> r(s);
  const double f = 0.5 / s;
  for (int i = 0; i < N; ++i) r.d[i] = f * a.d[i];
  return r;
}

/// Value of a scalar, whether `double` or `Dual`.
inline double value_of(double x) { return x; }
template <int N>
inline double value_of(const Dual<N>& x) {
  return x.v;
}

}  // namespace spiral::engine
