#pragma once
// A complex band matrix and its LU factorisation in the natural order,
// without row interchanges, for the frequency-domain systems of FE lines
// (engine/lines/fe_line_impedance.hpp): the dynamic stiffness K − ω² M + iω C of a
// tensioned line in the low-frequency band is dominated by its definite
// static stiffness, for which elimination without pivoting is stable
// (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., §9.4,
// §10.1). A pivot that has lost nearly all of its size says the matrix is
// not of that kind: factorize() then returns false and the caller solves
// with a pivoting solver. On a 4,920-DOF riser it is several times faster
// than Eigen's SparseLU (COLAMD ordering, supernodes), which the line's
// natural order, already banded, does not need.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <complex>
#include <cstddef>
#include <vector>

namespace spiral::engine {

class ComplexBandLu {
 public:
  using Complex = std::complex<double>;

  /// The zero n×n matrix of half bandwidth b (entries with |i − j| <= b).
  ComplexBandLu(int n, int half_band)
      : n_(n), b_(half_band), a_(static_cast<std::size_t>(n) * static_cast<std::size_t>(2 * half_band + 1)) {}

  int size() const { return n_; }
  /// Entry (i, j), |i − j| <= b, before factorize().
  Complex& at(int i, int j) { return a_[index(i, j)]; }

  /// In place; false when a pivot is smaller than 1e-10 of its row's largest
  /// entry before elimination (the matrix is then partly eliminated and of
  /// no use: factor a copy when another solver may need the matrix).
  bool factorize() {
    // Sizes as max(|re|, |im|), within √2 of the modulus, which is plenty for
    // a 1e-10 test and spares a hypot per band entry (a tenth of the
    // enhanced S-C's line reduction).
    const auto size = [](const Complex& z) { return std::max(std::abs(z.real()), std::abs(z.imag())); };
    std::vector<double> row_size(static_cast<std::size_t>(n_), 0.0);
    for (int i = 0; i < n_; ++i)
      for (int j = std::max(0, i - b_); j <= std::min(n_ - 1, i + b_); ++j)
        row_size[static_cast<std::size_t>(i)] = std::max(row_size[static_cast<std::size_t>(i)], size(at(i, j)));
    for (int k = 0; k < n_; ++k) {
      const Complex pivot = at(k, k);
      if (!(size(pivot) > 1e-10 * row_size[static_cast<std::size_t>(k)])) return false;
      const Complex inverse_pivot = 1.0 / pivot;
      const int last = std::min(n_ - 1, k + b_);
      for (int i = k + 1; i <= last; ++i) {
        Complex& l = at(i, k);
        if (l == Complex(0.0)) continue;
        l *= inverse_pivot;
        const Complex* u = &a_[index(k, k + 1)];
        Complex* row = &a_[index(i, k + 1)];
        for (int j = 0; j < last - k; ++j) row[j] -= l * u[j];
      }
    }
    return true;
  }

  /// Solves A X = B in place, every column of x, after factorize().
  template <class Matrix>
  void solve_in_place(Matrix& x) const {
    for (Eigen::Index c = 0; c < x.cols(); ++c) {
      for (int i = 0; i < n_; ++i) {
        Complex sum = x(i, c);
        for (int j = std::max(0, i - b_); j < i; ++j) sum -= a_[index(i, j)] * x(j, c);
        x(i, c) = sum;
      }
      for (int i = n_ - 1; i >= 0; --i) {
        Complex sum = x(i, c);
        for (int j = i + 1; j <= std::min(n_ - 1, i + b_); ++j) sum -= a_[index(i, j)] * x(j, c);
        x(i, c) = sum / a_[index(i, i)];
      }
    }
  }

  /// left A⁻¹ right after factorize(), for blocks that are zero before some
  /// row of `right` and some column of `left` (a condensation onto an end of
  /// the band: an FE line's end B). As (left U⁻¹)(L⁻¹ right), the two
  /// triangular solves start where their blocks do, so the cost is that of the
  /// blocks' tails, not of two passes over the whole band.
  template <class Left, class Right>
  Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> inverse_form(const Left& left, const Right& right) const {
    const auto first_nonzero = [this](const auto& entry) {
      for (int i = 0; i < n_; ++i)
        if (entry(i) != Complex(0.0)) return i;
      return n_;
    };
    int first_row = n_, first_column = n_;
    for (Eigen::Index c = 0; c < right.cols(); ++c)
      first_row = std::min(first_row, first_nonzero([&](int i) { return Complex(right(i, c)); }));
    for (Eigen::Index r = 0; r < left.rows(); ++r)
      first_column = std::min(first_column, first_nonzero([&](int j) { return Complex(left(r, j)); }));
    // X = L⁻¹ right (unit lower), zero above first_row.
    Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> x =
        Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic>::Zero(n_, right.cols());
    for (Eigen::Index c = 0; c < right.cols(); ++c)
      for (int i = first_row; i < n_; ++i) {
        Complex sum = right(i, c);
        for (int j = std::max(first_row, i - b_); j < i; ++j) sum -= a_[index(i, j)] * x(j, c);
        x(i, c) = sum;
      }
    // Y = left U⁻¹ (Y U = left, column by column), zero before first_column.
    Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> y =
        Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic>::Zero(left.rows(), n_);
    for (Eigen::Index r = 0; r < left.rows(); ++r)
      for (int j = first_column; j < n_; ++j) {
        Complex sum = left(r, j);
        for (int i = std::max(first_column, j - b_); i < j; ++i) sum -= y(r, i) * a_[index(i, j)];
        y(r, j) = sum / a_[index(j, j)];
      }
    const int from = std::max(first_row, first_column);
    return y.rightCols(n_ - from) * x.bottomRows(n_ - from);
  }

  /// The matrix (before factorize()) for another solver.
  Eigen::SparseMatrix<Complex> to_sparse() const {
    std::vector<Eigen::Triplet<Complex>> entries;
    for (int i = 0; i < n_; ++i)
      for (int j = std::max(0, i - b_); j <= std::min(n_ - 1, i + b_); ++j)
        if (a_[index(i, j)] != Complex(0.0)) entries.emplace_back(i, j, a_[index(i, j)]);
    Eigen::SparseMatrix<Complex> m(n_, n_);
    m.setFromTriplets(entries.begin(), entries.end());
    return m;
  }

 private:
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(2 * b_ + 1) + static_cast<std::size_t>(j - i + b_);
  }
  int n_, b_;
  std::vector<Complex> a_;
};

}  // namespace spiral::engine
