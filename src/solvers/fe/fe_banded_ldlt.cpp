// SPDX-License-Identifier: MIT
#include "solvers/fe/fe_banded_ldlt.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {
namespace {

// A compressed column holds its rows in ascending order: its first and last entries are the
// farthest from the diagonal.
int half_bandwidth(const Eigen::SparseMatrix<double>& A) {
  Eigen::Index b = 0;
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const auto* counts = A.innerNonZeroPtr();  // null when compressed
  for (Eigen::Index c = 0; c < A.outerSize(); ++c) {
    const Eigen::Index begin = outer[c], end = counts ? begin + counts[c] : outer[c + 1];
    if (begin == end) continue;
    b = std::max({b, std::abs(inner[begin] - c), std::abs(inner[end - 1] - c)});
  }
  return static_cast<int>(b);
}

}  // namespace

void BandedLdlt::prepare(Eigen::Index n, int bandwidth) {
  n_ = n;
  bandwidth_ = bandwidth;
  // assign() and setZero() keep the capacity: a later factorisation of the same size does not
  // touch fresh pages.
  lower_.assign(static_cast<std::size_t>(n_) * static_cast<std::size_t>(std::max(bandwidth, 1)),
                0.0);
  pivots_.setZero(n_);
}

// The lower triangle (column-major storage: column c, rows r >= c).
void BandedLdlt::scatter(const Eigen::SparseMatrix<double>& A, double scale) {
  const int b = bandwidth_;
  for (Eigen::Index c = 0; c < A.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) {
      const Eigen::Index r = it.row();
      if (r == c) {
        pivots_[r] += scale * it.value();
      } else if (r > c) {
        lower_[static_cast<std::size_t>(r * b + (c - r + b))] += scale * it.value();
      }
    }
  }
}

bool BandedLdlt::factorize(const Eigen::SparseMatrix<double>& A) {
  prepare(A.rows(), half_bandwidth(A));
  scatter(A, 1.0);
  return factor_scattered();
}

bool BandedLdlt::factorize(const Eigen::SparseMatrix<double>& K,
                           const Eigen::SparseMatrix<double>& M,
                           double sigma) {
  prepare(K.rows(), std::max(half_bandwidth(K), half_bandwidth(M)));
  // 0 + k = k and k + (-sigma m) = k - sigma m exactly: the entries of the sparse difference.
  scatter(K, 1.0);
  scatter(M, -sigma);
  return factor_scattered();
}

bool BandedLdlt::factor_scattered() {
  switch (bandwidth_) {
    case 1:
      return factor_rows<1>();
    case 3:
      return factor_rows<3>();
    default:
      return factor_rows<0>();
  }
}

// Row-oriented LDL^T: for row i, L(i, j) = (A(i, j) - sum_k L(i, k) D(k) L(j, k)) / D(j) for
// j < i, then D(i) = A(i, i) - sum_k L(i, k)^2 D(k). The entries are overwritten in place.
// B > 0: the half bandwidth as a compile-time constant; B = 0: bandwidth_ at run time.
template <int B>
bool BandedLdlt::factor_rows() {
  const Eigen::Index b = B > 0 ? B : bandwidth_;
  double* pivots = pivots_.data();
  for (Eigen::Index i = 0; i < n_; ++i) {
    const Eigen::Index first = std::max<Eigen::Index>(0, i - b);
    double* row_i = lower_.data() + i * b + b - i;  // row_i[j] = L(i, j)
    for (Eigen::Index j = first; j < i; ++j) {
      const double* row_j = lower_.data() + j * b + b - j;
      double sum = row_i[j];
      for (Eigen::Index k = std::max(first, j - b); k < j; ++k)
        sum -= row_i[k] * pivots[k] * row_j[k];
      row_i[j] = sum / pivots[j];
    }
    double d = pivots[i];
    for (Eigen::Index k = first; k < i; ++k) d -= row_i[k] * row_i[k] * pivots[k];
    if (!(d != 0.0) || !std::isfinite(d)) return false;
    pivots[i] = d;
  }
  return true;
}

// L y = x (unit lower), y /= D, L^T z = y. Rows i >= b have exactly b entries left of the
// diagonal: with B > 0 their loops have a fixed length and unroll; the order of the operations is
// the same either way.
template <int B>
void BandedLdlt::solve_rows(double* x) const {
  const Eigen::Index b = B > 0 ? B : bandwidth_;
  const double* pivots = pivots_.data();
  const double* lower = lower_.data();
  const Eigen::Index head = std::min(b, n_);
  for (Eigen::Index i = 0; i < head; ++i) {
    const double* row_i = lower + i * b + b - i;
    double sum = x[i];
    for (Eigen::Index k = 0; k < i; ++k) sum -= row_i[k] * x[k];
    x[i] = sum;
  }
  for (Eigen::Index i = head; i < n_; ++i) {
    const double* row = lower + i * b;  // row[t] = L(i, i - b + t)
    const double* xs = x + i - b;
    double sum = x[i];
    for (Eigen::Index t = 0; t < b; ++t) sum -= row[t] * xs[t];
    x[i] = sum;
  }
  for (Eigen::Index i = 0; i < n_; ++i) x[i] /= pivots[i];
  for (Eigen::Index i = n_ - 1; i >= head; --i) {
    const double* row = lower + i * b;
    double* xs = x + i - b;
    const double xi = x[i];
    for (Eigen::Index t = 0; t < b; ++t) xs[t] -= row[t] * xi;
  }
  for (Eigen::Index i = head - 1; i >= 0; --i) {
    const double* row_i = lower + i * b + b - i;
    const double xi = x[i];
    for (Eigen::Index k = 0; k < i; ++k) x[k] -= row_i[k] * xi;
  }
}

void BandedLdlt::solve_in_place(double* x) const {
  switch (bandwidth_) {
    case 1:
      solve_rows<1>(x);
      break;
    case 3:
      solve_rows<3>(x);
      break;
    default:
      solve_rows<0>(x);
      break;
  }
}

void BandedLdlt::solve_in_place(Eigen::Ref<Eigen::MatrixXd> x) const {
  for (Eigen::Index c = 0; c < x.cols(); ++c) solve_in_place(x.col(c).data());
}

int BandedLdlt::negative_pivots() const {
  return static_cast<int>((pivots_.array() < 0.0).count());
}

double BandedLdlt::pivot_ratio() const {
  const double largest = pivots_.cwiseAbs().maxCoeff();
  return largest > 0.0 ? pivots_.cwiseAbs().minCoeff() / largest : 0.0;
}

}  // namespace catena::internal
