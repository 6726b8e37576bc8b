#include "engine/numerics/fast_dense.hpp"

#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <utility>
#include <vector>

namespace spiral::engine::fast_dense {
namespace {

// --- matrix operations (sunmatrix_dense.c semantics) ---

int zero(SUNMatrix A) {
  realtype* data = SM_DATA_D(A);
  for (sunindextype i = 0; i < SM_LDATA_D(A); ++i) data[i] = 0.0;
  return SUNMAT_SUCCESS;
}

/// B = A (same shape: CVODE's matrices are clones of one another).
int copy(SUNMatrix A, SUNMatrix B) {
  if (SM_LDATA_D(A) != SM_LDATA_D(B)) return SUNMAT_ILL_INPUT;
  const realtype* a = SM_DATA_D(A);
  realtype* b = SM_DATA_D(B);
  for (sunindextype i = 0; i < SM_LDATA_D(A); ++i) b[i] = a[i];
  return SUNMAT_SUCCESS;
}

/// A = c A + I.
int scale_add_identity(realtype c, SUNMatrix A) {
  realtype** cols = SM_COLS_D(A);
  for (sunindextype j = 0; j < SM_COLUMNS_D(A); ++j) {
    realtype* col = cols[j];
    for (sunindextype i = 0; i < SM_ROWS_D(A); ++i) {
      col[i] *= c;
      if (i == j) col[i] += 1.0;
    }
  }
  return SUNMAT_SUCCESS;
}

SUNMatrix clone(SUNMatrix A) {
  SUNMatrix B = SUNDenseMatrix(SM_ROWS_D(A), SM_COLUMNS_D(A), A->sunctx);
  if (B != nullptr) install(B);
  return B;
}

// --- the LU (sundials_dense.c: SUNDlsMat_denseGETRF / denseGETRS) ---

/// Factors the m×n column-major matrix in place; p[k] the row swapped with
/// row k at step k. Returns 0, or k + 1 for a zero pivot at step k.
sunindextype factorize(realtype** a, sunindextype m, sunindextype n, sunindextype* p) {
  for (sunindextype k = 0; k < n; ++k) {
    realtype* col_k = a[k];
    sunindextype l = k;
    for (sunindextype i = k + 1; i < m; ++i)
      if (std::abs(col_k[i]) > std::abs(col_k[l])) l = i;
    p[k] = l;
    if (col_k[l] == 0.0) return k + 1;
    if (l != k)
      for (sunindextype i = 0; i < n; ++i) std::swap(a[i][l], a[i][k]);
    const realtype mult = 1.0 / col_k[k];
    for (sunindextype i = k + 1; i < m; ++i) col_k[i] *= mult;
    for (sunindextype j = k + 1; j < n; ++j) {
      realtype* col_j = a[j];
      const realtype a_kj = col_j[k];
      if (a_kj != 0.0)
        for (sunindextype i = k + 1; i < m; ++i) col_j[i] -= a_kj * col_k[i];
    }
  }
  return 0;
}

void back_substitute(realtype** a, sunindextype n, const sunindextype* p, realtype* b) {
  for (sunindextype k = 0; k < n; ++k)
    if (const sunindextype pk = p[k]; pk != k) std::swap(b[k], b[pk]);
  for (sunindextype k = 0; k < n - 1; ++k) {
    const realtype* col_k = a[k];
    for (sunindextype i = k + 1; i < n; ++i) b[i] -= col_k[i] * b[k];
  }
  for (sunindextype k = n - 1; k > 0; --k) {
    const realtype* col_k = a[k];
    b[k] /= col_k[k];
    for (sunindextype i = 0; i < k; ++i) b[i] -= col_k[i] * b[k];
  }
  b[0] /= a[0][0];
}

struct LuContent {
  std::vector<sunindextype> pivots;
  sunindextype last_flag = 0;
};

LuContent& content(SUNLinearSolver S) { return *static_cast<LuContent*>(S->content); }

SUNLinearSolver_Type solver_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID solver_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialize(SUNLinearSolver S) {
  content(S).last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

int setup(SUNLinearSolver S, SUNMatrix A) {
  LuContent& c = content(S);
  if (SM_ROWS_D(A) != SM_COLUMNS_D(A) || static_cast<sunindextype>(c.pivots.size()) != SM_COLUMNS_D(A)) {
    c.last_flag = SUNLS_ILL_INPUT;
    return SUNLS_ILL_INPUT;
  }
  c.last_flag = factorize(SM_COLS_D(A), SM_ROWS_D(A), SM_COLUMNS_D(A), c.pivots.data());
  return c.last_flag > 0 ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
}

int solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype /*tol*/) {
  N_VScale(1.0, b, x);
  back_substitute(SM_COLS_D(A), SM_COLUMNS_D(A), content(S).pivots.data(), N_VGetArrayPointer(x));
  content(S).last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

sunindextype last_flag(SUNLinearSolver S) { return content(S).last_flag; }

int free_solver(SUNLinearSolver S) {
  if (S == nullptr) return SUNLS_SUCCESS;
  delete static_cast<LuContent*>(S->content);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

void install(SUNMatrix dense) {
  SUNMatrix_Ops o = dense->ops;
  o->zero = &zero;
  o->copy = &copy;
  o->scaleaddi = &scale_add_identity;
  o->clone = &clone;
}

SUNLinearSolver make_lu_solver(sunindextype n, SUNContext context) {
  SUNLinearSolver S = SUNLinSolNewEmpty(context);
  if (S == nullptr) return nullptr;
  S->content = new LuContent{std::vector<sunindextype>(static_cast<std::size_t>(n)), 0};
  S->ops->gettype = &solver_type;
  S->ops->getid = &solver_id;
  S->ops->initialize = &initialize;
  S->ops->setup = &setup;
  S->ops->solve = &solve;
  S->ops->lastflag = &last_flag;
  S->ops->free = &free_solver;
  return S;
}

}  // namespace spiral::engine::fast_dense
