#pragma once
/// \file
/// Symmetric banded LDL^T factorisation without pivoting, for the fe solver's block-tridiagonal
/// matrices (half bandwidth 3 in plane, 1 out of plane). Without pivoting the factorisation is a
/// congruence A = L D L^T, so the signs of the pivots D give the inertia of A (Sylvester's law):
/// the number of negative pivots of K - sigma M is the number of eigenvalues below sigma. This is
/// the classical Sturm-count argument; it is reliable as long as no pivot is tiny, which the callers
/// check (a tiny pivot means sigma sits on an eigenvalue).
///
/// Cost: O(n b^2) to factor, O(n b) per solve, no symbolic analysis and no index indirection, which
/// is what makes the shift-invert Lanczos iterations cheap here (Eigen's general SimplicialLDLT
/// takes several times longer on the same band).

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace catena::internal {

class BandedLdlt {
 public:
  /// Factors the symmetric matrix A (both triangles stored or only the lower: the lower is read).
  /// Returns false when a pivot is zero or not finite.
  bool factorize(const Eigen::SparseMatrix<double>& A);

  /// Solves A x = b in place (b may hold several columns).
  void solve_in_place(Eigen::Ref<Eigen::MatrixXd> b) const;
  void solve_in_place(double* b) const;

  /// The pivots D.
  const Eigen::VectorXd& pivots() const { return pivots_; }
  /// Number of negative pivots (= eigenvalues of A below 0; of (K, M) below sigma for A = K - sigma M).
  int negative_pivots() const;
  /// min |D_i| / max |D_i|.
  double pivot_ratio() const;
  Eigen::Index rows() const { return n_; }

 private:
  Eigen::Index n_ = 0;
  int bandwidth_ = 0;
  // Row i holds L(i, i - b .. i - 1) at [i * b + (j - i + b)], j = column.
  std::vector<double> lower_;
  Eigen::VectorXd pivots_;
};

}  // namespace catena::internal
