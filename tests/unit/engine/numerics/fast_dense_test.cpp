// The CVODE adapter's compiled dense solver and matrix operations
// (fast_dense.hpp) and the library arithmetic of its vector operations
// (fast_nvector.hpp, Arithmetic::library): equal bit for bit to SUNDIALS's own
// (SUNLinSol_Dense, sunmatrix_dense, nvector_serial), which is what keeps a
// hull run's step sequence, and so its results, those of the library.

#include "engine/numerics/fast_dense.hpp"

#include <gtest/gtest.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cstring>
#include <random>
#include <utility>
#include <vector>

#include "engine/numerics/fast_nvector.hpp"

namespace spiral::engine {
namespace {

class Sundials : public testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(SUNContext_Create(nullptr, &context_), 0); }
  void TearDown() override { SUNContext_Free(&context_); }

  /// A dense n×n matrix of entries in [-1, 1], its diagonal pushed by `shift`.
  SUNMatrix random_matrix(sunindextype n, double shift) {
    SUNMatrix A = SUNDenseMatrix(n, n, context_);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (sunindextype j = 0; j < n; ++j)
      for (sunindextype i = 0; i < n; ++i) SM_ELEMENT_D(A, i, j) = u(random_) + (i == j ? shift : 0.0);
    return A;
  }
  N_Vector random_vector(sunindextype n) {
    N_Vector v = N_VNew_Serial(n, context_);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (sunindextype i = 0; i < n; ++i) NV_Ith_S(v, i) = u(random_);
    return v;
  }
  static bool same_bits(const double* a, const double* b, sunindextype n) {
    return std::memcmp(a, b, static_cast<std::size_t>(n) * sizeof(double)) == 0;
  }

  SUNContext context_ = nullptr;
  std::mt19937 random_{20261207};
};

TEST_F(Sundials, LuFactorsAndSolvesAsTheLibrary) {
  // 36: the enhanced S-C hull's states; a weak diagonal makes the pivoting swap rows.
  for (const auto& [n, shift] : {std::pair<sunindextype, double>{12, 0.0}, {36, 0.1}, {36, 5.0}}) {
    SUNMatrix A = random_matrix(n, shift);
    SUNMatrix B = SUNMatClone(A);
    ASSERT_EQ(SUNMatCopy(A, B), 0);
    N_Vector rhs = random_vector(n);
    N_Vector x_library = N_VClone(rhs), x_compiled = N_VClone(rhs);

    SUNLinearSolver library = SUNLinSol_Dense(rhs, A, context_);
    SUNLinearSolver compiled = fast_dense::make_lu_solver(n, context_);
    ASSERT_EQ(SUNLinSolInitialize(compiled), 0);
    ASSERT_EQ(SUNLinSolSetup(library, A), 0);
    ASSERT_EQ(SUNLinSolSetup(compiled, B), 0);
    EXPECT_TRUE(same_bits(SM_DATA_D(A), SM_DATA_D(B), n * n)) << "n = " << n;
    ASSERT_EQ(SUNLinSolSolve(library, A, x_library, rhs, 0.0), 0);
    ASSERT_EQ(SUNLinSolSolve(compiled, B, x_compiled, rhs, 0.0), 0);
    EXPECT_TRUE(same_bits(NV_DATA_S(x_library), NV_DATA_S(x_compiled), n)) << "n = " << n;
    EXPECT_EQ(SUNLinSolGetType(compiled), SUNLINEARSOLVER_DIRECT);

    SUNLinSolFree(library);
    SUNLinSolFree(compiled);
    N_VDestroy(x_library);
    N_VDestroy(x_compiled);
    N_VDestroy(rhs);
    SUNMatDestroy(A);
    SUNMatDestroy(B);
  }
}

TEST_F(Sundials, LuReportsASingularMatrixAsRecoverable) {
  SUNMatrix A = random_matrix(6, 0.0);
  for (sunindextype i = 0; i < 6; ++i) SM_ELEMENT_D(A, i, 3) = 0.0;  // a zero column
  SUNLinearSolver compiled = fast_dense::make_lu_solver(6, context_);
  EXPECT_EQ(SUNLinSolSetup(compiled, A), SUNLS_LUFACT_FAIL);
  EXPECT_EQ(SUNLinSolLastFlag(compiled), 4);  // the step of the zero pivot + 1, as the library's
  SUNLinSolFree(compiled);
  SUNMatDestroy(A);
}

