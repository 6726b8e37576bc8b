#include "engine/common/banded_lu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace spiral::engine {

BandMatrix::BandMatrix(int n, int kl, int ku)
    : n_(n),
      kl_(kl),
      ku_(ku),
      kv_(kl + ku),
      ld_(2 * kl + ku + 1),
      ab_(static_cast<std::size_t>(ld_) * static_cast<std::size_t>(n), 0.0) {}

void BandMatrix::reset(int n, int kl, int ku) {
  n_ = n;
  kl_ = kl;
  ku_ = ku;
  kv_ = kl + ku;
  ld_ = 2 * kl + ku + 1;
  ab_.assign(static_cast<std::size_t>(ld_) * static_cast<std::size_t>(n), 0.0);
}

void BandMatrix::set_identity_row(int i) {
  for (int j = std::max(0, i - kl_); j <= std::min(n_ - 1, i + ku_); ++j) at(i, j) = 0.0;
  at(i, i) = 1.0;
}

// dgbtf2, 0-based.
bool BandMatrix::factorize() {
  ipiv_.assign(static_cast<std::size_t>(n_), 0);
  int ju = 0;
  bool ok = true;
  for (int j = 0; j < n_; ++j) {
    const int km = std::min(kl_, n_ - 1 - j);
    int jp = 0;
    double best = std::abs(at(j, j));
    for (int p = 1; p <= km; ++p) {
      if (std::abs(at(j + p, j)) > best) {
        best = std::abs(at(j + p, j));
        jp = p;
      }
    }
    ipiv_[static_cast<std::size_t>(j)] = j + jp;
    if (best == 0.0) {
      ok = false;
      continue;
    }
    ju = std::max(ju, std::min(j + ku_ + jp, n_ - 1));
    if (jp != 0) {
      for (int c = j; c <= ju; ++c) std::swap(at(j, c), at(j + jp, c));
    }
    if (km > 0) {
      const double inv = 1.0 / at(j, j);
      // Column j below the diagonal, and each column c to its right from row
      // j on, are contiguous in the band storage (distinct columns: no alias).
      double* const l = &at(j, j);
      for (int i = 1; i <= km; ++i) l[i] *= inv;
      for (int c = j + 1; c <= ju; ++c) {
        double* const a = &at(j, c);
        const double u = a[0];
        if (u == 0.0) continue;
        for (int i = 1; i <= km; ++i) a[i] -= l[i] * u;
      }
    }
  }
  return ok;
}

void BandMatrix::solve_in_place(Eigen::Ref<Eigen::VectorXd> b) const {
  for (int j = 0; j < n_; ++j) {
    const int l = ipiv_[static_cast<std::size_t>(j)];
    if (l != j) std::swap(b[l], b[j]);
    const int km = std::min(kl_, n_ - 1 - j);
    for (int i = 1; i <= km; ++i) b[j + i] -= at(j + i, j) * b[j];
  }
  for (int j = n_ - 1; j >= 0; --j) {
    b[j] /= at(j, j);
    for (int i = std::max(0, j - kv_); i < j; ++i) b[i] -= at(i, j) * b[j];
  }
}

}  // namespace spiral::engine
