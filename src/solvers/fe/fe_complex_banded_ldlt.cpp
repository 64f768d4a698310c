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
  return factor_in_place();
}

// Row-oriented LDL^T, as BandedLdlt::factor_rows (transpose, not conjugate: A is symmetric).
bool ComplexBandedLdlt::factor_in_place() {
  const Eigen::Index b = bandwidth_;
  inverse_pivots_.resize(n_);
  for (Eigen::Index i = 0; i < n_; ++i) {
    const Eigen::Index first = std::max<Eigen::Index>(0, i - b);
    Complex* row_i = lower_.data() + i * b + b - i;
    for (Eigen::Index j = first; j < i; ++j) {
      const Complex* row_j = lower_.data() + j * b + b - j;
      Complex sum = row_i[j];
      for (Eigen::Index k = std::max(first, j - b); k < j; ++k)
        sum -= row_i[k] * pivots_[k] * row_j[k];
      row_i[j] = sum * inverse_pivots_[j];
    }
    Complex d = pivots_[i];
    for (Eigen::Index k = first; k < i; ++k) d -= row_i[k] * row_i[k] * pivots_[k];
    // |d|^2 rather than |d|: hypot's care for overflow costs more than the factorisation here.
    const double modulus2 = std::norm(d);
    if (!(modulus2 > 0.0) || !std::isfinite(modulus2)) return false;
    pivots_[i] = d;
    inverse_pivots_[i] = std::conj(d) / modulus2;
  }
  return true;
}

namespace {

// The lower band of A with half bandwidth b: row i's entries L(i, i - b .. i - 1) then A(i, i).
std::vector<double> band_of(const Eigen::SparseMatrix<double>& A, int b) {
  std::vector<double> band(static_cast<std::size_t>(A.rows() * (b + 1)), 0.0);
  for (Eigen::Index c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      if (it.row() >= c)
        band[static_cast<std::size_t>(it.row() * (b + 1) + (c - it.row() + b))] += it.value();
  return band;
}

}  // namespace

void ComplexBandedLdlt::set_pencil(const Eigen::SparseMatrix<double>& K,
                                   const Eigen::SparseMatrix<double>& C,
                                   const Eigen::SparseMatrix<double>& M) {
  n_ = K.rows();
  pencil_bandwidth_ = std::max({half_bandwidth(K), half_bandwidth(C), half_bandwidth(M), 1});
  band_K_ = band_of(K, pencil_bandwidth_);
  band_C_ = band_of(C, pencil_bandwidth_);
  band_M_ = band_of(M, pencil_bandwidth_);
}

bool ComplexBandedLdlt::factorize(Complex lambda) {
  bandwidth_ = pencil_bandwidth_;
  const Eigen::Index b = bandwidth_;
  lower_.resize(static_cast<std::size_t>(n_ * b));
  pivots_.resize(n_);
  const Complex lambda2 = lambda * lambda;
  for (Eigen::Index i = 0; i < n_; ++i) {
    const auto row = static_cast<std::size_t>(i * (b + 1));
    for (Eigen::Index t = 0; t < b; ++t)
      lower_[static_cast<std::size_t>(i * b + t)] =
          band_K_[row + t] + lambda * band_C_[row + t] + lambda2 * band_M_[row + t];
    pivots_[i] = band_K_[row + b] + lambda * band_C_[row + b] + lambda2 * band_M_[row + b];
  }
  return factor_in_place();
}

ComplexBandedLdlt::Complex ComplexBandedLdlt::log_derivative(Complex lambda) const {
  const Eigen::Index b = bandwidth_, n = n_;
  // Z = Q^{-1} = D^{-1} L^{-1} + (I - L^T) Z, from the last row up, inside the band only:
  // Z(i, j) = -sum_{k = i+1}^{i+b} L(k, i) Z(k, j) for i < j <= i + b, and
  // Z(i, i) = 1 / D(i) - sum_k L(k, i) Z(k, i). z[i * (b + 1) + d] holds Z(i, i + d).
  std::vector<Complex>& z = inverse_band_;
  z.resize(static_cast<std::size_t>(n * (b + 1)));
  auto L = [&](Eigen::Index k, Eigen::Index i) {  // L(k, i), k > i within the band
    return lower_[static_cast<std::size_t>(k * b + (i - k + b))];
  };
  auto Z = [&](Eigen::Index r, Eigen::Index c) -> Complex {  // symmetric, |r - c| <= b
    return r <= c ? z[static_cast<std::size_t>(r * (b + 1) + (c - r))]
                  : z[static_cast<std::size_t>(c * (b + 1) + (r - c))];
  };
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    const Eigen::Index last = std::min(n - 1, i + b);
    for (Eigen::Index j = last; j > i; --j) {
      Complex sum(0.0);
      for (Eigen::Index k = i + 1; k <= last; ++k) sum -= L(k, i) * Z(k, j);
      z[static_cast<std::size_t>(i * (b + 1) + (j - i))] = sum;
    }
    Complex diagonal = inverse_pivots_[i];
    for (Eigen::Index k = i + 1; k <= last; ++k) diagonal -= L(k, i) * Z(k, i);
    z[static_cast<std::size_t>(i * (b + 1))] = diagonal;
  }
  // tr(Z Q') with Q' = C + 2 lambda M from the pencil's bands (row r: L-part, then diagonal).
  const Eigen::Index pb = pencil_bandwidth_;
  Complex trace(0.0);
  for (Eigen::Index r = 0; r < n; ++r) {
    const auto row = static_cast<std::size_t>(r * (pb + 1));
    for (Eigen::Index t = 0; t <= pb; ++t) {
      const Eigen::Index c = r - pb + t;
      if (c < 0) continue;
      const Complex derivative = band_C_[row + t] + 2.0 * lambda * band_M_[row + t];
      trace += (c == r ? 1.0 : 2.0) * Z(r, c) * derivative;
    }
  }
  return trace;
}

