#pragma once
// Band matrix with LU factorisation by partial pivoting (the algorithm of
// LAPACK dgbtf2/dgbtrs: E. Anderson et al., LAPACK Users' Guide, 3rd ed.,
// SIAM 1999, §5.3.2), for the block-tridiagonal Jacobians of FE line models.
// Storage is LAPACK's: kl extra super-diagonals hold the fill-in of pivoting.

#include <vector>

#include <Eigen/Core>

namespace spiral::engine {

class BandMatrix {
 public:
  BandMatrix() = default;
  /// n×n, kl sub- and ku super-diagonals, zero-filled.
  BandMatrix(int n, int kl, int ku);
  /// Becomes the zero n×n matrix with kl sub- and ku super-diagonals, reusing
  /// the storage (no allocation when the size does not grow).
  void reset(int n, int kl, int ku);

  int size() const { return n_; }
  /// Entry (i, j); requires −ku ≤ j − i ≤ kl in the sense i − j ∈ [−ku, kl].
  double& at(int i, int j) { return ab_[static_cast<std::size_t>(kv_ + i - j + j * ld_)]; }
  double at(int i, int j) const { return ab_[static_cast<std::size_t>(kv_ + i - j + j * ld_)]; }
  bool in_band(int i, int j) const { return i - j <= kl_ && j - i <= ku_ && i >= 0 && j >= 0 && i < n_ && j < n_; }
  /// Replaces row i by the identity row (for a prescribed DOF).
  void set_identity_row(int i);

  /// In-place LU. Returns false if a zero pivot is met (singular matrix).
  bool factorize();
  /// Solves A x = b in place after factorize().
  void solve_in_place(Eigen::Ref<Eigen::VectorXd> b) const;

 private:
  int n_ = 0, kl_ = 0, ku_ = 0, kv_ = 0, ld_ = 0;
  std::vector<double> ab_;
  std::vector<int> ipiv_;
};

}  // namespace spiral::engine
