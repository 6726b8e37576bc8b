// The serial N_Vector's operations for the IDA adapter (fast_nvector.hpp).

#include "engine/numerics/fast_nvector.hpp"

#include <algorithm>
#include <cmath>

#include "engine/common/worker_pool.hpp"

namespace spiral::engine::fast_nvector {
namespace {

using Vec = Eigen::Map<Eigen::VectorXd>;

// The pool the integrator in IDASolve on this thread splits its vector
// operations over (IdaOptions::vector_pool), or null. Set by set_solve_context only.
thread_local WorkerPool* t_pool = nullptr;
// Below this many states a split costs more than it saves (a pool run is a
// few microseconds; an operation on 20,000 doubles ≈ 10 µs).
constexpr Eigen::Index kMinSplitStates = 20000;

/// Whether an operation on n states goes to the pool.
bool on_pool(Eigen::Index n) { return t_pool != nullptr && t_pool->threads() > 1 && n >= kMinSplitStates; }

/// op(begin, length) over [0, n): on the pool in one contiguous range per
/// thread, else at once. Elementwise operations give the same values either way.
template <class Op>
void elementwise(Eigen::Index n, const Op& op) {
  if (!on_pool(n)) {
    op(Eigen::Index{0}, n);
    return;
  }
  const int parts = t_pool->threads();
  t_pool->run(parts, [&](int i) {
    const Eigen::Index a = n * i / parts, b = n * (i + 1) / parts;
    op(a, b - a);
  });
}

void linear_sum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
  elementwise(NV_LENGTH_S(z), [&](Eigen::Index i, Eigen::Index m) {
    vec(z).segment(i, m) = a * vec(x).segment(i, m) + b * vec(y).segment(i, m);
  });
}
void constant(realtype c, N_Vector z) {
  elementwise(NV_LENGTH_S(z), [&](Eigen::Index i, Eigen::Index m) { vec(z).segment(i, m).setConstant(c); });
}
void prod(N_Vector x, N_Vector y, N_Vector z) {
  elementwise(NV_LENGTH_S(z), [&](Eigen::Index i, Eigen::Index m) {
    vec(z).segment(i, m) = vec(x).segment(i, m).cwiseProduct(vec(y).segment(i, m));
  });
}
void div(N_Vector x, N_Vector y, N_Vector z) {
  elementwise(NV_LENGTH_S(z), [&](Eigen::Index i, Eigen::Index m) {
    vec(z).segment(i, m) = vec(x).segment(i, m).cwiseQuotient(vec(y).segment(i, m));
  });
}
void scale(realtype c, N_Vector x, N_Vector z) {
  elementwise(NV_LENGTH_S(z), [&](Eigen::Index i, Eigen::Index m) { vec(z).segment(i, m) = c * vec(x).segment(i, m); });
}
void abs(N_Vector x, N_Vector z) {
  elementwise(NV_LENGTH_S(z),
              [&](Eigen::Index i, Eigen::Index m) { vec(z).segment(i, m) = vec(x).segment(i, m).cwiseAbs(); });
}
void inv(N_Vector x, N_Vector z) {
  elementwise(NV_LENGTH_S(z),
              [&](Eigen::Index i, Eigen::Index m) { vec(z).segment(i, m) = vec(x).segment(i, m).cwiseInverse(); });
}
void add_const(N_Vector x, realtype b, N_Vector z) {
  elementwise(NV_LENGTH_S(z),
              [&](Eigen::Index i, Eigen::Index m) { vec(z).segment(i, m) = vec(x).segment(i, m).array() + b; });
}
realtype dot(N_Vector x, N_Vector y) { return vec(x).dot(vec(y)); }
realtype max_norm(N_Vector x) { return NV_LENGTH_S(x) > 0 ? vec(x).cwiseAbs().maxCoeff() : 0.0; }
// Block error norms (IdaOptions::error_group_starts): the integrator in
// IDASolve on this thread, or null (one group). Set by set_solve_context only.
thread_local const std::vector<Eigen::Index>* t_error_groups = nullptr;

/// max over the groups of sqrt(Σ_g (x w)² / n_g), the terms with mask > 0
/// (no mask: all). Each group's sum is one Eigen reduction whether on the
/// pool or not, so the norm is the same either way.
realtype grouped_wrms(const Vec& x, const Vec& w, const double* mask) {
  const std::vector<Eigen::Index>& starts = *t_error_groups;
  const Eigen::Index n = x.size();
  std::vector<double> mean_square(starts.size(), 0.0);
  const auto group = [&](int gi) {
    const auto g = static_cast<std::size_t>(gi);
    const Eigen::Index a = starts[g], m = (g + 1 < starts.size() ? starts[g + 1] : n) - a;
    const auto xw2 = (x.segment(a, m).array() * w.segment(a, m).array()).square();
    const double sum =
        mask == nullptr ? xw2.sum() : (Eigen::Map<const Eigen::ArrayXd>(mask + a, m) > 0.0).select(xw2, 0.0).sum();
    mean_square[g] = sum / static_cast<double>(m);
  };
  const int groups = static_cast<int>(starts.size());
  if (on_pool(n)) {
    t_pool->run(groups, [&](int g) { group(g); });
  } else {
    for (int g = 0; g < groups; ++g) group(g);
  }
  return std::sqrt(*std::max_element(mean_square.begin(), mean_square.end()));
}

realtype wrms_norm(N_Vector x, N_Vector w) {
  if (t_error_groups != nullptr) return grouped_wrms(vec(x), vec(w), nullptr);
  return std::sqrt(vec(x).cwiseProduct(vec(w)).squaredNorm() / static_cast<double>(NV_LENGTH_S(x)));
}
realtype wrms_norm_mask(N_Vector x, N_Vector w, N_Vector id) {
  if (t_error_groups != nullptr) return grouped_wrms(vec(x), vec(w), NV_DATA_S(id));
  const auto xw = vec(x).cwiseProduct(vec(w)).array();
  const double sum = (vec(id).array() > 0.0).select(xw * xw, 0.0).sum();
  return std::sqrt(sum / static_cast<double>(NV_LENGTH_S(x)));
}
realtype min(N_Vector x) { return NV_LENGTH_S(x) > 0 ? vec(x).minCoeff() : BIG_REAL; }
realtype wl2_norm(N_Vector x, N_Vector w) { return vec(x).cwiseProduct(vec(w)).norm(); }
realtype l1_norm(N_Vector x) { return vec(x).lpNorm<1>(); }
void compare(realtype c, N_Vector x, N_Vector z) {
  elementwise(NV_LENGTH_S(z), [&](Eigen::Index i, Eigen::Index m) {
    vec(z).segment(i, m) = (vec(x).segment(i, m).array().abs() >= c).select(Eigen::VectorXd::Ones(m), 0.0);
  });
}
booleantype inv_test(N_Vector x, N_Vector z) {
  const Vec xv = vec(x);
  Vec zv = vec(z);
  booleantype ok = SUNTRUE;
  for (Eigen::Index i = 0; i < xv.size(); ++i) {
    if (xv[i] == 0.0) {
      ok = SUNFALSE;
    } else {
      zv[i] = 1.0 / xv[i];
    }
  }
  return ok;
}
realtype min_quotient(N_Vector num, N_Vector denom) {
  const Vec n = vec(num), d = vec(denom);
  double m = BIG_REAL;
  for (Eigen::Index i = 0; i < n.size(); ++i) {
    if (d[i] != 0.0) m = std::min(m, n[i] / d[i]);
  }
  return m;
}
// z = Σ c_j X_j in one pass (X[0] may be z); IDA's predictor and step
// completion call it with 2 to 4 vectors.
int linear_combination(int nvec, realtype* c, N_Vector* X, N_Vector z) {
  elementwise(NV_LENGTH_S(z), [&](Eigen::Index i, Eigen::Index m) {
    const auto x = [&](int j) { return vec(X[j]).segment(i, m); };
    auto out = vec(z).segment(i, m);
    switch (nvec) {
      case 1:
        out = c[0] * x(0);
        return;
      case 2:
        out = c[0] * x(0) + c[1] * x(1);
        return;
      case 3:
        out = c[0] * x(0) + c[1] * x(1) + c[2] * x(2);
        return;
      case 4:
        out = c[0] * x(0) + c[1] * x(1) + c[2] * x(2) + c[3] * x(3);
        return;
      default:
        out = c[0] * x(0);
        for (int j = 1; j < nvec; ++j) out += c[j] * x(j);
    }
  });
  return 0;
}
// Z_j = a_j x + Y_j.
int scale_add_multi(int nvec, realtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  elementwise(NV_LENGTH_S(x), [&](Eigen::Index i, Eigen::Index m) {
    for (int j = 0; j < nvec; ++j) vec(Z[j]).segment(i, m) = a[j] * vec(x).segment(i, m) + vec(Y[j]).segment(i, m);
  });
  return 0;
}
int dot_prod_multi(int nvec, N_Vector x, N_Vector* Y, realtype* d) {
  for (int j = 0; j < nvec; ++j) d[j] = vec(x).dot(vec(Y[j]));
  return 0;
}

// nvector_serial.c's own arithmetic, for an integrator whose adaptive step
// sequence hangs on the last bit (CVODE's error test on a few dozen states):
// the linear sum's special cases (a = b sums first, c (x + y)) and the
// reductions as one running sum in index order.
void linear_sum_as_library(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
  if (a == b || a == -b) {
    const double *xv = NV_DATA_S(x), *yv = NV_DATA_S(y);
    double* zv = NV_DATA_S(z);
    const bool sum = a == b && !((b == 1.0 && z == y) || (a == 1.0 && z == x));
    const bool difference = a == -b && a != 1.0 && a != -1.0 && !((b == 1.0 && z == y) || (a == 1.0 && z == x));
    if (sum && a != 1.0) {
      for (sunindextype i = 0; i < NV_LENGTH_S(z); ++i) zv[i] = a * (xv[i] + yv[i]);
      return;
    }
    if (difference) {
      for (sunindextype i = 0; i < NV_LENGTH_S(z); ++i) zv[i] = a * (xv[i] - yv[i]);
      return;
    }
  }
  linear_sum(a, x, b, y, z);
}
template <class Term>
double in_order_sum(Eigen::Index n, const Term& term) {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) sum += term(i);
  return sum;
}
realtype dot_in_order(N_Vector x, N_Vector y) {
  const double *a = NV_DATA_S(x), *b = NV_DATA_S(y);
  return in_order_sum(NV_LENGTH_S(x), [&](Eigen::Index i) { return a[i] * b[i]; });
}
/// Σ (x w)², the terms with mask > 0 (no mask: all).
double weighted_square_sum_in_order(N_Vector x, N_Vector w, const double* mask = nullptr) {
  const double *a = NV_DATA_S(x), *b = NV_DATA_S(w);
  return in_order_sum(NV_LENGTH_S(x), [&](Eigen::Index i) {
    const double p = a[i] * b[i];
    return mask == nullptr || mask[i] > 0.0 ? p * p : 0.0;
  });
}
realtype wrms_norm_in_order(N_Vector x, N_Vector w) {
  return std::sqrt(weighted_square_sum_in_order(x, w) / static_cast<double>(NV_LENGTH_S(x)));
}
realtype wrms_norm_mask_in_order(N_Vector x, N_Vector w, N_Vector id) {
  return std::sqrt(weighted_square_sum_in_order(x, w, NV_DATA_S(id)) / static_cast<double>(NV_LENGTH_S(x)));
}
realtype wl2_norm_in_order(N_Vector x, N_Vector w) { return std::sqrt(weighted_square_sum_in_order(x, w)); }
realtype l1_norm_in_order(N_Vector x) {
  const double* a = NV_DATA_S(x);
  return in_order_sum(NV_LENGTH_S(x), [&](Eigen::Index i) { return std::abs(a[i]); });
}
int dot_prod_multi_in_order(int nvec, N_Vector x, N_Vector* Y, realtype* d) {
  for (int j = 0; j < nvec; ++j) d[j] = dot_in_order(x, Y[j]);
  return 0;
}

}  // namespace