void ComplexBandedLdlt::solve_in_place(Complex* x) const {
  const Eigen::Index b = bandwidth_;
  for (Eigen::Index i = 0; i < n_; ++i) {
    const Complex* row_i = lower_.data() + i * b + b - i;
    Complex sum = x[i];
    for (Eigen::Index k = std::max<Eigen::Index>(0, i - b); k < i; ++k) sum -= row_i[k] * x[k];
    x[i] = sum;
  }
  for (Eigen::Index i = 0; i < n_; ++i) x[i] *= inverse_pivots_[i];
  for (Eigen::Index i = n_ - 1; i >= 0; --i) {
    const Complex* row_i = lower_.data() + i * b + b - i;
    const Complex xi = x[i];
    for (Eigen::Index k = std::max<Eigen::Index>(0, i - b); k < i; ++k) x[k] -= row_i[k] * xi;
  }
}

double ComplexBandedLdlt::pivot_ratio() const {
  const double largest = pivots_.cwiseAbs2().maxCoeff();
  return largest > 0.0 ? std::sqrt(pivots_.cwiseAbs2().minCoeff() / largest) : 0.0;
}

double ComplexBandedLdlt::determinant_phase() const {
  // The product of the pivots, rescaled by a power of two (exact, no change of phase) whenever
  // it leaves [2^-256, 2^256]: the determinant itself over- or underflows for a few hundred
  // unknowns.
  Complex product(1.0, 0.0);
  for (Eigen::Index i = 0; i < n_; ++i) {
    product *= pivots_[i];
    const double size = std::max(std::abs(product.real()), std::abs(product.imag()));
    int exponent = 0;
    std::frexp(size, &exponent);
    if (exponent > 256 || exponent < -256) product = std::ldexp(1.0, -exponent) * product;
  }
  return std::arg(product);
}

}  // namespace catena::internal
