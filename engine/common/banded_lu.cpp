#include "engine/common/banded_lu.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace spiral::engine {

BandMatrix::BandMatrix(int n, int kl, int ku) { reset(n, kl, ku); }

void BandMatrix::reset(int n, int kl, int ku) {
  n_ = n;
  kl_ = kl;
  ku_ = ku;
  kv_ = ku;
  ld_ = kl + ku + 1;
  ab_.assign(static_cast<std::size_t>(ld_) * static_cast<std::size_t>(n), 0.0);
}

void BandMatrix::widen() {
  const auto old_ld = static_cast<std::size_t>(ld_);
  const auto new_ld = old_ld + static_cast<std::size_t>(kl_);
  const auto fill = static_cast<std::size_t>(kl_);
  ab_.resize(new_ld * static_cast<std::size_t>(n_));
  // Last column first: each column moves to a higher address, never onto a
  // column still to be moved.
  for (std::size_t j = static_cast<std::size_t>(n_); j-- > 0;) {
    double* const to = ab_.data() + j * new_ld;
    std::copy_backward(ab_.data() + j * old_ld, ab_.data() + (j + 1) * old_ld, to + new_ld);
    std::fill(to, to + fill, 0.0);
  }
  kv_ = kl_ + ku_;
  ld_ = static_cast<int>(new_ld);
}

void BandMatrix::set_identity_row(int i) {
  for (int j = std::max(0, i - kl_); j <= std::min(n_ - 1, i + ku_); ++j) at(i, j) = 0.0;
  at(i, i) = 1.0;
}

namespace {

// A diagonal pivot is kept while it has its diagonal's sign (before
// elimination) and at least this fraction of its size: in a definite matrix
// elimination leaves every pivot with its diagonal's sign, and a pivot that
// lost all but 1e-8 of its diagonal to cancellation is where an indefinite
// matrix would grow its factors without bound.
constexpr double kKeptDiagonalFraction = 1e-8;
constexpr double kDefiniteSlack = 4.0;

}  // namespace

// dgbtf2, 0-based, with the pivot rule of the header. The interior columns'
// loops have a compile-time length for the FE lines' bandwidths (KL = 0: run
// time), so that they unroll.
template <int KL>
bool BandMatrix::factorize_band(Pivoting pivoting) {
  const int kl = KL > 0 ? KL : kl_;
  ipiv_.assign(static_cast<std::size_t>(n_), 0);
  inverse_pivot_.resize(static_cast<std::size_t>(n_));
  column_top_.resize(static_cast<std::size_t>(n_));
  for (int j = 0; j < n_; ++j) {
    column_top_[static_cast<std::size_t>(j)] = j;
    inverse_pivot_[static_cast<std::size_t>(j)] = at(j, j);  // the diagonal before elimination, for the rule
  }
  int ju = 0;
  bool ok = true;
  for (int j = 0; j < n_; ++j) {
    const int km = std::min(kl, n_ - 1 - j);
    double* l = &at(j, j);  // column j from the diagonal down: contiguous
    int jp = 0;
    double best = std::abs(l[0]);
    const double diagonal = inverse_pivot_[static_cast<std::size_t>(j)];
    bool keep_diagonal =
        pivoting == Pivoting::diagonal_while_definite && diagonal != 0.0 && l[0] / diagonal > kKeptDiagonalFraction;
    // Definite: |a_ij a_ji| ≤ |a_ii a_jj| in every Schur complement, which
    // bounds each update a_ik − a_ij a_jk / a_jj by the diagonals (slack 4
    // for the unsymmetric drag part). A column that breaks it is indefinite
    // there: interchanges.
    for (int i = 1; keep_diagonal && i <= std::min(km, ku_); ++i) {
      keep_diagonal = std::abs(l[i] * at(j, j + i)) <= kDefiniteSlack * std::abs(l[0] * at(j + i, j + i));
    }
    if (!keep_diagonal) {
      for (int p = 1; p <= km; ++p) {
        if (std::abs(l[p]) > best) {
          best = std::abs(l[p]);
          jp = p;
        }
      }
    }
    ipiv_[static_cast<std::size_t>(j)] = j + jp;
    if (best == 0.0) {
      ok = false;
      inverse_pivot_[static_cast<std::size_t>(j)] = std::numeric_limits<double>::infinity();
      continue;
    }
    const int reach = std::min(j + ku_ + jp, n_ - 1);
    for (int c = ju + 1; c <= reach; ++c) column_top_[static_cast<std::size_t>(c)] = j;
    ju = std::max(ju, reach);
    if (jp != 0) {
      if (compact()) {
        widen();
        l = &at(j, j);
      }
      for (int c = j; c <= ju; ++c) std::swap(at(j, c), at(j + jp, c));
    }
    const double inv = 1.0 / l[0];
    inverse_pivot_[static_cast<std::size_t>(j)] = inv;
    if (km == 0) continue;
    // Each column c to the right of j is contiguous from row j on (distinct
    // columns: no alias with l). `rows` is a compile-time constant for the
    // interior columns of the FE bandwidths.
    auto eliminate = [&](auto rows) {
      for (int i = 1; i <= rows; ++i) l[i] *= inv;
      for (int c = j + 1; c <= ju; ++c) {
        double* const a = &at(j, c);
        const double u = a[0];
        if (u == 0.0) continue;
        for (int i = 1; i <= rows; ++i) a[i] -= l[i] * u;
      }
    };
    if (KL > 0 && km == KL) {
      eliminate(std::integral_constant<int, KL>{});
    } else {
      eliminate(km);
    }
  }
  return ok;
}

