// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Complex symmetric (not Hermitian) banded LDL^T without pivoting, for the damped fe chain's
/// dynamic matrix Q(lambda) = K + lambda C + lambda^2 M (docs/explanation/methods/fe.md,
/// "Damping"). Q is complex symmetric (K, C, M real symmetric), so A = L D L^T with a unit lower
/// banded L and complex pivots D: det Q = prod D_i, whose phase the argument-principle count reads
/// (fe_argument_count.hpp), and the same factor solves the damped forced response and polishes the
/// damped eigenpairs. Written by hand as the real BandedLdlt beside it (fe_banded_ldlt.hpp): Eigen
/// has no banded complex symmetric factorisation, and its SparseLU (pivoting, a symbolic analysis
/// per matrix) costs tens of times more on a half bandwidth of 3. Without pivoting the
/// factorisation fails (returns false) on a zero or non-finite pivot; the callers check the
/// smallest pivot against the largest.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <complex>
#include <vector>

namespace catena::internal {

class ComplexBandedLdlt {
 public:
  using Complex = std::complex<double>;
  /// Factors K + lambda C + lambda^2 M (the lower triangles are read; the band is the widest of
  /// the three).
  bool factorize(const Eigen::SparseMatrix<double>& K,
                 const Eigen::SparseMatrix<double>& C,
                 const Eigen::SparseMatrix<double>& M,
                 Complex lambda);
  /// Keeps the bands of K, C and M (lower triangles) for factorize(lambda): a run of
  /// factorisations of one pencil (the count's boundary walk, the polishing steps) then forms
  /// each Q(lambda) from three band arrays, not from the sparse matrices.
  void set_pencil(const Eigen::SparseMatrix<double>& K,
                  const Eigen::SparseMatrix<double>& C,
                  const Eigen::SparseMatrix<double>& M);
  /// Factors K + lambda C + lambda^2 M of the pencil set last.
  bool factorize(Complex lambda);
  /// After factorize(lambda): d/dlambda log det Q = tr(Q^{-1} (C + 2 lambda M)) (Jacobi's formula),
  /// with the entries of Q^{-1} inside the band from the factors by Takahashi's recurrence
  /// (O(n b^2), the cost of the factorisation).
  Complex log_derivative(Complex lambda) const;
  /// Solves A x = b in place.
  void solve_in_place(Complex* x) const;
  const Eigen::VectorXcd& pivots() const { return pivots_; }
  /// min |D_i| / max |D_i|.
  double pivot_ratio() const;
  /// arg det A = sum arg D_i, reduced to (-pi, pi] (as a unit complex product, no overflow).
  double determinant_phase() const;
  Eigen::Index rows() const { return n_; }

 private:
  void scatter(const Eigen::SparseMatrix<double>& A, Complex scale);
  bool factor_in_place();
  // The pencil's bands: per matrix, n * (b + 1) values, row i's L-part then its diagonal.
  std::vector<double> band_K_, band_C_, band_M_;
  int pencil_bandwidth_ = 0;
  Eigen::Index n_ = 0;
  int bandwidth_ = 0;
  // Row i holds L(i, i - b .. i - 1) at [i * b + (j - i + b)], j = column (as BandedLdlt).
  std::vector<Complex> lower_;
  Eigen::VectorXcd pivots_;
  Eigen::VectorXcd inverse_pivots_;
  // Takahashi's band of the inverse (log_derivative), kept between calls.
  mutable std::vector<Complex> inverse_band_;
};

}  // namespace catena::internal
