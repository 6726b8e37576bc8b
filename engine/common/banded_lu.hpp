#pragma once
// Band matrix with LU factorisation by partial pivoting (the algorithm of
// LAPACK dgbtf2/dgbtrs: E. Anderson et al., LAPACK Users' Guide, 3rd ed.,
// SIAM 1999, §5.3.2), for the block-tridiagonal Jacobians of FE line models.
// Storage is LAPACK's band layout, column by column, but without the kl extra
// super-diagonals for the fill-in of row interchanges until the first
// interchange needs them: the FE lines' factorisations mostly make none (see
// below), and a line keeps its factor between solves (the every-line
// optimization keeps one per riser and scenario: in LAPACK's layout about
// 1 GB of its 1.4 GB peak), so the unused third of each column was zeroed,
// faulted in and streamed through every back substitution.
//
// The pivot rule is the caller's choice. Partial pivoting (LAPACK's) for any
// matrix; or the diagonal while the matrix behaves as definite, for the FE
// lines' static Jacobians: a tensioned line's stiffness K is symmetric
// positive definite (plus a small unsymmetric drag part) and the Jacobian of
// the net nodal forces is −K, for which elimination in the natural order is
// backward stable without interchanges (Higham, Accuracy and Stability of
// Numerical Algorithms, 2nd ed., §10.1 for Cholesky, §9.4: growth factor 1
// for definite and diagonally dominant matrices). Partial pivoting on these
// matrices swaps rows in 70–80 % of the columns (the axial stiffness couples
// x, y and z of an inclined element far more than the transverse stiffness
// holds each), which doubles the factor's upper band and its work for no
// accuracy. A column whose pivot changed sign, lost nearly all of its
// diagonal, or is dwarfed by its coupling to a later row (|a_ij a_ji| >
// 4 |a_ii a_jj|, impossible in a definite matrix) — slack or compressed
// elements, an indefinite tangent — falls back to partial pivoting for that
// column.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace spiral::engine {

enum class Pivoting {
  partial,                  ///< the column's largest entry (LAPACK dgbtf2)
  diagonal_while_definite,  ///< the diagonal while it keeps its sign and size (see above)
};

class BandMatrix {
 public:
  BandMatrix() = default;
  /// n×n, kl sub- and ku super-diagonals, zero-filled.
  BandMatrix(int n, int kl, int ku);
  /// Becomes the zero n×n matrix with kl sub- and ku super-diagonals, reusing
  /// the storage (no allocation when the size does not grow). Compact (no
  /// fill-in rows) until factorize() interchanges rows.
  void reset(int n, int kl, int ku);

  int size() const { return n_; }
  /// Diagonals held per column: kl + ku + 1, or 2 kl + ku + 1 once a row
  /// interchange needed the fill-in rows.
  int stored_diagonals() const { return ld_; }
  /// Entry (i, j); requires −ku ≤ j − i ≤ kl in the sense i − j ∈ [−ku, kl].
  double& at(int i, int j) { return ab_[static_cast<std::size_t>(kv_ + i - j + j * ld_)]; }
  double at(int i, int j) const { return ab_[static_cast<std::size_t>(kv_ + i - j + j * ld_)]; }
  bool in_band(int i, int j) const { return i - j <= kl_ && j - i <= ku_ && i >= 0 && j >= 0 && i < n_ && j < n_; }
  /// Replaces row i by the identity row (for a prescribed DOF).
  void set_identity_row(int i);

  /// In-place LU. Returns false if a zero pivot is met (singular matrix).
  bool factorize(Pivoting pivoting = Pivoting::partial);
  /// Solves A x = b in place after factorize().
  void solve_in_place(Eigen::Ref<Eigen::VectorXd> b) const;
  /// Each column of b, as solve_in_place (the same result, bit for bit), the
  /// factor read once for three columns at a time.
  void solve_columns_in_place(Eigen::Ref<Eigen::MatrixXd> b) const;

 private:
  const double* address(int i, int j) const { return &ab_[static_cast<std::size_t>(kv_ + i - j + j * ld_)]; }
  template <int KL>
  bool factorize_band(Pivoting pivoting);
  /// Adds the kl fill-in rows above each column (in place, values kept).
  void widen();
  bool compact() const { return kv_ == ku_; }
  // NC right-hand sides, column_stride apart, from x.
  template <int KL, int NC>
  void solve_band(double* x, std::ptrdiff_t column_stride) const;
  template <int NC>
  void solve_columns(double* x, std::ptrdiff_t column_stride) const;

  // kv_: the diagonal's row in a stored column (ku_ compact, kl_ + ku_
  // wide); ld_: a stored column's length.
  int n_ = 0, kl_ = 0, ku_ = 0, kv_ = 0, ld_ = 0;
  std::vector<double> ab_;
  std::vector<int> ipiv_;
  std::vector<double> inverse_pivot_;
  // First row of U's column j that can be nonzero: row interchanges widen U's
  // band only near them, so the back substitution skips the fill-in
  // diagonals that stay zero elsewhere.
  std::vector<int> column_top_;
};

}  // namespace spiral::engine