bool BandMatrix::factorize(Pivoting pivoting) {
  if (kl_ == 11) return factorize_band<11>(pivoting);
  if (kl_ == 14) return factorize_band<14>(pivoting);
  return factorize_band<0>(pivoting);
}

// NC columns of x, column_stride apart (n rows each), each column with the same
// arithmetic as a single solve: the factor is read once for all of them and
// their independent recurrences overlap.
template <int KL, int NC>
void BandMatrix::solve_band(double* x, std::ptrdiff_t column_stride) const {
  const int kl = KL > 0 ? KL : kl_;
  std::array<double*, NC> columns;
  for (int c = 0; c < NC; ++c) columns[static_cast<std::size_t>(c)] = x + c * column_stride;
  // Above its first nonzero (less the reach of a row interchange) a
  // right-hand side stays zero through L: a line's response to its end B
  // (the end-stiffness condensation) starts there.
  int first = n_;
  for (const double* xc : columns) {
    int f = 0;
    while (f < first && xc[f] == 0.0) ++f;
    first = std::min(first, f);
  }
  for (int j = std::max(0, first - kl); j < n_; ++j) {
    const int l = ipiv_[static_cast<std::size_t>(j)];
    const double* const col = address(j, j);
    for (double* xc : columns) {
      if (l != j) std::swap(xc[l], xc[j]);
      const double xj = xc[j];
      if (KL > 0 && j + KL < n_) {
        for (int i = 1; i <= KL; ++i) xc[j + i] -= col[i] * xj;
      } else {
        const int km = std::min(kl, n_ - 1 - j);
        for (int i = 1; i <= km; ++i) xc[j + i] -= col[i] * xj;
      }
    }
  }
  for (int j = n_ - 1; j >= 0; --j) {
    const double inverse = inverse_pivot_[static_cast<std::size_t>(j)];
    const int top = column_top_[static_cast<std::size_t>(j)];
    const double* const col = address(top, j);  // rows top..j−1 of column j: contiguous
    for (double* xc : columns) {
      const double xj = xc[j] * inverse;
      xc[j] = xj;
      for (int i = 0; i < j - top; ++i) xc[top + i] -= col[i] * xj;
    }
  }
}

template <int NC>
void BandMatrix::solve_columns(double* x, std::ptrdiff_t column_stride) const {
  if (kl_ == 11) return solve_band<11, NC>(x, column_stride);
  if (kl_ == 14) return solve_band<14, NC>(x, column_stride);
  solve_band<0, NC>(x, column_stride);
}

void BandMatrix::solve_in_place(Eigen::Ref<Eigen::VectorXd> b) const { solve_columns<1>(b.data(), 0); }

void BandMatrix::solve_columns_in_place(Eigen::Ref<Eigen::MatrixXd> b) const {
  // The columns of a block of a larger matrix lie outerStride() apart.
  const std::ptrdiff_t stride = b.outerStride();
  Eigen::Index c = 0;
  for (; c + 3 <= b.cols(); c += 3) solve_columns<3>(b.col(c).data(), stride);
  for (; c < b.cols(); ++c) solve_columns<1>(b.col(c).data(), stride);
}

}  // namespace spiral::engine