void install(N_Vector v, Arithmetic arithmetic) {
  N_Vector_Ops o = v->ops;
  o->nvlinearsum = &linear_sum;
  o->nvconst = &constant;
  o->nvprod = &prod;
  o->nvdiv = &div;
  o->nvscale = &scale;
  o->nvabs = &abs;
  o->nvinv = &inv;
  o->nvaddconst = &add_const;
  o->nvdotprod = &dot;
  o->nvmaxnorm = &max_norm;
  o->nvwrmsnorm = &wrms_norm;
  o->nvwrmsnormmask = &wrms_norm_mask;
  o->nvmin = &min;
  o->nvwl2norm = &wl2_norm;
  o->nvl1norm = &l1_norm;
  o->nvcompare = &compare;
  o->nvinvtest = &inv_test;
  o->nvminquotient = &min_quotient;
  o->nvlinearcombination = &linear_combination;
  o->nvscaleaddmulti = &scale_add_multi;
  o->nvdotprodmulti = &dot_prod_multi;
  if (arithmetic == Arithmetic::library) {
    o->nvlinearsum = &linear_sum_as_library;
    o->nvdotprod = &dot_in_order;
    o->nvwrmsnorm = &wrms_norm_in_order;
    o->nvwrmsnormmask = &wrms_norm_mask_in_order;
    o->nvwl2norm = &wl2_norm_in_order;
    o->nvl1norm = &l1_norm_in_order;
    o->nvdotprodmulti = &dot_prod_multi_in_order;
  }
}

void set_solve_context(WorkerPool* pool, const std::vector<Eigen::Index>* error_groups) {
  t_pool = pool;
  t_error_groups = error_groups;
}

}  // namespace spiral::engine::fast_nvector
