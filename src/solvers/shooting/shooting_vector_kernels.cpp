// SPDX-License-Identifier: MIT
// The compiled vector kernels of a shot's N_Vectors: see shooting_vector_kernels.hpp.
#include "solvers/shooting/shooting_vector_kernels.hpp"

#include <nvector/nvector_serial.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace catena::internal {

namespace {

double* data(N_Vector v) { return NV_DATA_S(v); }
sunindextype length(N_Vector v) { return NV_LENGTH_S(v); }

void linear_sum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(z); i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
}

void constant(double c, N_Vector z) { std::fill_n(data(z), length(z), c); }

void scale(double c, N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(z); i < n; ++i) zd[i] = c * xd[i];
}

void product(N_Vector x, N_Vector y, N_Vector z) {
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(z); i < n; ++i) zd[i] = xd[i] * yd[i];
}

void quotient(N_Vector x, N_Vector y, N_Vector z) {
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(z); i < n; ++i) zd[i] = xd[i] / yd[i];
}

void absolute(N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(z); i < n; ++i) zd[i] = std::abs(xd[i]);
}

void inverse(N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(z); i < n; ++i) zd[i] = 1.0 / xd[i];
}

void add_constant(N_Vector x, double b, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(z); i < n; ++i) zd[i] = xd[i] + b;
}

double max_norm(N_Vector x) {
  const double* xd = data(x);
  double largest = 0.0;
  for (sunindextype i = 0, n = length(x); i < n; ++i) largest = std::max(largest, std::abs(xd[i]));
  return largest;
}

double weighted_squares(N_Vector x, N_Vector w) {
  const double *xd = data(x), *wd = data(w);
  double sum = 0.0;
  for (sunindextype i = 0, n = length(x); i < n; ++i) {
    const double term = xd[i] * wd[i];
    sum += term * term;
  }
  return sum;
}

double weighted_rms(N_Vector x, N_Vector w) {
  return std::sqrt(weighted_squares(x, w) / static_cast<double>(length(x)));
}

double minimum(N_Vector x) {
  const double* xd = data(x);
  double smallest = std::numeric_limits<double>::max();
  for (sunindextype i = 0, n = length(x); i < n; ++i) smallest = std::min(smallest, xd[i]);
  return smallest;
}

// z = (...((z + c_0 X_0) + c_1 X_1) + ...), or without the leading z when Start, in SUNDIALS'
// order for each element; terms with c_k = 0 (ERKStep passes every earlier stage) are skipped,
// since adding 0 X_k changes no finite sum. No X_k is z. N > 0: a shot's state size, known at
// compile time, so that the sum stays in registers (the loops over N unroll and vectorise);
// N = 0: any size n.
template <int N, bool Start>
void accumulate(const double* c, const N_Vector* X, int count, double* z, sunindextype n) {
  if constexpr (N > 0) {
    using Vector = Eigen::Matrix<double, N, 1>;
    Vector sum;
    if constexpr (Start) {
      sum = c[0] * Vector::Map(data(X[0]));
    } else {
      sum = Vector::Map(z) + c[0] * Vector::Map(data(X[0]));
    }
    for (int k = 1; k < count; ++k) {
      if (c[k] != 0.0) sum += c[k] * Vector::Map(data(X[k]));
    }
    Vector::Map(z) = sum;
  } else {
    for (sunindextype i = 0; i < n; ++i) {
      double sum = Start ? c[0] * data(X[0])[i] : z[i] + c[0] * data(X[0])[i];
      for (int k = 1; k < count; ++k) sum += c[k] * data(X[k])[i];
      z[i] = sum;
    }
  }
}

// accumulate for the size n: the shot's state sizes 2 D^2 + 1 and 4 D^2 + 1 (D = 1, 2) by
// their own code, any other by the general loop.
template <bool Start>
void accumulate_all(const double* c, const N_Vector* X, int count, double* z, sunindextype n) {
  if (count < 1) return;
  switch (n) {
    case 3:
      return accumulate<3, Start>(c, X, count, z, n);
    case 5:
      return accumulate<5, Start>(c, X, count, z, n);
    case 9:
      return accumulate<9, Start>(c, X, count, z, n);
    case 17:
      return accumulate<17, Start>(c, X, count, z, n);
    default:
      return accumulate<0, Start>(c, X, count, z, n);
  }
}

// z = sum_j c_j X_j, accumulated from j = 0 up as SUNDIALS' serial version does, with z = X_0
// allowed (then z = c_0 z first). When z is a later X_j, element by element, so that each X_j
// is read before z is written.
int linear_combination(int count, double* c, N_Vector* X, N_Vector z) {
  if (count < 1) return -1;
  const sunindextype n = length(z);
  double* zd = data(z);
  bool later_alias = false;
  for (int j = 1; j < count; ++j) later_alias = later_alias || X[j] == z;
  if (later_alias) {
    accumulate<0, true>(c, X, count, zd, n);
  } else if (X[0] == z) {
    if (c[0] != 1.0) scale(c[0], z, z);
    accumulate_all<false>(c + 1, X + 1, count - 1, zd, n);
  } else {
    accumulate_all<true>(c, X, count, zd, n);
  }
  return 0;
}

}  // namespace

void use_compiled_kernels(N_Vector vector) {
  N_Vector_Ops ops = vector->ops;
  ops->nvlinearsum = linear_sum;
  ops->nvconst = constant;
  ops->nvscale = scale;
  ops->nvprod = product;
  ops->nvdiv = quotient;
  ops->nvabs = absolute;
  ops->nvinv = inverse;
  ops->nvaddconst = add_constant;
  ops->nvmaxnorm = max_norm;
  ops->nvwrmsnorm = weighted_rms;
  ops->nvwsqrsumlocal = weighted_squares;
  ops->nvmin = minimum;
  ops->nvlinearcombination = linear_combination;
}

}  // namespace catena::internal
