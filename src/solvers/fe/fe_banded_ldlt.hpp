// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Symmetric banded LDL^T factorisation without pivoting, for the fe solver's block-tridiagonal
/// matrices (half bandwidth 3 in plane, 1 out of plane). Without pivoting the factorisation is a
/// congruence A = L D L^T, so the signs of the pivots D give the inertia of A (Sylvester's law):
/// the number of negative pivots of K - sigma M is the number of eigenvalues below sigma. This is
/// the classical Sturm-count argument; it is reliable as long as no pivot is tiny, which the
/// callers check (a tiny pivot means sigma sits on an eigenvalue).
///
/// Cost: O(n b^2) to factor, O(n b) per solve, no symbolic analysis and no index indirection, which
/// is what makes the shift-invert Lanczos iterations cheap here (Eigen's general SimplicialLDLT
/// takes several times longer on the same band). The half bandwidths 1 and 3 of the fe matrices
/// have kernels with a fixed inner length (the compiler unrolls them); every other bandwidth runs
/// the same loops with a run-time length. Both do the same operations in the same order, so the
/// result does not depend on which kernel ran. The storage is kept between factorisations: a
/// factorisation of the same or a smaller size allocates nothing.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace catena::internal {

class BandedLdlt {
 public:
  /// Factors the symmetric matrix A (both triangles stored or only the lower: the lower is read).
  /// Returns false when a pivot is zero or not finite.
  bool factorize(const Eigen::SparseMatrix<double>& A);
  /// Factors A = K - sigma M without forming A (M's pattern must lie within the band of K's or
  /// widen it; each entry is k - sigma m, as the sparse difference would compute it).
  bool factorize(const Eigen::SparseMatrix<double>& K,
                 const Eigen::SparseMatrix<double>& M,
                 double sigma);

  /// Solves A x = b in place (b may hold several columns).
  void solve_in_place(Eigen::Ref<Eigen::MatrixXd> b) const;
  void solve_in_place(double* b) const;

  /// The pivots D.
  const Eigen::VectorXd& pivots() const { return pivots_; }
  /// Number of negative pivots (= eigenvalues of A below 0; of (K, M) below sigma for A = K - sigma
  /// M).
  int negative_pivots() const;
  /// min |D_i| / max |D_i|.
  double pivot_ratio() const;
  Eigen::Index rows() const { return n_; }

 private:
  // Sizes the storage for A's n and half bandwidth and scatters A's lower triangle, scaled by
  // `scale` and added to what is there (the first call of a factorisation starts from zero).
  void prepare(Eigen::Index n, int bandwidth);
  void scatter(const Eigen::SparseMatrix<double>& A, double scale);
  bool factor_scattered();
  template <int B>
  bool factor_rows();
  template <int B>
  void solve_rows(double* x) const;

  Eigen::Index n_ = 0;
  int bandwidth_ = 0;
  // Row i holds L(i, i - b .. i - 1) at [i * b + (j - i + b)], j = column.
  std::vector<double> lower_;
  Eigen::VectorXd pivots_;
};

}  // namespace catena::internal
