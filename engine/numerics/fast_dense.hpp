#pragma once
// Internal to the CVODE adapter (sundials_cvode.cpp), not a public engine
// API: SUNDIALS's dense direct linear solver and the dense-matrix operations
// CVODE's Newton setup calls, compiled here.
//
// Why compiled here: the Debian SUNDIALS 6.4.1 libraries are built without
// optimisation (-O0), as fast_nvector.hpp says for the vector operations. On
// the default FPS's 3-h enhanced S-C storm (36 hull states: 12 of motion and
// 24 of the lines' relaxations) CVODE's LU, its solves and the matrix
// copies took 9 % of the task's profile (SUNDlsMat_denseGETRS and GETRF,
// SUNMatCopy_Dense, SUNMatScaleAddI_Dense: docs/decisions/hull-dynamics-tolerances.md).
// The algorithms are SUNDIALS's own (sundials_dense.c: column-oriented LU with
// partial pivoting on the largest magnitude, the same loops in the same order),
// so the factors and solutions are the library's bit for bit.

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

namespace spiral::engine::fast_dense {

/// Replaces the zero, copy, scale-add-identity and clone operations in the
/// ops table of a SUNDIALS dense matrix (SUNDenseMatrix); its clones (CVODE's
/// saved Jacobian) get them too.
void install(SUNMatrix dense);

/// A direct linear solver for SUNDIALS dense matrices of n×n: setup factors
/// the matrix in place (LU with row pivots; a zero pivot is a recoverable
/// failure, SUNLS_LUFACT_FAIL), solve back-substitutes. What SUNLinSol_Dense
/// does. Free with SUNLinSolFree.
SUNLinearSolver make_lu_solver(sunindextype n, SUNContext context);

}  // namespace spiral::engine::fast_dense
