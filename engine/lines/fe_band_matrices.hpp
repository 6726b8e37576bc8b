#pragma once
// Band-matrix kernels of the FE line dynamics' Newton solve (fe_dynamic_line.hpp):
// a symmetric band kept by its lower band, and the reduced Newton matrix
// S = c² M − c C − K factored by banded Cholesky with a band-LU fallback.
// Private to engine/lines and the coupled system that assembles lines.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "engine/common/banded_lu.hpp"

namespace spiral::engine::fe_detail {

/// Σ a[r] b[r] for r in [1, len], in four partial sums: the band solves are
/// otherwise bound by the latency of one long chain of additions.
inline double band_dot(const double* a, const double* b, int len) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  int r = 1;
  for (; r + 3 <= len; r += 4) {
    s0 += a[r] * b[r];
    s1 += a[r + 1] * b[r + 1];
    s2 += a[r + 2] * b[r + 2];
    s3 += a[r + 3] * b[r + 3];
  }
  for (; r <= len; ++r) s0 += a[r] * b[r];
  return (s0 + s1) + (s2 + s3);
}

/// A symmetric band matrix by its lower band (column-major, b + 1 entries
/// per column), for a matrix whose products the Newton solves need but
/// never its factors.
struct SymmetricBand {
  int n = 0, b = 0;
  std::vector<double> a;
  void reset(int size, int half_band) {
    n = size;
    b = half_band;
    a.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(b + 1), 0.0);
  }
  /// Where entry (i, j), i ≥ j, i − j ≤ half_band, sits in the lower band.
  static std::size_t offset(int i, int j, int half_band) {
    return static_cast<std::size_t>(j * (half_band + 1) + i - j);
  }
  double& lower(int i, int j) { return a[offset(i, j, b)]; }
  double* lower_data() { return a.data(); }
  /// y += A x.
  void multiply_add(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    const double* xp = x.data();
    double* yp = y.data();
    for (int j = 0; j < n; ++j) {
      const double* col = &a[static_cast<std::size_t>(j * (b + 1))];
      const int km = std::min(b, n - 1 - j);
      const double xj = xp[j];
      for (int r = 1; r <= km; ++r) yp[j + r] += col[r] * xj;
      yp[j] += col[0] * xj + band_dot(col, xp + j, km);
    }
  }
};

/// The reduced Newton matrix S = c² M − c C − K, symmetric (M, the drag,
/// damping and friction Jacobians and the elastic and contact tangents all
/// are; the drag's direction derivatives, which are not, are left out) and
/// positive definite for a line in tension: factored by banded Cholesky
/// (dpbtf2 / dpbtrs, LAPACK Users' Guide §5.3.2) on its lower band — a
/// third of the operations of the pivoted band LU and no fill-in — with the
/// band LU (BandMatrix) as the fallback when a pivot is not positive (slack
/// or compressed elements at long steps). Prescribed DOFs get identity
/// rows and zero columns (their corrections are the right-hand side's).
class NewtonMatrix {
 public:
  /// The zero matrix of this size (the matrix assembled, not its factors).
  void reset(int size, int half_band) {
    n_ = size;
    b_ = half_band;
    assembled_.reset(size, half_band);
    factored_ = Factored::none;
  }
  /// Entry (i, j), i ≥ j, i − j ≤ half band, of the matrix assembled.
  double& lower(int i, int j) { return assembled_.lower(i, j); }
  /// The assembled lower band, column-major (SymmetricBand::offset).
  double* lower_data() { return assembled_.lower_data(); }

  /// Factors the assembled matrix; false if singular (both factorisations
  /// failed). `first_changed_column`: the assembled matrix equals the one
  /// factored last in its columns before this one (n: in every column).
  /// Cholesky's columns before it are then that factorisation's, and it
  /// refactors from there: the trailing updates of the b columns before
  /// it replayed on the fresh columns, then the columns themselves — each
  /// entry updated by the same operations in the same order as a whole
  /// factorisation, so the factors are the same bit for bit.
  bool factorize(int first_changed_column = 0) {
    const bool partial = factored_ == Factored::cholesky && first_changed_column > 0 &&
                         band_.a.size() == assembled_.a.size() && inv_diagonal_.size() == static_cast<std::size_t>(n_);
    if (factored_ != Factored::none && first_changed_column >= n_) return true;  // nothing changed
    const int from = partial ? first_changed_column : 0;
    if (partial) {
      std::copy(assembled_.a.begin() + static_cast<std::ptrdiff_t>(from) * (b_ + 1), assembled_.a.end(),
                band_.a.begin() + static_cast<std::ptrdiff_t>(from) * (b_ + 1));
    } else {
      band_.a = assembled_.a;
      inv_diagonal_.resize(static_cast<std::size_t>(n_));
    }
    if (cholesky(from)) {
      factored_ = Factored::cholesky;
      return true;
    }
    lu_.reset(n_, b_, b_);
    for (int j = 0; j < n_; ++j) {
      for (int i = j; i <= std::min(n_ - 1, j + b_); ++i) {
        const double v = assembled_.a[SymmetricBand::offset(i, j, b_)];
        lu_.at(i, j) = v;
        lu_.at(j, i) = v;
      }
    }
    const bool ok = lu_.factorize();
    factored_ = ok ? Factored::lu : Factored::none;
    return ok;
  }