TEST_F(Sundials, MatrixOperationsAsTheLibraryAndTheirClonesKeepThem) {
  SUNMatrix library = random_matrix(36, 0.0);
  SUNMatrix compiled = SUNMatClone(library);
  fast_dense::install(compiled);
  ASSERT_EQ(SUNMatCopy(library, compiled), 0);
  ASSERT_EQ(SUNMatScaleAddI(-0.37, library), 0);
  ASSERT_EQ(SUNMatScaleAddI(-0.37, compiled), 0);
  EXPECT_TRUE(same_bits(SM_DATA_D(library), SM_DATA_D(compiled), 36 * 36));

  SUNMatrix saved = SUNMatClone(compiled);  // CVODE's saved Jacobian
  EXPECT_EQ(saved->ops->scaleaddi, compiled->ops->scaleaddi);
  EXPECT_EQ(saved->ops->copy, compiled->ops->copy);
  ASSERT_EQ(SUNMatCopy(compiled, saved), 0);
  EXPECT_TRUE(same_bits(SM_DATA_D(compiled), SM_DATA_D(saved), 36 * 36));
  ASSERT_EQ(SUNMatZero(saved), 0);
  EXPECT_EQ(SM_ELEMENT_D(saved, 7, 11), 0.0);
  SUNMatDestroy(saved);
  SUNMatDestroy(compiled);
  SUNMatDestroy(library);
}

TEST_F(Sundials, LibraryArithmeticOfTheVectorOperationsIsTheLibrarys) {
  constexpr sunindextype n = 36;
  N_Vector x = random_vector(n), y = random_vector(n), w = random_vector(n);
  N_Vector fast = N_VClone(x);
  fast_nvector::install(fast, fast_nvector::Arithmetic::library);
  N_Vector z_library = N_VClone(x);
  // Every case of nvector_serial.c's linear sum: the axpy forms, a = ±b
  // (summed first), ±1 and the general case.
  const std::vector<std::pair<double, double>> cases{{1.0, 1.0},  {1.0, -1.0}, {-1.0, 1.0}, {-1.0, -1.0},
                                                     {0.3, 0.3},  {0.3, -0.3}, {1.0, 0.7},  {0.7, 1.0},
                                                     {-1.0, 0.7}, {0.7, -1.0}, {0.4, 0.9},  {0.0, 0.0}};
  for (const auto& [a, b] : cases) {
    N_VLinearSum_Serial(a, x, b, y, z_library);
    fast->ops->nvlinearsum(a, x, b, y, fast);
    EXPECT_TRUE(same_bits(NV_DATA_S(z_library), NV_DATA_S(fast), n)) << a << ", " << b;
    // In place (z = y, z = x): the library's axpy forms.
    N_VScale_Serial(1.0, y, z_library);
    N_VLinearSum_Serial(a, x, b, z_library, z_library);
    N_VScale_Serial(1.0, y, fast);
    fast->ops->nvlinearsum(a, x, b, fast, fast);
    EXPECT_TRUE(same_bits(NV_DATA_S(z_library), NV_DATA_S(fast), n)) << a << ", " << b << " in place";
  }
  N_VScale_Serial(1.0, x, fast);
  EXPECT_EQ(fast->ops->nvwrmsnorm(fast, w), N_VWrmsNorm_Serial(x, w));
  EXPECT_EQ(fast->ops->nvwrmsnormmask(fast, w, y), N_VWrmsNormMask_Serial(x, w, y));
  EXPECT_EQ(fast->ops->nvdotprod(fast, y), N_VDotProd_Serial(x, y));
  EXPECT_EQ(fast->ops->nvwl2norm(fast, w), N_VWL2Norm_Serial(x, w));
  EXPECT_EQ(fast->ops->nvl1norm(fast), N_VL1Norm_Serial(x));
  for (N_Vector v : {x, y, w, fast, z_library}) N_VDestroy(v);
}

}  // namespace
}  // namespace spiral::engine
