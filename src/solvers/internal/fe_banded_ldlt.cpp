#include "solvers/internal/fe_banded_ldlt.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {

bool BandedLdlt::factorize(const Eigen::SparseMatrix<double>& A) {
  n_ = A.rows();
  int b = 0;
  for (Eigen::Index c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      b = std::max(b, static_cast<int>(std::abs(it.row() - it.col())));
  bandwidth_ = b;
  lower_.assign(static_cast<std::size_t>(n_) * static_cast<std::size_t>(std::max(b, 1)), 0.0);
  pivots_.setZero(n_);
  // Scatter the lower triangle (column-major storage: column c, rows r >= c).
  for (Eigen::Index c = 0; c < A.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) {
      const Eigen::Index r = it.row();
      if (r == c) {
        pivots_[r] = it.value();
      } else if (r > c) {
        lower_[static_cast<std::size_t>(r * b + (c - r + b))] = it.value();
      }
    }
  }
  // Row-oriented LDL^T: for row i, L(i, j) = (A(i, j) - sum_k L(i, k) D(k) L(j, k)) / D(j) for
  // j < i, then D(i) = A(i, i) - sum_k L(i, k)^2 D(k). The entries are overwritten in place.
  for (Eigen::Index i = 0; i < n_; ++i) {
    const Eigen::Index first = std::max<Eigen::Index>(0, i - b);
    double* row_i = lower_.data() + i * b + b - i;  // row_i[j] = L(i, j)
    for (Eigen::Index j = first; j < i; ++j) {
      const double* row_j = lower_.data() + j * b + b - j;
      double sum = row_i[j];
      for (Eigen::Index k = std::max(first, j - b); k < j; ++k) sum -= row_i[k] * pivots_[k] * row_j[k];
      row_i[j] = sum / pivots_[j];
    }
    double d = pivots_[i];
    for (Eigen::Index k = first; k < i; ++k) d -= row_i[k] * row_i[k] * pivots_[k];
    if (!(d != 0.0) || !std::isfinite(d)) return false;
    pivots_[i] = d;
  }
  return true;
}

void BandedLdlt::solve_in_place(double* x) const {
  const int b = bandwidth_;
  // L y = x (unit lower), y /= D, L^T z = y.
  for (Eigen::Index i = 0; i < n_; ++i) {
    const double* row_i = lower_.data() + i * b + b - i;
    double sum = x[i];
    for (Eigen::Index k = std::max<Eigen::Index>(0, i - b); k < i; ++k) sum -= row_i[k] * x[k];
    x[i] = sum;
  }
  for (Eigen::Index i = 0; i < n_; ++i) x[i] /= pivots_[i];
  for (Eigen::Index i = n_ - 1; i >= 0; --i) {
    const double* row_i = lower_.data() + i * b + b - i;
    const double xi = x[i];
    for (Eigen::Index k = std::max<Eigen::Index>(0, i - b); k < i; ++k) x[k] -= row_i[k] * xi;
  }
}

void BandedLdlt::solve_in_place(Eigen::Ref<Eigen::MatrixXd> x) const {
  for (Eigen::Index c = 0; c < x.cols(); ++c) solve_in_place(x.col(c).data());
}

int BandedLdlt::negative_pivots() const { return static_cast<int>((pivots_.array() < 0.0).count()); }

double BandedLdlt::pivot_ratio() const {
  const double largest = pivots_.cwiseAbs().maxCoeff();
  return largest > 0.0 ? pivots_.cwiseAbs().minCoeff() / largest : 0.0;
}

}  // namespace catena::internal