  void solve_in_place(Eigen::VectorXd& x) const {
    if (factored_ != Factored::cholesky) {
      lu_.solve_in_place(x);
    } else {
      solve_columns<1>(x.data(), 0);
    }
  }

  /// Three right-hand sides (the columns of x) that are zero above row
  /// `first_nonzero` — a line's response to its end's motion: the same
  /// arithmetic as solve_in_place on each column (the same result, bit for
  /// bit), with the forward substitution started at that row (above it the
  /// solution of L y = x is zero) and the factor read once for the three.
  void solve_end_columns(Eigen::Matrix<double, Eigen::Dynamic, 3>& x, int first_nonzero) const {
    if (factored_ != Factored::cholesky) {
      for (int c = 0; c < 3; ++c) lu_.solve_in_place(x.col(c));
    } else {
      solve_columns<3>(x.data(), first_nonzero);
    }
  }

 private:
  // The band kernels with the half bandwidth a compile-time constant for the
  // two bandwidths of FE lines (11; 14 with a hinge joint): the interior
  // columns' loops then have fixed lengths and unroll (KD = 0: run time).
  template <int KD>
  int kd() const {
    return KD > 0 ? KD : b_;
  }

  template <int NC>
  void solve_columns(double* x, int first_nonzero) const {
    if (b_ == 11) {
      solve_kd<11, NC>(x, first_nonzero);
    } else if (b_ == 14) {
      solve_kd<14, NC>(x, first_nonzero);
    } else {
      solve_kd<0, NC>(x, first_nonzero);
    }
  }

  // NC columns of x (column-major, n rows), each zero above first_nonzero.
  template <int KD, int NC>
  void solve_kd(double* x, int first_nonzero) const {
    const int b = kd<KD>(), ld = b + 1;
    const double* l = band_.a.data();
    const double* inv = inv_diagonal_.data();
    std::array<double*, NC> columns;
    for (int c = 0; c < NC; ++c) columns[static_cast<std::size_t>(c)] = x + static_cast<std::ptrdiff_t>(c) * n_;
    for (int j = std::max(first_nonzero, 0); j < n_; ++j) {  // L y = x
      const double* col = l + static_cast<std::ptrdiff_t>(j) * ld;
      for (double* xc : columns) {
        const double xj = xc[j] * inv[j];
        xc[j] = xj;
        double* xr = xc + j;
        if (j + b < n_) {
          for (int r = 1; r <= b; ++r) xr[r] -= col[r] * xj;
        } else {
          for (int r = 1; r < n_ - j; ++r) xr[r] -= col[r] * xj;
        }
      }
    }
    for (int j = n_ - 1; j >= 0; --j) {  // Lᵀ x = y
      const double* col = l + static_cast<std::ptrdiff_t>(j) * ld;
      for (double* xc : columns) {
        const double* xr = xc + j;
        const double sum = j + b < n_ ? band_dot(col, xr, b) : band_dot(col, xr, n_ - 1 - j);
        xc[j] = (xc[j] - sum) * inv[j];
      }
    }
  }

  /// Columns from `from` on; those before it are factors already (and their
  /// trailing updates of columns from `from` on are replayed first).
  bool cholesky(int from) {
    if (b_ == 11) return cholesky_kd<11>(from);
    if (b_ == 14) return cholesky_kd<14>(from);
    return cholesky_kd<0>(from);
  }

  template <int KD>
  bool cholesky_kd(int from) {
    const int b = kd<KD>(), ld = b + 1;
    double* l = band_.a.data();
    for (int j = std::max(0, from - b); j < from; ++j) {
      const double* col = l + static_cast<std::ptrdiff_t>(j) * ld;
      const int km = std::min(b, n_ - 1 - j);
      for (int c = from - j; c <= km; ++c) {
        double* target = l + static_cast<std::ptrdiff_t>(j + c) * ld - c;
        const double f = col[c];
        for (int r = c; r <= km; ++r) target[r] -= col[r] * f;
      }
    }
    for (int j = from; j < n_; ++j) {
      double* col = l + static_cast<std::ptrdiff_t>(j) * ld;
      if (!(col[0] > 0.0)) return false;
      const double d = std::sqrt(col[0]);
      col[0] = d;
      const double inv = 1.0 / d;
      inv_diagonal_[static_cast<std::size_t>(j)] = inv;
      const int km = std::min(b, n_ - 1 - j);
      for (int r = 1; r <= km; ++r) col[r] *= inv;
      // Trailing update of columns j + c: L(j+r, j+c) −= L(j+r, j) L(j+c, j).
      if (km == b) {
        for (int c = 1; c <= b; ++c) {
          double* target = col + c * ld - c;
          const double f = col[c];
          for (int r = c; r <= b; ++r) target[r] -= col[r] * f;
        }
      } else {
        for (int c = 1; c <= km; ++c) {
          double* target = col + c * ld - c;
          const double f = col[c];
          for (int r = c; r <= km; ++r) target[r] -= col[r] * f;
        }
      }
    }
    return true;
  }

  enum class Factored { none, cholesky, lu };
  int n_ = 0, b_ = 0;
  SymmetricBand assembled_;  // the matrix
  SymmetricBand band_;       // its Cholesky factors (lower band)
  std::vector<double> inv_diagonal_;
  BandMatrix lu_;
  Factored factored_ = Factored::none;
};

}  // namespace spiral::engine::fe_detail
