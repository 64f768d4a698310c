// SPDX-License-Identifier: MIT
// Complex symmetric banded LDL^T: see fe_complex_banded_ldlt.hpp.
#include "solvers/fe/fe_complex_banded_ldlt.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {
namespace {

int half_bandwidth(const Eigen::SparseMatrix<double>& A) {
  Eigen::Index b = 0;
  for (Eigen::Index c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      b = std::max(b, std::abs(it.row() - c));
  return static_cast<int>(b);
}

}  // namespace

void ComplexBandedLdlt::scatter(const Eigen::SparseMatrix<double>& A, Complex scale) {
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

bool ComplexBandedLdlt::factorize(const Eigen::SparseMatrix<double>& K,
                                  const Eigen::SparseMatrix<double>& C,
                                  const Eigen::SparseMatrix<double>& M,
                                  Complex lambda) {
  n_ = K.rows();
  bandwidth_ = std::max({half_bandwidth(K), half_bandwidth(C), half_bandwidth(M), 1});
  const Eigen::Index b = bandwidth_;
  lower_.assign(static_cast<std::size_t>(n_ * b), Complex(0.0));
  pivots_.setZero(n_);
  scatter(K, 1.0);
  scatter(C, lambda);
  scatter(M, lambda * lambda);
  // Row-oriented LDL^T, as BandedLdlt::factor_rows (transpose, not conjugate: A is symmetric).
  for (Eigen::Index i = 0; i < n_; ++i) {
    const Eigen::Index first = std::max<Eigen::Index>(0, i - b);
    Complex* row_i = lower_.data() + i * b + b - i;
    for (Eigen::Index j = first; j < i; ++j) {
      const Complex* row_j = lower_.data() + j * b + b - j;
      Complex sum = row_i[j];
      for (Eigen::Index k = std::max(first, j - b); k < j; ++k)
        sum -= row_i[k] * pivots_[k] * row_j[k];
      row_i[j] = sum / pivots_[j];
    }
    Complex d = pivots_[i];
    for (Eigen::Index k = first; k < i; ++k) d -= row_i[k] * row_i[k] * pivots_[k];
    if (!(std::abs(d) > 0.0) || !std::isfinite(std::abs(d))) return false;
    pivots_[i] = d;
  }
  return true;
}

void ComplexBandedLdlt::solve_in_place(Complex* x) const {
  const Eigen::Index b = bandwidth_;
  for (Eigen::Index i = 0; i < n_; ++i) {
    const Complex* row_i = lower_.data() + i * b + b - i;
    Complex sum = x[i];
    for (Eigen::Index k = std::max<Eigen::Index>(0, i - b); k < i; ++k) sum -= row_i[k] * x[k];
    x[i] = sum;
  }
  for (Eigen::Index i = 0; i < n_; ++i) x[i] /= pivots_[i];
  for (Eigen::Index i = n_ - 1; i >= 0; --i) {
    const Complex* row_i = lower_.data() + i * b + b - i;
    const Complex xi = x[i];
    for (Eigen::Index k = std::max<Eigen::Index>(0, i - b); k < i; ++k) x[k] -= row_i[k] * xi;
  }
}

double ComplexBandedLdlt::pivot_ratio() const {
  const double largest = pivots_.cwiseAbs().maxCoeff();
  return largest > 0.0 ? pivots_.cwiseAbs().minCoeff() / largest : 0.0;
}

double ComplexBandedLdlt::determinant_phase() const {
  // The product of the unit phases, renormalised as it goes: the determinant itself over- or
  // underflows for a few hundred unknowns.
  Complex phase(1.0, 0.0);
  for (Eigen::Index i = 0; i < n_; ++i) {
    phase *= pivots_[i] / std::abs(pivots_[i]);
    phase /= std::abs(phase);
  }
  return std::arg(phase);
}

}  // namespace catena::internal
